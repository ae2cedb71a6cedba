#!/usr/bin/env bash
# Builds the sanitizer build (build-sanitize/, as scripts/test.sh --sanitize:
# one compile for both) and runs every libFuzzer target of fuzz/ in turn, the
# SECONDS (default 60) split evenly between them. Exit 0 when no target found
# anything; otherwise each input that crashed, timed out or ran out of memory
# is copied to tests/data/fuzz/<target>/ (ctest replays that folder as
# fuzz_replay.<target>: fix the bug, keep the file) and the exit code is 1.
#
#   scripts/fuzz.sh [SECONDS]
#
# Seeds: scenes/, tests/data/bad/, trimmed golden data files and EAR cases
# (fuzz/make_seeds.py, written afresh each run), and tests/data/fuzz/<target>/.
# The growing corpus and the logs stay in build-sanitize/fuzz-work/<target>/.
# Environment: PITA_SANITIZE_BUILD (the build folder), PITA_JOBS (compile jobs).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"

total="${1:-60}"
if ! [[ "$total" =~ ^[0-9]+$ ]] || [ $# -gt 1 ]; then
  echo "usage: scripts/fuzz.sh [SECONDS]   (the total time, split between the targets)" >&2
  exit 2
fi

# The targets: the one list, PITA_FUZZ_TARGETS of fuzz/CMakeLists.txt.
read -r -a targets <<<"$(sed -n 's/^set(PITA_FUZZ_TARGETS \(.*\))$/\1/p' "$PITA_ROOT/fuzz/CMakeLists.txt")"
if [ ${#targets[@]} -eq 0 ]; then
  echo "pita: no fuzz target found in fuzz/CMakeLists.txt (set(PITA_FUZZ_TARGETS ...))" >&2
  exit 1
fi
per=$(( total / ${#targets[@]} ))
[ "$per" -ge 1 ] || per=1

pita_build_sanitize >/dev/null
work="$PITA_SANITIZE_BUILD/fuzz-work"
mkdir -p "$work"
python3 "$PITA_ROOT/fuzz/make_seeds.py" "$work/seeds"

# Per target (into the array `options`): the dictionary, the longest input
# tried, the time one input may take (a scene within the documented limits
# must render in seconds, also under ASan) and libFuzzer's memory limit (also
# for single allocations).
set_options() {
  options=(-print_final_stats=1 -rss_limit_mb=2048 -timeout=25 "-max_total_time=$per")
  case "$1" in
    fuzz_scene_reader|fuzz_eval|fuzz_render)
      options+=("-dict=$PITA_ROOT/fuzz/scene.dict" -max_len=8192) ;;
    fuzz_golden_data)
      options+=("-dict=$PITA_ROOT/fuzz/golden_data.dict" -max_len=16384) ;;
    fuzz_affine_power)
      options+=(-max_len=64) ;;
    fuzz_sweep)
      options+=(-max_len=4096) ;;
    fuzz_animate)
      options+=("-dict=$PITA_ROOT/fuzz/scene.dict" -max_len=8192) ;;
    fuzz_http_request)
      options+=("-dict=$PITA_ROOT/fuzz/http.dict" -max_len=8192) ;;
    fuzz_python_entry)
      options+=(-max_len=160) ;;
    fuzz_edit_body)
      options+=("-dict=$PITA_ROOT/fuzz/scene.dict" -max_len=2048) ;;
    fuzz_batch_line)
      options+=(-max_len=4096) ;;
  esac
}

failed=()
summary=()
echo "pita: fuzzing ${#targets[@]} targets for ${per} s each (${total} s in all); logs in $work/<target>/log"
for target in "${targets[@]}"; do
  dir="$work/$target"
  # libFuzzer ends at once on a corpus folder that does not exist: a target
  # without generated seeds still starts, from its regression inputs.
  mkdir -p "$dir/corpus" "$dir/artifacts" "$work/seeds/$target"
  rm -f "$dir"/artifacts/*
  log="$dir/log"
  set_options "$target"
  set +e
  "$PITA_SANITIZE_BUILD/fuzz/$target" "${options[@]}" "-artifact_prefix=$dir/artifacts/" \
    "$dir/corpus" "$work/seeds/$target" "$PITA_ROOT/tests/data/fuzz/$target" >"$log" 2>&1
  status=$?
  set -e
  # A target that fails while loading its seeds prints no statistics: each
  # reading may find nothing (and must not end the script under pipefail).
  execs="$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)"
  rate="$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)"
  corpus="$({ grep -o 'corp: [0-9]*/[0-9]*[a-zA-Z]*' "$log" || true; } | tail -1 | cut -d' ' -f2)"  # inputs/size
  [ -n "$corpus" ] || corpus="?/?"
  line="$(printf '%-18s %9s execs %7s exec/s  corpus %s inputs (%s)' "$target" "${execs:-?}" \
          "${rate:-?}" "${corpus%%/*}" "${corpus#*/}")"
  slow="$(find "$dir/artifacts" -name 'slow-unit-*' | wc -l)"
  [ "$slow" -eq 0 ] || line+="  $slow slow inputs (> 10 s) in $dir/artifacts"
  if [ "$status" -ne 0 ]; then
    failed+=("$target")
    line+="  FAILED (exit $status)"
    echo "pita: $target FAILED (exit $status); the report:" >&2
    grep -m1 -A30 -E '^==[0-9]+==ERROR|runtime error|fuzz check failed|^==[0-9]+== ERROR: libFuzzer|terminate called|deadly signal' "$log" >&2 || tail -30 "$log" >&2
    kept=0
    for artifact in "$dir"/artifacts/{crash,leak,timeout,oom}-*; do
      [ -f "$artifact" ] || continue
      mkdir -p "$PITA_ROOT/tests/data/fuzz/$target"
      cp "$artifact" "$PITA_ROOT/tests/data/fuzz/$target/"
      echo "pita: kept the input as tests/data/fuzz/$target/$(basename "$artifact")" >&2
      kept=1
    done
    [ "$kept" -eq 1 ] || echo "pita: no input was written for $target (see $log)" >&2
  fi
  summary+=("$line")
  echo "$line"
done

echo
echo "pita: fuzzing summary (${per} s per target)"
printf '  %s\n' "${summary[@]}"
if [ ${#failed[@]} -gt 0 ]; then
  echo "pita: these targets found a crash, a timeout or an out-of-memory: ${failed[*]}" >&2
  exit 1
fi
