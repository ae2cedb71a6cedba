#!/usr/bin/env bash
# ctest packaging.deb: cpack -G DEB from the build folder makes
# pita_<version>_<arch>.deb; its control fields carry the version and a
# Depends from dpkg-shlibdeps (the C and C++ run-times, cairo, pango); unpacked
# with dpkg -x into a scratch root, every file dpkg -c lists is there, the
# pieces docs/guide/install.md "Install" names are at their places under /usr, and the
# unpacked binary runs (--version, and eval of a scene).
# With PYTHON (a build with -DPITA_PYTHON=ON), cpack also makes
# python3-pita_<version>_<arch>.deb: its Depends names python3 and NumPy, it
# holds the module and its stubs only, and the unpacked module imports and
# evaluates (check_python_deb below).
# Usage: check_deb.sh BUILD_DIR VERSION SOURCE_DIR [PYTHON]
set -euo pipefail
build="$1" version="$2" source="$3" python="${4:-}"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT

arch="$(dpkg --print-architecture)"
cpack --config "$build/CPackConfig.cmake" -G DEB -B "$scratch/out" >"$scratch/cpack.log" 2>&1 || {
  cat "$scratch/cpack.log" >&2
  exit 1
}
deb="$scratch/out/pita_${version}_${arch}.deb"
if [ ! -f "$deb" ]; then
  echo "cpack did not make pita_${version}_${arch}.deb; it made: $(ls "$scratch/out")" >&2
  exit 1
fi
status=0
fail() { echo "$*" >&2; status=1; }

[ "$(dpkg-deb -f "$deb" Package)" = pita ] || fail "Package is not pita"
[ "$(dpkg-deb -f "$deb" Version)" = "$version" ] || fail "Version is $(dpkg-deb -f "$deb" Version), not $version"
[ "$(dpkg-deb -f "$deb" Architecture)" = "$arch" ] || fail "Architecture is not $arch"
depends="$(dpkg-deb -f "$deb" Depends)"
# What pita links against dynamically (ldd), by Debian package (dpkg -S): each must be in Depends.
for library in libc.so.6 libstdc++.so.6 libcairo.so.2 libpango-1.0.so.0 libpangocairo-1.0.so.0 libfmt.so; do
  name="$(ldd "$build/pita" | awk -v l="$library" 'index($1, l) == 1 { print $1; exit }')"
  [ -n "$name" ] || continue
  package="$( (dpkg -S "*/$name" 2>/dev/null || true) | head -1 | cut -d: -f1)"
  if [ -z "$package" ]; then
    fail "no Debian package holds $name"
  elif [[ ", $depends," != *", $package "* && ", $depends," != *", $package,"* ]]; then
    fail "Depends lacks $package (for $name): $depends"
  fi
done
grep -q "fonts-dejavu-core" <<< "$depends" || fail "Depends lacks fonts-dejavu-core: $depends"
# pango is loaded with dlopen when text is first drawn (src/render/pango_library.hpp): ldd cannot see it.
grep -q "libpangocairo-1.0-0" <<< "$depends" || fail "Depends lacks libpangocairo-1.0-0 (loaded at run time): $depends"

root="$scratch/root"
dpkg -x "$deb" "$root"
# Every regular file the package lists is unpacked where it says.
while read -r mode _ _ _ _ path _; do
  path="${path#./}"
  case "$mode" in
    -*) [ -f "$root/$path" ] || fail "dpkg -c lists $path, not unpacked there" ;;
    d*) [ -d "$root/$path" ] || fail "dpkg -c lists directory $path, not unpacked there" ;;
  esac
done < <(dpkg -c "$deb")
listing="$(dpkg -c "$deb" | awk '{ print $6 }' | sed 's|^\./||')"
for path in usr/bin/pita usr/libexec/pita/pita-serve usr/include/pita/core/arrow.hpp usr/include/pita/core/affine_power.hpp \
            usr/lib/libpita_core.a usr/lib/libpita_render.a usr/lib/cmake/pita/pitaConfig.cmake \
            usr/lib/cmake/pita/pitaConfigVersion.cmake usr/lib/pkgconfig/pita.pc usr/share/man/man1/pita.1 \
            usr/share/bash-completion/completions/pita usr/share/zsh/vendor-completions/_pita \
            usr/share/doc/pita/CHANGELOG.md usr/share/doc/pita/docs/reference/eval.md \
            usr/share/pita/scenes/fig01-eight-pitas.json usr/share/pita/scenes/images/picture.png; do
  grep -qxF "$path" <<< "$listing" || fail "the package lacks $path"
