#!/usr/bin/env bash
# One render test: the mingw-built demo draws frame N of a scene offscreen under wine, then
# the native check_png looks for the ground, the bodies, the ImGui panels and the enabled debug
# views in the image. Each --expect-output REGEX must match a line the demo printed (a scripted
# pick or rewind says what it did).
#   screenshot_test.sh [--expect-output REGEX]... DEMO.exe OUT.png CHECK_PNG [demo arguments...]
# Exit 77 (ctest: skipped) when the cross build or the wine setup is absent.
set -u
expected=()
while [[ ${1:-} == --expect-output ]]; do
  expected+=("$2")
  shift 2
done
exe="$1" out="$2" check="$3"
shift 3
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
if [[ ! -f $exe ]]; then
  echo "SKIP: $exe not built: cmake --preset mingw && cmake --build build/mingw (after tools/setup-renderer.sh)"
  exit 77
fi
mkdir -p "$(dirname "$out")"
rm -f "$out" "$out.txt" "$out.log"
"$here/run_under_wine.sh" --log "$out.log" -- "$exe" --hidden --screenshot "$out" "$@"
status=$?
[[ $status -eq 0 ]] || exit $status
for regex in "${expected[@]}"; do
  grep -qE "$regex" "$out.log" || { echo "FAIL the demo did not print a line matching '$regex'"; exit 1; }
done
"$check" "$out" "$out.txt"
