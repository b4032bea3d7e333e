#!/usr/bin/env bash
# The scripted pick: a first offscreen run lists, in its expectations, the dynamic bodies whose
# centre pixel a click would pick ("pickable INDEX NAME X Y", computed by ray casting from the
# camera); a second run clicks the first of those pixels with --pick X,Y and must print
# "picked body INDEX 'NAME'". Its screenshot (inspector open, body in wireframe) is checked too.
#   pick_test.sh DEMO.exe OUT.png CHECK_PNG [demo arguments...]
set -u
exe="$1" out="$2" check="$3"
shift 3
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
"$here/screenshot_test.sh" "$exe" "$out" "$check" "$@" || exit $?
# The demo writes the file in Windows text mode: CR LF line ends.
read -r _ index name x y < <(grep -m 1 '^pickable ' "$out.txt" | tr -d '\r') || true
if [[ -z ${index:-} ]]; then
  echo "FAIL no dynamic body can be picked at its centre in $out"
  exit 1
fi
echo "picking body $index '$name' at pixel ($x, $y)"
picked="${out%.png}-picked.png"
# The expectations write spaces in names as underscores: either may be meant.
"$here/screenshot_test.sh" --expect-output "^picked body $index '${name//_/[ _]}'" \
  "$exe" "$picked" "$check" "$@" --pick "$x,$y" --open inspector
