#!/usr/bin/env bash
# ctest packaging.headers_alone: every installed public header compiles on its
# own, as the first line of a translation unit, against the installed prefix
# only (include/ and include/pita, the paths pita::core exports) and the
# system's packages (Eigen; cairo and pango for render's headers): no path
# into the source tree. Runs up to 2 compilers at once. A header that parses,
# resolves every name and instantiates what it uses on its own is what the
# check asks, so the compiler stops there (-fsyntax-only: no code is made).
#
# Eigen/Core was half of the time of each header (1.4 s of 2.7 s for
# pita/core/pose_motion.hpp). It is precompiled once here, and a header whose
# own includes reach Eigen (its #include lines followed through pita's
# headers, pita_includes_eigen below) gets it as a precompiled -include. That
# adds nothing the header does not include itself: Eigen/Core comes first
# instead of at the header's own #include line, and every other pita header
# it includes is checked alone as well. A header that does not reach Eigen is
# compiled without it, so a missing #include <Eigen/...> still fails.
# (docs/explanation/build-time.md "Build time".) Through ccache when it is there.
# Usage: check_headers.sh PREFIX COMPILER WORK_DIR
set -euo pipefail
prefix="$1" compiler="${2:-c++}" work="$3"
# Eigen as a system header, as a consumer's CMake gives it (Eigen3::Eigen):
# its own warnings are not the check's business.
eigen="$(pkg-config --cflags-only-I eigen3 | sed 's/-I/-isystem /g')"
graphics="$(pkg-config --cflags cairo pangocairo)"
launcher=""
if command -v ccache >/dev/null; then launcher=ccache; fi
rm -rf "$work"
mkdir -p "$work"
std_flags="-std=c++20 -Wall -Wextra"

# The precompiled Eigen/Core (clang names it .pch, gcc .gch; a compiler that
# finds it unusable reads the header itself, which is slower, not weaker).
pch="$work/pita_eigen_core.hpp"
printf '#include <Eigen/Core>\n' > "$pch"
suffix=gch
if "$compiler" --version | grep -qi clang; then suffix=pch; fi
# shellcheck disable=SC2086
"$compiler" $std_flags $eigen -x c++-header "$pch" -o "$pch.$suffix"

cd "$prefix/include"
# "header 1" when the header's #include lines, followed through pita's own
# headers (quoted, from include/pita), reach an #include <Eigen/...>; else "header 0".
find pita -name '*.hpp' | sort | python3 -c '
import re, sys
headers = [line.strip() for line in sys.stdin]
include = re.compile(r"^\s*#\s*include\s*([<\"])([^>\"]+)[>\"]", re.M)
direct = {}
for header in headers:
    with open(header, encoding="utf-8") as f:
        direct[header] = include.findall(f.read())
def reaches_eigen(header, seen):
    for kind, name in direct.get(header, ()):
        if kind == "<" and name.startswith("Eigen/"):
            return True
        if kind == "\"":
            child = "pita/" + name
            if child not in seen:
                seen.add(child)
                if reaches_eigen(child, seen):
                    return True
    return False
for header in headers:
    print(header, int(reaches_eigen(header, {header})))
' > "$work/headers.list"

export compiler eigen graphics work prefix launcher pch std_flags
xargs -P 2 -n 2 bash -c '
  header="$1" uses_eigen="$2"
  flags="$eigen"
  case "$header" in pita/core/*) ;; *) flags="$eigen $graphics" ;; esac
  if [ "$uses_eigen" = 1 ]; then flags="-include $pch $flags"; fi
  unit="$work/$(echo "$header" | tr / _).cpp"
  printf "#include <%s>\n" "$header" > "$unit"
  # shellcheck disable=SC2086
  if ! $launcher "$compiler" $std_flags -fsyntax-only -I"$prefix/include" -I"$prefix/include/pita" \
       $flags "$unit" 2> "$unit.err"; then
    echo "$header does not compile on its own:" >&2
    head -5 "$unit.err" >&2
    exit 255
  fi' _ < "$work/headers.list"
echo "$(wc -l < "$work/headers.list") headers compile on their own" \
     "($(grep -c ' 1$' "$work/headers.list") of them reach Eigen and were given it precompiled)"
