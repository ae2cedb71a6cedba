#!/usr/bin/env bash
# The two recipes of docs/reference/sweep.md "pita sweep" for more than one machine, run here:
#  - scripts/slurm-sweep.sbatch: --submit calls sbatch for the job array and the
#    dependent merge (a stand-in sbatch on PATH records the calls); each array
#    task, run as Slurm would run it (SLURM_ARRAY_TASK_ID/COUNT set), then the
#    merge give the manifest of the unsharded sweep;
#  - the GNU parallel one-liner gives it too.
# Usage: sweep_recipes.sh PITA_BINARY SOURCE_DIR
set -euo pipefail
pita="$1"
root="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
scene="$root/scenes/fig13-knot-ratio.json"
args=(--vary /keyframes/1/t=0.2:0.8:5 --vary /method=P1,P6 --format svg,csv)
fail() { echo "FAIL: $*" >&2; exit 1; }

"$pita" sweep "$scene" "${args[@]}" -o whole -q >/dev/null

# --submit: the calls it makes (a stand-in sbatch prints job ids).
mkdir bin
cat >bin/sbatch <<'FAKE'
#!/usr/bin/env bash
echo "$*" >>"$SBATCH_LOG"
n=$(wc -l <"$SBATCH_LOG")
# The merge's command, as Slurm will give it to /bin/sh.
prev=""
for a; do
  if [ "$prev" = --wrap ]; then printf '%s' "$a" >"$SBATCH_LOG.wrap"; fi
  prev="$a"
done
echo "$((1000 + n));cluster"
FAKE
chmod +x bin/sbatch
export SBATCH_LOG="$work/sbatch.log"
PATH="$work/bin:$PATH" PITA="$pita" bash "$root/scripts/slurm-sweep.sbatch" --submit 3 "$scene" slurm "${args[@]}" >submit.out
grep -q -- "--parsable --cpus-per-task=1 --array=0-2 --output=slurm/logs/shard-%a-%A.log $root/scripts/slurm-sweep.sbatch $scene slurm --vary /keyframes/1/t=0.2:0.8:5" sbatch.log ||
  fail "the array job: $(cat sbatch.log)"
grep -qF -- "--dependency=afterok:1001 --kill-on-invalid-dep=yes --wrap '$pita' sweep --merge 'slurm'" sbatch.log ||
  fail "the merge job: $(cat sbatch.log)"
[ -d slurm/logs ] || fail "--submit did not create the log folder slurm/logs"
# The options of the recipe reach both jobs: partition, time, memory; the width the array.
PATH="$work/bin:$PATH" PITA="$pita" bash "$root/scripts/slurm-sweep.sbatch" --submit 4 --partition short \
  --time=30:00 --width 2 --mem 1G --cpus 2 --logs "$work/my-logs" "$scene" opts "${args[@]}" >/dev/null
grep -q -- "--parsable --partition=short --time=30:00 --mem=1G --cpus-per-task=2 --array=0-3%2 --output=$work/my-logs/shard-%a-%A.log" sbatch.log ||
  fail "the array job with options: $(tail -2 sbatch.log)"
grep -q -- "--parsable --partition=short --time=30:00 --mem=1G --job-name=pita-sweep-merge --output=$work/my-logs/merge-%j.log" sbatch.log ||
  fail "the merge job with options: $(tail -1 sbatch.log)"
bad_submit() {  # bad_submit MESSAGE ARGS...: --submit ARGS is refused, saying MESSAGE
  local message="$1"
  shift
  if PATH="$work/bin:$PATH" bash "$root/scripts/slurm-sweep.sbatch" --submit "$@" 2>err.txt; then
    fail "--submit $* was accepted"
  fi
  grep -qF -- "$message" err.txt || fail "--submit $*: $(cat err.txt)"
}
bad_submit "--width: must be a whole number from 1 to 999999999 (got '0')" 4 --width 0 "$scene" opts
bad_submit "--time needs a value" 4 --time
bad_submit "unknown option --bogus before SCENE" 4 --bogus 1 "$scene" opts
bad_submit "SCENE and OUT are required" 4 --mem 1G "$scene"
bad_submit "--submit N: must be a whole number from 1 to 999999999 (got 'x')" x "$scene" opts
bad_submit "--submit N: must be a whole number from 1 to 999999999 (got '0')" 0 "$scene" opts
# Counts are decimal: 010 is ten tasks (bash would read it as octal eight), 08 is eight.
PATH="$work/bin:$PATH" PITA="$pita" bash "$root/scripts/slurm-sweep.sbatch" --submit 010 --width 08 "$scene" opts \
  "${args[@]}" >/dev/null
grep -q -- "--array=0-9%8 " sbatch.log || fail "--submit 010 --width 08: $(tail -2 sbatch.log)"
# The merge runs under /bin/sh in the C locale: any folder name reaches pita as it is.
odd="$work/a b'c"$'\t'"d"$'\n'"é"
printf '#!/bin/sh\nprintf "%%s\\n" "$@" >"%s"\n' "$work/merge-args" >bin/record-args
chmod +x bin/record-args
PATH="$work/bin:$PATH" PITA="$work/bin/record-args" bash "$root/scripts/slurm-sweep.sbatch" --submit 2 "$scene" "$odd" \
  "${args[@]}" >/dev/null
LC_ALL=C sh -c "$(cat sbatch.log.wrap)"
[ "$(cat merge-args)" = "sweep
--merge
$odd" ] || fail "the merge's command under sh gave the arguments: $(cat merge-args)"
rm -rf opts "$odd"
rm -rf opts
grep -q "job array 1001 (3 tasks) and the merge as job 1002" submit.out || fail "$(cat submit.out)"
if PITA="$pita" bash "$root/scripts/slurm-sweep.sbatch" "$scene" slurm "${args[@]}" 2>err.txt; then
  fail "outside an array the script must refuse"
fi
grep -q "not inside a Slurm job array" err.txt || fail "$(cat err.txt)"

# The array's tasks as Slurm runs them, in any order, then the merge.
for k in 2 0 1; do
  SLURM_ARRAY_TASK_ID=$k SLURM_ARRAY_TASK_COUNT=3 PITA="$pita" bash "$root/scripts/slurm-sweep.sbatch" \
    "$scene" slurm "${args[@]}" >/dev/null
done
"$pita" sweep --merge slurm >/dev/null
cmp whole/manifest.csv slurm/manifest.csv || fail "Slurm shards merged differ from the unsharded sweep"
cmp whole/contact.svg slurm/contact.svg || fail "the Slurm contact sheet differs"

# GNU parallel, the one-liner of docs/guide/cluster-sweeps.md "GNU parallel".
command -v parallel >/dev/null || fail "GNU parallel is not installed (Debian package parallel, in PITA_TEST_PACKAGES)"
parallel --will-cite -j 2 "$pita" sweep "$scene" "${args[@]}" -o par --shard {}/4 -q ::: 0 1 2 3 >/dev/null &&
  "$pita" sweep --merge par >/dev/null
cmp whole/manifest.csv par/manifest.csv || fail "GNU parallel shards merged differ from the unsharded sweep"
echo "ok: Slurm array + merge and GNU parallel + merge reproduce the unsharded sweep"
