#!/usr/bin/env bash
# Measures what each README command installs on a Debian 12 machine that has
# only build-essential (docs/guide/setup.md). Nothing is installed: apt-get
# simulates (-s) against a made-up dpkg status that holds Debian's
# "required" packages, apt, and what build-essential pulls in, using this
# machine's package lists (run `apt-get update` first if they are old).
#
#   scripts/measure-setup.sh [--list]     (--list: name every package)
#
# Prints, for scripts/run.sh and then for what scripts/test.sh adds: the
# number of packages apt-get would install and their installed size.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/deps.sh"

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/state"
: >"$work/state/status"
apt_sim() {
  apt-get -s -o Dir::State::status="$work/state/status" -o Debug::NoLocking=1 \
    install --no-install-recommends "$@" 2>/dev/null | awk '/^Inst /{print $2}'
}
# Adds the stanzas of these packages (candidate versions) to the status file.
mark_installed() {
  [ $# -gt 0 ] || return 0
  apt-cache show --no-all-versions "$@" 2>/dev/null |
    awk -v RS= '{sub(/\n/, "\nStatus: install ok installed\n"); print; print ""}' >>"$work/state/status"
}
# Installed size (kB) of these packages, summed.
size_of() {
  [ $# -gt 0 ] || { echo 0; return; }
  apt-cache show --no-all-versions "$@" 2>/dev/null | awk '/^Installed-Size:/{s += $2} END {print s + 0}'
}

# The base: Debian's required packages and apt (debootstrap's minbase).
mapfile -t base < <(apt-cache dumpavail | awk -v RS= '/\nPriority: required/{match($0,/^Package: [^\n]*/); print substr($0,10,RLENGTH-9)}' | sort -u)
mapfile -t closure < <(apt_sim "${base[@]}" apt)
mark_installed "${closure[@]}"
mapfile -t essential < <(apt_sim build-essential)
mark_installed build-essential "${essential[@]}"

mapfile -t run < <(apt_sim "${PITA_RUN_PACKAGES[@]}")
[ "${1:-}" = "--list" ] && printf '  %s\n' "${run[@]}"
printf 'scripts/run.sh: %d packages, %d MB installed\n' "${#run[@]}" "$(( $(size_of "${run[@]}") / 1024 ))"
mark_installed "${run[@]}"
mapfile -t test < <(apt_sim "${PITA_TEST_PACKAGES[@]}")
[ "${1:-}" = "--list" ] && printf '  %s\n' "${test[@]}"
printf 'scripts/test.sh adds: %d packages, %d MB installed\n' "${#test[@]}" "$(( $(size_of "${test[@]}") / 1024 ))"
mapfile -t old < <(apt-get -s -o Dir::State::status="$work/state/status" -o Debug::NoLocking=1 install libvalijson-dev 2>/dev/null | awk '/^Inst /{print $2}')
printf 'for comparison, libvalijson-dev (the old schema validator, with recommends) would add: %d packages, %d MB\n' \
  "${#old[@]}" "$(( $(size_of "${old[@]}") / 1024 ))"
