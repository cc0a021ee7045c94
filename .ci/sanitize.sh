#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer run of the fast tests.
#
# Configures build-sanitize/ with -DFLOORBLOCK_SANITIZE=ON, builds the test
# executables of the named subset and runs them through ctest. Exits non-zero
# on any failing test or sanitizer report: UBSan only prints and continues
# unless halt_on_error=1, so the options below are essential, not cosmetic.
#
# Subset: labels unit, cli and fuzz of the executables in `targets`.
# Left out: unit_tests_geometry, unit_tests_contact and unit_tests_verification
# (Gmsh meshing and FEM contact solves; too slow under ASan + deal.II debug for a CI step). ctest
# lists tests of unbuilt executables as "<target>_NOT_BUILT"; they are
# excluded by name.
#
# Environment: SANITIZE_BUILD_TYPE (default Debug: deal.II's debug library
# adds its own Assert checks), JOBS (default nproc), SANITIZE_TARGETS and
# SANITIZE_EXCLUDE to change the subset.
set -euo pipefail
cd "$(dirname "$0")/.."
repository=$(pwd)

build=build-sanitize
build_type=${SANITIZE_BUILD_TYPE:-Debug}
jobs=${JOBS:-$(nproc)}
targets=(${SANITIZE_TARGETS:-unit_tests_common unit_tests_analytic
  unit_tests_parameters fuzz_tests cli_tests floorblock})
# ctest -E regex of tests left out, with the reason in the header above.
excluded_tests=${SANITIZE_EXCLUDE:-'_NOT_BUILT$'}

start=$(date +%s)
# PRE_TEST: list each executable's tests when ctest starts, not right after
# linking. Starting an ASan executable linked to deal.II's debug library
# takes 1-4 s, close to gtest_discover_tests' 5 s default timeout, and a
# busy machine made the build itself fail.
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE="$build_type" \
  -DFLOORBLOCK_SANITIZE=ON -DCMAKE_GTEST_DISCOVER_TESTS_DISCOVERY_MODE=PRE_TEST \
  >/dev/null
cmake --build "$build" -j"$jobs" --target "${targets[@]}" -- --no-print-directory
built=$(date +%s)

# halt_on_error/abort: the first report fails the test (UBSan's default is
# to print and carry on with exit code 0). detect_leaks: LeakSanitizer at
# exit; suppressions only for third-party leaks, each justified in the file.
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1"
export UBSAN_OPTIONS="halt_on_error=1:abort_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$repository/tests/fuzz/lsan.supp:print_suppressions=0"

status=0
ctest --test-dir "$build" -L 'unit|cli|fuzz' -E "$excluded_tests" \
  --output-on-failure -j"$jobs" --timeout 600 || status=$?
end=$(date +%s)
echo "sanitize: build $((built - start)) s, tests $((end - built)) s," \
  "excluded: $excluded_tests, status $status"
exit "$status"
