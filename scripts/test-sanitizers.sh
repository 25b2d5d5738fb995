#!/usr/bin/env bash
# Builds sloshsph and its unit tests with AddressSanitizer + UndefinedBehaviorSanitizer (CMake
# preset `asan`: Debug, -O1 with line tables, SLOSHSPH_SANITIZE=ON) and runs the whole `unit`
# label under them, the command-line tests included (scripts/test.sh, and so CI, runs those on the
# Release program). Any sanitizer report fails the run (UB is fatal, ASan aborts). About 8 minutes
# to build and 13 to test on 2 cores (2026-12-02). Extra arguments go to ctest
# (e.g. -R case_reader). Build directory: build-asan/, or $SLOSHSPH_ASAN_BUILD_DIR.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${SLOSHSPH_ASAN_BUILD_DIR:-$root/build-asan}
jobs=${SLOSHSPH_JOBS:-$(getconf _NPROCESSORS_ONLN)}
# shellcheck source=scripts/sanitizer-env.sh
. "$root/scripts/sanitizer-env.sh"
start=$(date +%s)
cmake --preset asan -S "$root" -B "$build" > /dev/null
cmake --build "$build" -j "$jobs"
ctest --test-dir "$build" -L unit --output-on-failure -j "$jobs" "$@"
echo "sanitizers: unit tests passed under ASan+UBSan in $(( $(date +%s) - start )) s"
