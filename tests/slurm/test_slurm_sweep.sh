#!/usr/bin/env bash
# The Slurm recipe of docs/guide/cluster-sweeps.md against a real Slurm (run inside
# tests/slurm/start-cluster.sh: SLURM_CONF set). Each case submits with the
# guide's command, scripts/slurm-sweep.sbatch --submit, and waits for the jobs:
#  1. an array of shards and the afterok merge give manifest.csv equal byte for
#     byte to the unsharded sweep's, with a log per task where the guide says;
#  2. one array task requeued while it runs (killed, then run again by Slurm)
#     resumes: the merged manifest is the unsharded one, no variant lost or
#     twice, and no temporary file is left;
#  3. one array task cancelled (scancel JOB_K): the merge is cancelled, pita
#     sweep --merge names the shard, and the same --submit again completes it;
#  4. a task that fails (its journal cannot be written): the merge job does
#     not run, Slurm shows the task FAILED, its log and --merge name the shard.
# Usage: test_slurm_sweep.sh PITA_BINARY SOURCE_DIR
set -euo pipefail
pita="$1"
root="$2"
[ -n "${SLURM_CONF:-}" ] || { echo "FAIL: run inside tests/slurm/start-cluster.sh" >&2; exit 1; }
work="$(mktemp -d)"
# The jobs first (a running pita would write on into the folder), then the folder.
finish() {
  scancel --quiet --user="$(id -un)" 2>/dev/null || true
  for _ in $(seq 100); do [ -z "$(squeue -h -o %i 2>/dev/null)" ] && break; sleep 0.1; done
  rm -rf "$work"
}
trap finish EXIT
cd "$work"
export PITA="$pita"
recipe="$root/scripts/slurm-sweep.sbatch"
fail() { echo "FAIL: $*" >&2; exit 1; }

# submit OUT ARGS...: the guide's command; sets $array and $merge_job.
submit() {
  local out
  out="$(bash "$recipe" --submit "$@")" || fail "--submit $*"
  echo "$out"
  array="$(sed -n 's/.*job array \([0-9]*\) .*/\1/p' <<<"$out")"
  merge_job="$(sed -n 's/.*the merge as job \([0-9]*\).*/\1/p' <<<"$out")"
  [ -n "$array" ] && [ -n "$merge_job" ] || fail "no job ids in: $out"
}
# wait_gone JOBS: until squeue lists none of them (at most 240 s).
wait_gone() {
  for _ in $(seq 1200); do
    [ -z "$(squeue -h -j "$1" -o %i 2>/dev/null)" ] && return 0
    sleep 0.2
  done
  squeue >&2
  fail "jobs $1 still queued after 240 s"
}
# state JOB: JobState of a job (or "JOB_K" of an array task) as scontrol shows it.
state() { scontrol -o show job "$1" | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | head -1; }
# running DIR K: waits until shard K of 2 has journaled 3 variants (it is running, far from done).
running() {
  local journal="$1/.manifest.$2-of-2.csv.journal"
  for _ in $(seq 1200); do
    [ -s "$journal" ] && [ "$(wc -l <"$journal")" -ge 3 ] && return 0
    sleep 0.1
  done
  fail "shard $2 never started writing into $1: $(squeue)"
}
# merge_names DIR K/N: pita sweep --merge DIR exits 1 and names shard K/N as missing variants.
merge_names() {
  local code=0
  "$pita" sweep --merge "$1" >/dev/null 2>merge.err || code=$?
  [ $code -eq 1 ] || fail "--merge $1 with a shard missing exited $code: $(cat merge.err)"
  grep -q "shard $2" merge.err || fail "--merge $1 does not name shard $2: $(cat merge.err)"
}
no_temporaries() {
  local left
  left="$(find "$1" -name '.*.??????' -print)"
  [ -z "$left" ] || fail "temporary files left in $1: $left"
}

scene="$root/scenes/fig13-knot-ratio.json"
# The first panel's knot and method: what its figure draws and its metrics measure.
args=(--vary /panels/0/keyframes/1/t=0.1:0.9:100 --vary /panels/0/method=P1,P4,P6 --format svg)
"$pita" sweep "$scene" "${args[@]}" -o whole -q >/dev/null

