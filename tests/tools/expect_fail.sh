# Sourced by the tools' ctest scripts. expect_fail WANT ARGS...: runs "$py" "$tool" ARGS (stdout discarded) and
# requires that it fails with WANT in its one-line message on stderr and no Python traceback. Needs $py, $tool
# and $work set by the script.
expect_fail() {
  local want=$1; shift
  if "$py" "$tool" "$@" 2>"$work/err" >/dev/null; then echo "FAIL: accepted $*" >&2; exit 1; fi
  grep -q "$want" "$work/err" || { cat "$work/err" >&2; echo "FAIL: message lacks '$want'" >&2; exit 1; }
  ! grep -q Traceback "$work/err" || { cat "$work/err" >&2; echo "FAIL: traceback" >&2; exit 1; }
}
