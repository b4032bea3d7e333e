#!/usr/bin/env bash
# Sets up everything the DirectX 12 demo shell needs on a Debian 12 machine without a GPU:
# the mingw-w64 cross compiler, wine64 + Xvfb to run the .exe, the Mesa 25 software Vulkan
# driver (lavapipe) from bookworm-backports unpacked into a project-owned folder, and the
# Dear ImGui sources from Debian's source package. Idempotent: a second run only checks.
# Everything comes from Debian's archive; nothing fetched is installed over system libraries
# or committed (see docs/renderer.md and shared/design/renderer-on-linux.md for why).
#
#   tools/setup-renderer.sh            # deps into build/renderer-deps
#   STEPWISE_RENDER_DEPS=/x tools/setup-renderer.sh
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
deps="${STEPWISE_RENDER_DEPS:-$root/build/renderer-deps}"
fail() { echo "setup-renderer: error: $*" >&2; exit 1; }
note() { echo "setup-renderer: $*"; }

# --- 1. Debian packages -------------------------------------------------------------------
# The last line: what Mesa 25's lavapipe links that bookworm itself provides new enough.
packages=(g++-mingw-w64-x86-64-posix mingw-w64-x86-64-dev wine64 libvulkan1 xvfb x11-apps
          libstb-dev dpkg-dev debian-archive-keyring
          libllvm15 libx11-xcb1 libxcb-dri3-0 libxcb-present0 libxcb-randr0 libxcb-shm0
          libxcb-sync1 libxcb-xfixes0 libxshmfence1 libzstd1 libexpat1 zlib1g)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q 'install ok installed' || missing+=("$package")
