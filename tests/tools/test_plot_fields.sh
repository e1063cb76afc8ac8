#!/usr/bin/env bash
# ctest tools.plot_fields: tools/plot_fields.py draws the grid flow fields (.vti, as src/io/vti_file.cpp writes
# them) like Figs. 4-5 of the paper: velocity arrows and gas turbulence intensity, from ascii and binary-appended
# files, 2D and 3D (middle slice), one file or a folder (--all); and fails cleanly (exit 1) on bad input.
# Usage: test_plot_fields.sh SOURCE_DIR
set -euo pipefail
source_dir=$1
py=/usr/bin/python3
tool="$source_dir/tools/plot_fields.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Small grids written by hand in the writer's layout: liquid in the lower left (falling), gas elsewhere
# (swirling), gas k growing to the right. ascii and raw-appended (UInt64 byte count + little-endian Float64).
mkdir -p "$work/frames"
"$py" - "$work" <<'PY'
import os, struct, sys
work = sys.argv[1]

def fields(nx, ny, nz):
    gas_u, liq_u, gas_k, liq_k, gas_c, liq_c = [], [], [], [], [], []
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                liquid = i < nx // 3 and j < 2 * ny // 3
                gas = not liquid or i == nx // 3 - 1
                gas_u += [0.1 * (j - ny / 2), -0.1 * (i - nx / 2), 0.0] if gas else [0.0] * 3
                liq_u += [0.05, -0.8, 0.0] if liquid else [0.0] * 3
                gas_k.append(1e-4 * i if gas else 0.0)
                liq_k.append(2e-5 if liquid else 0.0)
                gas_c.append(6.5 if gas else 0.0)
                liq_c.append(6.5 - 0.1 * j if liquid else 0.0)
    return [("gas_velocity", 3, gas_u), ("liquid_velocity", 3, liq_u), ("gas_sps_k", 1, gas_k),
            ("liquid_sps_k", 1, liq_k), ("gas_coverage", 1, gas_c), ("liquid_coverage", 1, liq_c)]

def write(path, nx, ny, nz, ascii, time=0.25):
    ext = f"0 {nx - 1} 0 {ny - 1} 0 {nz - 1}"
    head = ('<?xml version="1.0"?>\n<VTKFile type="ImageData" version="1.0" byte_order="LittleEndian" '
            f'header_type="UInt64">\n  <ImageData WholeExtent="{ext}" Origin="0.1 -0.05 0" '
            'Spacing="0.005 0.005 0.005">\n    <FieldData>\n      <DataArray type="Float64" Name="TimeValue" '
            f'NumberOfTuples="1" format="ascii">\n        {time!r}\n      </DataArray>\n    </FieldData>\n'
            f'    <Piece Extent="{ext}">\n      <PointData>\n')
    blob = b""
    for name, comps, values in fields(nx, ny, nz):
        head += f'        <DataArray type="Float64" Name="{name}" NumberOfComponents="{comps}"'
        if ascii:
            text = " ".join(repr(float(v)) for v in values)
            head += f' format="ascii">\n          {text}\n        </DataArray>\n'
        else:
            head += f' format="appended" offset="{len(blob)}"/>\n'
            blob += struct.pack("<Q", 8 * len(values)) + struct.pack(f"<{len(values)}d", *values)
    head += "      </PointData>\n    </Piece>\n  </ImageData>\n"
    with open(path, "wb") as f:
        f.write(head.encode())
        if not ascii:
            f.write(b'  <AppendedData encoding="raw">\n   _' + blob + b"\n  </AppendedData>\n")
        f.write(b"</VTKFile>\n")

write(os.path.join(work, "frames", "fields_00000.vti"), 24, 16, 1, True)
write(os.path.join(work, "frames", "fields_00001.vti"), 24, 16, 1, False, 0.5)
write(os.path.join(work, "cube.vti"), 9, 7, 5, True)
PY

not_blank() {
  [[ -s "$1" ]] || { echo "FAIL: $1 was not written" >&2; exit 1; }
  "$py" - "$1" <<'PY'
import sys
import matplotlib.image as mpimg
import numpy as np
img = mpimg.imread(sys.argv[1])
if len(np.unique(img.reshape(-1, img.shape[-1]), axis=0)) <= 2:
    sys.exit(f"FAIL: {sys.argv[1]} is blank")
PY
}

"$py" "$tool" --all "$work/frames" --out "$work/png" --dpi 60 > "$work/out.txt"
for stem in fields_00000 fields_00001; do
  for kind in velocity turbulence; do not_blank "$work/png/${stem}_$kind.png"; done
done
[[ $(wc -l < "$work/out.txt") -eq 4 ]] ||
  { cat "$work/out.txt" >&2; echo "FAIL: expected 4 images listed" >&2; exit 1; }
# One file, default output folder (plots beside it); a 3D grid is drawn as its middle slice.
"$py" "$tool" "$work/cube.vti" --dpi 60 --arrows 5 > /dev/null
not_blank "$work/plots/cube_velocity.png"
not_blank "$work/plots/cube_turbulence.png"
# The reader agrees between the ascii and binary files and cuts 3D grids in the middle.
"$py" - "$source_dir/tools" "$work" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
import numpy as np
from plot_fields import read_vti, plane
ga, a = read_vti(sys.argv[2] + "/frames/fields_00000.vti")
gb, b = read_vti(sys.argv[2] + "/frames/fields_00001.vti")
assert ga["dims"] == (24, 16, 1) and ga["time"] == 0.25 and gb["time"] == 0.5, (ga, gb)
assert all(np.array_equal(a[k], b[k]) for k in a), "ascii and binary grids differ"
assert a["gas_velocity"].shape == (1, 16, 24, 3) and abs(a["gas_sps_k"][0, 3, 12] - 1.2e-3) < 1e-15
g3, c = read_vti(sys.argv[2] + "/cube.vti")
cut, x, y, note = plane(g3, c)
assert cut["gas_sps_k"].shape == (7, 9) and "middle slice z = 0.01" in note, note
PY

source "$(dirname "${BASH_SOURCE[0]}")/expect_fail.sh"
mkdir -p "$work/bad" "$work/empty"
head -c 2000 "$work/frames/fields_00001.vti" > "$work/bad/cut.vti"
expect_fail "missing </VTKFile> (truncated?)" "$work/bad/cut.vti" --out "$work/badpng"
sed 's/type="ImageData"/type="PolyData"/' "$work/frames/fields_00000.vti" > "$work/bad/poly.vti"
expect_fail "not a VTK ImageData file" "$work/bad/poly.vti" --out "$work/badpng"
sed 's/Name="gas_sps_k"/Name="other"/' "$work/frames/fields_00000.vti" > "$work/bad/nok.vti"
expect_fail "missing array 'gas_sps_k'" "$work/bad/nok.vti" --out "$work/badpng"
printf 'not xml at all </VTKFile>\n' > "$work/bad/junk.vti"
expect_fail "not a VTK XML file" "$work/bad/junk.vti" --out "$work/badpng"
expect_fail "is not a file" "$work/missing.vti"
expect_fail "use --all" "$work/frames"
expect_fail "holds no .vti file" --all "$work/empty"
expect_fail "is not a directory" --all "$work/cube.vti"
expect_fail "expected 10..1000" "$work/cube.vti" --dpi 5
expect_fail "unrecognized arguments" "$work/cube.vti" --bogus
[[ -z "$(ls -A "$work/badpng" 2>/dev/null)" ]] || { echo "FAIL: an image was written for bad input" >&2; exit 1; }
echo "plot_fields: ok"
