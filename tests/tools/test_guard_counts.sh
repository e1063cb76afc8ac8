#!/usr/bin/env bash
# ctest tools.guard_counts: tools/guard_counts.py's sums of the guards' firings in diagnostics.csv. A run directory
# made by hand: rows at t = 0, 1, 2, 3 s; the case sets shift_limit, respacing_limit, respacing_stop and
# collision_distance, not gas_speed_limit.
#   respacing_cuts 0, 2, 0, 3: total 5 in 2 rows, first 1 s, last 3 s; from 1.5 s: 3 in 1 row;
#   respacing_fluid_stops 5, 0, 0, 7: total 12 in 2 rows (0 and 3 s);
#   shift_cuts 0 throughout with its key set: listed, and named as the one set guard that did not fire;
#   gas_speed_capped 0 with its key not set: listed with --all only;
#   largest_shift 0.1, 0.9, 0.3, 0.2: the most 0.9 at 1 s, particle id 2867 in the step from 0.9426 s;
#   long_respacings 0, 2, 1, 3: 6 in all.
# Bad input exits 1 with a one-line message.
# Usage: test_guard_counts.sh SOURCE_DIR
set -euo pipefail
source_dir=$1
py=/usr/bin/python3
tool="$source_dir/tools/guard_counts.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$source_dir/tests/tools/expect_fail.sh"
run="$work/run"
mkdir -p "$run"
cat >"$run/diagnostics.csv" <<'CSV'
time,step,escaped,gas_speed_capped,collisions,shift_cuts,respacing_cuts,respacing_fluid_stops,largest_shift,long_respacings,largest_shift_id,largest_shift_time
0,0,0,0,10,0,0,5,0.1,0,-1,0
1,100,0,0,10,0,2,0,0.9,2,2867,0.9426101725
2,200,0,0,10,0,0,0,0.3,1,12,1.5
3,300,1,0,10,0,3,7,0.2,3,7,2.5
CSV
cat >"$run/case.toml" <<'TOML'
[numerics]
collision_distance = 0.8
shift_limit = 1.0
respacing_limit = 1.0
respacing_stop = "fluid"
TOML

fail() { echo "FAIL: $1" >&2; echo "$out" >&2; exit 1; }
row() { grep -E "^$1 " <<<"$out" | tr -s ' ' || true; }

out=$("$py" "$tool" "$run")
[[ $(row respacing_cuts) == "respacing_cuts 5 2 1.00 3.00 respacing_limit = 1.0" ]] || fail "respacing_cuts"
[[ $(row respacing_fluid_stops) == 'respacing_fluid_stops 12 2 0.00 3.00 respacing_stop = "fluid"' ]] \
  || fail "respacing_fluid_stops"
[[ $(row shift_cuts) == "shift_cuts 0 0 - - shift_limit = 1.0" ]] || fail "shift_cuts"
[[ $(row collisions) == "collisions 40 4 0.00 3.00 collision_distance = 0.8" ]] || fail "collisions"
[[ -z $(row gas_speed_capped) ]] || fail "an unset silent guard listed without --all"
grep -q "escaped 1" <<<"$out" || fail "escaped"
grep -q "^largest_shift: 0.9 .* 0.9 at 1.00 s: particle id 2867, in the step from 0.942610 s)" <<<"$out" \
  || fail "largest_shift"
grep -q "^long_respacings: 6 .* 3 at 3.00 s" <<<"$out" || fail "long_respacings"
grep -q "did not fire over these rows .*: shift_limit$" <<<"$out" || fail "the silent set guards"

out=$("$py" "$tool" "$run" --from 1.5 --all)
[[ $(row respacing_cuts) == "respacing_cuts 3 1 3.00 3.00 respacing_limit = 1.0" ]] || fail "--from"
[[ $(row gas_speed_capped) == "gas_speed_capped 0 0 - - default" ]] || fail "--all"
grep -q "rows 2.00-3.00 s (2)" <<<"$out" || fail "the rows read"

expect_fail "not found" "$work/none"
expect_fail "no row" "$run" --from 4
echo "[numerics" >"$run/case.toml"
expect_fail "cannot read" "$run"
echo "tools.guard_counts: passed"