done
# No file outside /usr, none of the build's or the tests' files.
if grep -vE '^usr/' <<< "$listing" | grep -vxE '\.?/?' | grep .; then fail "files outside /usr"; fi
if grep -E 'test_|gtest|bench|\.o$' <<< "$listing"; then fail "test or build files in the package"; fi

[ "$("$root/usr/bin/pita" --version)" = "pita $version" ] || fail "unpacked pita --version: $("$root/usr/bin/pita" --version)"
"$root/usr/bin/pita" eval "$source/scenes/fig01-eight-pitas.json" --samples 3 >/dev/null ||
  fail "unpacked pita cannot evaluate scenes/fig01-eight-pitas.json"
# pita serve finds its server at ../libexec/pita/pita-serve (it answers for a missing scene).
served="$("$root/usr/bin/pita" serve "$scratch/no-such-scene.json" 2>&1 || true)"
[[ "$served" == *"no such scene file"* ]] || fail "the unpacked pita serve does not find pita-serve: $served"

if [ -n "$python" ]; then
  pydeb="$scratch/out/python3-pita_${version}_${arch}.deb"
  if [ ! -f "$pydeb" ]; then
    fail "cpack did not make python3-pita_${version}_${arch}.deb; it made: $(ls "$scratch/out")"
  else
    [ "$(dpkg-deb -f "$pydeb" Package)" = python3-pita ] || fail "Package is not python3-pita"
    [ "$(dpkg-deb -f "$pydeb" Version)" = "$version" ] || fail "python3-pita: Version is not $version"
    # pita holds the scenes pita.example() finds
    [ "$(dpkg-deb -f "$pydeb" Recommends)" = "pita (= $version)" ] ||
      fail "python3-pita: Recommends is not pita (= $version): $(dpkg-deb -f "$pydeb" Recommends)"
    pydepends="$(dpkg-deb -f "$pydeb" Depends)"
    for needed in "python3 (>= " python3-numpy libpangocairo-1.0-0 fonts-dejavu-core libcairo2; do
      grep -qF "$needed" <<< "$pydepends" || fail "python3-pita: Depends lacks $needed: $pydepends"
    done
    pylisting="$(dpkg -c "$pydeb" | awk '$1 ~ /^-/ { print $6 }' | sed 's|^\./||')"
    grep -qE '^usr/lib/python3/dist-packages/pita\.cpython-[0-9]+-[^/]*\.so$' <<< "$pylisting" ||
      fail "python3-pita lacks usr/lib/python3/dist-packages/pita.cpython-*.so: $pylisting"
    grep -qxF usr/lib/python3/dist-packages/pita.pyi <<< "$pylisting" || fail "python3-pita lacks pita.pyi"
    if grep -vE '^usr/lib/python3/dist-packages/' <<< "$pylisting" | grep .; then
      fail "python3-pita holds files outside usr/lib/python3/dist-packages"
    fi
    if grep -qE 'dist-packages' <<< "$listing"; then fail "the pita package holds the Python module"; fi
    pyroot="$scratch/pyroot"
    dpkg -x "$pydeb" "$pyroot"
    PYTHONPATH="$pyroot/usr/lib/python3/dist-packages" PYTHONDONTWRITEBYTECODE=1 "$python" -c "
import pita, sys
assert pita.__file__.startswith(sys.argv[1]), pita.__file__
assert pita.__version__ == sys.argv[2], pita.__version__
scene = pita.load_scene(sys.argv[3] + '/scenes/fig01-eight-pitas.json')
assert scene.eval(samples=3).m.shape == (3,)
" "$pyroot" "$version" "$source" || fail "the unpacked python3-pita does not import and evaluate"
  fi
fi
exit "$status"
