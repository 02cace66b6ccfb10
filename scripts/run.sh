#!/usr/bin/env bash
# Builds everything and runs the main job: for now the physics lab simulating an 8-ball break, with a plot.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${POOL_BUILD_DIR:-$root/build}
"$root/scripts/build.sh"
out=${1:-$root/break.svg}
"$build/bin/pool-sim" "$root/assets/scenes/break.json" --plot "$out"
echo "plot of the break written to $out" >&2
