#!/usr/bin/env bash
# Lays out pita's C++ sources (src/, tests/, bench/, fuzz/) as .clang-format
# says, in place:
#   scripts/format.sh           formats every file
#   scripts/format.sh FILE...   formats these files
#   scripts/format.sh --check   changes nothing; lists the files that differ
#                               from the layout and exits 1 if there are any
#                               (the test style.format runs this)
# Needs clang-format 14 (Debian's clang-format, a test package of scripts/test.sh).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

formatter="$(command -v clang-format-14 || command -v clang-format || true)"
if [ -z "$formatter" ]; then
  echo "pita: clang-format is not installed (apt-get install clang-format)" >&2
  exit 2
fi

check=0
if [ "${1:-}" = "--check" ]; then
  check=1
  shift
fi
if [ $# -gt 0 ]; then
  files=("$@")
else
  # The tests' data folders hold inputs, not pita's code.
  mapfile -t files < <(find src tests bench fuzz \( -name '*.cpp' -o -name '*.hpp' \) -not -path '*/data/*' | sort)
fi

if [ "$check" -eq 0 ]; then
  "$formatter" -i --style=file "${files[@]}"
  exit 0
fi
# One run over every file; clang-format names each file that differs in its
# warnings ("FILE:LINE:COL: error: code should be clang-formatted").
mapfile -t differing < <("$formatter" --style=file --dry-run -Werror --ferror-limit=1 "${files[@]}" 2>&1 |
  sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' | sort -u)
if [ ${#differing[@]} -gt 0 ]; then
  echo "pita: ${#differing[@]} file(s) do not follow .clang-format; scripts/format.sh FILE... lays them out:" >&2
  printf '  %s\n' "${differing[@]}" >&2
  exit 1
fi
echo "all ${#files[@]} files follow .clang-format"
