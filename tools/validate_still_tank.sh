#!/usr/bin/env bash
# The still tank of issue 15 (docs/validation.md): cases/hydrostatic.toml run for 10 s at l0 = 8, 4 and 2 mm with
# the stabilised scheme it ships with and with the paper's MPS (numerics.scheme = "paper", mixed source
# relaxation 0.01, collision at 0.5 l0: the case as it was before), the figures of tools/still_tank.py for each and
# the speed-against-time plot docs/figures/still_tank_speed.png.
# Usage: tools/validate_still_tank.sh [BUILD_DIR] [OUT_DIR]   (part of `make validate`; about 25 min on 2 cores)
set -euo pipefail
build=${1:-build}
out=${2:-out/validate/still_tank}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
mkdir -p "$out"
export OMP_WAIT_POLICY=passive

# case_for SCHEME L0_MM: the shipped tank at spacing L0_MM with 4-layer walls, run to 10 s.
case_for() {
  local scheme=$1 mm=$2
  local l0 wall right
  l0=$(awk -v m="$mm" 'BEGIN { printf "%.6g", m / 1000 }')
  wall=$(awk -v m="$mm" 'BEGIN { printf "%.6g", 4 * m / 1000 }')
  right=$(awk -v m="$mm" 'BEGIN { printf "%.6g", 0.2 + 4 * m / 1000 }')
  sed -E -e "s/^end_time *=.*/end_time = 10.0/" -e "s/^particle_spacing = 0.008/particle_spacing = $l0/" \
      -e "s/-0\.032/-$wall/g" -e "s/0\.232/$right/g" "$here/cases/hydrostatic.toml" |
    if [ "$scheme" = paper ]; then
      sed -E -e 's/^scheme = "stabilised"/scheme = "paper"/' -e 's/^source_relaxation = 0.0/source_relaxation = 0.01/' \
          -e 's/^collision_distance = 0.8/collision_distance = 0.5/'
    else
      cat
    fi
}

for mm in 8 4 2; do
  for scheme in stabilised paper; do
    name="${scheme}_${mm}mm"
    case_for "$scheme" "$mm" >"$out/$name.toml"
    rm -rf "${out:?}/$name"
    "$build/mistfall" simulate "$out/$name.toml" --out "$out/$name" --plain-progress 2>"$out/$name.log" || true
    echo "== $name: $(tail -n 1 "$out/$name.log")"
    /usr/bin/python3 "$here/tools/still_tank.py" "$out/$name" --csv "$out/$name.csv" --quiet || true
  done
done
/usr/bin/python3 "$here/tools/plot_still_tank.py" "$out" --out "$out/still_tank_speed.png"
