# Sourced by scripts/test.sh and scripts/test-sanitizers.sh: the run-time options of the
# sanitizer build (CMake preset `asan`). Any report stops the test with a failure: UB is fatal,
# ASan aborts. Open MPI keeps some allocations until exit (the MPI sweep test): suppressed by
# library name (scripts/lsan-suppressions.txt). Options already set in the environment win.
# Binaries built without the sanitizers ignore these variables.
sanitizer_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1:strict_string_checks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$sanitizer_root/scripts/lsan-suppressions.txt:fast_unwind_on_malloc=0:print_suppressions=0}
