#!/usr/bin/env bash
# A recording made by one build replays on another of the same precision: the native float
# `stepwise` records a scene and the mingw-w64 `stepwise.exe` replays it under wine, then the other
# way round. Both must meet every frame's hash and the report (exit 0).
#   replay_across_builds.sh NATIVE_STEPWISE MINGW_STEPWISE_EXE OUT_DIR SCENE FRAMES
# Exit 77 (ctest: skipped) when the .exe or wine is absent.
set -u
native="$1" exe="$2" out="$3" scene="$4" frames="$5"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
wine_run="$here/../render/run_under_wine.sh"
[[ -f $exe ]] || { echo "SKIP: $exe not built (cmake --preset mingw && cmake --build build/mingw --target stepwise)"; exit 77; }
mkdir -p "$out"
rm -f "$out"/native.json "$out"/windows.json

"$native" record "$scene" --frames "$frames" --output "$out/native.json" || exit 1
"$wine_run" --log "$out/windows-replay.log" -- "$exe" replay "$out/native.json"
status=$?
[[ $status -eq 77 ]] && exit 77
[[ $status -eq 0 ]] || { echo "FAIL the Windows build does not replay the native recording"; exit 1; }

"$wine_run" --log "$out/windows-record.log" -- "$exe" record "$scene" --frames "$frames" --output "$out/windows.json" || exit 1
"$native" replay "$out/windows.json" || { echo "FAIL the native build does not replay the Windows recording"; exit 1; }
echo "recordings of $scene ($frames frames) replay across the native and the Windows build"
