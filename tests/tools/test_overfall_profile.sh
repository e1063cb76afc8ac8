#!/usr/bin/env bash
# ctest tools.overfall_profile: tools/overfall_profile.py measures the brink depth and the nappe of a 2D run.
# A run directory made by hand: two rows of water particles, the lower on the bed's top edge as on mistfall's
# lattice at l0 = 1 cm (so a 2 cm deep channel by the tool's count, depth = N l0^2 / window; counting only particles
# above the edge found 1 cm) moving at (U, V) = (0.7, -0.1) m/s up to the brink, a sheet of particles on the
# ballistic path of a point leaving the brink's mid-depth with that velocity (three per level and one stray drop
# far off, which the median must ignore), and a pool. The tool must find the 2 cm depth, the velocity, and the
# sheet on that path (RMS under 2 mm), the jet's velocity from the brink's momentum flux with the channel's water at
# 70 Pa, and the channel's specific energy; the sheet through splash beyond it (the first water from the cavity);
# bad input exits 1 with a message.
# Usage: test_overfall_profile.sh SOURCE_DIR
set -euo pipefail
source_dir=$1
py=/usr/bin/python3
tool="$source_dir/tools/overfall_profile.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run="$work/run"
mkdir -p "$run/frames"

"$py" - "$run" "$source_dir" <<'PY'
import math, os, sys
run = sys.argv[1]
sys.path.insert(0, os.path.join(sys.argv[2], "tests", "tools"))
from hand_made_run import write_frames
l0, g, u, v = 0.01, 9.81, 0.7, -0.1
x_brink, y_bed, pool = 0.30, 0.435, 0.11
with open(os.path.join(run, "case.toml"), "w") as f:
    f.write(f"""[case]
name = "overfall_test"
dimension = 2
[physics]
gravity = [0.0, -{g}]
[numerics]
particle_spacing = {l0}
[[region]]
name = "channel_bed"
material = "wall"
min = [0.0, 0.395]
max = [{x_brink}, {y_bed}]
[[region]]
name = "weir"
material = "wall"
min = [1.0, 0.0]
max = [1.04, {pool}]
[[inflow]]
name = "upstream"
min = [0.0, {y_bed}]
max = [0.04, 0.485]
direction = [1, 0]
discharge = 0.016
""")
pts = []                                  # (x, y, kind, phase)
for i in range(10):                       # the channel's last 10 cm: 2 rows, the lower ON the bed's top edge, as
                                          # on mistfall's lattice at l0 = 1 cm (bed top 0.435 = a lattice point)
    for j in range(2):
        pts.append((x_brink - 0.095 + i * l0, y_bed + j * l0, 0, 0))
y0 = y_bed + 0.01                         # mid-depth of the 2 cm deep brink
level = y_bed - l0
while level > 0.2:
    t = (v + math.sqrt(v * v + 2 * g * (y0 - level))) / g
    x = x_brink + u * t
    pts += [(x - 0.002, level, 0, 0), (x, level, 0, 0), (x + 0.002, level, 0, 0), (x + 0.25, level, 0, 0)]
    level -= l0
for i in range(60):                       # pool and a wall row
    pts += [(0.005 + i * l0, 0.105, 0, 0), (0.005 + i * l0, -0.005, 1, 0), (0.005 + i * l0, 0.3, 0, 1)]
# The channel's water at 70 Pa: the brink's momentum flux over its mass flux is U_j = u + p / (rho u) = 0.8 m/s.
write_frames(run, [0.5], pts, [(u, v)] * len(pts), [70.0 if p[1] >= y_bed else 0.0 for p in pts])
PY

out=$("$py" "$tool" "$run")
echo "$out"
"$py" - "$out" <<'PY'
import math, re, sys
out = sys.argv[1]
depth = float(re.search(r"brink depth\s+measured ([0-9.]+) cm", out).group(1))
edge = float(re.search(r"over the last l0 only ([0-9.]+) cm", out).group(1))
u, v = (float(s) for s in re.search(r"measured U = ([-0-9.]+) m/s, V = ([-0-9.]+) m/s", out).groups())
rms = float(re.search(r"from the measured brink ([0-9.]+) cm", out).group(1))
ratio = float(re.search(r"measured/critical = ([0-9.]+)", out).group(1))
assert abs(depth - 2.0) < 1e-9, depth
assert abs(edge - 2.0) < 1e-9, edge
assert abs(u - 0.7) < 1e-9 and abs(v + 0.1) < 1e-9, (u, v)
assert abs(ratio - 2.0 / 2.967) < 0.002, ratio      # h_c = (0.016^2 / 9.81)^(1/3) = 2.967 cm
assert rms < 0.2, rms
# The brink section (the last l0) moves as the channel here, so its path is the same.
u_edge, v_edge, rms_edge = (float(s) for s in re.search(
    r"the last l0: U = ([-0-9.]+) m/s, V = ([-0-9.]+) m/s; .* RMS ([0-9.]+) cm", out).groups())
