#!/usr/bin/env bash
# ctest tools.water_in_walls: tools/water_in_walls.py's fluid particles past a wall's face. A run directory made by
# hand, l0 = 0.1 m, three walls in its case.toml: the floor (box, y < 0), a weir (box, x 1.0-1.2 m, y 0-0.5 m) and a
# post (circle of radius 0.1 m about (0.5, 0.5)), and a gas region that must not count. Frames at t = 0, 1, 2 s:
#   t = 0: water 0.5 l0 above the floor (outside), water 5 at 0.3 l0 under the floor's face, a wall particle inside;
#   t = 1: water 7 at 0.3 l0 into the weir, air 8 at the post's centre (1.0 l0 in);
#   t = 2: water 7 at 0.8 l0 into the weir, air 8 as before, water 9 at 0.7 l0 under the floor, beside the weir.
# Past the default 0.5 l0: 8 (from 1 s), 9 and 7 (from 2 s); 2 frames, at most 3 in one. Past 0.25 l0: 5 too, and 7
# from 1 s. Bad input exits 1 with a one-line message.
# Usage: test_water_in_walls.sh SOURCE_DIR
set -euo pipefail
source_dir=$1
py=/usr/bin/python3
tool="$source_dir/tools/water_in_walls.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run="$work/run"

"$py" - "$run" "$source_dir" <<'PY'
import os, sys
run = sys.argv[1]
sys.path.insert(0, os.path.join(sys.argv[2], "tests", "tools"))
from hand_made_run import write_frames
FLUID, WALL = 0, 1
LIQUID, GAS = 0, 1
frames = [[(0.5, 0.05, FLUID, LIQUID), (0.5, -0.03, FLUID, LIQUID), (0.5, -0.1, WALL, LIQUID)],
          [(1.03, 0.2, FLUID, LIQUID), (0.5, 0.5, FLUID, GAS)],
          [(1.08, 0.2, FLUID, LIQUID), (0.5, 0.5, FLUID, GAS), (1.06, -0.07, FLUID, LIQUID)]]
ids = [[4, 5, 100], [7, 8], [7, 8, 9]]
write_frames(run, [0.0, 1.0, 2.0], frames, [[(0.0, 0.0)] * len(f) for f in frames],
             pressures=[[0.0] * len(f) for f in frames], arrays={"id": ("Int64", ids)})
with open(os.path.join(run, "case.toml"), "w") as f:
    f.write("""[case]
name = "hand"
[domain]
min = [-0.2, -0.2]
max = [2.0, 1.0]
[numerics]
particle_spacing = 0.1
[[region]]
name = "air"
material = "gas"
min = [0.0, 0.0]
max = [1.0, 1.0]
[[region]]
name = "floor"
material = "wall"
min = [-0.2, -0.2]
max = [2.0, 0.0]
[[region]]
name = "weir"
material = "wall"
min = [1.0, 0.0]
max = [1.2, 0.5]
[[region]]
name = "post"
material = "wall"
shape = "circle"
center = [0.5, 0.5]
radius = 0.1
""")
PY

expect_line() {  # expect_line OUTPUT PATTERN
  grep -q -- "$2" <<<"$1" || { echo "$1" >&2; echo "FAIL: no line '$2'" >&2; exit 1; }
}
out=$("$py" "$tool" "$run")
echo "$out"
expect_line "$out" "^frames 3 (t = 0.000 .. 2.000 s), walls 3, l0 = 0.1 m; counted: fluid particles more than 0.5 l0"
expect_line "$out" "^frames with fluid in a wall  2 (most in one frame: 3); particles 3$"
expect_line "$out" "^  particle 8: air, first in a wall at t = 1 s, in 'post', deepest 1.00 l0$"
expect_line "$out" "^  particle 9: water, first in a wall at t = 2 s, in 'floor', deepest 0.70 l0$"
expect_line "$out" "^  particle 7: water, first in a wall at t = 2 s, in 'weir', deepest 0.80 l0$"
[ "$(grep -c "^  particle" <<<"$out")" = 3 ] || { echo "FAIL: particles listed" >&2; exit 1; }
out=$("$py" "$tool" "$run" --depth 0.25)
expect_line "$out" "^frames with fluid in a wall  3 (most in one frame: 3); particles 4$"
expect_line "$out" "^  particle 5: water, first in a wall at t = 0 s, in 'floor', deepest 0.30 l0$"
expect_line "$out" "^  particle 7: water, first in a wall at t = 1 s, in 'weir', deepest 0.80 l0$"
out=$("$py" "$tool" "$run" --from 1.5 --list 1)
expect_line "$out" "^frames 1 (t = 2.000 .. 2.000 s)"
expect_line "$out" "^frames with fluid in a wall  1 (most in one frame: 3); particles 3$"
[ "$(grep -c "^  particle" <<<"$out")" = 1 ] || { echo "FAIL: --list 1" >&2; exit 1; }
# The lattice shifted by half a spacing (points at -0.2 + 0.1 k): a row falls on the floor's face y = 0, which the
# floor's particles stop below (its top row at y = -0.1), so its face is y = -0.05: water 5 at y = -0.03 is outside
# it and water 9 (y = -0.07) 0.2 l0 inside; the weir's faces move to x = 0.95 and 1.15 (water 7 at x = 1.03, then
# 1.08: 0.8, then 0.7 l0).
cp -r "$run" "$work/shifted"
sed -i 's/^min = \[-0.2, -0.2\]$/min = [-0.25, -0.25]/' "$work/shifted/case.toml"
out=$("$py" "$tool" "$work/shifted" --depth 0.1)
echo "$out"
expect_line "$out" "^  particle 9: water, first in a wall at t = 2 s, in 'floor', deepest 0.20 l0$"
expect_line "$out" "^  particle 7: water, first in a wall at t = 1 s, in 'weir', deepest 0.80 l0$"
! grep -q "^  particle 5:" <<<"$out" || { echo "FAIL: water 5 counted on the shifted lattice" >&2; exit 1; }
"$py" "$tool" --help | grep -q "first row of particles" || { echo "FAIL: --help" >&2; exit 1; }

source "$(dirname "${BASH_SOURCE[0]}")/expect_fail.sh"
expect_fail "is not a directory" "$work/missing"
mkdir -p "$work/empty"
expect_fail "cannot read" "$work/empty"
expect_fail "must be 0 or more" "$run" --depth -1
expect_fail "no frame between t = 5" "$run" --from 5
cp -r "$run" "$work/no_walls"
sed -i 's/material = "wall"/material = "water"/' "$work/no_walls/case.toml"
expect_fail "has no wall region" "$work/no_walls"
cp -r "$run" "$work/no_domain"
sed -i '/^\[domain\]$/,/^max = /d' "$work/no_domain/case.toml"
expect_fail "\\[domain\\] min is missing" "$work/no_domain"
echo "water_in_walls: ok"
