#!/usr/bin/env bash
# One command from a fresh machine to the test results (CI: .ci/run calls it).
#
#  1. Installs the Debian packages (scripts/install-deps.sh).
#  2. Builds the Release tree build/ (the program and the validation tests) and the sanitizer tree
#     build-asan/ (AddressSanitizer + UndefinedBehaviorSanitizer, CMake preset `asan`: the unit
#     tests and the readers' mutation test; scripts/test-sanitizers.sh also builds the program there).
#  3. Runs in one ctest invocation (one summary line), one test per core:
#       - the unit tests (label `unit`, with `unit-theory`: the gtest executables) and the
#         mutation fuzz test of the readers, built with the sanitizers: any report fails the test;
#       - the Python module's tests (python/tests, pytest: label `unit`) on the Release module;
#       - the command-line tests (tests/cli: exit codes, the hostile-input corpus, runs, sweeps,
#         interrupt and resume, reports; label `unit`) on the Release program: under the
#         sanitizers they take about 1,080 s of test time instead of about 345 s, more than CI's
#         budget allows (scripts/test-sanitizers.sh runs them too);
#       - the physics validation (label `validation`) and the time-series regression tests (label
#         `regression`: short runs against tests/regression/reference/) on the Release build.
#     About 30 minutes on 2 cores from scratch (docs/validation/notes.md, "Hostile input and sanitizers").
#
# Options (anything else goes to ctest, e.g. -R case_reader):
#   --long           the `long` label on the Release build instead (hours; no sanitizers)
#   --no-sanitizers  the labels `unit`, `validation` and `regression` on the Release build alone
#                    (no build-asan/; about 20 minutes from scratch)
#
# Tests run one per core (ctest -j, SLOSHSPH_TEST_JOBS to change) with one OpenMP thread each
# (OMP_NUM_THREADS, unless set): one simulation gains only 1.15x from a second thread on this
# 2-core machine (docs/performance.md), so two single-threaded tests at once finish the
# validation label of 2026-12-01 in 1061 s against about 1500 s one at a time on two threads. Tests that check
# thread counts set them themselves.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mode=sanitized
case "${1:-}" in
  --long) mode=long; shift ;;
  --no-sanitizers) mode=release; shift ;;
esac
build=${SLOSHSPH_BUILD_DIR:-$root/build}
asan_build=${SLOSHSPH_ASAN_BUILD_DIR:-$root/build-asan}
# The core count from getconf, not nproc: GNU nproc honours OMP_NUM_THREADS, so after the export
# below it said 1 and the tests ran one at a time (the 2553 s CI of 2026-12-01).
jobs="${SLOSHSPH_TEST_JOBS:-$(getconf _NPROCESSORS_ONLN)}"
export OMP_NUM_THREADS="${OMP_NUM_THREADS:-1}"

"$root/scripts/install-deps.sh"
if [ "$mode" = long ]; then
  "$root/scripts/build.sh"
  exec ctest --test-dir "$build" -L long -j "$jobs" --output-on-failure "$@"
fi
if [ "$mode" = release ]; then
  "$root/scripts/build.sh"
  exec ctest --test-dir "$build" -L "unit|validation|regression" -j "$jobs" --output-on-failure "$@"
fi

# Release: only what the Release half runs (the program, the validation and regression tests, the
# theory tests that `sloshsph validate` runs in cli.validate_theory, and the Python module).
"$root/scripts/build.sh" sloshsph test_validation test_regression test_linear sloshsph_python
# Sanitizers: the gtest executables and the readers' mutation test (target unit_tests; the
# program is not needed: its command-line tests run on the Release build).
# shellcheck source=scripts/sanitizer-env.sh
. "$root/scripts/sanitizer-env.sh"
cmake --preset asan -S "$root" -B "$asan_build" > /dev/null
cmake --build "$asan_build" -j "$jobs" --target unit_tests

# One test tree made of both: the Release validation and command-line folders, and the gtest
# executables and fuzz folder of the sanitizer tree (the gtest include files hold absolute paths).
combined="$root/build-ci-tests"
mkdir -p "$combined"
{
  echo "# Written by scripts/test.sh: the Release validation, regression and command-line tests, the unit tests under the sanitizers."
  echo "subdirs(\"$build/tests/validation\")"
  echo "subdirs(\"$build/tests/cli\")"
  echo "subdirs(\"$build/python/tests\")"
  for include in "$asan_build"/tests/*_include.cmake; do echo "include(\"$include\")"; done
  echo "subdirs(\"$asan_build/tests/fuzz\")"
} > "$combined/CTestTestfile.cmake"
ctest --test-dir "$combined" -L "unit|validation|regression" -j "$jobs" --output-on-failure "$@"
