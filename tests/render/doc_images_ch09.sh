#!/usr/bin/env bash
# Regenerates chapter 9's screenshots (docs/images/ch09_*.png) from the mingw-built ch09 demo,
# offscreen under wine, with the same scripted options the render tests use; each image is
# checked by check_png before it is copied.
#   tests/render/doc_images_ch09.sh [build/mingw/ch09_demo.exe] [build/linux/tests/render/check_png]
set -eu
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
exe="${1:-$root/build/mingw/ch09_demo.exe}"
check="${2:-$root/build/linux/tests/render/check_png}"
work="$(mktemp -d "${TMPDIR:-/tmp}/ch09-images.XXXXXX")"
trap 'rm -rf "$work"' EXIT
shot() {  # shot NAME demo-arguments...
  local name=$1
  shift
  "$root/tests/render/screenshot_test.sh" "$exe" "$work/$name.png" "$check" "$@" >"$work/$name.out" ||
    { cat "$work/$name.out"; exit 1; }
  cp "$work/$name.png" "$root/docs/images/$name.png"
  echo "docs/images/$name.png: $(stat -c %s "$work/$name.png") bytes"
}
shot ch09_contacts --scene debug-drop --frames 90 --views colliders,contacts,normals --select-contact --open hits
shot ch09_epa_face --scene debug-hull-on-box --frames 60 --views colliders,epa,wireframe,contacts --select gem
shot ch09_minkowski --scene debug-hull-on-box --frames 60 --views colliders,simplex,minkowski,epa --select gem
shot ch09_wireframe --scene debug-jitter --frames 120 --views colliders,contacts,wireframe --select 2
shot ch09_bounds_joints --scene joints-sandbox --frames 60 --views colliders,bounds,joints
shot ch09_inspector --scene debug-hull-on-box --frames 60 --views colliders,contacts,wireframe --select gem --open inspector
shot ch09_hit_tree --scene debug-jitter --frames 120 --views colliders,contacts,normals,wireframe --select-contact --open hits
shot ch09_perf --scene debug-jitter --frames 240 --views colliders,contacts --open perf --draw-every-frame
shot ch09_rewind --scene debug-drop --frames 90 --views colliders,contacts,normals --rewind 55 --open session
