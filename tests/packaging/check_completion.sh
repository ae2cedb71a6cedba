#!/usr/bin/env bash
# ctest packaging.bash_completion: the generated bash completion, sourced in a
# clean bash (no bash-completion package needed), completes as a user would
# see after TAB: subcommands, flags, the registry's method names, formats and
# scene files. The expected words are written here, from the papers and the
# README, not read from the registry.
# Usage: check_completion.sh COMPLETION_SCRIPT
set -euo pipefail
script="$1"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
touch "$scratch/fig.json" "$scratch/notes.txt"
mkdir "$scratch/scenes"

# The words offered for the command line "$1" with the cursor at its end
# (a trailing space: a new, empty word), one per line, sorted.
complete_line() {
  ( cd "$scratch" && bash --norc --noprofile -c '
      source "$1"
      read -r -a COMP_WORDS <<< "$2"
      [[ "$2" == *" " ]] && COMP_WORDS+=("")
      COMP_CWORD=$(( ${#COMP_WORDS[@]} - 1 ))
      COMP_LINE="$2"; COMP_POINT=${#COMP_LINE}
      _pita pita "${COMP_WORDS[COMP_CWORD]}" "${COMP_WORDS[COMP_CWORD-1]}"
      printf "%s\n" "${COMPREPLY[@]}" | sort' _ "$script" "$1" )
}

status=0
expect() {  # expect LINE WORD...: each WORD is offered
  local line="$1" got
  shift
  got="$(complete_line "$line")"
  for word in "$@"; do
    if ! grep -qxF -- "$word" <<< "$got"; then
      echo "'$line<TAB>' does not offer '$word'; it offers: $(tr '\n' ' ' <<< "$got")" >&2
      status=1
    fi
  done
}
expect_only() {  # expect_only LINE WORD...: exactly these words
  local line="$1" got want
  shift
  got="$(complete_line "$line")"
  want="$(printf '%s\n' "$@" | sort)"
  if [ "$got" != "$want" ]; then
    echo "'$line<TAB>' offers: $(tr '\n' ' ' <<< "$got"); expected: $*" >&2
    status=1
  fi
}

expect_only "pita ev" eval
expect "pita " eval render animate check update-goldens audit measure sweep
expect "pita --" --help --version
# The ten PITAs of the paper, P5S and the steady morph, by id; SMA is not a P.
expect "pita eval x.json --method P" P1 P2 P3 P4 P5 P5S P6 P7 P8 P9 P10
expect "pita eval x.json --method " P6 SMA SAM La-LP
expect_only "pita eval x.json --method SA" SAM
expect_only "pita eval x.json --format " csv json
expect_only "pita render x.json --format " pdf png svg
expect_only "pita animate x.json -o out --format " png svg
expect "pita eval --" --method --samples --t --panel --format --help
expect "pita render --" --output --format --scale --dpi --budget --list
expect "pita render -" -o -h
# Scene files: the *.json files and the directories, nothing else.
expect_only "pita eval " fig.json scenes
expect_only "pita render f" fig.json
expect_only "pita check --golden " scenes
exit "$status"
