#!/usr/bin/env bash
# The README's test command (and .ci/run): installs what is missing, builds,
# and runs every test with ctest. Exit 0 only if all pass.
#
#   scripts/test.sh              the Release build in build/ (gcc): every test
#   scripts/test.sh --sanitize   the same suite in build-sanitize/: clang with
#                                ASan + UBSan (every report fatal, leaks
#                                included), plus the fuzz targets' replays;
#                                but the tests of labels slurm (the cluster),
#                                oracle (numbers against SciPy), checks
#                                (the docs' text, the format of the sources)
#                                packaging (the install tree, the .deb,
#                                each header compiled alone) and browser
#                                (pages in Chromium), which test numbers,
#                                text, files and pages, not memory: the
#                                Release step runs them
#   scripts/test.sh --quick [LAYER...]
#                                the edit loop: builds only the unit tests of
#                                the layers named (io core text scene motion analysis
#                                render lint animate golden sweep serve; default: all of
#                                them) and runs them (ctest -L). Not the
#                                suite: the CLI, oracle, golden, packaging and
#                                script tests run only without --quick.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"

PITA_UNIT_LAYERS=(io core text scene motion analysis render lint animate golden sweep serve)
mode=full
layers=()
for arg in "$@"; do
  case "$arg" in
    --sanitize) mode=sanitize ;;
    --quick) mode=quick ;;
    -h|--help) sed -n '2,18s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"; exit 0 ;;
    -*) echo "scripts/test.sh: unknown option \"$arg\" (use --sanitize, --quick [LAYER...] or nothing)" >&2; exit 2 ;;
    *)
      if [ "$mode" != quick ] || [[ ! " ${PITA_UNIT_LAYERS[*]} " == *" $arg "* ]]; then
        echo "scripts/test.sh: \"$arg\" is not a layer with unit tests (after --quick: ${PITA_UNIT_LAYERS[*]})" >&2
        exit 2
      fi
      layers+=("$arg") ;;
  esac
done

# One test more than cores: many tests spend much of their time starting
# processes and waiting on them (the CLI, Chromium, ffmpeg, Slurm's queue).
case "$mode" in
  sanitize)
    pita_build_sanitize
    ctest --test-dir "$PITA_SANITIZE_BUILD" --output-on-failure -j "$((PITA_JOBS + 1))" -LE '^(slurm|oracle|checks|packaging|browser)$' ;;
  quick)
    if [ ${#layers[@]} -eq 0 ]; then layers=("${PITA_UNIT_LAYERS[@]}"); fi
    pita_build_tests "${layers[@]/#/test_}"
    label="^($(IFS='|'; echo "${layers[*]}"))\$"
    ctest --test-dir "$PITA_BUILD" --output-on-failure -j "$PITA_JOBS" -L "$label" ;;
  full)
    pita_build_tests
    ctest --test-dir "$PITA_BUILD" --output-on-failure -j "$((PITA_JOBS + 1))" ;;
esac
