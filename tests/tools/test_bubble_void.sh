#!/usr/bin/env bash
# ctest tools.bubble_void: tools/bubble_void.py on a run made by hand (l0 = 5 mm): a lattice disc of gas in lattice
# water reads its void as N l0^2 exactly, against eq. (17)'s equilibrium for its pressure; an empty cavity of 12
# lattice sites opened above it is read, less the scalloped band its water rim covers (samples within 0.75 l0 of a rim
# particle: 0.17 l0 deep on average), and a hole in the water beside it, not joined to it, is not; a channel to open
# space is reported open; and the tool fails cleanly (exit 1) on bad input.
# Usage: test_bubble_void.sh SOURCE_DIR
set -euo pipefail
source_dir=$1
py=/usr/bin/python3
tool="$source_dir/tools/bubble_void.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

run="$work/run"
"$py" - "$run" "$source_dir" <<'PY'
import os, sys
import numpy as np
run = sys.argv[1]
sys.path.insert(0, os.path.join(sys.argv[2], "tests", "tools"))
from hand_made_run import write_frames
l0, rho, c = 0.005, 1.2, 340.0
os.makedirs(run)
with open(os.path.join(run, "case.toml"), "w") as f:
    f.write(f"[case]\nname = \"void_test\"\ndimension = 2\n[numerics]\nparticle_spacing = {l0}\n"
            f"[physics.gas]\ndensity = {rho}\nsound_speed = {c}\n")
sites = [((i + 0.5) * l0, (j + 0.5) * l0) for i in range(40) for j in range(30)]  # water 0.2 m x 0.15 m
in_disc = lambda x, y: np.hypot(x - 0.1025, y - 0.0775) < 0.0225
cavity = lambda x, y: 0.09 < x < 0.11 and 0.1 < y < 0.115           # 4 x 3 sites just above the disc
hole = lambda x, y: 0.13 < x < 0.14 and 0.07 < y < 0.08             # 2 x 2 sites a column of water away
channel = lambda x, y: 0.095 < x < 0.11 and y > 0.1                  # up to the open space over the water
def frame(removed):
    kept = [(x, y) for x, y in sites if not removed(x, y)]
    return [(x, y, 0, 1 if in_disc(x, y) else 0) for x, y in kept], [1 if in_disc(x, y) else 0 for x, y in kept]
frames = [frame(lambda x, y: False), frame(lambda x, y: False),
          frame(lambda x, y: cavity(x, y) or hole(x, y)), frame(channel)]
gas = sum(in_disc(x, y) for x, y in sites)
assert not any(in_disc(x, y) for x, y in sites if cavity(x, y))
times = [0.01, 0.02, 0.03, 0.04]
p0 = 500.0
pressures = [p0, p0 + 0.01 * rho * c * c, p0, p0]  # the second: squeezed by 1 % at equilibrium
write_frames(run, times, [f for f, _ in frames], [[(0.0, 0.0)] * len(f) for f, _ in frames],
             arrays={"enclosed": ("UInt8", [e for _, e in frames])})
with open(os.path.join(run, "bubbles.csv"), "w") as f:
    f.write("time,bubble,particles,mean_pressure,centroid_x,centroid_y,centroid_z,size\n")
    for t, p in zip(times, pressures):
        f.write(f"{t},0,{gas},{p},0.1,0.08,0,{gas * l0 * l0}\n")
with open(os.path.join(run, "expected"), "w") as f:
    f.write(f"{gas}\n")
PY
"$py" "$tool" "$run" --reach 10 > "$work/out"
"$py" - "$work/out" "$run/expected" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
gas = int(open(sys.argv[2]).read())
rows = re.findall(r"^(0\.\d+)\s+(\d+)\s+([-0-9.]+)\s+([0-9.]+)\s+([0-9.]+)\s+([-+0-9.]+)(\s+open)?$", text, re.M)
assert len(rows) == 4, text
t, n, p, cells, cavity, departure, is_open = zip(*rows)
assert all(int(k) == gas for k in n), (n, gas)
assert "P_0 = 500.0 Pa" in text, text
# the disc on the lattice: its cells are N l0^2 exactly, no cavity; at 1 % compression A_eq = 0.99 N l0^2
assert float(cells[0]) == 1.0 and float(cavity[0]) == 0.0 and float(departure[0]) == 0.0, rows[0]
assert abs(float(departure[1]) - (1 / 0.99 - 1)) < 1e-4, rows[1]
# the cavity of 12 sites: read as 12 l0^2 less the band its water rim covers, 0.17 l0 deep on average along its
# 3 + 4 + 3 spacings (measured: 10.39 l0^2); the hole of 4 sites away from the bubble is not in it
opened = (float(cells[2]) + float(cavity[2]) - 1.0) * gas
assert abs(opened - (12 - 0.17 * 10)) < 0.3, (opened, rows[2])
assert float(cavity[2]) > 0 and not is_open[2], rows[2]
assert is_open[3] and not any(is_open[:3]), rows
assert re.search(r"largest \|void / A_eq - 1\|: ([0-9.]+)", text), text
PY

source "$(dirname "${BASH_SOURCE[0]}")/expect_fail.sh"
expect_fail "at least 1 sample" "$run" --sample 0
expect_fail "is not a directory" "$work/missing"
expect_fail "no frame with a bubble" "$run" --from 5
echo "tools.bubble_void: passed"
