#!/usr/bin/env bash
# Bounded fuzzing of scene reading, validation and the closed forms.
#
# With FUZZ_MODE=libfuzzer (needs clang++ and libclang_rt.fuzzer, Debian
# package clang-14; see the note at "auto" below) it builds the target
# scene_libfuzzer into build-fuzz/ (clang, ASan+UBSan) and runs it for
# FUZZ_SECONDS (default 60). Otherwise, or with FUZZ_MODE=gtest, it runs the
# randomized GoogleTest fuzz_tests (Release, build-fuzz-gtest/ or
# $FUZZ_GTEST_BUILD) again and again with fresh seeds (from FUZZ_SEED,
# default the clock) for the same time. Either way it prints how many
# inputs were tried and exits non-zero on the first crash or defect;
# libFuzzer saves the crashing input under build-fuzz/artifacts/.
# FUZZ_SANITIZE=1 (gtest mode) runs the rounds in the sanitized build.
set -euo pipefail
cd "$(dirname "$0")/.."
repository=$(pwd)

seconds=${FUZZ_SECONDS:-60}
mode=${FUZZ_MODE:-auto}
jobs=${JOBS:-$(nproc)}

have_libfuzzer() {
  command -v clang++ >/dev/null &&
    compgen -G "/usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a" >/dev/null
}
# auto = gtest: the libFuzzer build links (clang 14 against the g++-built
# deal.II) but ASan reports an alloc-dealloc mismatch inside read_scenario
# on the very first, valid seed input, and with that check off it segfaults:
# not usable until explained. FUZZ_MODE=libfuzzer runs it anyway.
if [ "$mode" = auto ]; then
  mode=gtest
fi
if [ "$mode" = libfuzzer ] && ! have_libfuzzer; then
  echo "fuzz: clang++ or libclang_rt.fuzzer missing" >&2
  exit 2
fi

run_libfuzzer() {
  local build=build-fuzz
  # fuzzer-no-link instruments our libraries for coverage feedback; the
  # fuzzer runtime itself is linked into scene_libfuzzer only.
  cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFLOORBLOCK_SANITIZE=ON \
    -DFLOORBLOCK_LIBFUZZER=ON -DCMAKE_CXX_FLAGS=-fsanitize=fuzzer-no-link \
    >/dev/null
  cmake --build "$build" -j"$jobs" --target scene_libfuzzer
  # Seed corpus: the shipped scenes, as .prm ('p') and as JSON/XML ('j', 'x')
  # written by deal.II itself is not available without the tool, so the
  # .prm scenes seed all three; mutations find the other formats' syntax.
  mkdir -p "$build/corpus" "$build/artifacts"
  for scene in params/*.prm; do
    { printf 'p'; cat "$scene"; } >"$build/corpus/$(basename "$scene")"
  done
  export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1"
  export UBSAN_OPTIONS="halt_on_error=1:abort_on_error=1:print_stacktrace=1"
  export LSAN_OPTIONS="suppressions=$repository/tests/fuzz/lsan.supp:print_suppressions=0"
  local log="$build/fuzz.log" status=0
  # -timeout: one input running longer than 10 s counts as a hang.
  "$build/tests/fuzz/scene_libfuzzer" -max_total_time="$seconds" \
    -timeout=10 -rss_limit_mb=2048 -max_len=16384 -print_final_stats=1 \
    -dict=tests/fuzz/scene.dict -artifact_prefix="$build/artifacts/" \
    "$build/corpus" 2>"$log" || status=$?
  tail -n 25 "$log"
  local executed
  executed=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  echo "fuzz: libFuzzer executed $executed inputs in ${seconds} s, status $status"
  return "$status"
}

run_gtest() {
  # FUZZ_GTEST_BUILD=build reuses the CI's Release build instead of a new
  # one; FUZZ_SANITIZE=1 runs .ci/sanitize.sh's build (build-sanitize/)
  # under its sanitizer options instead, and fails on any report.
  local build=${FUZZ_GTEST_BUILD:-build-fuzz-gtest} reports=""
  if [ "${FUZZ_SANITIZE:-0}" = 1 ]; then
    . .ci/sanitizer_env.sh
    build=build-sanitize
    configure_sanitized_build "$build" Debug
    reports="$repository/$build/fuzz-sanitizer-reports"
    rm -rf "$reports"
    mkdir -p "$reports"
    export_sanitizer_options "$reports" fast # fuzz_tests starts no MPI
  else
    cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  fi
  cmake --build "$build" -j"$jobs" --target fuzz_tests
  local executable="$build/tests/fuzz/fuzz_tests"
  local inputs_per_round=${FUZZ_INPUTS_PER_ROUND:-2000}
  local deadline=$(($(date +%s) + seconds)) rounds=0 scene_inputs=0 analytic_inputs=0
  local seed=${FUZZ_SEED:-$(date +%s)}
  while [ "$(date +%s)" -lt "$deadline" ]; do
    local output
    if ! output=$(FLOORBLOCK_FUZZ_SEED=$seed FLOORBLOCK_FUZZ_INPUTS=$inputs_per_round \
      "$executable" --gtest_filter='*Fuzz.Random*:*Fuzz.Hostile*' 2>&1); then
      echo "$output" | tail -n 40
      [ -z "$reports" ] || print_sanitizer_reports "$reports"
      echo "fuzz: FAILED at seed $seed (rerun: FLOORBLOCK_FUZZ_SEED=$seed" \
        "FLOORBLOCK_FUZZ_INPUTS=$inputs_per_round $executable; an input that" \
        "aborted is kept in ${TMPDIR:-/tmp}/floorblock_fuzz_failures)"
      return 1
    fi
    scene_inputs=$((scene_inputs + $(echo "$output" | grep -o '[0-9]* scene inputs tried' | grep -o '^[0-9]*')))
    analytic_inputs=$((analytic_inputs + $(echo "$output" | grep -o '[0-9]* analytic inputs tried' | grep -o '^[0-9]*')))
    rounds=$((rounds + 1))
    seed=$((seed + 1))
  done
  local n_reports=0
  if [ -n "$reports" ]; then
    print_sanitizer_reports "$reports"
    n_reports=$(find "$reports" -type f | wc -l)
  fi
  echo "fuzz: randomized gtest${reports:+ (sanitized)}, $rounds rounds in" \
    "${seconds} s: $scene_inputs scene inputs and $analytic_inputs analytic" \
    "inputs tried, no failing test, $n_reports sanitizer reports"
  [ "$n_reports" -eq 0 ]
}

echo "fuzz: mode $mode, ${seconds} s"
if [ "$mode" = libfuzzer ]; then run_libfuzzer; else run_gtest; fi
