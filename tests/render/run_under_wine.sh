#!/usr/bin/env bash
# Runs one mingw-built .exe under wine64 on a private Xvfb display, with the environment that
# tools/setup-renderer.sh wrote (Mesa 25 lavapipe, vkd3d settings), and stops the Xvfb and
# wineserver it started by PID. The program's output goes to a file, never a pipe: wine's
# helper processes inherit it and would keep a pipe open.
#   run_under_wine.sh [--log FILE] [--xwd FILE --xwd-after REGEX] -- program.exe args...
# Exit code: the program's; 77 (skip) when wine, Xvfb or the setup is missing.
set -u
log=""; xwd_out=""; xwd_after=""
while (($#)); do
  case "$1" in
    --log) log="$2"; shift 2 ;;
    --xwd) xwd_out="$2"; shift 2 ;;
    --xwd-after) xwd_after="$2"; shift 2 ;;
    --) shift; break ;;
    *) break ;;
  esac
done
(($#)) || { echo "usage: run_under_wine.sh [--log FILE] -- program.exe args..." >&2; exit 2; }

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
deps="${STEPWISE_RENDER_DEPS:-$root/build/renderer-deps}"
skip() { echo "SKIP: $*" >&2; exit 77; }
[[ -f $deps/env.sh ]] || skip "no $deps/env.sh: run tools/setup-renderer.sh first"
# shellcheck source=/dev/null
source "$deps/env.sh"
[[ -x ${WINE64:-} ]] || skip "wine64 not installed (tools/setup-renderer.sh installs it)"
command -v Xvfb >/dev/null || skip "Xvfb not installed (tools/setup-renderer.sh installs it)"
[[ -f $1 ]] || skip "$1 not built (cmake --preset mingw && cmake --build build/mingw)"

work="$(mktemp -d "${TMPDIR:-/tmp}/stepwise-wine.XXXXXX")"
export WINEPREFIX="${STEPWISE_WINEPREFIX:-$root/build/wineprefix}"
mkdir -p "$WINEPREFIX"
[[ -n $log ]] || log="$work/output.log"

# A display number nobody uses: Xvfb picks a free one and tells us on -displayfd.
Xvfb -displayfd 3 -screen 0 1600x1000x24 -nolisten tcp 3>"$work/display" >"$work/xvfb.log" 2>&1 &
xvfb_pid=$!
for _ in $(seq 1 100); do [[ -s $work/display ]] && break; sleep 0.05; done
[[ -s $work/display ]] || { kill "$xvfb_pid" 2>/dev/null; skip "Xvfb did not start: $(cat "$work/xvfb.log")"; }
export DISPLAY=":$(head -n 1 "$work/display")"

cleanup() {
  # Only what this script started: the wineserver of our prefix, then our Xvfb.
  WINEPREFIX="$WINEPREFIX" /usr/lib/wine/wineserver -k >/dev/null 2>&1 || true
  kill "$xvfb_pid" 2>/dev/null || true
  wait "$xvfb_pid" 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT

"$WINE64" "$@" >"$log" 2>&1 &
program_pid=$!
if [[ -n $xwd_out ]]; then
  # Grab the screen once the program says it got there (it keeps presenting afterwards).
  for _ in $(seq 1 1200); do
    grep -qE "$xwd_after" "$log" 2>/dev/null && break
    kill -0 "$program_pid" 2>/dev/null || break
    sleep 0.05
  done
  xwd -root -silent -display "$DISPLAY" >"$xwd_out" 2>/dev/null || echo "xwd failed" >>"$log"
fi
wait "$program_pid"
status=$?
cat "$log"
exit $status
