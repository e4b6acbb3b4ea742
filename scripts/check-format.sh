#!/usr/bin/env bash
# Checks that every C++ file of the project follows .clang-format (CTest format_check):
# prints the files that do not, and how to fix them, and exits 1. With --fix, reformats them.
# Usage: check-format.sh [--fix]
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
command -v clang-format >/dev/null || { echo "check-format: clang-format is not installed (scripts/setup.sh)"; exit 77; }
mapfile -t files < <(cd "$here" && find bench cli core filter_fcvt frontend fuzz io python tests \( -name '*.cpp' -o -name '*.h' \) | sort)
cd "$here"
if [ "${1:-}" = "--fix" ]; then
  clang-format -i "${files[@]}"
  exit 0
fi
bad=()
for f in "${files[@]}"; do
  clang-format --dry-run --Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done
if [ ${#bad[@]} -gt 0 ]; then
  printf 'not formatted: %s\n' "${bad[@]}"
  echo "check-format: ${#bad[@]} of ${#files[@]} files differ from .clang-format; run scripts/check-format.sh --fix"
  exit 1
fi
echo "check-format: ${#files[@]} files follow .clang-format"
