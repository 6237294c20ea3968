#!/usr/bin/env bash
# Regenerates docs/images/face.svg, the picture of a mesh that README shows:
# tests/data/face.poly (an outline with two eyes as holes, and a nose, a
# mouth and eyebrows as segments inside) quality-meshed with a 30 degree
# angle bound and an area bound, drawn by --svg.  One thread, so the mesh,
# and so the picture, is the same on every run; gpdr is run by the name
# "gpdr" so that the closing comment names no folder of this machine.
#
#   scripts/make-picture.sh          (after building: build/gpdr, or GPDR=...)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
gpdr=$(realpath "${GPDR:-$root/build/gpdr}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/bin"
ln -s "$gpdr" "$work/bin/gpdr"
cp "$root/tests/data/face.poly" "$work/"
(cd "$work" && PATH="$work/bin:$PATH" gpdr -Q -j1 -pq30a2 -NEP --svg face.poly)
mkdir -p "$root/docs/images"
cp "$work/face.1.svg" "$root/docs/images/face.svg"
echo "wrote docs/images/face.svg ($(stat -c %s "$root/docs/images/face.svg") bytes)"
