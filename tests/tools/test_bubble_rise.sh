#!/usr/bin/env bash
# ctest tools.bubble_rise: tools/bubble_rise.py's nose radius of lattice discs (within 1.5 spacings) and of a
# lattice cap (10 %), none for a flat layer; --windows' speeds and Froude numbers of a disc carried up at a known
# speed; and the tool fails cleanly (exit 1) on bad input.
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

# --windows on a run made by hand: a lattice disc of 2 cm (l0 = 2.5 mm) carried up rigidly at U = 0.25 m/s, frames
# every 10 ms from 0.05 to 0.15 s. Each window of 0.05 s reads the apex and the centroid at U, and their Froude
# numbers U/(g R)^(1/2) at the nose radius the summary measures, within 0.5 % (the printed digits).
run="$work/run"
"$py" - "$run" "$source_dir" <<'PY'
import os, sys
import numpy as np
run = sys.argv[1]
sys.path.insert(0, os.path.join(sys.argv[2], "tests", "tools"))
from hand_made_run import write_frames
l0, U = 0.0025, 0.25
os.makedirs(run)
with open(os.path.join(run, "case.toml"), "w") as f:
    f.write(f"[case]\nname = \"rise_test\"\ndimension = 2\n[numerics]\nparticle_spacing = {l0}\n")
disc = [(i * l0, j * l0) for i in range(-8, 9) for j in range(-8, 9) if np.hypot(i, j) * l0 < 0.02]
times = [0.05 + 0.01 * k for k in range(11)]
frames = [[(0.1 + x, 0.06 + y + U * t, 0, 1) for x, y in disc] for t in times]
write_frames(run, times, frames, [[(0.0, U)] * len(disc)] * len(times),
             arrays={"enclosed": ("UInt8", [1] * len(disc))})
PY
"$py" "$tool" "$run" --from 0.05 --to 0.15 --windows 0.05 > "$work/out"
"$py" - "$work/out" <<'PY'
import math, re, sys
text = open(sys.argv[1]).read()
radius = float(re.search(r"nose radius\s+median ([0-9.]+) cm", text).group(1)) / 100
windows = re.findall(r"^(\d\.\d+)-\d\.\d+\s+([-0-9.]+)\s+([-0-9.]+)\s+([0-9.]+)\s+([-0-9.]+)\s+([-0-9.]+)$", text, re.M)
assert len(windows) == 2, text
froude = 0.25 / math.sqrt(9.81 * radius)
for start, apex, centroid, r, fr_apex, fr_centroid in windows:
    assert abs(float(apex) - 0.25) < 1e-3 and abs(float(centroid) - 0.25) < 1e-3, (apex, centroid)
    assert abs(float(r) / 100 - radius) < 1e-4, (r, radius)
    assert abs(float(fr_apex) / froude - 1) < 5e-3 and abs(float(fr_centroid) / froude - 1) < 5e-3, (fr_apex, froude)
PY

source "$(dirname "${BASH_SOURCE[0]}")/expect_fail.sh"
expect_fail "a window is a positive number" "$run" --windows -0.01
expect_fail "is not a directory" "$work/missing"
mkdir -p "$work/empty"
expect_fail "does not exist" "$work/empty"
