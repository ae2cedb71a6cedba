#!/usr/bin/env bash
# The README's test command (and .ci/run): installs what is missing, builds,
# and runs every test with ctest. Exit 0 only if all pass.
#
#   scripts/test.sh              the Release build in build/ (gcc)
#   scripts/test.sh --sanitize   the same suite in build-sanitize/: clang with
#                                ASan + UBSan (every report fatal, leaks
#                                included), plus the fuzz targets' replays
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"

sanitize=0
for arg in "$@"; do
  case "$arg" in
    --sanitize) sanitize=1 ;;
    -h|--help) sed -n '2,9s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"; exit 0 ;;
    *) echo "scripts/test.sh: unknown argument \"$arg\" (use --sanitize or nothing)" >&2; exit 2 ;;
  esac
done

if [ "$sanitize" -eq 1 ]; then
  pita_build_sanitize
  ctest --test-dir "$PITA_SANITIZE_BUILD" --output-on-failure -j "$PITA_JOBS"
else
  pita_build_tests
  ctest --test-dir "$PITA_BUILD" --output-on-failure -j "$PITA_JOBS"
fi
