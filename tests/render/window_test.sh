#!/usr/bin/env bash
# The swap-chain path: the demo opens its window on the Xvfb display, presents N frames
# through an HWND swap chain, and the screen is grabbed (xwd -root) after it reports them;
# check_png --window then looks for the ImGui shell on that screen.
#   window_test.sh DEMO.exe OUT.xwd CHECK_PNG FRAMES
set -u
exe="$1" out="$2" check="$3" frames="$4"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
if [[ ! -f $exe ]]; then
  echo "SKIP: $exe not built: cmake --preset mingw && cmake --build build/mingw (after tools/setup-renderer.sh)"
  exit 77
fi
mkdir -p "$(dirname "$out")"
rm -f "$out"
"$here/run_under_wine.sh" --xwd "$out" --xwd-after "^presented" -- "$exe" --frames "$frames" --linger-frames 20
status=$?
[[ $status -eq 0 ]] || exit $status
"$check" --window "$out"
