#!/usr/bin/env bash
# A sweep over a regular pattern (SAM paper Sec. 7.1, Fig. 1): the same poses
# F0 and Fn with copy counts n = 2..12. For each n it prints the increment
# M = A^(1/n) between consecutive copies as CSV on stdout (the frame at
# t = 1/n of the SAM), and renders the pattern to OUT/n<N>.png:
#
#   scripts/sweep-sam-count.sh out/sweep > increments.csv
#
# Copy it and change the loop or the poses to sweep what you need.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"
pita_build >/dev/null
out="${1:-out/sam-count-sweep}"
mkdir -p "$out"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

echo "n,t,a,b,tx,c,d,ty"
for n in 2 3 4 5 6 8 10 12; do
  cat >"$work/n$n.json" <<SCENE
{"method": "SAM", "title": "n = $n",
 "shapes": [{"outline": "F"}],
 "poses": [
   {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
   {"t": 1, "matrix": [[-1.1327, -1.6641, 9], [1.2677, -0.689, 3]]}],
 "samples": $((n + 1)),
 "canvas": {"width": 600, "height": 400}}
SCENE
  t=$(awk "BEGIN { printf \"%.17g\", 1 / $n }")
  "$PITA_BUILD/pita" eval "$work/n$n.json" --t "$t" --format csv | tail -n +2 | sed "s/^/$n,/"
  "$PITA_BUILD/pita" render "$work/n$n.json" -o "$out/n$n.png" >/dev/null
done
