#!/usr/bin/env bash
# ctest install.tiny_case: `cmake --install` into a temporary prefix puts bin/mistfall, share/mistfall/render/*.inc
# and share/mistfall/cases/*.toml there; the installed mistfall, run from outside the source and build trees,
# names its data directory in --help, simulates a shipped case from the prefix, and (with povray and ffmpeg)
# renders it with the prefix's materials.inc, edited there.
# Usage: test_install.sh BUILD_DIR
set -euo pipefail
build=$1
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT

cmake --install "$build" --prefix "$prefix" >/dev/null
for f in bin/mistfall share/mistfall/render/materials.inc share/mistfall/cases/hydrostatic.toml \
         share/mistfall/cases/waterfall_small.toml share/doc/mistfall/README.md; do
  [[ -e "$prefix/$f" ]] || { echo "FAIL: $prefix/$f was not installed" >&2; exit 1; }
done
[[ -x "$prefix/bin/mistfall" ]] || { echo "FAIL: $prefix/bin/mistfall is not executable" >&2; exit 1; }

cd "$prefix"
mistfall=$prefix/bin/mistfall
if ! "$mistfall" --help | grep -qF "$prefix/share/mistfall"; then
  echo "FAIL: the installed mistfall does not name its data directory $prefix/share/mistfall in --help" >&2
  exit 1
fi
"$mistfall" simulate share/mistfall/cases/hydrostatic.toml --out run --until 0.02 --threads 1 --plain-progress \
  2>log.txt || { cat log.txt >&2; echo "FAIL: the installed mistfall could not simulate" >&2; exit 1; }
for f in run/frames/frame_00000.vtp run/checkpoint.bin run/case.toml; do
  [[ -f "$f" ]] || { echo "FAIL: the installed run has no $f" >&2; exit 1; }
done

if command -v povray >/dev/null && command -v ffmpeg >/dev/null; then
  echo "// edited in the installed share/mistfall/render" >>share/mistfall/render/materials.inc
  "$mistfall" render run --preview --jobs 1 --plain-progress 2>log.txt ||
    { cat log.txt >&2; echo "FAIL: the installed mistfall could not render" >&2; exit 1; }
  cmp -s run/render/materials.inc share/mistfall/render/materials.inc ||
    { echo "FAIL: the run's materials.inc is not the installed (edited) one" >&2; exit 1; }
else
  echo "note: povray or ffmpeg missing: the installed render is not tried"
fi
echo "PASS: installed into $prefix and ran a case from there"
