#!/usr/bin/env bash
# The million-variant figures of docs/reference/sweep.md "A million variants", measured in one run
# on Fig. 13's scene (scenes/fig13-knot-ratio.json), its first panel's middle knot swept, --format metrics
# (no file per variant), --jobs = the cores (PITA_JOBS):
#   - wall time and peak memory (GNU time's maximum resident set) at 10^4 and 10^6 variants, and
#     the throughput in variants per second per core;
#   - the same 10^6 sweep killed (SIGKILL) at a random point, resumed, stopped (SIGTERM) at a
#     random point of that run, resumed again: its manifest must equal the clean run's byte for
#     byte (nothing lost, nothing twice); the memory of the resumed runs;
#   - a complete 10^6 sweep run again (everything resumed);
#   - --merge of 1000 shards (GNU parallel runs them) at 10^4 and 10^5 variants: time and memory,
#     and the merged manifest equal to the unsharded run's.
# Prints a Markdown table; exits 1 when a manifest differs or a run at 10^6 peaks above 1.2x the
# memory of the 10^4 one. About 25 minutes on 2 cores, and
# 1 GB of disk. Usage: scripts/bench-million.sh [WORK_DIR]
# (PITA_BENCH_VARIANTS and PITA_BENCH_SHARDS make a smaller trial run: 10^6 and 1000 by default.)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"
pita_install_dependencies time parallel >/dev/null
pita_build >/dev/null
pita="$PITA_BUILD/pita"
scene="$PITA_ROOT/scenes/fig13-knot-ratio.json"
jobs="$PITA_JOBS"
work="${1:-$(mktemp -d)}"
mkdir -p "$work"
cd "$work"
rm -rf m4 m6 k6 s4 s5 w4 w5
big="${PITA_BENCH_VARIANTS:-1000000}"  # smaller for a trial run of the script
shards="${PITA_BENCH_SHARDS:-1000}"

vary() { echo "--vary /panels/0/keyframes/1/t=0.05:0.95:$1"; }
# measure NAME COMMAND...: writes "seconds max-RSS-KB" of COMMAND to time-NAME.txt (its exit
# status 0 or 1 accepted; "sweep N DIR" is the sweep of N variants into DIR); got NAME prints it.
measure() {
  local name="$1"
  shift
  if [ "$1" = sweep ]; then set -- "$pita" sweep "$scene" $(vary "$2") --format metrics -o "$3" -q --jobs "$jobs"; fi
  /usr/bin/time -f "%e %M" -o "$work/time-$name.txt" "$@" >/dev/null 2>&1 || [ $? -le 1 ]
}
got() { tail -1 "$work/time-$1.txt"; }
sweep() { "$pita" sweep "$scene" $(vary "$1") --format metrics -o "$2" -q --jobs "$jobs" || [ $? -le 1 ]; }
# kill_at SIGNAL FRACTION_LOW FRACTION_HIGH SECONDS DIR: runs the 10^6 sweep into DIR and sends
# SIGNAL after a random time between the two fractions of SECONDS.
kill_at() {
  local signal="$1" low="$2" high="$3" full="$4" dir="$5" delay
  delay=$(awk -v l="$low" -v h="$high" -v s="$full" -v r="$RANDOM" 'BEGIN { printf "%.1f", s * (l + (h - l) * r / 32767) }')
  "$pita" sweep "$scene" $(vary "$big") --format metrics -o "$dir" -q --jobs "$jobs" >/dev/null 2>&1 &
  local pid=$!
  sleep "$delay"
  kill "-$signal" "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  echo "$delay"
}

