#!/usr/bin/env bash
# Installs what penumbra needs (Debian 12), builds it, and runs one step:
#   bash scripts/setup.sh example   the main job on the bundled example scene
#   bash scripts/setup.sh test      every test through ctest, then a minute of fuzzing the
#                                   input readers, then the host-side tests under ASan + UBSan
#                                   (build-sanitize, clang-14; docs/reliability.md)
#   bash scripts/setup.sh sanitize  only the host-side tests under ASan + UBSan (build-sanitize)
#   bash scripts/setup.sh build     only install + build
# Safe to run again: apt is skipped when every package is present, the build is incremental.
set -euo pipefail

# Under `env -i` bash has a default PATH but does not export it; every program started from here
# needs one (PoCL links kernels with `ld`, the Slurm test starts daemons and jobs).
export PATH="${PATH:-/usr/local/bin:/usr/bin:/bin}"

cd "$(dirname "${BASH_SOURCE[0]}")/.."
ROOT="$(pwd)"
BUILD="${ROOT}/build"

PACKAGES=(
  build-essential cmake pkg-config ca-certificates
  pocl-opencl-icd ocl-icd-opencl-dev opencl-headers opencl-clhpp-headers clinfo
  libeigen3-dev libyaml-cpp-dev libcli11-dev nlohmann-json3-dev libfmt-dev libtbb-dev
  libgtest-dev libbenchmark-dev
  libvtk9-dev xvfb xauth libmuparser-dev fonts-dejavu-core
  libopenimageio-dev openimageio-tools librsvg2-bin
  slurm-wlm munge
  clang-14 libfuzzer-14-dev libclang-rt-14-dev
)

# The step `example` runs: the example office's window-width study, a sweep of 21 cases. Its
# charts are rendered through X (VTK): without a display, under a virtual one.
run_example() {
  local display=()
  if [[ -z "${DISPLAY:-}" ]] && command -v xvfb-run >/dev/null; then
    display=(xvfb-run -a -s "-screen 0 1920x1080x24 -noreset")
  fi
  "${display[@]}" "${BUILD}/penumbra" sweep studies/window-width.yaml -o out/window-width
}

missing_packages() {
  local pkg
  for pkg in "${PACKAGES[@]}"; do
    if [[ "$(dpkg-query -W -f='${db:Status-Status}' "${pkg}" 2>/dev/null || true)" != "installed" ]]; then
      echo "${pkg}"
    fi
  done
}

install_packages() {
  local missing
  mapfile -t missing < <(missing_packages)
  if ((${#missing[@]} == 0)); then
    return
  fi
  echo "setup: installing ${missing[*]}"
  local sudo=()
  if ((EUID != 0)); then
    if command -v sudo >/dev/null; then
      sudo=(sudo)
    else
      echo "setup: missing packages (${missing[*]}) and not root; install them and run again" >&2
      exit 1
    fi
  fi
  "${sudo[@]}" apt-get update
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends \
    "${missing[@]}"
}

# PoCL caches compiled kernels under $HOME/.cache; without a usable HOME, keep them in build/.
pocl_cache() {
  if [[ -z "${POCL_CACHE_DIR:-}" ]]; then
    if [[ -z "${HOME:-}" ]] || ! mkdir -p "${HOME}/.cache" 2>/dev/null || [[ ! -w "${HOME}/.cache" ]]; then
      export POCL_CACHE_DIR="${BUILD}/pocl-cache"
      mkdir -p "${POCL_CACHE_DIR}"
    fi
  fi
}

build() {
  cmake -S "${ROOT}" -B "${BUILD}" -DCMAKE_BUILD_TYPE=Release
  cmake --build "${BUILD}" -j"$(nproc)"
}

# The reliability build (docs/reliability.md): clang-14 with ASan + UBSan and libFuzzer's
# coverage, in a build of its own (build-sanitize).
sanitize_build() {
  CC=clang-14 CXX=clang++-14 cmake -S "${ROOT}" -B "${ROOT}/build-sanitize" \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPENUMBRA_FUZZ=ON
  cmake --build "${ROOT}/build-sanitize" -j"$(nproc)" --target "$@"
}

# Each fuzz target for a while: a minute in all. Part of `test`, so part of CI.
fuzz_tests() {
  sanitize_build penumbra_fuzzers
  bash "${ROOT}/tests/fuzz/run.sh" 60 "${ROOT}/build-sanitize"
}

# The host-side tests (all but viz/, which renders through X) under ASan + UBSan, in the build the
# fuzzers use. Part of `test`, so part of CI. The tests sample the reference more coarsely there
# (tests/sanitized_build.hpp): at full n the suite did not fit CI's hour.
sanitize_tests() {
  # penumbra_tests: `penumbra` and every test program of the build (CMakeLists.txt), which in
  # this build leaves the viz tests out.
  sanitize_build penumbra_tests
  # A leak, an invalid access or undefined behaviour fails the test that shows it.
  # Each program starts with the options of tests/sanitizer_defaults.cpp (docs/reliability.md).
  ctest --test-dir "${ROOT}/build-sanitize" --output-on-failure -j2
}

step="${1:-}"
case "${step}" in
  example | test | sanitize | build) ;;
  *)
    echo "usage: bash scripts/setup.sh example|test|sanitize|build" >&2
    exit 2
    ;;
esac

install_packages
build
pocl_cache

case "${step}" in
  example) run_example ;;
  test)
    # PoCL starts one thread per core in every test process; ctest runs two at a time.
    export POCL_MAX_PTHREAD_COUNT="${POCL_MAX_PTHREAD_COUNT:-2}"
    ctest --test-dir "${BUILD}" --output-on-failure -j2
    fuzz_tests
    sanitize_tests
    ;;
  sanitize)
    export POCL_MAX_PTHREAD_COUNT="${POCL_MAX_PTHREAD_COUNT:-2}"
    sanitize_tests
    ;;
  build) ;;
esac
