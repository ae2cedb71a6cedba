#!/usr/bin/env bash
# The performance figures of docs/reference/sweep.md "pita sweep", measured in one run on
# Fig. 1's scene (scenes/fig01-eight-pitas.json, eight panels), its middle
# knot swept:
#   - 1000 SVG variants: pita sweep --jobs 1 against one `pita render` process
#     per variant (the variants' own scene files), and --jobs 2 against --jobs 1;
#   - the time per variant for SVG, PNG and CSV (1000 variants, --jobs 1);
#   - the peak memory (GNU time's maximum resident set) of 1000 and 10 000
#     variant CSV sweeps: it must not grow with the number of variants.
# Prints a Markdown table. Usage: scripts/bench-sweep.sh [WORK_DIR]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"
pita_install_dependencies time >/dev/null
pita_build >/dev/null
pita="$PITA_BUILD/pita"
scene="$PITA_ROOT/scenes/fig01-eight-pitas.json"
work="${1:-$(mktemp -d)}"
mkdir -p "$work"
cd "$work"

seconds() {  # seconds COMMAND...: the wall time of COMMAND, in seconds
  local start end
  start=$(date +%s.%N)
  "$@" >/dev/null
  end=$(date +%s.%N)
  awk "BEGIN { print $end - $start }"
}
vary() { echo "--vary /keyframes/1/t=0.05:0.95:$1"; }

rm -rf svg1 svg2 png1 csv1 csv10k procs
t_svg1=$(seconds "$pita" sweep "$scene" $(vary 1000) -o svg1 --format svg --jobs 1 -q)
t_svg2=$(seconds "$pita" sweep "$scene" $(vary 1000) -o svg2 --format svg --jobs 2 -q)
t_png1=$(seconds "$pita" sweep "$scene" $(vary 1000) -o png1 --format png --jobs 1 -q)
t_csv1=$(seconds "$pita" sweep "$scene" $(vary 1000) -o csv1 --format csv --jobs 1 -q)
mkdir procs
one_process_each() {
  for f in svg1/*.scene.json; do
    "$pita" render "$f" -o "procs/$(basename "${f%.scene.json}").svg"
  done
}
t_procs=$(seconds one_process_each)
rss() { /usr/bin/time -f %M "$@" 2>&1 >/dev/null | tail -1; }
rm -rf csv1k csv10k
m_1k=$(rss "$pita" sweep "$scene" $(vary 1000) -o csv1k --format csv --jobs 2 -q)
m_10k=$(rss "$pita" sweep "$scene" $(vary 10000) -o csv10k --format csv --jobs 2 -q)

calc() { awk "BEGIN { print $1 }"; }
ms() { printf '%.2f' "$(calc "1000 * $1 / 1000")"; }
echo "| measure (Fig. 1, 1000 variants unless said) | value |"
echo "|---|---|"
printf '| one `pita render` process per variant (SVG) | %.1f s |\n' "$t_procs"
printf '| `pita sweep --jobs 1` (SVG) | %.1f s: %.1fx faster |\n' "$t_svg1" "$(calc "$t_procs / $t_svg1")"
printf '| `pita sweep --jobs 2` (SVG) | %.1f s: %.2fx faster than --jobs 1 |\n' "$t_svg2" "$(calc "$t_svg1 / $t_svg2")"
printf '| per variant, --jobs 1: SVG / PNG / CSV | %s / %s / %s ms |\n' "$(ms "$t_svg1")" "$(ms "$t_png1")" "$(ms "$t_csv1")"
printf '| peak memory, CSV sweep of 1000 / 10 000 variants | %.0f / %.0f MB |\n' "$(calc "$m_1k / 1024")" "$(calc "$m_10k / 1024")"
