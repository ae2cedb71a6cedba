#!/usr/bin/env bash
# The set-up stays lean (docs/guide/setup.md): scripts/run.sh asks for exactly
# the number of Debian packages the README and docs/guide/setup.md state (a package added to
# PITA_RUN_PACKAGES fails this test until their figures are measured
# again with scripts/measure-setup.sh and updated), it asks for no test-only
# package, and no package is in both lists.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
source "$root/scripts/lib/deps.sh"

for page in README.md docs/guide/setup.md; do
  stated="$(sed -n 's/.*`scripts\/run.sh` asks for \([0-9][0-9]*\) Debian packages.*/\1/p' "$root/$page" | head -1)"
  if [ -z "$stated" ]; then
    echo "$page does not say how many Debian packages scripts/run.sh asks for" >&2
    exit 1
  fi
  if [ "${#PITA_RUN_PACKAGES[@]}" -ne "$stated" ]; then
    echo "scripts/run.sh asks for ${#PITA_RUN_PACKAGES[@]} packages (PITA_RUN_PACKAGES), $page says $stated:" >&2
    echo "measure again with scripts/measure-setup.sh and update README.md and docs/guide/setup.md" >&2
    exit 1
  fi
done
for p in "${PITA_TEST_PACKAGES[@]}" "${PITA_SANITIZE_PACKAGES[@]}"; do
  for q in "${PITA_RUN_PACKAGES[@]}"; do
    if [ "$p" = "$q" ]; then
      echo "$p is in PITA_RUN_PACKAGES and in a test list" >&2
      exit 1
    fi
  done
done
for p in "${PITA_RUN_PACKAGES[@]}"; do
  case "$p" in
    *gtest*|*gmock*|*benchmark*|*jsonschema*|*valijson*|clang*|*rsvg*|*xml2-utils*)
      echo "$p is a test-only package in PITA_RUN_PACKAGES" >&2
      exit 1 ;;
  esac
done
echo "scripts/run.sh asks for $stated packages, as README.md and docs/guide/setup.md say"
