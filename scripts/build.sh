#!/usr/bin/env bash
# Installs what is missing and builds everything into build/ (build/pita,
# the tests, build/pita_bench).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"
pita_build_tests
