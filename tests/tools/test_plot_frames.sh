#!/usr/bin/env bash
# ctest tools.plot_frames: tools/plot_frames.py draws the frames of a real (tiny) run as PNG images with real
# content, reads both binary-appended and ascii frames, and fails cleanly (exit 1) on bad input.
# Usage: test_plot_frames.sh MISTFALL_BINARY SOURCE_DIR
set -euo pipefail
binary=$1
source_dir=$2
py=/usr/bin/python3
tool="$source_dir/tools/plot_frames.py"

if ! "$py" -c "import numpy, matplotlib" 2>/dev/null; then
  echo "FAIL: $py lacks numpy/matplotlib: install Debian's python3-matplotlib and python3-numpy (make deps)" >&2
  exit 1
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# A 0.05 x 0.1 m water column at the left of a small open tank (inner 0.2 x 0.13 m, walls 3 layers), l0 = 0.01.
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
name = "bottom"
material = "wall"
min = [-0.03, -0.03]
max = [0.23, 0.0]
[[region]]
name = "left"
material = "wall"
min = [-0.03, 0.0]
max = [0.0, 0.13]
[[region]]
name = "right"
material = "wall"
min = [0.2, 0.0]
max = [0.23, 0.13]
TOML

check_png() {  # file: exists and has more than 2 distinct colours
  "$py" - "$1" <<'PY'
import sys
import matplotlib.image as mpimg
import numpy as np
img = mpimg.imread(sys.argv[1])
colours = len(np.unique(img.reshape(-1, img.shape[-1]), axis=0))
if colours <= 2:
    sys.exit(f"FAIL: {sys.argv[1]}: only {colours} colours, the plot is empty")
PY
}

export OMP_NUM_THREADS=1
"$binary" simulate "$work/tiny.toml" --out "$work/run" --plain-progress 2>"$work/sim.log" ||
  { cat "$work/sim.log" >&2; echo "FAIL: mistfall simulate failed" >&2; exit 1; }
"$py" "$tool" "$work/run" --frames all --diagnostics --out "$work/plots"
for f in frame_00000 frame_00001 frame_00002 diagnostics; do
  [[ -s "$work/plots/$f.png" ]] || { echo "FAIL: $f.png was not written" >&2; exit 1; }
  check_png "$work/plots/$f.png"
done
[[ $(ls "$work/plots" | wc -l) -eq 4 ]] || { ls -a "$work/plots" >&2; echo "FAIL: unexpected files" >&2; exit 1; }

# Coloured by the six-category classification (simulate writes the category array with every frame).
"$py" "$tool" "$work/run" --frames 0 --color category --out "$work/plots_category"
check_png "$work/plots_category/frame_00000.png"

# ASCII frames, default output folder RUN_DIR/plots.
"$binary" simulate "$work/tiny.toml" --out "$work/run_ascii" --ascii --until 0.01 --plain-progress 2>/dev/null
"$py" "$tool" "$work/run_ascii" --frames last --color speed
check_png "$work/run_ascii/plots/frame_00001.png"

# Bad input: a clear message and exit code 1, no traceback.
expect_fail() {  # expected-message args...
  local msg=$1; shift
  local rc=0
  "$py" "$tool" "$@" --out "$work/bad" 2>"$work/err" >/dev/null || rc=$?
  if [[ $rc -ne 1 ]] || ! grep -q "$msg" "$work/err" || grep -q Traceback "$work/err"; then
    cat "$work/err" >&2; echo "FAIL: '$*' should fail with exit 1 and '$msg' (got $rc)" >&2; exit 1
  fi
}
expect_fail "is not a directory" "$work/nothing"
expect_fail "frames.pvd does not exist" "$work/plots"
expect_fail "no frame 7" "$work/run" --frames 7
frame="$work/run/frames/$(ls "$work/run/frames" | head -n 1)"
head -c 2000 "$frame" > "$work/cut" && mv "$work/cut" "$frame"
expect_fail "unreadable frame" "$work/run" --frames 0
[[ ! -e "$work/bad" ]] || [[ -z $(ls -A "$work/bad") ]] || { echo "FAIL: half-written output left" >&2; exit 1; }

echo "plot_frames: 3 frames + diagnostics drawn, ascii frame read, bad input rejected"
