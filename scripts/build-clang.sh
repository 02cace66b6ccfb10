#!/usr/bin/env bash
# Builds everything (programs, tests, benchmarks) with clang into build-clang (or
# $POOL_CLANG_BUILD_DIR), warnings as errors in CI: a compile check, nothing runs. Extra args go to cmake.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${POOL_CLANG_BUILD_DIR:-$root/build-clang}
"$root/scripts/deps.sh"
werror=()
[[ ${CI:-} == true ]] && werror=(-DPOOL_WERROR=ON)
# -O0 without debug info: clang's warnings come from its front end, so the quickest build sees
# them all (the suite runs once, on the g++ build).
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_C_FLAGS_DEBUG=-O0 -DCMAKE_CXX_FLAGS_DEBUG=-O0 "${werror[@]}" "$@" >/dev/null
cmake --build "$build" -j "$(nproc)"
