#!/usr/bin/env bash
# The free overfall's grid series (issue 16, item 3; docs/waterfall.md, "The brink depth against resolution"):
# cases/waterfall.toml without its air region (water alone), run 0-6 s at l0 = 10, 7 and 5 mm (dt_max scaled with
# l0), and the brink depth (with its standard error from 0.5 s blocks) and nappe of tools/overfall_profile.py over
# 2-6 s against Rouse's 0.715 h_c. Over 1-3 s alone the standard error is 0.03-0.07 h_c (seventh session).
# Measured 2026-11-25 over 1-3 s (runs to 3 s): 0.891, 0.865 and 0.807 h_c; at 2.5 mm 0.793 (OVERFALL_SPACINGS=2.5,
# 50 min on 1 thread). Over 2-6 s (runs to 6 s, 2026-11-25): paper 0.843, 0.863, 0.785 +- 0.02-0.04 h_c; stabilised
# 0.765, 0.734, 0.732 +- 0.02 (nappe 0.62, 0.58, 0.32 cm). Also printed: the channel's specific energy from the gate
# to the brink (critical: 1.5 h_c). Since the nineteenth session the cases carry waterfall.toml's
# source_relaxation_basis = "time" (the figures above were taken per step; the two agree at steps of dt_max, and the
# 10 mm case ran 3 s in 6,029 steps of at most 5e-4 s: nearly all of them at dt_max).
# OVERFALL_SCHEME=stabilised runs numerics.scheme = "stabilised" with collision_distance = 0.8 (at the default 0.5
# its 1 cm run diverged at 0.46 s; docs/waterfall.md, "The stabilised scheme on the channel and the overfall");
# the default, paper, sets scheme = "paper" (cases/waterfall.toml itself runs the stabilised liquid since the
# twenty-second session; its scheme keys are replaced, and closed_pockets, which needs the air's vents, dropped).
# Usage: [OVERFALL_SPACINGS="10 7 5"] [OVERFALL_SCHEME=paper|stabilised] tools/validate_overfall.sh [BUILD_DIR] [OUT_DIR]
#        (part of `make validate` with the default spacings in mm and the paper scheme; about 35 min on one core)
set -euo pipefail
build=${1:-build}
out=${2:-out/validate/overfall}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
scheme=${OVERFALL_SCHEME:-paper}
case "$scheme" in
  paper | stabilised) ;;
  *) echo "validate_overfall.sh: OVERFALL_SCHEME must be paper or stabilised, not '$scheme'" >&2; exit 1 ;;
esac
mkdir -p "$out"
export OMP_WAIT_POLICY=passive

# case_for L0_MM: the paper's waterfall, water alone, at spacing L0_MM, to 6 s.
case_for() {
  local mm=$1
  /usr/bin/python3 - "$here/cases/waterfall.toml" "$mm" "$scheme" <<'PY'
import re, sys
text, mm, scheme = open(sys.argv[1]).read(), float(sys.argv[2]), sys.argv[3]
blocks = re.split(r"(?m)^(?=\[)", text)                              # one block per table header
air = lambda b: b.startswith("[[vent]]") or (b.startswith("[[region]]") and 'material = "gas"' in b)
text = "".join(b for b in blocks if not air(b))                      # the air region and its vents go
text = re.sub(r'^name = "waterfall"', f'name = "overfall_{mm:g}mm"'.replace(".", "p"), text, flags=re.M)
text = re.sub(r"^particle_spacing = .*", f"particle_spacing = {mm / 1000:g}", text, flags=re.M)
text = re.sub(r"^dt_max = .*", f"dt_max = {mm * 5e-5:g}", text, flags=re.M)
text = re.sub(r"^field_spacing = .*", f"field_spacing = {2 * mm / 1000:g}", text, flags=re.M)
text = re.sub(r"^end_time = .*", "end_time = 6.0", text, flags=re.M)
# The case's own scheme keys go (closed_pockets needs the air's vents); the scheme asked for is set here.
text = re.sub(r"^(scheme|closed_pockets|collision_distance) = .*\n", "", text, flags=re.M)
if scheme == "stabilised":
    text = re.sub(r"^\[numerics\]$", '[numerics]\nscheme = "stabilised"\ncollision_distance = 0.8', text, count=1, flags=re.M)
else:
    text = re.sub(r"^\[numerics\]$", '[numerics]\nscheme = "paper"', text, count=1, flags=re.M)
sys.stdout.write(text)
PY
}

for mm in ${OVERFALL_SPACINGS:-10 7 5}; do
  name="water_${mm}mm_$scheme"
  case_for "$mm" >"$out/$name.toml"
  rm -rf "${out:?}/$name"
  rc=0
  "$build/mistfall" simulate "$out/$name.toml" --out "$out/$name" --plain-progress 2>"$out/$name.log" || rc=$?
  if [ "$rc" = 1 ]; then  # bad input: the case this script wrote is wrong, so nothing below would mean anything
    echo "validate_overfall.sh: $name.toml refused: $(tail -n 1 "$out/$name.log")" >&2
    exit 1
  fi
  echo "== $name: $(tail -n 1 "$out/$name.log")"
  /usr/bin/python3 "$here/tools/overfall_profile.py" "$out/$name" --from 2 --to 6 | grep -v "^wrote" || true
done