done
if ((${#missing[@]})); then
  if [[ $(id -u) -ne 0 ]]; then
    fail "missing packages: ${missing[*]}; run as root or: sudo apt-get install ${missing[*]}"
  fi
  note "installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq || fail "apt-get update failed"
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null \
    || fail "apt-get install ${missing[*]} failed"
fi
[[ -x /usr/lib/wine/wine64 ]] || fail "/usr/lib/wine/wine64 not found after installing wine64"
[[ -f /usr/include/stb/stb_image_write.h ]] || fail "stb_image_write.h missing (package libstb-dev)"
command -v x86_64-w64-mingw32-g++-posix >/dev/null || fail "x86_64-w64-mingw32-g++-posix not found"

# --- 2. A private apt setup: the machine's own Debian mirror, other suites ----------------
# Copies the URIs of the machine's Debian sources so the same mirror (or proxy) is used.
mirror=""
for file in /etc/apt/sources.list.d/*.sources; do
  [[ -f $file ]] || continue
  mirror=$(awk '/^URIs:/ {for (i = 2; i <= NF; i++) if ($i ~ /debian\/?$/) {print $i; exit}}' "$file")
  [[ -n $mirror ]] && break
done
if [[ -z $mirror && -f /etc/apt/sources.list ]]; then
  mirror=$(awk '$1 == "deb" && $0 ~ /bookworm/ {for (i = 2; i <= NF; i++) if ($i ~ /^(http|https|file):/) {print $i; exit}}' /etc/apt/sources.list)
fi
[[ -n $mirror ]] || fail "no Debian mirror URI found in /etc/apt/sources.list.d/*.sources or /etc/apt/sources.list"
keyring=/usr/share/keyrings/debian-archive-keyring.gpg
[[ -f $keyring ]] || fail "$keyring missing (package debian-archive-keyring)"

apt_dir="$deps/apt"
mkdir -p "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial" "$apt_dir/sources"
cat > "$apt_dir/sources/private.sources" <<SOURCES
Types: deb
URIs: $mirror
Suites: bookworm-backports
Components: main
Signed-By: $keyring

Types: deb-src
URIs: $mirror
Suites: bookworm
Components: main
Signed-By: $keyring
SOURCES
apt_private=(-o "Dir::Etc::SourceList=/dev/null" -o "Dir::Etc::SourceParts=$apt_dir/sources"
             -o "Dir::State::Lists=$apt_dir/lists" -o "Dir::Cache=$apt_dir/cache"
             -o "Debug::NoLocking=1" -o "APT::Sandbox::User=root")
private_update() {
  if [[ ! -f $apt_dir/updated ]]; then
    note "reading bookworm-backports and deb-src lists from $mirror"
    apt-get "${apt_private[@]}" update -qq || fail "apt-get update on the private sources list failed"
    touch "$apt_dir/updated"
  fi
}

# --- 3. Mesa 25 lavapipe (and the libraries it needs that bookworm has only older) --------
# Debian 12's own lavapipe (Mesa 22.3) drops descriptor-table bindings under wine 8's vkd3d,
# so every textured draw (all of Dear ImGui) comes out blank; backports' Mesa 25 works.
mesa_root="$deps/mesa"
icd="$deps/lvp_icd.json"
if [[ ! -f $icd ]]; then
  private_update
  mkdir -p "$deps/debs" && cd "$deps/debs"
  rm -f ./*.deb
  apt-get "${apt_private[@]}" download mesa-vulkan-drivers/bookworm-backports >/dev/null \
    || fail "could not download mesa-vulkan-drivers from bookworm-backports"
  # Libraries that lavapipe links and bookworm itself has in too old a version (LLVM, ...):
  # take the backports builds of those that backports carries.
  for dep in $(dpkg-deb -f mesa-vulkan-drivers_*.deb Depends | tr ',' '\n' | sed -E 's/[[:space:]]*\(.*//; s/\|.*//; s/^[[:space:]]+//'); do
    if apt-get "${apt_private[@]}" download "$dep/bookworm-backports" >/dev/null 2>&1; then
      note "using $dep from bookworm-backports"
    fi
  done
  rm -rf "$mesa_root" && mkdir -p "$mesa_root"
  for deb in ./*.deb; do dpkg-deb -x "$deb" "$mesa_root" || fail "dpkg-deb -x $deb failed"; done
  lvp=$(find "$mesa_root" -name libvulkan_lvp.so | head -n 1)
  [[ -n $lvp ]] || fail "libvulkan_lvp.so not found in the unpacked mesa-vulkan-drivers"
  unresolved=$(LD_LIBRARY_PATH="$(dirname "$lvp")" ldd "$lvp" | grep 'not found' || true)
  [[ -z $unresolved ]] || fail "lavapipe needs libraries that are missing: $unresolved"
  cat > "$icd" <<JSON
{
    "file_format_version": "1.0.0",
    "ICD": { "library_path": "$lvp", "api_version": "1.3.0" }
}
JSON
  note "lavapipe: $lvp"
fi

# --- 4. Dear ImGui sources (core from the Debian source package, backends with it) --------
imgui_dir="$deps/imgui"
if [[ ! -f $imgui_dir/imgui.cpp || ! -f $imgui_dir/backends/imgui_impl_dx12.cpp ]]; then
  private_update
  mkdir -p "$deps/src" && cd "$deps/src"
  apt-get "${apt_private[@]}" source --download-only imgui >/dev/null \
    || fail "apt-get source --download-only imgui failed"
  dsc=$(ls imgui_*.dsc | head -n 1)
  rm -rf unpacked && dpkg-source --no-check -x "$dsc" unpacked >/dev/null \
    || fail "dpkg-source -x $dsc failed"
  rm -rf "$imgui_dir" && mkdir -p "$imgui_dir/backends"
  cp unpacked/*.cpp unpacked/*.h "$imgui_dir/"
  for backend in imgui_impl_dx12 imgui_impl_win32; do
    source_file=unpacked/backends/$backend.cpp
    [[ -f $source_file ]] || source_file=/usr/share/doc/libimgui-dev/examples/backends/$backend.cpp
    [[ -f $source_file ]] || source_file=""
    [[ -n $source_file ]] || fail "$backend.cpp is in neither the imgui source package nor libimgui-dev"
    cp "$source_file" "${source_file%.cpp}.h" "$imgui_dir/backends/"
  done
  note "Dear ImGui $(grep -m1 'define IMGUI_VERSION ' "$imgui_dir/imgui.h" | awk '{print $3}') in $imgui_dir"
fi

# --- 5. The environment the tests and tools/render-env.sh use ----------------------------
cat > "$deps/env.sh" <<ENV
# Written by tools/setup-renderer.sh: the environment for running the mingw demos under wine.
export STEPWISE_RENDER_DEPS="$deps"
export VK_DRIVER_FILES="$icd"
export VK_ICD_FILENAMES="$icd"
export LD_LIBRARY_PATH="$(find "$mesa_root" -type d -name 'x86_64-linux-gnu' -path '*/lib/*' -print | head -n 1)\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH}"
export WINEDEBUG=-all
export WINEDLLOVERRIDES="mscoree,mshtml="
export VKD3D_CONFIG=virtual_heaps
export VKD3D_DEBUG=err
export WINE64=/usr/lib/wine/wine64
export STEPWISE_IMGUI_DIR="$imgui_dir"
ENV
note "ready: $deps (source $deps/env.sh for the wine environment)"
