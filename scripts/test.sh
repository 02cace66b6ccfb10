#!/usr/bin/env bash
# Builds everything and runs the whole test suite (unit, integration, tool tests, the benchmarks'
# smoke runs). POOL_SANITIZE=1: the same in the sanitizer build (clang, ASan + UBSan), every test
# under both sanitizers. Extra args go to ctest.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/build-env.sh"
"$root/scripts/build.sh"
cd "$build"
# More tests than cores: most real-process tests wait on their servers, bots and windows
# (tests/CMakeLists.txt says what may not run side by side). The plain suite runs three a core: at
# two a core it kept the cores a quarter idle and took 284 s, at three 226 s, the cores 83 % busy
# (two cores, nothing else running); the sanitized suite, whose tests compute far more, keeps the
# cores busy at two a core.
start=$SECONDS
if [[ ${POOL_SANITIZE:-0} != 1 ]]; then
  ctest --output-on-failure -j "$(($(nproc) * 3))" "$@"
else
  jobs=$(($(nproc) * 2))
  # Spawned processes (servers, bots, clients) inherit these, so they run sanitized too. Leaks are
  # suppressed only inside third-party libraries (tests/sanitize/lsan.supp), never in project code.
  export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
  export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
  export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$root/tests/sanitize/lsan.supp:print_suppressions=0}
  # The tests that draw with OpenGL run without LeakSanitizer (Mesa's leaks show no frame to
  # suppress): their ctest property appends detect_leaks=0 (tests/CMakeLists.txt).
  ctest --output-on-failure -j "$jobs" "$@"
fi
echo "test.sh: ctest took $((SECONDS - start)) s"
