#!/usr/bin/env bash
# Sourced by the build and test scripts: which build folder they share, and how it is configured.
# POOL_SANITIZE=1 chooses the sanitizer build (clang, ASan + UBSan, the fuzz targets beside the rest,
# the `asan` preset) in build-asan (or $POOL_ASAN_BUILD_DIR); otherwise the plain g++ build in
# build/ (or $POOL_BUILD_DIR).
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if [[ ${POOL_SANITIZE:-0} == 1 ]]; then
  build=${POOL_ASAN_BUILD_DIR:-$root/build-asan}
else
  build=${POOL_BUILD_DIR:-$root/build}
fi

# configure_build [CMAKE ARGS...]: (re)configures $build; warnings are errors in CI (CI=true) and
# in the sanitizer build's preset, not in everyone's plain build.
configure_build() {
  if [[ ${POOL_SANITIZE:-0} == 1 ]]; then
    (cd "$root" && cmake --preset asan -B "$build" "$@" >/dev/null)
  else
    local werror=()
    [[ ${CI:-} == true ]] && werror=(-DPOOL_WERROR=ON)
    cmake -S "$root" -B "$build" -G Ninja "${werror[@]}" "$@" >/dev/null
  fi
}
