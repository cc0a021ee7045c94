# Sourced by .ci/sanitize.sh and .ci/fuzz.sh: the sanitized build and the
# sanitizer options, in one place.

# Debug (deal.II's debug library adds its own Assert checks, and Boost's
# headers theirs) with -fsanitize=address,undefined.
# PRE_TEST: list each executable's tests when ctest starts, not right after
# linking. Starting an ASan executable linked to deal.II's debug library
# takes 1-4 s, close to gtest_discover_tests' 5 s default timeout, and a
# busy machine made the build itself fail.
# Ninja for a new build folder, as .ci/setup.sh.
configure_sanitized_build() { # <build folder> <build type>
  local generator=()
  [ -f "$1/CMakeCache.txt" ] || generator=(-G Ninja)
  cmake "${generator[@]}" -S . -B "$1" -DCMAKE_BUILD_TYPE="$2" \
    -DFLOORBLOCK_SANITIZE=ON \
    -DCMAKE_GTEST_DISCOVER_TESTS_DISCOVERY_MODE=PRE_TEST >/dev/null
}

# Exports the sanitizer options; every report also goes to a file under
# <reports folder>, so that "no report" can be checked after a run instead
# of being inferred from exit codes. <unwinder> is fast or slow:
# - fast (frame pointers) for processes that do not start MPI;
# - slow (DWARF) for processes that do: Open MPI and glibc have no frame
#   pointers, so the fast unwinder ends a leak's stack at their first frame
#   and the suppressions could not tell Open MPI's leaks from ours. It costs
#   about four times the run time of a contact solve.
# halt_on_error/abort_on_error: the first report fails the process (UBSan's
# default is to print and carry on with exit code 0). detect_leaks:
# LeakSanitizer at exit; suppressions only for third-party leaks, each
# justified in tests/fuzz/lsan.supp.
export_sanitizer_options() { # <reports folder> <fast|slow>
  local fast_unwind=1
  [ "$2" = slow ] && fast_unwind=0
  export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1:fast_unwind_on_malloc=$fast_unwind:log_path=$1/asan"
  export UBSAN_OPTIONS="halt_on_error=1:abort_on_error=1:print_stacktrace=1:log_path=$1/ubsan"
  export LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan.supp:print_suppressions=0"
}

# Prints every report under <reports folder>.
print_sanitizer_reports() { # <reports folder>
  local report
  while IFS= read -r -d '' report; do
    echo "sanitizer report $report:"
    head -n 60 "$report"
  done < <(find "$1" -type f -print0 | sort -z)
}
