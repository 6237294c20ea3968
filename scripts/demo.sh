#!/usr/bin/env bash
# Sets up and builds gpdr (scripts/setup.sh), then runs its main job on a
# bundled sample in a scratch folder (build/demo) and lists what it wrote.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/setup.sh >/dev/null
rm -rf build/demo && mkdir -p build/demo
cp poly-samples/DEMO_SAMPLE build/demo/
cd build/demo
echo "\$ gpdr DEMO_SWITCHES DEMO_SAMPLE"
../gpdr DEMO_SWITCHES DEMO_SAMPLE
echo
echo "Files written in build/demo:"
ls -l --time-style=+ | tail -n +2
