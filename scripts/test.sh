#!/usr/bin/env bash
# Builds everything and runs the whole test suite (unit, integration, tool tests), then the benchmarks' smoke run.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${POOL_BUILD_DIR:-$root/build}
"$root/scripts/build.sh"
cd "$build"
ctest --output-on-failure -j "$(nproc)"
