#!/usr/bin/env bash
# Builds sloshsph and its tests with AddressSanitizer + UndefinedBehaviorSanitizer (CMake preset
# `asan`: Debug, -O1 -g, SLOSHSPH_SANITIZE=ON) and runs the `unit` label under them. Any
# sanitizer report fails the run (UB is fatal, ASan aborts). Extra arguments go to ctest
# (e.g. -R case_reader). Build directory: build-asan/, or $SLOSHSPH_ASAN_BUILD_DIR.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${SLOSHSPH_ASAN_BUILD_DIR:-$root/build-asan}
jobs=${SLOSHSPH_JOBS:-$(getconf _NPROCESSORS_ONLN)}
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1:strict_string_checks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
# Open MPI keeps some allocations until exit (the MPI sweep test): suppressed by library name.
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$root/scripts/lsan-suppressions.txt:fast_unwind_on_malloc=0:print_suppressions=0}
start=$(date +%s)
cmake --preset asan -S "$root" -B "$build" > /dev/null
cmake --build "$build" -j "$jobs"
ctest --test-dir "$build" -L unit --output-on-failure -j "$jobs" "$@"
echo "sanitizers: unit tests passed under ASan+UBSan in $(( $(date +%s) - start )) s"
