#!/usr/bin/env bash
# One command from a fresh machine to the test results:
# installs the Debian packages, builds, and runs the ctest labels `unit` and `validation`
# (about 15 minutes on 2 cores). With --long it runs the `long` label instead (hours).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
labels="unit|validation"
if [ "${1:-}" = "--long" ]; then labels="long"; shift; fi
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
cd "${SLOSHSPH_BUILD_DIR:-$root/build}"
ctest -L "$labels" --output-on-failure "$@"
