#!/usr/bin/env bash
# The layout check (scripts/format.sh --check) passes on the tree and fails
# when it should: on a file laid out against .clang-format, it exits 1 and
# names the file.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
bad="tests/style/data/badly_laid_out.cpp"

"$root/scripts/format.sh" --check || exit 1

output="$("$root/scripts/format.sh" --check "$bad" 2>&1)"
status=$?
if [ "$status" -ne 1 ]; then
  echo "format.sh --check $bad exited $status, not 1" >&2
  exit 1
fi
if ! grep -q "$bad" <<<"$output"; then
  echo "format.sh --check $bad did not name the file:" >&2
  echo "$output" >&2
  exit 1
fi
echo "format.sh --check refuses $bad"
