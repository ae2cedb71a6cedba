#!/usr/bin/env bash
# ctest packaging.cli_installed: the installed pita behaves like build/pita,
# which the CLI suite (test_cli) checks.
# - When the installed file is build/pita byte for byte, with no RUNPATH and no
#   path into the build or source tree in it (pita reads nothing relative to
#   its own location), the suite once more against it could only find what it
#   found already: the start-up and render tests of the suite run against it,
#   from the prefix.
# - Otherwise (an install that strips, sets a RUNPATH or rewrites the binary)
#   the whole CLI suite runs against the installed pita (test_cli and the
#   executables after it: test_cli_bad_scenes).
# Usage: check_cli_installed.sh BUILD_PITA PREFIX SOURCE_DIR BUILD_DIR TEST_CLI [MORE_TEST_EXECUTABLES...]
set -euo pipefail
built="$1" prefix="$2" source="$3" build="$4" test_cli="$5"
shift 5
installed="$prefix/bin/pita"
filter="--gtest_filter=Main.*:Render.*"
reason=""
if ! cmp -s "$built" "$installed"; then
  reason="the installed pita is not build/pita byte for byte"
elif readelf -d "$installed" | grep -Eq 'R(UN)?PATH'; then
  reason="the installed pita has a RUNPATH: $(readelf -d "$installed" | grep -E 'R(UN)?PATH')"
elif strings "$installed" | grep -qF -e "$source" -e "$build"; then
  reason="the installed pita holds a path into the source or build tree: $(strings "$installed" | grep -F -e "$source" -e "$build" | head -3)"
fi
export PITA_TEST_BINARY="$installed"
if [ -z "$reason" ]; then
  "$test_cli" --gtest_brief=1 "$filter"
  exit
fi
echo "$reason: the whole CLI suite runs against it"
status=0
for executable in "$test_cli" "$@"; do
  "$executable" --gtest_brief=1 || status=1
done
exit "$status"
