#!/usr/bin/env bash
# ctest tools.bubble_rise: tools/bubble_rise.py's nose radius of lattice discs (within 1.5 spacings) and of a
# lattice cap (10 %), none for a flat layer, and the tool fails cleanly (exit 1) on bad input.
# Usage: test_bubble_rise.sh SOURCE_DIR
set -euo pipefail
source_dir=$1
py=/usr/bin/python3
tool="$source_dir/tools/bubble_rise.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$py" - "$source_dir/tools" <<'PY'
import sys
import numpy as np
sys.path.insert(0, sys.argv[1])
from bubble_rise import nose_radius
l0 = 0.0025
grid = np.array([(i * l0, j * l0) for i in range(-20, 21) for j in range(-20, 21)])
# Discs on the lattice, centred on a particle and off it: the nose is the disc's top. The edge is a staircase of
# particles, so the radius is read within 1.5 l0 (measured: 1.93 and 2.10 cm for 2.25 cm at l0 = 2.5 mm).
for R in (0.02, 0.0225, 0.03, 0.04):
    for shift in ((0.0, 0.0), (0.3 * l0, 0.45 * l0)):
        disc = grid[np.hypot(grid[:, 0] + shift[0], grid[:, 1] + shift[1]) < R]
        apex, radius, half = nose_radius(disc, l0)
        assert abs(radius - R) < 1.5 * l0, (R, shift, radius)
        assert abs(half - R) < l0, (R, half)
cap = grid[(np.hypot(grid[:, 0], grid[:, 1] + 0.02) < 0.045) & (grid[:, 1] > -0.005)]  # a cap of radius 4.5 cm
apex, radius, half = nose_radius(cap, l0)
assert abs(radius - 0.045) < 0.1 * 0.045, radius
flat = grid[np.abs(grid[:, 1]) < 0.002]  # a flat layer has no nose
assert np.isnan(nose_radius(flat, l0)[1])
PY

source "$(dirname "${BASH_SOURCE[0]}")/expect_fail.sh"
expect_fail "is not a directory" "$work/missing"
mkdir -p "$work/empty"
expect_fail "does not exist" "$work/empty"
