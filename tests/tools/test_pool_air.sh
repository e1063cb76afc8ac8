#!/usr/bin/env bash
# ctest tools.pool_air: tools/pool_air.py's air in the pool (gas fluid particles under y = 0.14 m with x in 0.3-1.0 m,
# and every bubble point) and water above it (liquid fluid particles above y = 0.15 m, x in 0.3-1.0 m), a frame.
# A run directory made by hand: in the window (t = 2.0, 2.5 s) the frames hold 3 + 2 and 6 + 1 air (gas particles
# + bubble points, one of the points far from the pool) and 4 and 10 water particles above the pool, so 6.0 and 7.0 a
# frame; around them, in every frame, what must not count: gas above y = 0.14 m or outside the span, liquid under
# the pool, wall, escaped and inflow particles, water beside the span; and a frame at t = 1.0 s, outside the window,
# with 10 gas particles, 10 points and 12 water particles. The options move the span and the heights. The pool's
# packing (with [numerics] particle_spacing = 0.1 m in case.toml; no line without it): under y = 0.10 m in the span
# the frames hold 3 and 6 gas and 1 and 1 water fluid particles (not the water under the floor), in a box of 7 l0^2,
# so 0.786 (water 0.143, air 0.643). Bad input exits 1 with a one-line message.
# Usage: test_pool_air.sh SOURCE_DIR
set -euo pipefail
source_dir=$1
py=/usr/bin/python3
tool="$source_dir/tools/pool_air.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run="$work/run"

"$py" - "$run" "$source_dir" <<'PY'
import os, sys
run = sys.argv[1]
sys.path.insert(0, os.path.join(sys.argv[2], "tests", "tools"))
from hand_made_run import write_frames
FLUID, WALL, ESCAPED, INFLOW, POINT = 0, 1, 3, 4, 5
LIQUID, GAS = 0, 1

def frame(gas, points, water):
    pts = [(0.35 + 0.05 * k, 0.05, FLUID, GAS) for k in range(gas)]            # air in the pool
    pts += [(0.5, 0.08, POINT, GAS)] * (points - 1) + [(0.1, 0.5, POINT, GAS)]  # bubble points: anywhere
    pts += [(0.32 + 0.06 * k, 0.2, FLUID, LIQUID) for k in range(water)]      # water above the pool
    pts += [(0.5, 0.145, FLUID, GAS), (0.6, 0.3, FLUID, GAS),                  # gas above y = 0.14 m
            (0.25, 0.05, FLUID, GAS), (1.05, 0.05, FLUID, GAS),                # gas outside x 0.3-1.0 m
            (0.5, 0.05, WALL, GAS), (0.5, 0.05, ESCAPED, GAS),                 # not fluid
            (0.5, 0.05, FLUID, LIQUID), (0.5, 0.145, FLUID, LIQUID),           # water in the pool
            (0.2, 0.44, FLUID, LIQUID), (1.02, 0.2, FLUID, LIQUID),            # water beside the span
            (0.5, 0.2, WALL, LIQUID), (0.5, 0.2, INFLOW, LIQUID),              # not fluid
            (0.5, -0.01, FLUID, LIQUID)]                                       # under the floor
    return pts

frames = [frame(10, 10, 12), frame(3, 2, 4), frame(6, 1, 10)]
write_frames(run, [1.0, 2.0, 2.5], frames, [[(0.0, 0.0)] * len(f) for f in frames])
PY

check() {  # check OUTPUT FRAMES AIR WATER
  "$py" - "$@" <<'PY'
import re, sys
out, frames, air, water = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
assert f"frames {frames} " in out, out
m = re.search(r"air in the pool\s+([0-9.]+) a frame", out)
assert m and abs(float(m.group(1)) - air) < 1e-9, out
m = re.search(r"water above the pool\s+([0-9.]+) a frame", out)
assert m and abs(float(m.group(1)) - water) < 1e-9, out
PY
}

out=$("$py" "$tool" "$run")                    # the default window: from 2 s to the last frame
echo "$out"
check "$out" 2 6.0 7.0
if grep -q "packing" <<<"$out"; then echo "FAIL: a packing without the particle spacing" >&2; exit 1; fi
printf '[case]\nname = "hand"\n[numerics]\nparticle_spacing = 0.1\n' >"$run/case.toml"
out=$("$py" "$tool" "$run")
check "$out" 2 6.0 7.0
grep -q "the pool's packing     0.786 (.* l0 = 0.1 m: water 0.143, air 0.643); least 0.571, most 1.000" <<<"$out" ||
  { echo "FAIL: the pool's packing: $out" >&2; exit 1; }
grep -q "the pool's packing     0.000 " <<<"$("$py" "$tool" "$run" --packing-below 0.04)" ||
  { echo "FAIL: the packing's height" >&2; exit 1; }
grep -q "gas particles under y = 0.14 m, x 0.3-1 m: 4.5; bubble points: 1.5" <<<"$out" ||
  { echo "FAIL: gas particles and points apart" >&2; exit 1; }
check "$("$py" "$tool" "$run" --from 2.2)" 1 7.0 10.0
check "$("$py" "$tool" "$run" --from 0 --to 2.0)" 2 12.5 8.0
# The span 0.3-0.47 m keeps the gas at x = 0.35, 0.40, 0.45 (3 and 3; the points count wherever they lie) and the
# water at x = 0.32, 0.38, 0.44 (3 and 3); --air-below 0.146 adds the gas at y = 0.145 m; --water-above 0.25 leaves
# none of the water.
check "$("$py" "$tool" "$run" --x-to 0.47)" 2 4.5 3.0
check "$("$py" "$tool" "$run" --air-below 0.146 --water-above 0.25)" 2 7.0 0.0
"$py" "$tool" --help | grep -q "waterfall cases" || { echo "FAIL: --help" >&2; exit 1; }

source "$(dirname "${BASH_SOURCE[0]}")/expect_fail.sh"
expect_fail "is not a directory" "$work/missing"
mkdir -p "$work/empty"
expect_fail "frames.pvd does not exist" "$work/empty"
expect_fail "no frame between t = 5" "$run" --from 5
expect_fail "must lie below --x-to" "$run" --x-from 1.0 --x-to 0.3
expect_fail "invalid float" "$run" --x-to far
expect_fail "must be above the floor" "$run" --packing-below 0
echo "pool_air: ok"
