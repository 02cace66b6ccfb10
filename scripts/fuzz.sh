#!/usr/bin/env bash
# Builds the libFuzzer targets in the sanitizer build (clang, ASan + UBSan: build-asan or
# $POOL_ASAN_BUILD_DIR, shared with `POOL_SANITIZE=1 scripts/test.sh`) and runs each for SECONDS
# (default 60) on a copy of its seed corpus, as many at once as there are cores; fails on any crash.
# Usage: scripts/fuzz.sh [SECONDS] [TARGET...]   (targets: fuzz_shot_command fuzz_shot_command_cdr
# fuzz_scenario fuzz_table_spec; all by default). Crashing inputs are kept in build-asan/artifacts.
set -euo pipefail
export POOL_SANITIZE=1
source "$(dirname "${BASH_SOURCE[0]}")/build-env.sh"
seconds=${1:-60}
[[ $# -gt 0 ]] && shift
targets=("$@")
((${#targets[@]})) || targets=(fuzz_shot_command fuzz_shot_command_cdr fuzz_scenario fuzz_table_spec)
if ! [[ $seconds =~ ^[1-9][0-9]*$ ]]; then
  echo "fuzz.sh: SECONDS must be a positive whole number, got '$seconds'" >&2
  exit 2
fi
"$root/scripts/deps.sh"
configure_build
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
# fuzz_one TARGET: runs it on its corpus; its summary line goes to $work/TARGET.summary.
fuzz_one() {
  local target=$1 corpus=$work/corpus-$1 dir
  mkdir -p "$corpus"
  for dir in $(seed_dirs "$target"); do
    find "$dir" -maxdepth 1 -type f \( -name '*.json' -o -name '*.cdr' \) -exec cp -t "$corpus" {} +
  done
  local dict=() name=${target#fuzz_}
  [[ -f $root/tests/fuzz/$name.dict ]] && dict=("-dict=$root/tests/fuzz/$name.dict")
  local log=$build/artifacts/$target.log
  echo "fuzzing $target for ${seconds} s ($(ls "$corpus" | wc -l) seeds)"
  local status=0
  "$build/bin/$target" "$corpus" "${dict[@]}" -max_total_time="$seconds" -timeout=30 \
    -print_final_stats=1 -artifact_prefix="$build/artifacts/$target-" >"$log" 2>&1 || status=$?
  local runs
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  if ((status != 0)); then
    grep -E 'ERROR|SUMMARY|runtime error|broken promise|Test unit written' "$log" | head -20 >&2 || true
    echo "$target: FAILED (exit $status) after ${runs:-?} executions; log: $log" > "$work/$target.summary"
  else
    echo "$target: ${runs:-?} executions in ${seconds} s, no crash ($(ls "$corpus" | wc -l) inputs in the corpus)" > "$work/$target.summary"
  fi
}

# The targets side by side, one a core.
running=0
for target in "${targets[@]}"; do
  if ((running >= $(nproc))); then
    wait -n
    running=$((running - 1))
  fi
  fuzz_one "$target" &
  running=$((running + 1))
done
wait
failed_count=0
for target in "${targets[@]}"; do
  cat "$work/$target.summary"
  grep -q FAILED "$work/$target.summary" && failed_count=$((failed_count + 1))
done
echo "fuzz: $((${#targets[@]} - failed_count)) passed, $failed_count failed"
((failed_count == 0))
