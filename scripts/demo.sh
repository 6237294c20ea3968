#!/usr/bin/env bash
# Sets up and builds gpdr (scripts/setup.sh), then runs its main job on a
# bundled sample in a scratch folder (build/demo) and lists what it wrote.
# (The job grows with gpdr: Delaunay triangulation of points for now.)
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/setup.sh >/dev/null
rm -rf build/demo && mkdir -p build/demo
cp poly-samples/points.node build/demo/
cd build/demo
echo "\$ gpdr -cen points.node"
../gpdr -cen points.node
echo
echo "Files written in build/demo:"
ls -l --time-style=+ | tail -n +2
