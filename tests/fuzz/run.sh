#!/usr/bin/env bash
# Runs the libFuzzer targets (docs/reliability.md):
#   tests/fuzz/run.sh SECONDS [BUILD_DIR]
# SECONDS are shared out between the targets. BUILD_DIR (default build-sanitize) is configured
# with CC=clang-14 CXX=clang++-14 -DPENUMBRA_FUZZ=ON and the targets built. First every saved
# regression input is replayed, then each target fuzzes a corpus seeded from data/, studies/,
# the scene files the tests write (their R"(...)" strings) and tests/fuzz/seeds (the photometry
# targets: data/luminaires and tests/fuzz/seeds/ies, seeds/ldt). A crash, a leak,
# a UB report or a hang fails the script; the input is left in BUILD_DIR/fuzz-artifacts/TARGET/:
# copy it to tests/fuzz/regressions/TARGET/ once fixed. A hang is an input still running after
# FUZZ_TIMEOUT seconds (default 10): libFuzzer measures wall-clock time, and a CI machine under
# load must not fail on a slow input. The long run (docs/reliability.md) used 1 s.
set -euo pipefail

seconds="${1:?usage: tests/fuzz/run.sh SECONDS [BUILD_DIR]}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "${here}/../.." && pwd)"
build="${2:-${root}/build-sanitize}"
targets=(scene pts study ies ldt)
per_target=$((seconds / ${#targets[@]}))
timeout="${FUZZ_TIMEOUT:-10}"
((per_target >= 1)) || per_target=1

# Leaks count as failures; a UB report aborts so that libFuzzer keeps the input.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

# The YAML texts the tests feed the loaders, one file each.
extract_test_texts() {
  local out="$1" source
  for source in "${root}"/tests/*.cpp; do
    awk -v out="${out}" -v prefix="$(basename "${source}" .cpp)" '
      {
        line = $0
        while (1) {
          if (!inraw) {
            i = index(line, "R\"(")
            if (!i) break
            inraw = 1; text = ""; line = substr(line, i + 3)
          }
          j = index(line, ")\"")
          if (!j) { text = text line "\n"; break }
          n++
          file = out "/" prefix "-" n ".yaml"
          printf "%s", text substr(line, 1, j - 1) > file
          close(file)
          inraw = 0; line = substr(line, j + 2)
        }
      }' "${source}"
  done
}

seed() {
  local target="$1" corpus="$2"
  mkdir -p "${corpus}"
  case "${target}" in
    scene)
      cp "${root}"/data/*.yaml "${root}"/tests/validation/cie171/*.yaml "${corpus}/"
      extract_test_texts "${corpus}"
      ;;
    study)
      cp "${root}"/studies/*.yaml "${corpus}/"
      extract_test_texts "${corpus}"
      ;;
    pts) cp "${root}"/data/*.pts "${here}"/seeds/pts/* "${corpus}/" ;;
    ies | ldt) cp "${root}"/data/luminaires/*."${target}" "${here}/seeds/${target}/"* "${corpus}/" ;;
  esac
  cp "${here}/regressions/${target}/"* "${corpus}/" 2>/dev/null || true
}

status=0
for target in "${targets[@]}"; do
  binary="${build}/tests/fuzz/${target}_fuzz"
  if [[ ! -x "${binary}" ]]; then
    echo "fuzz: ${binary} is missing; build it with -DPENUMBRA_FUZZ=ON (clang)" >&2
    exit 2
  fi
  regressions=("${here}/regressions/${target}/"*)
  if [[ -e "${regressions[0]}" ]]; then
    echo "fuzz: ${target}: replaying ${#regressions[@]} regression inputs"
    "${binary}" -timeout="${timeout}" "${regressions[@]}" > "${build}/fuzz-${target}-regressions.log" 2>&1 ||
      { tail -40 "${build}/fuzz-${target}-regressions.log" >&2; status=1; continue; }
  fi
  corpus="${build}/fuzz-corpus/${target}"
  artifacts="${build}/fuzz-artifacts/${target}"
  seed "${target}" "${corpus}"
  mkdir -p "${artifacts}"
  echo "fuzz: ${target}: ${per_target} s on $(find "${corpus}" -type f | wc -l) corpus inputs"
  if ! "${binary}" "${corpus}" -max_total_time="${per_target}" -timeout="${timeout}" -rss_limit_mb=2048 \
    -max_len=16384 -print_final_stats=1 -artifact_prefix="${artifacts}/" \
    > "${build}/fuzz-${target}.log" 2>&1; then
    tail -60 "${build}/fuzz-${target}.log" >&2
    echo "fuzz: ${target} FAILED; the input is in ${artifacts}/" >&2
    status=1
    continue
  fi
  grep -E '^stat::number_of_executed_units|^#[0-9]+.*DONE' "${build}/fuzz-${target}.log" || true
done
exit "${status}"
