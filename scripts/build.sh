#!/usr/bin/env bash
# Configures and builds sloshsph (Release) into build/. Used by quickstart.sh and test.sh.
# Arguments name targets to build (default: all), e.g. scripts/build.sh sloshsph test_validation.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${SLOSHSPH_BUILD_DIR:-$root/build}
jobs=${SLOSHSPH_JOBS:-$(getconf _NPROCESSORS_ONLN)}
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$build" -j "$jobs" ${1:+--target "$@"}
