#!/usr/bin/env bash
# A parameter sweep: the same three keyframes with the middle knot b moved
# from 0.2 to 0.8 (Sec. 4.8, knot control), under every PITA, printing the
# frame at t = 0.5 as one CSV table on stdout:
#
#   scripts/sweep-example.sh > sweep.csv
#
# Copy it and change the loops to sweep what you need.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"
pita_build >/dev/null
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

echo "method,b,t,px,py,m,w,qx,qy"
for b in 0.2 0.3 0.4 0.5 0.6 0.7 0.8; do
  cat >"$work/scene.json" <<SCENE
{"method": "P6",
 "keyframes": [
   {"t": 0,  "p": [0, 0], "m": 1,   "w": 0.2},
   {"t": $b, "p": [3, 2], "m": 0.7, "w": 1.6},
   {"t": 1,  "p": [6, 0], "m": 1.3, "w": 3.0}]}
SCENE
  for method in P1 P2 P3 P4 P5 P5S P6 P7 P8 P9 P10; do
    "$PITA_BUILD/pita" eval "$work/scene.json" --method "$method" --t 0.5 --format csv |
      tail -n +2 | sed "s/^/$method,$b,/"
  done
done