assert abs(u_edge - 0.7) < 1e-9 and abs(v_edge + 0.1) < 1e-9 and rms_edge < 0.2, (u_edge, v_edge, rms_edge)
# Against the path with U_j = 0.8 m/s the sheet (median 1 mm past the 0.7 m/s path) lies 1 mm - 0.1 m/s t behind, at
# the levels from y_bed - l0 down to the pool + 35 % of the drop (0.425 ... 0.225 m).
u_jet = float(re.search(r"U_j = ([0-9.]+) m/s", out).group(1))
offset, scatter = (float(s) for s in re.search(r"mean ([-+0-9.]+) cm, scatter about the mean ([0-9.]+) cm", out).groups())
assert abs(u_jet - 0.8) < 1e-9, u_jet
times = [(-0.1 + math.sqrt(0.01 + 2 * 9.81 * (0.445 - (0.425 - 0.01 * k)))) / 9.81 for k in range(21)]
lag = [0.1 - 10.0 * t for t in times]          # in cm: 1 mm - 0.1 m/s t
mean = sum(lag) / len(lag)
assert abs(offset - mean) < 0.006, (offset, mean)
assert abs(scatter - math.sqrt(sum((d - mean) ** 2 for d in lag) / len(lag))) < 0.006, scatter
# The channel's specific energy in 4 cm bins from the inflow box's end (x = 0.04; no gate region here) to the
# brink: water only in the bins [0.20, 0.24) and [0.24, 0.28), 4 columns of 2 rows each: h = 8 l0^2 / 0.04 = 2 cm,
# U = 0.7 m/s, E = h + U^2 / (2 g) = 1.516 h_c; the bins without water are left out.
rows = re.findall(r"^\s+(0\.\d{3})\s+([0-9.]+)\s+([-0-9.]+)\s+([0-9.]+)\s+([0-9.]+)$", out.split("channel energy")[1], re.M)
assert [r[0] for r in rows] == ["0.220", "0.260"], rows
h_c = (0.016 ** 2 / 9.81) ** (1 / 3)
for x, h, u, froude, energy in rows:
    assert float(h) == 2.0 and float(u) == 0.7, (x, h, u)
    assert abs(float(froude) - 0.7 / math.sqrt(9.81 * 0.02)) < 0.006, froude
    assert abs(float(energy) - (0.02 + 0.7 ** 2 / (2 * 9.81)) / h_c) < 0.0006, energy
print("overfall_profile: depth, velocity, nappe and channel energy recovered")
PY
test -s "$run/plots/overfall.png"
test -s "$run/plots/overfall.csv"

# The brink section: the last l0 of the channel moves at (0.8, -0.15) m/s, the l0 before it at (0.7, -0.1), and the
# sheet leaves the section's mid-depth with the section's velocity. The tool must put the sheet on the section's path
# (RMS under 2 mm) and 0.5 cm and more off the path with the 2 l0 window's mean velocity (0.75, -0.125).
section="$work/section"
mkdir -p "$section" && cp "$run/case.toml" "$section/case.toml"
"$py" - "$section" "$source_dir" <<'PY'
import math, os, sys
sys.path.insert(0, os.path.join(sys.argv[2], "tests", "tools"))
from hand_made_run import write_frames
l0, g, x_brink, y_bed = 0.01, 9.81, 0.30, 0.435
pts, vel = [], []
for i in range(10):
    for j in range(2):
        x = x_brink - 0.095 + i * l0
        pts.append((x, y_bed + j * l0, 0, 0))
        vel.append((0.8, -0.15) if x > x_brink - l0 else (0.7, -0.1))
level = y_bed - l0
while level > 0.2:
    t = (-0.15 + math.sqrt(0.15 ** 2 + 2 * g * (y_bed + 0.01 - level))) / g
    pts.append((x_brink + 0.8 * t, level, 0, 0))
    vel.append((0.8, -0.15 - g * t))
    level -= l0
write_frames(sys.argv[1], [0.5], pts, vel)
PY
out=$("$py" "$tool" "$section")
"$py" - "$out" <<'PY'
import re, sys
out = sys.argv[1]
window = float(re.search(r"from the measured brink ([0-9.]+) cm", out).group(1))
section = float(re.search(r"the last l0: U = 0.800 m/s, V = -0.150 m/s; .* RMS ([0-9.]+) cm", out).group(1))
assert section < 0.2 and window > 0.5, (section, window)
PY

