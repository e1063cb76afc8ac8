#!/usr/bin/env bash
# ctest tools.plot_texture: tools/plot_texture.py reads a run's texture/texture.pvd and its point clouds (ascii VTK
# PolyData as `mistfall texture` writes them), writes texture_extent.csv with the mist count and extent per frame,
# the extent plot and a snapshot; bad input exits 1 with a message. The clouds are made by hand: at t = 0.1 s,
# 100 mist particles at x = 0.01 .. 1.00, y = 0.2 and 10 micro-bubbles at y = 0.05; at t = 0.2 s no mist.
# Usage: test_plot_texture.sh SOURCE_DIR
set -euo pipefail
source_dir=$1
py=/usr/bin/python3
tool="$source_dir/tools/plot_texture.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run="$work/run"
mkdir -p "$run/texture"

"$py" - "$run" <<'PY'
import os, sys
run = sys.argv[1]
def cloud(path, time, pts):
    n = len(pts)
    def arr(name, typ, comps, values):
        return (f'<DataArray type="{typ}" Name="{name}" NumberOfComponents="{comps}" format="ascii">'
                + " ".join(str(v) for v in values) + "</DataArray>\n")
    with open(path, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian">\n'
                '<PolyData>\n<FieldData>' + arr("TIME", "Float64", 1, [time]) + '</FieldData>\n'
                f'<Piece NumberOfPoints="{n}" NumberOfVerts="0">\n<Points>'
                + arr("Points", "Float64", 3, [c for p in pts for c in (p[0], p[1], 0.0)]) + '</Points>\n<PointData>\n'
                + arr("kind", "UInt8", 1, [p[2] for p in pts])
                + arr("diameter", "Float64", 1, [7.5e-5] * n)
                + '</PointData>\n</Piece>\n</PolyData>\n</VTKFile>\n')
mist = [(0.01 * (i + 1), 0.2, 1) for i in range(100)]
micro = [(0.5, 0.05, 3) for _ in range(10)]
cloud(os.path.join(run, "texture", "texture_00000.vtp"), 0.1, mist + micro + [(0.4, 0.3, 0)])
cloud(os.path.join(run, "texture", "texture_00001.vtp"), 0.2, micro)
with open(os.path.join(run, "texture", "texture.pvd"), "w") as f:
    f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="1.0">\n<Collection>\n'
            '<DataSet timestep="0.1" file="texture_00000.vtp"/>\n<DataSet timestep="0.2" file="texture_00001.vtp"/>\n'
            '</Collection>\n</VTKFile>\n')
PY

"$py" "$tool" "$run" --frames 0
"$py" - "$run/plots/texture_extent.csv" <<'PY'
import sys
rows = [line.split(",") for line in open(sys.argv[1]).read().split("\n")[1:] if line]
t, mist, micro, x05, x95, y50, y95, micro_y = (float(v) for v in rows[0])
assert (t, mist, micro) == (0.1, 100, 10), rows[0]
assert abs(x05 - 0.0595) < 1e-6 and abs(x95 - 0.9505) < 1e-6, (x05, x95)   # numpy's linear percentiles
assert y50 == 0.2 and y95 == 0.2 and micro_y == 0.05, rows[0]
assert float(rows[1][1]) == 0 and rows[1][3] == "nan", rows[1]
print("plot_texture: counts and extent as built")
PY
test -s "$run/plots/texture_extent.png"
test -s "$run/plots/texture_00000.png"

# [texture] vtp = false: texture.pvd lists nothing and the tool reads the texture_NNNNN.bin files instead (format:
# src/io/texture_files.hpp); the same clouds give the same table.
bin_run="$work/bin_run"
mkdir -p "$bin_run/texture"
"$py" - "$bin_run" <<'PY'
import os, struct, sys
run = sys.argv[1]
def cloud(path, time, pts):
    n = len(pts)
    with open(path, "wb") as f:
        f.write(b"MFTEXTR1" + struct.pack("<IIdQ", 1, 0, time, n))
        f.write(b"".join(struct.pack("<3d", p[0], p[1], 0.0) for p in pts))
        f.write(struct.pack(f"<{3 * n}d", *([0.0] * 3 * n)) + struct.pack(f"<{n}d", *([7.5e-5] * n)))
        f.write(bytes(p[2] for p in pts) + struct.pack(f"<{n}Q", *range(n)))
mist = [(0.01 * (i + 1), 0.2, 1) for i in range(100)]
micro = [(0.5, 0.05, 3) for _ in range(10)]
cloud(os.path.join(run, "texture", "texture_00000.bin"), 0.1, mist + micro + [(0.4, 0.3, 0)])
cloud(os.path.join(run, "texture", "texture_00001.bin"), 0.2, micro)
with open(os.path.join(run, "texture", "texture.pvd"), "w") as f:
    f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="1.0">\n<Collection>\n</Collection>\n</VTKFile>\n')
PY
"$py" "$tool" "$bin_run" --frames 0
cmp "$run/plots/texture_extent.csv" "$bin_run/plots/texture_extent.csv"

if "$py" "$tool" "$work/missing" 2>"$work/err"; then echo "missing run accepted"; exit 1; fi
grep -q "plot_texture: .*texture.pvd does not exist" "$work/err"
if "$py" "$tool" "$run" --frames 7 2>"$work/err"; then echo "bad frame accepted"; exit 1; fi
grep -q "no texture frame" "$work/err"
echo "tools.plot_texture: ok"
