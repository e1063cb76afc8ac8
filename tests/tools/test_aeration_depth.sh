#!/usr/bin/env bash
# ctest tools.aeration_depth: tools/aeration_depth.py measures the plunging jet under the pool and the air it carries.
# A run directory made by hand (l0 = 1 cm): a pool 14 cm deep on a lattice, one column of it moving down at the plane
# jet's centreline speed K V0 (B / s)^(1/2) (Rajaratnam's K = 2.47, V0 and B from the case's q and drop as the tool
# computes them), three air particles among the water at depths 2.5, 6.5 and 12.5 cm, and air above the pool and at
# its surface, which are not under water. The tool must find the 14 cm level, the three air particles and their
# depths, and the jet at 1.00 of the correlation; bad input exits 1 with a message.
# The correlation is capped at V0 within the jet's potential core.
# Usage: test_aeration_depth.sh SOURCE_DIR
set -euo pipefail
source_dir=$1
py=/usr/bin/python3
tool="$source_dir/tools/aeration_depth.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run="$work/run"
mkdir -p "$run/frames"

"$py" - "$run" "$source_dir" <<'PY'
import math, os, sys
run = sys.argv[1]
sys.path.insert(0, os.path.join(sys.argv[2], "tests", "tools"))
from hand_made_run import write_frames
l0, g, q, y_bed, level = 0.01, 9.81, 0.016, 0.435, 0.14
with open(os.path.join(run, "case.toml"), "w") as f:
    f.write(f"""[case]
name = "aeration_test"
dimension = 2
[physics]
gravity = [0.0, -{g}]
[numerics]
particle_spacing = {l0}
entrained_gas_rise_speed = 0.23
[[region]]
name = "floor"
material = "wall"
min = [-0.04, -0.04]
max = [1.14, 0.0]
[[region]]
name = "channel_bed"
material = "wall"
min = [0.0, 0.395]
max = [0.30, {y_bed}]
[[region]]
name = "weir"
material = "wall"
min = [1.0, 0.0]
max = [1.04, 0.11]
[[inflow]]
name = "upstream"
min = [0.0, {y_bed}]
max = [0.04, 0.485]
direction = [1, 0]
discharge = {q}
""")
h = 0.715 * (q * q / g) ** (1 / 3)                     # the tool's plane jet: Rouse's brink, free fall
u_b, v_b = q / h, math.sqrt(2 * g * (y_bed + 0.5 * h - level))
v0, theta = math.hypot(u_b, v_b), math.atan2(v_b, u_b)
b0 = q / v0
pts = []                                               # (x, y, kind, phase, downward speed)
air_at = {(20, 11), (20, 7), (20, 1)}                  # (column, row): depths 2.5, 6.5, 12.5 cm
for i in range(100):
    for j in range(14):
        x, y = 0.005 + i * l0, 0.005 + j * l0
        down = 0.0
        if i == 45:
            s = (level - y) / math.sin(theta)
            down = 2.47 * v0 * math.sqrt(b0 / s)
        pts.append((x, y, 0, 1 if (i, j) in air_at else 0, down))
    pts.append((0.005 + i * l0, -0.005, 1, 0, 0.0))   # the floor's top row
    pts.append((0.005 + i * l0, 0.3, 0, 1, 0.0))      # air above the pool
pts.append((0.705, 0.145, 0, 1, 0.0))                  # air at the surface, within l0 of the level
write_frames(run, [1.0, 1.1], [p[:4] for p in pts], [(0.0, -p[4]) for p in pts])
PY

out=$("$py" "$tool" "$run" --from 1.0)
echo "$out"
"$py" - "$out" <<'PY'
import re, sys
out = sys.argv[1]
num = lambda pattern: float(re.search(pattern, out).group(1))
assert "frames averaged: 2" in out, out
assert abs(num(r"pool level\s+([0-9.]+) cm") - 14.0) < 1e-6
assert abs(num(r"air under water ([0-9.]+) particles") - 3.0) < 1e-9
assert abs(num(r"deepest ([0-9.]+) cm") - 12.5) < 1e-6
assert abs(num(r"90th pct ([0-9.]+) cm") - 11.3) < 1e-6            # 6.5 + 0.8 (12.5 - 6.5)
assert abs(num(r"lowest quarter of the pool: ([0-9.]+) %") - 33.3) < 0.1
assert abs(num(r"Rajaratnam's over 1/4-1/2 of the pool depth: ([0-9.]+)") - 1.0) < 0.005
assert num(r"penetration H = B \(K V0/u_t\)\^2 = ([0-9.]+)-") > 3.0  # q V0 K^2 / u_t^2: metres, many pools deep
print("aeration_depth: level, air under water and jet recovered")
PY
test -s "$run/plots/aeration.csv"
# Within the potential core (s < K^2 B) the correlation keeps the jet's V0: it never exceeds V0, and the shallowest
# band (s about half a centimetre, under one B) reads V0 itself.
"$py" - "$run/plots/aeration.csv" "$out" <<'PY'
import csv, re, sys
v0 = float(re.search(r"V0 = ([0-9.]+) m/s", sys.argv[2]).group(1))
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["u_c_rajaratnam"] != "nan"]
for name in ("u_c_albertson", "u_c_rajaratnam"):
    values = [float(r[name]) for r in rows]
    assert max(values) < v0 + 0.006, (name, max(values), v0)
    assert abs(values[0] - v0) < 0.006, (name, values[0], v0)
PY

# Bad input: a missing run, no frame in the window.
if "$py" "$tool" "$work/missing" 2>"$work/err"; then echo "missing run accepted"; exit 1; fi
grep -q "aeration_depth:" "$work/err"
if "$py" "$tool" "$run" --from 5 2>"$work/err"; then echo "empty window accepted"; exit 1; fi
grep -q "no frame between" "$work/err"
echo "tools.aeration_depth: ok"
