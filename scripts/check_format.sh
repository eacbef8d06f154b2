#!/usr/bin/env bash
# Fails when a C++ file of the tree is not as clang-format (.clang-format, Debian's clang-format
# 14) would write it, naming the files; `scripts/check_format.sh --fix` rewrites them. The tree was
# formatted whole once, so checking every file checks every changed line.
set -euo pipefail
cd "$(dirname "$0")/.."
clang_format=${CLANG_FORMAT:-clang-format}
if [ -d .git ] || git rev-parse --git-dir > /dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.h' '*.cpp')
else
  mapfile -t files < <(find app batch bench controller fuzz geometry planner python render robot sim \
                            tests util worlds -name '*.h' -o -name '*.cpp' | sort)
fi
if [ "${1:-}" = --fix ]; then
  "$clang_format" -i "${files[@]}"
  exit 0
fi
# One clang-format for all files (one per file costs half a minute); it names each file that differs.
if ! report=$("$clang_format" --dry-run --Werror "${files[@]}" 2>&1); then
  mapfile -t unformatted < <(grep -o '^[^:]*\.\(h\|cpp\):[0-9]*:[0-9]*: error' <<< "$report" | cut -d: -f1 | sort -u)
  echo "check_format: ${#unformatted[@]} files differ from clang-format (scripts/check_format.sh --fix):"
  printf '  %s\n' "${unformatted[@]}"
  exit 1
fi
echo "check_format: ${#files[@]} files as clang-format writes them"
