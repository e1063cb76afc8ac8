#!/usr/bin/env bash
# ctest: tools/plot_frames.py draws the frames of a real (tiny) run as PNG images with real content.
# Usage: test_plot_frames.sh MISTFALL_BINARY SOURCE_DIR
set -euo pipefail
binary=$1
source_dir=$2
/usr/bin/python3 -c "import numpy, matplotlib" 2>/dev/null ||
  { echo "needs Debian's python3-numpy and python3-matplotlib (make deps installs them)"; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/tiny.toml" <<'TOML'
[case]
name = "tiny"
dimension = 2
[domain]
min = [-0.03, -0.03]
max = [0.23, 0.16]
[numerics]
particle_spacing = 0.01
[output]
end_time = 0.02
interval = 0.01
[[region]]
name = "column"
material = "water"
min = [0.0, 0.0]
max = [0.05, 0.1]
[[region]]
name = "tank"
material = "wall"
min = [-0.03, -0.03]
max = [0.23, 0.0]
[[region]]
name = "left"
material = "wall"
min = [-0.03, 0.0]
max = [0.0, 0.13]
TOML
OMP_NUM_THREADS=1 "$binary" simulate "$work/tiny.toml" --out "$work/run" --plain-progress 2>/dev/null
/usr/bin/python3 "$source_dir/tools/plot_frames.py" "$work/run" --frames all --diagnostics --out "$work/plots" >/dev/null
for f in frame_00000 frame_00001 frame_00002 diagnostics; do
  /usr/bin/python3 - "$work/plots/$f.png" <<'PY'
import sys
import matplotlib.image as mpimg
import numpy as np
img = mpimg.imread(sys.argv[1])
colours = len(np.unique(img.reshape(-1, img.shape[-1]), axis=0))
if colours <= 2:
    sys.exit(f"{sys.argv[1]}: only {colours} colours, the plot is empty")
PY
done
# A missing run directory is a clear error, exit 1.
if /usr/bin/python3 "$source_dir/tools/plot_frames.py" "$work/nothing" 2>"$work/err"; then exit 1; fi
grep -q "is not a directory" "$work/err"
echo "plot_frames: 3 frames and diagnostics drawn"
