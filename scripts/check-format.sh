#!/usr/bin/env bash
# Fails when a tracked C or C++ file differs from the repository's .clang-format (prints the files).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
mapfile -t files < <(git ls-files '*.c' '*.cpp' '*.h' '*.hpp')
existing=()
for f in "${files[@]}"; do
  [[ -f $f ]] && existing+=("$f")  # a file deleted in the work tree, not yet committed, is skipped
done
# 40 files a clang-format process, as many processes as cores; each difference is reported as
# "path:line:col: error: code should be clang-formatted".
status=0
out=$(printf '%s\0' "${existing[@]}" |
  xargs -0 -n 40 -P "$(nproc)" clang-format --dry-run --Werror 2>&1 >/dev/null) || status=$?
mapfile -t bad < <(sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' \
  <<<"$out" | sort -u)
if ((${#bad[@]})); then
  printf 'not formatted (run clang-format -i on them):\n' >&2
  printf '  %s\n' "${bad[@]}" >&2
  exit 1
fi
if ((status != 0)); then
  printf 'clang-format failed:\n%s\n' "$out" >&2
  exit 1
fi
echo "format: ${#existing[@]} files match .clang-format"
