#!/usr/bin/env bash
# Measures pita side by side with its floors and with itself (interleaved
# runs) and rewrites the performance tables of the docs with the results, the
# machine and the date: every block between <!-- bench-report:begin NAME -->
# and <!-- bench-report:end NAME --> (scripts/bench_report.py says what each
# report measures). Run it on an idle machine, then review the diff.
#
#   scripts/bench-report.sh              every report (several minutes)
#   scripts/bench-report.sh startup eval  the reports named
#   scripts/bench-report.sh --check      each report's commands once, tiny (the ctest docs.bench_report)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"
pita_build_tests pita pita_bench pita_cairo_floor pita_pango_floor pita_fmt_floor pita_python >/dev/null
exec python3 "$PITA_ROOT/scripts/bench_report.py" --build "$PITA_BUILD" "$@"
