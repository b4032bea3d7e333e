#!/usr/bin/env bash
# Runs the DirectX 12 build of a chapter demo under wine (made by the mingw preset).
# With $DISPLAY: opens the demo window there. Without: renders a screenshot offscreen on a
# private Xvfb (tests/render/run_under_wine.sh) into out/chNN_demo.png.
#   tools/run-windows-demo.sh NN [demo options...]
set -euo pipefail
cd "$(dirname "$0")/.."
chapter=$1; shift
exe="build/mingw/ch${chapter}_demo.exe"
deps="build/renderer-deps"
[ -f "$exe" ] || { echo "run-windows-demo: $exe is not built (cmake --preset mingw && cmake --build --preset mingw)" >&2; exit 1; }
[ -f "$deps/env.sh" ] || { echo "run-windows-demo: run tools/setup-renderer.sh first" >&2; exit 1; }
mkdir -p out
if [ -n "${DISPLAY:-}" ]; then
  # shellcheck source=/dev/null
  source "$deps/env.sh"
  export WINEPREFIX="${STEPWISE_WINEPREFIX:-$PWD/build/wineprefix}"
  echo "ch${chapter}_demo: opening the DirectX 12 window on $DISPLAY (F1 lists the hotkeys)"
  "$WINE64" "$exe" "$@" >out/ch${chapter}_demo-wine.log 2>&1
else
  screenshot="out/ch${chapter}_demo.png"
  tests/render/run_under_wine.sh --log "out/ch${chapter}_demo-wine.log" -- \
    "$exe" --hidden --frames 120 --screenshot "$screenshot" "$@"
  echo "screenshot $screenshot (DirectX 12 under wine, offscreen)"
fi
