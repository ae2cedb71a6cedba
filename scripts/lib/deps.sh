# Sourced by the scripts in scripts/: installs the Debian 12 packages pita
# needs when any is missing, then configures and builds into build/ (or, for
# scripts/test.sh --sanitize and scripts/fuzz.sh, into build-sanitize/).
# Nothing is downloaded from anywhere but Debian's package archive.

PITA_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
PITA_BUILD="${PITA_BUILD:-$PITA_ROOT/build}"
# The sanitizer and fuzzing build (clang, ASan + UBSan, the libFuzzer targets).
PITA_SANITIZE_BUILD="${PITA_SANITIZE_BUILD:-$PITA_ROOT/build-sanitize}"
# Parallel compile and test jobs (default: every core).
PITA_JOBS="${PITA_JOBS:-$(nproc)}"

# One package per need; the comment says which. What scripts/run.sh (the main
# job: build pita, render every scene) needs, and nothing more. The README's
# "Quick start" states how many there are; tests/setup/check_packages.sh
# fails when this list and that number disagree.
PITA_RUN_PACKAGES=(
  build-essential cmake ninja-build pkg-config  # compiler and build
  libcli11-dev         # command line
  nlohmann-json3-dev   # scenes
  libfmt-dev           # formatting
  libeigen3-dev        # matrices (affine motions)
  libcairo2-dev        # figures: SVG, PNG, PDF (it depends on libpng-dev, whose libpng pita writes PNGs with)
  libpango1.0-dev      # figures: text (banners, titles)
  fonts-dejavu-core    # figures: the fonts the scenes and goldens use (DejaVu Sans, Serif)
  libcpp-httplib-dev   # pita serve: its HTTP server (in the helper program pita-serve)
)

# What scripts/test.sh adds: the tests and the benchmark.
PITA_TEST_PACKAGES=(
  libgtest-dev libgmock-dev   # tests
  libbenchmark-dev            # benchmarks
  libxml2-utils librsvg2-bin  # tests: SVG read back by xmllint and rsvg-convert
  python3                     # tests: the independent oracles (tests/oracle)
  clang-format                # tests: the C++ layout (.clang-format, scripts/format.sh --check)
  python3-jsonschema          # tests: the scene schema checked by an independent validator
  ffmpeg                      # tests: `pita animate OUT.mp4` encodes video (read back by ffprobe)
  chromium                    # tests: the animated SVG played in a real browser (headless), pita serve's page
  python3-websocket           # tests: pita serve's page driven in Chromium over the DevTools protocol
  slurmctld slurmd slurm-client munge  # tests: the Slurm recipe on a real one-node Slurm (tests/slurm)
  parallel                    # tests: the GNU parallel recipe of pita sweep (docs/reference/sweep.md "pita sweep")
  time                        # benchmarks: peak memory of a sweep (scripts/bench-sweep.sh, GNU time)
  man-db                      # tests: the man page rendered by man -l (with groff-base; tests/packaging)
  pybind11-dev python3-dev    # the Python module (-DPITA_PYTHON=ON, src/python)
  python3-numpy python3-pytest  # the Python module: its arrays and its tests (tests/python)
  python3-scipy               # tests: SciPy's matrix functions, the module's independent reference
  python3-matplotlib          # the Python examples (examples/python) plot with it
  jupyter-nbconvert python3-ipykernel  # tests: the notebook examples/python/tour.ipynb, executed
)

# Only for scripts/test.sh --sanitize and scripts/fuzz.sh.
PITA_SANITIZE_PACKAGES=(
  clang                # the sanitizer build: libFuzzer is clang's
  libclang-rt-14-dev   # the ASan, UBSan, LSan and libFuzzer run-times
)

# Installs what is missing of PITA_RUN_PACKAGES and of the packages given,
# without Debian's "recommends" (they would bring desktop stacks along).
pita_install_dependencies() {
  local missing=()
  for p in "${PITA_RUN_PACKAGES[@]}" "$@"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$p")
    fi
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return 0
  fi
  echo "pita: installing missing Debian packages: ${missing[*]}" >&2
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null; then
      sudo="sudo"
    else
      echo "pita: these packages are missing and I am not root (and there is no sudo):" >&2
      echo "      apt-get install ${missing[*]}" >&2
      return 1
    fi
  fi
  if ! { $sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"; } >&2; then
    echo "pita: apt-get could not install: ${missing[*]}" >&2
    echo "      install them by hand (apt-get install ${missing[*]}) and run this again." >&2
    return 1
  fi
}

# The main job's build (scripts/run.sh): installs PITA_RUN_PACKAGES only,
# configures build/ the first time (tests and benchmark only if their
# libraries happen to be there) and builds build/pita. Release unless
# PITA_BUILD_TYPE says otherwise.
pita_build() {
  pita_install_dependencies || return 1
  if [ ! -f "$PITA_BUILD/build.ninja" ]; then
    cmake -S "$PITA_ROOT" -B "$PITA_BUILD" -G Ninja \
      -DCMAKE_BUILD_TYPE="${PITA_BUILD_TYPE:-Release}" >/dev/null || return 1
  fi
  cmake --build "$PITA_BUILD" -j "$PITA_JOBS" --target pita
}

# The test build (scripts/test.sh): adds PITA_TEST_PACKAGES, configures build/
# with the tests and the benchmark required, and builds the targets given
# (default: every target).
pita_build_tests() {
  pita_install_dependencies "${PITA_TEST_PACKAGES[@]}" || return 1
  cmake -S "$PITA_ROOT" -B "$PITA_BUILD" -G Ninja -DCMAKE_BUILD_TYPE="${PITA_BUILD_TYPE:-Release}" \
    -DPITA_BUILD_TESTS=ON -DPITA_BUILD_BENCHMARKS=ON -DPITA_REQUIRE_TESTS=ON -DPITA_PYTHON=ON >/dev/null || return 1
  local targets=()
  if [ $# -gt 0 ]; then targets=(--target "$@"); fi
  cmake --build "$PITA_BUILD" -j "$PITA_JOBS" "${targets[@]}"
}

# Configures (first time) and builds the sanitizer build: clang, Debug at -O1
# (assertions on), -fsanitize=address,undefined on every target, and the
# libFuzzer targets of fuzz/ (CMake options PITA_SANITIZE and PITA_FUZZ).
# Then exports the sanitizer options that CMake wrote for this build
# (ASAN_OPTIONS, UBSAN_OPTIONS, LSAN_OPTIONS with scripts/sanitizers/lsan.supp).
pita_build_sanitize() {
  pita_install_dependencies "${PITA_TEST_PACKAGES[@]}" "${PITA_SANITIZE_PACKAGES[@]}" || return 1
  if [ ! -f "$PITA_SANITIZE_BUILD/build.ninja" ]; then
    cmake -S "$PITA_ROOT" -B "$PITA_SANITIZE_BUILD" -G Ninja \
      -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug \
      -DPITA_SANITIZE=ON -DPITA_FUZZ=ON -DPITA_BUILD_BENCHMARKS=OFF -DPITA_REQUIRE_TESTS=ON >/dev/null || return 1
  fi
  # shellcheck source=/dev/null
  source "$PITA_SANITIZE_BUILD/sanitizer-env.sh" || return 1
  cmake --build "$PITA_SANITIZE_BUILD" -j "$PITA_JOBS"
}
