#!/usr/bin/env bash
# ctest tools.bubble_pressure_gap: tools/bubble_pressure_gap.py's P_B - P_water of the enclosed gas clusters.
# A run directory made by hand (l0 = 1 cm): a lattice of water with bubbles cut out of it, each bubble's gas at one
# pressure and the water within 1.5 l0 of it at another (the rest of the water at 3,000 Pa, which a wider ring
# would catch). In the window (t = 2.0, 2.5 s):
#   A  8 gas particles, 1,200 then 1,300 Pa in water at 1,000 Pa: +200, +300;
#   C  6 gas particles (the smallest bubble), 2,100 Pa in water at 2,000 Pa: +100;
#   D  two columns of 3 gas particles 2 l0 apart, one water particle between them: linked within 2.1 l0 into one
#      bubble of 6, 450 Pa in water at 500 Pa: -50;
# and left out: E, 5 enclosed gas particles; F, two columns of 4 enclosed gas 3 l0 apart (two clusters of 4); G, 8 gas
# particles not enclosed; 6 wall particles of phase gas flagged enclosed; a wall particle within 1.5 l0 of A's gas
# (not water); the frames at t = 1.0 and 3.0 s, outside
# the window, where A reads +4,000 Pa. So 6 bubble-frames, gaps -50 -50 +100 +100 +200 +300: median +100, quartiles
# -12.5 and +175 (linear interpolation); water around 500 500 1,000 1,000 2,000 2,000: median 1,000.
# With gas_region_link = 1.5 in the case D is two clusters of 3: 4 bubble-frames, median +150 (+100..+225).
# Bad input exits 1 with a one-line message.
# Usage: test_bubble_pressure_gap.sh SOURCE_DIR
set -euo pipefail
source_dir=$1
py=/usr/bin/python3
tool="$source_dir/tools/bubble_pressure_gap.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run="$work/run"

"$py" - "$run" "$source_dir" <<'PY'
import os, sys
run = sys.argv[1]
sys.path.insert(0, os.path.join(sys.argv[2], "tests", "tools"))
from hand_made_run import write_frames
l0 = 0.01
os.makedirs(run)
with open(os.path.join(run, "case.toml"), "w") as f:
    f.write(f"[case]\nname = \"gap_test\"\ndimension = 2\n[numerics]\nparticle_spacing = {l0}\n")

def block(i0, j0, ni, nj):
    return [(i0 + i, j0 + j) for i in range(ni) for j in range(nj)]

# bubbles: (lattice cells, enclosed, gas pressure, ring water pressure); the rings lie > 3 l0 apart
def bubbles(p_a):
    return [(block(5, 5, 2, 4), 1, p_a, 1000.0),                          # A
            (block(15, 5, 2, 3), 1, 2100.0, 2000.0),                      # C
            (block(25, 5, 1, 3) + block(27, 5, 1, 3), 1, 450.0, 500.0),   # D: 3 + 3, 2 l0 apart
            (block(5, 15, 1, 5), 1, 9000.0, 4000.0),                      # E: 5
            (block(15, 15, 1, 4) + block(18, 15, 1, 4), 1, 9000.0, 4000.0),  # F: 4 + 4, 3 l0 apart
            (block(25, 15, 2, 4), 0, 9000.0, 4000.0)]                     # G: not enclosed

def frame(p_a):
    cells = {}
    for members, enclosed, p_gas, p_ring in bubbles(p_a):
        for c in members:
            cells[c] = (enclosed, p_gas, p_ring)
    pts, pressure, flag = [], [], []
    for i in range(35):
        for j in range(25):
            x, y = (i + 0.5) * l0, (j + 0.5) * l0
            if (i, j) in cells:
                enclosed, p_gas, _ = cells[(i, j)]
                pts.append((x, y, 0, 1)); pressure.append(p_gas); flag.append(enclosed)
                continue
            p = 3000.0
            for (ci, cj), (_, _, p_ring) in cells.items():
                if (ci - i) ** 2 + (cj - j) ** 2 <= 1.5 ** 2 * (1 + 1e-9):
                    p = p_ring
            pts.append((x, y, 0, 0)); pressure.append(p); flag.append(0)
    for i in range(6):  # a floor row of wall particles of phase gas, flagged enclosed: no bubble
        pts.append(((i + 0.5) * l0, -0.5 * l0, 1, 1)); pressure.append(50000.0); flag.append(1)
    pts.append((0.045, 0.05, 1, 0)); pressure.append(50000.0); flag.append(0)  # a wall particle beside A: no water
    return pts, pressure, flag

