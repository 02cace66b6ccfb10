#!/usr/bin/env bash
# Configures and builds the project into build/ (or $POOL_BUILD_DIR); extra args go to cmake.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${POOL_BUILD_DIR:-$root/build}
"$root/scripts/deps.sh"
# Warnings are errors in CI (CI=true), not in everyone's build (POOL_WERROR is off by default).
werror=()
[[ ${CI:-} == true ]] && werror=(-DPOOL_WERROR=ON)
cmake -S "$root" -B "$build" -G Ninja "${werror[@]}" "$@" >/dev/null
cmake --build "$build" -j "$(nproc)"
