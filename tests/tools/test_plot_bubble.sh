#!/usr/bin/env bash
# ctest tools.plot_bubble: tools/plot_bubble.py draws bubble pressure / height against time from bubbles.csv of
# two runs (the largest bubble per time, the divergence from diverged.txt) and fails cleanly (exit 1) on bad input.
# Usage: test_plot_bubble.sh SOURCE_DIR
set -euo pipefail
source_dir=$1
py=/usr/bin/python3
tool="$source_dir/tools/plot_bubble.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

mkdir -p "$work/a" "$work/b"
cat > "$work/a/bubbles.csv" <<'CSV'
time,bubble,particles,mean_pressure,centroid_x,centroid_y,centroid_z,size
0,1,256,0,0.1,0.09,0,0.0016
0.01,1,256,500,0.1,0.095,0,0.0016
0.01,2,3,9999,0.1,0.05,0,0.00002
0.02,1,250,560,0.1,0.1,0,0.0015
CSV
printf 'time,bubble,particles,mean_pressure,centroid_x,centroid_y,centroid_z,size\n0,1,10,0,0,0.05,0,1e-4\n0.005,1,10,4000,0,0.05,0,1e-4\n' \
  > "$work/b/bubbles.csv"
printf 'time = 0.0061\nstep = 12\nreason = test\n' > "$work/b/diverged.txt"
"$py" "$tool" "$work/a" "$work/b" --out "$work/fig2.png" --label one --label two > "$work/out.txt"
[[ -s "$work/fig2.png" ]] || { echo "FAIL: fig2.png was not written" >&2; exit 1; }
"$py" - "$work/fig2.png" <<'PY'
import sys
import matplotlib.image as mpimg
import numpy as np
img = mpimg.imread(sys.argv[1])
if len(np.unique(img.reshape(-1, img.shape[-1]), axis=0)) <= 2:
    sys.exit("FAIL: the plot is empty")
PY
# The largest bubble is the one drawn: its pressure 500 at t = 0.01, not the 3-particle one's 9999.
"$py" - "$source_dir/tools" "$work/a" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
from plot_bubble import largest_bubble_series, divergence_time
t, p, y = largest_bubble_series(sys.argv[2])
assert t == [0.0, 0.01, 0.02] and p == [0.0, 500.0, 560.0] and y == [0.09, 0.095, 0.1], (t, p, y)
assert divergence_time(sys.argv[2]) is None
PY

source "$(dirname "${BASH_SOURCE[0]}")/expect_fail.sh"
mkdir -p "$work/empty"
expect_fail "bubbles.csv does not exist" "$work/empty" --out "$work/x.png"
expect_fail "2 --label for 1" "$work/a" --label x --label y --out "$work/x.png"
expect_fail "is not a directory" "$work/missing" --out "$work/x.png"
printf 'time,particles\n0,1\n' > "$work/empty/bubbles.csv"
expect_fail "expected the columns" "$work/empty" --out "$work/x.png"
[[ ! -e "$work/x.png" ]] || { echo "FAIL: an image was written for bad input" >&2; exit 1; }
echo "plot_bubble: ok"
