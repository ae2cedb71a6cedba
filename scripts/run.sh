#!/usr/bin/env bash
# The README's main command: installs what is missing, builds, then renders
# every scene in scenes/ into out/<scene>.svg and out/<scene>.png, prints
# its frames into out/<scene>.frames.json, and plays each scene that has an
# "animation" into out/<scene>.anim.svg (an animated SVG), two scenes at a
# time (one per core). Each output is written to a temporary file and renamed into place, so
# out/ never holds a half-written file. Exit 0 only if every scene succeeded.
#
#   scripts/run.sh [OUT_DIR]      (default: out/)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"
pita_build >/dev/null

out="${1:-$PITA_ROOT/out}"
mkdir -p "$out"
export PITA_BIN="$PITA_BUILD/pita" PITA_OUT="$out"

shopt -s nullglob
scenes=("$PITA_ROOT"/scenes/*.json)
if [ ${#scenes[@]} -eq 0 ]; then
  echo "pita: no scenes in $PITA_ROOT/scenes" >&2
  exit 2
fi

eval_one() {
  local scene="$1" name
  name="$(basename "$scene" .json)"
  local tmp
  tmp="$(mktemp "$PITA_OUT/.$name.XXXXXX")"
  if "$PITA_BIN" render "$scene" -o "$PITA_OUT" --format svg,png &&
     "$PITA_BIN" eval "$scene" >"$tmp" &&
     { ! grep -q '"animation"' "$scene" || "$PITA_BIN" animate "$scene" -o "$PITA_OUT/$name.anim.svg" --quiet; }; then
    mv -f "$tmp" "$PITA_OUT/$name.frames.json"
    echo "wrote $PITA_OUT/$name.frames.json"
  else
    rm -f "$tmp"
    echo "pita: FAILED $scene" >&2
    return 1
  fi
}
export -f eval_one

printf '%s\0' "${scenes[@]}" | xargs -0 -n 1 -P "$(nproc)" bash -c 'eval_one "$1"' _
