#!/usr/bin/env bash
# The README's test command (and .ci/run): installs what is missing, builds,
# and runs every test with ctest. Exit 0 only if all pass.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"
pita_build
ctest --test-dir "$PITA_BUILD" --output-on-failure -j "$(nproc)"