echo "--- $SECONDS s: 1. 4 shards, 2 at a time, and the merge"
submit 4 --width 2 --time 10:00 --mem 500M "$scene" "$work/one" "${args[@]}"
wait_gone "$array,$merge_job"
[ "$(state "$merge_job")" = COMPLETED ] || fail "the merge job is $(state "$merge_job"): $(cat one/logs/merge-*.log)"
cmp whole/manifest.csv one/manifest.csv || fail "the merged manifest differs from the unsharded sweep's"
cmp whole/contact.svg one/contact.svg || fail "the merged contact sheet differs"
for k in 0 1 2 3; do
  log="one/logs/shard-$k-$array.log"
  [ -f "$log" ] || fail "no log $log"
  grep -q "shard $k/4 done" "$log" || fail "$log: $(cat "$log")"
  [ "$(state "${array}_$k")" = COMPLETED ] || fail "task $k is $(state "${array}_$k")"
done
grep -q "merged manifest.0-of-4.csv, .*300 rows of 300 variants" one/logs/merge-"$merge_job".log ||
  fail "merge log: $(cat one/logs/merge-"$merge_job".log)"
no_temporaries one

echo "--- $SECONDS s: 2. a running task requeued: it resumes"
heavy="$root/scenes/fig26-banners.json"
hargs=(--vary /keyframes/1/t=0.1:0.9:60 --format png)
"$pita" sweep "$heavy" "${hargs[@]}" -o whole-heavy -q --jobs 2 >/dev/null
submit 2 --width 1 "$heavy" "$work/two" "${hargs[@]}"
running two 0
scontrol requeue "${array}_0" || fail "scontrol requeue ${array}_0"
# Slurm holds a requeued job back for about two minutes (its BeginTime); the
# test lets it start at once.
sleep 0.5
scontrol -o show job "${array}_0" | grep -o 'Reason=[A-Za-z]*' || true
scontrol update JobId="${array}_0" StartTime=now || true
wait_gone "$array,$merge_job"
[ "$(state "$merge_job")" = COMPLETED ] || fail "after the requeue the merge is $(state "$merge_job")"
log="two/logs/shard-0-$array.log"
grep -q "(restart 1)" "$log" || fail "task 0 did not run again: $(cat "$log")"
grep -Eq "variants: [0-9]+ written, [1-9][0-9]* resumed" "$log" || fail "task 0 did not resume: $(cat "$log")"
cmp whole-heavy/manifest.csv two/manifest.csv || fail "after a requeue the merged manifest differs"
no_temporaries two

echo "--- $SECONDS s: 3. a task cancelled, the merge with it; the same --submit again"
submit 2 --width 1 "$heavy" "$work/three" "${hargs[@]}"
running three 1
scancel "${array}_1"
wait_gone "$array,$merge_job"
[ "$(state "${array}_1")" = CANCELLED ] || fail "task 1 is $(state "${array}_1")"
[ "$(state "$merge_job")" = CANCELLED ] || fail "the merge is $(state "$merge_job") after a task was cancelled"
[ ! -e three/manifest.csv ] || fail "manifest.csv written although a task was cancelled"
merge_names three 1/2
rm -f three/manifest.csv three/index.html
submit 2 --width 1 "$heavy" "$work/three" "${hargs[@]}"
wait_gone "$array,$merge_job"
[ "$(state "$merge_job")" = COMPLETED ] || fail "the second --submit's merge is $(state "$merge_job")"
grep -Eq "variants: 0 written, 30 resumed" "three/logs/shard-0-$array.log" ||
  fail "shard 0, complete, was not resumed whole: $(cat "three/logs/shard-0-$array.log")"
cmp whole-heavy/manifest.csv three/manifest.csv || fail "after a cancel and a new --submit the manifest differs"
no_temporaries three

echo "--- $SECONDS s: 4. a task that fails: no merge, and the shard is named"
mkdir -p four/.manifest.2-of-3.csv.journal/in-the-way  # shard 2 cannot write its journal
submit 3 "$scene" "$work/four" "${args[@]}"
wait_gone "$array,$merge_job"
[ "$(state "${array}_2")" = FAILED ] || fail "task 2 is $(state "${array}_2")"
for k in 0 1; do [ "$(state "${array}_$k")" = COMPLETED ] || fail "task $k is $(state "${array}_$k")"; done
[ "$(state "$merge_job")" = CANCELLED ] || fail "the merge is $(state "$merge_job") after a task failed"
[ ! -e four/manifest.csv ] || fail "manifest.csv written although a task failed"
grep -q "shard 2/3 FAILED" "four/logs/shard-2-$array.log" || fail "the log: $(cat "four/logs/shard-2-$array.log")"
grep -q "manifest.2-of-3.csv" "four/logs/shard-2-$array.log" || fail "the log does not name the file"
merge_names four 2/3
echo "ok: the Slurm recipe on a real Slurm: merge, requeue, cancel and resubmit, failure"
