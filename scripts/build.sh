#!/usr/bin/env bash
# Configures and builds the project into build/ (POOL_SANITIZE=1: the sanitizer build in
# build-asan/; scripts/build-env.sh); extra args go to cmake.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/build-env.sh"
"$root/scripts/deps.sh"
configure_build "$@"
cmake --build "$build" -j "$(nproc)"
