#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan) into build-fuzz (or $POOL_FUZZ_BUILD_DIR)
# and runs each for SECONDS (default 60) on a copy of its seed corpus; fails on any crash.
# Usage: scripts/fuzz.sh [SECONDS] [TARGET...]   (targets: fuzz_shot_command fuzz_shot_command_cdr
# fuzz_scenario fuzz_table_spec; all by default). Crashing inputs are kept in build-fuzz/artifacts.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${POOL_FUZZ_BUILD_DIR:-$root/build-fuzz}
seconds=${1:-60}
[[ $# -gt 0 ]] && shift
targets=("$@")
((${#targets[@]})) || targets=(fuzz_shot_command fuzz_shot_command_cdr fuzz_scenario fuzz_table_spec)
if ! [[ $seconds =~ ^[1-9][0-9]*$ ]]; then
  echo "fuzz.sh: SECONDS must be a positive whole number, got '$seconds'" >&2
  exit 2
fi
"$root/scripts/deps.sh"

flags="-O1 -g1"
werror=()
[[ ${CI:-} == true ]] && werror=(-DPOOL_WERROR=ON)  # CI builds with warnings as errors
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DPOOL_FUZZ=ON "${werror[@]}" \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_C_FLAGS_RELWITHDEBINFO=$flags" \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=$flags" >/dev/null
cmake --build "$build" -j "$(nproc)" --target fuzz

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/bin/fuzz-seeds" "$work/generated"
mkdir -p "$build/artifacts"

# Seeds: the project's own files, plus what exists only as code (fuzz-seeds).
seed_dirs() {
  case $1 in
    fuzz_shot_command) ;;  # its input is raw field bytes: starts from nothing
    fuzz_shot_command_cdr) echo "$work/generated/shot_command_cdr" ;;
    fuzz_scenario) echo "$root/assets/scenes $work/generated/scenario" ;;
    fuzz_table_spec) echo "$root/assets/tables" ;;
  esac
}

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$root/tests/sanitize/lsan.supp}
failed=0
failed_count=0
summary=()
for target in "${targets[@]}"; do
  corpus=$work/corpus-$target
  mkdir -p "$corpus"
  for dir in $(seed_dirs "$target"); do
    find "$dir" -maxdepth 1 -type f \( -name '*.json' -o -name '*.cdr' \) -exec cp -t "$corpus" {} +
  done
  dict=()
  name=${target#fuzz_}
  [[ -f $root/tests/fuzz/$name.dict ]] && dict=("-dict=$root/tests/fuzz/$name.dict")
  log=$build/artifacts/$target.log
  echo "fuzzing $target for ${seconds} s ($(ls "$corpus" | wc -l) seeds)"
  status=0
  "$build/bin/$target" "$corpus" "${dict[@]}" -max_total_time="$seconds" -timeout=30 \
    -print_final_stats=1 -artifact_prefix="$build/artifacts/$target-" >"$log" 2>&1 || status=$?
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  if ((status != 0)); then
    failed=1
    failed_count=$((failed_count + 1))
    grep -E 'ERROR|SUMMARY|runtime error|broken promise|Test unit written' "$log" | head -20 >&2 || true
    summary+=("$target: FAILED (exit $status) after ${runs:-?} executions; log: $log")
  else
    summary+=("$target: ${runs:-?} executions in ${seconds} s, no crash ($(ls "$corpus" | wc -l) inputs in the corpus)")
  fi
done
printf '%s\n' "${summary[@]}"
echo "fuzz: $((${#targets[@]} - failed_count)) passed, $failed_count failed"
exit "$failed"
