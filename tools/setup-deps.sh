#!/usr/bin/env bash
# Installs the Debian packages the native build, tests and docs need, if any is missing.
# Idempotent; needs root (or sudo). Nothing is fetched from outside Debian's archive.
set -euo pipefail
# clang and libclang-rt-dev: the sanitizer build and its libFuzzer targets (linux-asan preset).
# lld: the Linux presets' linker (STEPWISE_LINKER, cmake/StepwiseBuildFlags.cmake).
# libbullet-dev: the Bullet peer (bench/peers, docs/peers.md), a yardstick only; the build skips
# the peer without it.
packages=(cmake ninja-build g++ clang libclang-rt-dev lld libeigen3-dev nlohmann-json3-dev libcli11-dev catch2 doxygen
          libjs-mathjax chromium libbullet-dev)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "setup: installing ${missing[*]}"
as_root=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: need root or sudo to install ${missing[*]}" >&2; exit 1; }
  as_root=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
