#!/usr/bin/env bash
# One render test: the mingw-built demo draws frame N of a scene offscreen under wine, then
# the native check_png looks for the ground, the bodies and the ImGui panel in the image.
#   screenshot_test.sh DEMO.exe OUT.png CHECK_PNG [demo arguments...]
# Exit 77 (ctest: skipped) when the cross build or the wine setup is absent.
set -u
exe="$1" out="$2" check="$3"
shift 3
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
if [[ ! -f $exe ]]; then
  echo "SKIP: $exe not built: cmake --preset mingw && cmake --build build/mingw (after tools/setup-renderer.sh)"
  exit 77
fi
mkdir -p "$(dirname "$out")"
rm -f "$out" "$out.txt"
"$here/run_under_wine.sh" -- "$exe" --hidden --screenshot "$out" "$@"
status=$?
[[ $status -eq 0 ]] || exit $status
"$check" "$out" "$out.txt"