times = [1.0, 2.0, 2.5, 3.0]
frames = [frame(p) for p in (5000.0, 1200.0, 1300.0, 5000.0)]
write_frames(run, times, [f[0] for f in frames], [[(0.0, 0.0)] * len(f[0]) for f in frames],
             [f[1] for f in frames], {"enclosed": ("UInt8", [f[2] for f in frames])})
PY

check() {  # check OUTPUT BUBBLE_FRAMES MEDIAN Q25 Q75 WATER_MEDIAN
  "$py" - "$@" <<'PY'
import re, sys
out, frames, median, q25, q75, water = sys.argv[1], int(sys.argv[2]), *map(float, sys.argv[3:])
m = re.search(r"bubble-frames\s+(\d+)", out)
assert m and int(m.group(1)) == frames, out
m = re.search(r"P_B - P_water\s+median ([-+0-9.]+) \(([-+0-9.]+)\.\.([-+0-9.]+)\) Pa", out)
assert m, out
got = tuple(float(v) for v in m.groups())
assert all(abs(a - b) < 0.051 for a, b in zip(got, (median, q25, q75))), (got, out)
m = re.search(r"P_water\s+median ([-+0-9.]+) Pa", out)
assert m and abs(float(m.group(1)) - water) < 0.051, out
PY
}

out=$("$py" "$tool" "$run" --from 1.5 --to 2.8 --csv "$work/gap.csv")
echo "$out"
check "$out" 6 100 -12.5 175 1000
grep -q "in 2 frames" <<<"$out" || { echo "FAIL: frames with bubbles" >&2; exit 1; }
[[ $(wc -l < "$work/gap.csv") == 7 ]] || { cat "$work/gap.csv" >&2; echo "FAIL: csv rows" >&2; exit 1; }
# The default window starts at 2 s and runs to the last frame: t = 3.0 s adds A at +4,000, C and D.
out=$("$py" "$tool" "$run")
check "$out" 9 100 -50 200 1000
# The case's gas_region_link (1.5 l0) links touching particles only: D is two clusters of 3, left out.
cp -r "$run" "$work/link"
printf 'gas_region_link = 1.5\n' >> "$work/link/case.toml"
out=$("$py" "$tool" "$work/link" --from 1.5 --to 2.8)
check "$out" 4 150 100 225 1500
# --link overrides the case (here back to 2.1 l0), --min-particles 5 lets E in (+5,000 Pa in water at 4,000 Pa):
# gaps -50 -50 +100 +100 +200 +300 +5,000 +5,000.
out=$("$py" "$tool" "$work/link" --from 1.5 --to 2.8 --link 2.1 --min-particles 5)
check "$out" 8 150 62.5 1475 1500

source "$(dirname "${BASH_SOURCE[0]}")/expect_fail.sh"
expect_fail "is not a directory" "$work/missing"
mkdir -p "$work/empty"
expect_fail "case.toml" "$work/empty"
cp "$run/case.toml" "$work/empty/"
expect_fail "frames.pvd does not exist" "$work/empty"
expect_fail "no frame between t = 5" "$run" --from 5
expect_fail "no enclosed gas cluster of 20 or more" "$run" --min-particles 20
expect_fail "invalid float" "$run" --from soon
# frames written before bubbles were marked carry no 'enclosed' array
mkdir -p "$work/old"
cp "$run/case.toml" "$work/old/"
"$py" - "$work/old" "$source_dir" <<'PY'
import os, sys
sys.path.insert(0, os.path.join(sys.argv[2], "tests", "tools"))
from hand_made_run import write_frames
write_frames(sys.argv[1], [2.0], [(0.0, 0.0, 0, 1)], [(0.0, 0.0)])
PY
expect_fail "has no 'enclosed' array" "$work/old"
echo "bubble_pressure_gap: ok"
