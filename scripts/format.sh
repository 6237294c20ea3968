#!/usr/bin/env bash
# Formats every tracked C and C++ file with the repository's .clang-format
# (100 columns).  `scripts/format.sh --check` changes nothing and exits 1,
# listing the files, when any file is not formatted.
set -euo pipefail
cd "$(dirname "$0")/.."
format=${CLANG_FORMAT:-clang-format}
mapfile -t files < <(git ls-files '*.c' '*.h' '*.cpp' '*.hpp')
if [ "${1:-}" = "--check" ]; then
  bad=0
  for f in "${files[@]}"; do
    if ! "$format" --dry-run --Werror "$f" >/dev/null 2>&1; then
      echo "not formatted: $f"
      bad=1
    fi
  done
  exit "$bad"
fi
"$format" -i "${files[@]}"