measure t4 sweep 10000 m4
measure t6 sweep "$big" m6
measure again sweep "$big" m6
read -r s6 _ <<<"$(got t6)"
kill1=$(kill_at KILL 0.2 0.7 "$s6" k6)
measure r1 sweep "$big" k6 &
resume_pid=$!
# The first resume, stopped by SIGTERM after a random time too: the run under GNU time is its child.
sleep "$(awk -v s="$s6" -v r="$RANDOM" 'BEGIN { printf "%.1f", s * (0.05 + 0.2 * r / 32767) }')"
pkill -TERM -P "$(pgrep -P "$resume_pid" | head -1)" || true  # the subshell's child is time, its child pita
wait "$resume_pid" || true
measure r2 sweep "$big" k6
same=yes
cmp -s m6/manifest.csv k6/manifest.csv || same=no

# $shards shards, merged, at 10^4 and 10^5 variants.
shards() {  # shards VARIANTS DIR
  seq 0 $((shards - 1)) | parallel --will-cite -j "$jobs" "$pita" sweep "$scene" $(vary "$1") --format metrics -o "$2" -q \
    --jobs 1 --shard {}/"$shards" >/dev/null || [ $? -le 1 ]
}
shards 10000 s4
shards 100000 s5
measure g4 "$pita" sweep --merge s4 -q
measure g5 "$pita" sweep --merge s5 -q
sweep 10000 w4 >/dev/null
sweep 100000 w5 >/dev/null
merged=yes
cmp -s s4/manifest.csv w4/manifest.csv || merged=no
cmp -s s5/manifest.csv w5/manifest.csv || merged=no

read -r t4s t4m <<<"$(got t4)"
read -r t6s t6m <<<"$(got t6)"
read -r as am <<<"$(got again)"
read -r r1s r1m <<<"$(got r1)"
read -r r2s r2m <<<"$(got r2)"
read -r g4s g4m <<<"$(got g4)"
read -r g5s g5m <<<"$(got g5)"
calc() { awk "BEGIN { print $1 }"; }
echo "| measure (Fig. 13, --format metrics, --jobs $jobs) | value |"
echo "|---|---|"
printf '| 10⁴ variants | %.1f s, peak %.1f MB |\n' "$t4s" "$(calc "$t4m / 1024")"
printf '| %s variants | %.0f s, peak %.1f MB: %.2f× the peak at 10⁴ |\n' "$big" "$t6s" "$(calc "$t6m / 1024")" "$(calc "$t6m / $t4m")"
printf '| throughput at %s | %.0f variants/s, %.0f per core |\n' "$big" "$(calc "$big / $t6s")" "$(calc "$big / $t6s / $jobs")"
printf '| %s again, every variant resumed | %.0f s, peak %.1f MB |\n' "$big" "$as" "$(calc "$am / 1024")"
printf '| %s killed (SIGKILL) at %s s, resumed and stopped (SIGTERM), resumed | %.0f s + %.0f s, peaks %.1f and %.1f MB; manifest equal to the clean run'"'"'s: %s |\n' \
  "$big" "$kill1" "$r1s" "$r2s" "$(calc "$r1m / 1024")" "$(calc "$r2m / 1024")" "$same"
printf '| --merge of %s shards, 10⁴ / 10⁵ variants | %.1f s / %.1f s, peak %.1f / %.1f MB; equal to the unsharded run: %s |\n' \
  "$shards" "$g4s" "$g5s" "$(calc "$g4m / 1024")" "$(calc "$g5m / 1024")" "$merged"
printf '| disk at %s | manifest.csv %s, index/ %s |\n' "$big" "$(du -sh m6/manifest.csv | cut -f1)" "$(du -sh m6/index | cut -f1)"
# Flat: every run of the big sweep within 1.2x the peak memory of the 10^4 one.
flat=yes
for m in "$t6m" "$am" "$r1m" "$r2m"; do
  awk -v m="$m" -v base="$t4m" 'BEGIN { exit !(m <= 1.2 * base) }' || flat=no
done
echo "| every run at $big within 1.2× the peak at 10⁴ | $flat |"
[ "$same" = yes ] && [ "$merged" = yes ] && [ "$flat" = yes ]
