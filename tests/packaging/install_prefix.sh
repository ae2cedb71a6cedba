#!/usr/bin/env bash
# ctest packaging.install: cmake --install BUILD --prefix PREFIX into a fresh
# PREFIX (the fixture the other packaging tests use), and checks that each
# piece docs/guide/install.md "Install" names is there.
set -euo pipefail
build="$1" prefix="$2"
rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
status=0
for path in bin/pita include/pita/core/arrow.hpp include/pita/core/affine_power.hpp \
            include/pita/core/pitas/registry.hpp include/pita/motion/scene_motion.hpp \
            include/pita/render/figure.hpp lib/libpita_core.a lib/libpita_render.a \
            lib/cmake/pita/pitaConfig.cmake lib/cmake/pita/pitaConfigVersion.cmake \
            lib/cmake/pita/pitaCoreTargets.cmake lib/cmake/pita/pitaRenderTargets.cmake \
            lib/pkgconfig/pita.pc share/man/man1/pita.1 share/bash-completion/completions/pita \
            share/zsh/vendor-completions/_pita share/doc/pita/CHANGELOG.md share/doc/pita/docs/reference/eval.md \
            share/pita/scenes/fig01-eight-pitas.json share/pita/scenes/images/picture.png; do
  if [ ! -f "$prefix/$path" ]; then
    echo "missing after cmake --install: $path" >&2
    status=1
  fi
done
# Every header of src/core is installed, and nothing but headers under include/.
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
while IFS= read -r header; do
  if [ ! -f "$prefix/include/pita/${header#"$root"/src/}" ]; then
    echo "not installed: ${header#"$root"/}" >&2
    status=1
  fi
done < <(find "$root/src/core" -name '*.hpp')
if find "$prefix/include" -type f ! -name '*.hpp' | grep .; then
  echo "files other than headers under include/" >&2
  status=1
fi
exit "$status"
