#!/usr/bin/env bash
# ctest packaging.headers_alone: every installed public header compiles on its
# own, as the first line of a translation unit, against the installed prefix
# only (include/ and include/pita, the paths pita::core exports) and the
# system's packages (Eigen; cairo and pango for render's headers): no path
# into the source tree. Runs up to 2 compilers at once. A header that parses,
# resolves every name and instantiates what it uses on its own is what the
# check asks, so the compiler stops there (-fsyntax-only: no code is made;
# parsing Eigen, cairo and pango for each header is most of the time).
# Through ccache when it is there.
# Usage: check_headers.sh PREFIX COMPILER WORK_DIR
set -euo pipefail
prefix="$1" compiler="${2:-c++}" work="$3"
eigen="$(pkg-config --cflags eigen3)"
graphics="$(pkg-config --cflags cairo pangocairo)"
launcher=""
if command -v ccache >/dev/null; then launcher=ccache; fi
rm -rf "$work"
mkdir -p "$work"
cd "$prefix/include"
export compiler eigen graphics work prefix launcher
find pita -name '*.hpp' | sort | xargs -P 2 -n 1 bash -c '
  header="$1"
  flags="$eigen"
  case "$header" in pita/core/*) ;; *) flags="$eigen $graphics" ;; esac
  unit="$work/$(echo "$header" | tr / _).cpp"
  printf "#include <%s>\n" "$header" > "$unit"
  # shellcheck disable=SC2086
  if ! $launcher "$compiler" -std=c++20 -fsyntax-only -Wall -Wextra -I"$prefix/include" -I"$prefix/include/pita" \
       $flags "$unit" 2> "$unit.err"; then
    echo "$header does not compile on its own:" >&2
    head -5 "$unit.err" >&2
    exit 255
  fi' _
echo "$(find pita -name '*.hpp' | wc -l) headers compile on their own"