# Splash beyond the sheet: the brink section's sheet again, and at the five lowest levels eight drops 8-15 cm
# downstream of it (the plunge zone's mound and spray). The median of all water at those levels lies in the splash;
# the first water met from the cavity is the sheet's, on its path (RMS under 2 mm), where the median is 2 cm and more off.
splash="$work/splash"
mkdir -p "$splash" && cp "$run/case.toml" "$splash/case.toml"
"$py" - "$splash" "$source_dir" <<'PY'
import math, os, sys
sys.path.insert(0, os.path.join(sys.argv[2], "tests", "tools"))
from hand_made_run import write_frames
l0, g, x_brink, y_bed = 0.01, 9.81, 0.30, 0.435
pts = [(x_brink - 0.095 + i * l0, y_bed + j * l0, 0, 0) for i in range(10) for j in range(2)]
levels = []
level = y_bed - l0
while level > 0.2:
    levels.append(level)
    level -= l0
for k, level in enumerate(levels):
    t = (-0.1 + math.sqrt(0.01 + 2 * g * (y_bed + 0.01 - level))) / g
    x = x_brink + 0.7 * t
    pts += [(x - 0.002, level, 0, 0), (x + 0.002, level, 0, 0)]
    if k >= len(levels) - 5:
        pts += [(x + 0.08 + 0.01 * i, level, 0, 0) for i in range(8)]
write_frames(sys.argv[1], [0.5], pts, [(0.7, -0.1)] * len(pts))
PY
out=$("$py" "$tool" "$splash")
"$py" - "$out" <<'PY'
import re, sys
out = sys.argv[1]
median = float(re.search(r"the last l0: U = 0.700 m/s, V = -0.100 m/s; .* RMS ([0-9.]+) cm", out).group(1))
first = float(re.search(r"sheet from cavity .* RMS ([0-9.]+) cm from the brink section's path", out).group(1))
assert first < 0.2 and median > 2.0, (first, median)
PY
grep -q "x_sheet_from_cavity" "$splash/plots/overfall.csv"

# The standard error of the brink depth from block means: four frames 0.5 s apart, the channel 2, 3, 2 and 3 rows
# deep at the brink: mean 2.5 cm, block means 2, 3, 2, 3 cm, standard error std(ddof 1) / sqrt(4) = 0.2887 cm =
# 0.0973 h_c; with blocks of 1 s (two frames each) the block means are equal and the error is 0.
blocks="$work/blocks"
mkdir -p "$blocks" && cp "$run/case.toml" "$blocks/case.toml"
"$py" - "$blocks" "$source_dir" <<'PY'
import os, sys
sys.path.insert(0, os.path.join(sys.argv[2], "tests", "tools"))
from hand_made_run import write_frames
frames = []
for rows in (2, 3, 2, 3):
    pts = [(0.205 + i * 0.01, 0.435 + j * 0.01, 0, 0) for i in range(10) for j in range(rows)]
    pts += [(0.33, 0.30, 0, 0)]            # one particle of sheet, below the brink
    frames.append(pts)
write_frames(sys.argv[1], [0.5, 1.0, 1.5, 2.0], frames, [[(0.7, -0.1)] * len(p) for p in frames])
PY
out=$("$py" "$tool" "$blocks" --from 0.5)
echo "$out"
"$py" - "$out" <<'PY'
import re, sys
out = sys.argv[1]
ratio = float(re.search(r"measured/critical = ([0-9.]+)", out).group(1))
error = float(re.search(r"standard error\s+of measured/critical \+- ([0-9.]+) \((\d+) blocks", out).group(1))
blocks = int(re.search(r"\+- [0-9.]+ \((\d+) blocks", out).group(1))
assert abs(ratio - 2.5 / 2.967) < 0.002, ratio
assert blocks == 4 and abs(error - 0.0973) < 0.001, (error, blocks)
PY
out=$("$py" "$tool" "$blocks" --from 0.5 --block 1.0)
echo "$out" | grep -q "+- 0.000 (2 blocks of 1 s" || { echo "1 s blocks: $out"; exit 1; }
out=$("$py" "$tool" "$blocks" --from 0.5 --to 0.5)
echo "$out" | grep -q "standard error  none" || { echo "one frame: $out"; exit 1; }
if "$py" "$tool" "$blocks" --block 0 2>"$work/err"; then echo "--block 0 accepted"; exit 1; fi
grep -q "block must be > 0" "$work/err"
if "$py" "$tool" "$blocks" --energy-bin 0 2>"$work/err"; then echo "--energy-bin 0 accepted"; exit 1; fi
grep -q "energy-bin must be > 0" "$work/err"

# Bad input: a missing run, a run without a brink region.
if "$py" "$tool" "$work/missing" 2>"$work/err"; then echo "missing run accepted"; exit 1; fi
grep -q "overfall_profile:" "$work/err"
if "$py" "$tool" "$run" --bed-region nothere 2>"$work/err"; then echo "bad region accepted"; exit 1; fi
grep -q "no \[\[region\]\] named 'nothere'" "$work/err"
echo "tools.overfall_profile: ok"
