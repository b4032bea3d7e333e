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
# File names relative to the output folder: the Windows program's command line parser (CLI11)
# reads an argument that starts with "/" as a Windows-style option.
cd "$out" || exit 1
rm -f native.json windows.json

"$native" record "$scene" --frames "$frames" --output native.json || exit 1
"$wine_run" --log windows-replay.log -- "$exe" replay native.json
status=$?
[[ $status -eq 77 ]] && exit 77
[[ $status -eq 0 ]] || { echo "FAIL the Windows build does not replay the native recording"; exit 1; }

"$wine_run" --log windows-record.log -- "$exe" record "$scene" --frames "$frames" --output windows.json || exit 1
"$native" replay windows.json || { echo "FAIL the native build does not replay the Windows recording"; exit 1; }
echo "recordings of $scene ($frames frames) replay across the native and the Windows build"
