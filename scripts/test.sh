#!/usr/bin/env bash
# One command from a fresh machine to the test results:
# installs the Debian packages, builds, and runs the ctest labels `unit` and `validation`
# (about 20 minutes on 2 cores from scratch). With --long it runs the `long` label instead (hours).
#
# Tests run one per core (ctest -j, SLOSHSPH_TEST_JOBS to change) with one OpenMP thread each
# (OMP_NUM_THREADS, unless set): one simulation gains only 1.15x from a second thread on this
# 2-core machine (docs/performance.md), so two single-threaded tests at once finish the
# validation label of 2026-12-01 in 1061 s against about 1500 s one at a time on two threads. Tests that check
# thread counts set them themselves.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
labels="unit|validation"
if [ "${1:-}" = "--long" ]; then labels="long"; shift; fi
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
cd "${SLOSHSPH_BUILD_DIR:-$root/build}"
# The core count from getconf, not nproc: GNU nproc honours OMP_NUM_THREADS, so after the export
# below it said 1 and the tests ran one at a time (the 2553 s CI of 2026-12-01).
jobs="${SLOSHSPH_TEST_JOBS:-$(getconf _NPROCESSORS_ONLN)}"
export OMP_NUM_THREADS="${OMP_NUM_THREADS:-1}"
ctest -L "$labels" -j "$jobs" --output-on-failure "$@"
