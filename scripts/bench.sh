#!/usr/bin/env bash
# Throughput benchmark (docs/performance.md): runs each case for a short simulated time at 1
# and 2 OpenMP threads, one after the other, and prints a markdown table of particle-steps per
# second and wall seconds per simulated second, read from each run's summary.json.
# Usage: scripts/bench.sh [SIMULATED_SECONDS] (default 2). Needs a build (scripts/build.sh).
# The machine should be otherwise idle: compare ratios measured in one run of this script.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
exe=${SLOSHSPH_BUILD_DIR:-$root/build}/app/sloshsph
seconds=${1:-2}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cases=("hydrostatic.toml" "tld_no_screens.toml" "tait2005_screens.toml")
echo "| case | dp (m) | particles | threads | particle-steps/s | wall s per simulated s | steps |"
echo "|---|---|---|---|---|---|---|"
for c in "${cases[@]}"; do
  for t in 1 2; do
    d="$out/${c%.toml}_$t"
    "$exe" run "$root/cases/$c" --out "$d" --threads "$t" --quiet \
      --set time.end="$seconds" --set output.snapshot_interval=0 >/dev/null 2>&1
    /usr/bin/python3 - "$d/summary.json" "$c" "$t" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
n = s["fluid_particles"] + s["wall_particles"]
print(f"| {sys.argv[2]} | {s['dp_m']:g} | {n} | {sys.argv[3]} | {s['particle_steps_per_second']:.3g} "
      f"| {s['wall_seconds_per_simulated_second']:.3g} | {s['steps']} |")
PY
  done
done
echo
echo "($(date -u +%Y-%m-%d), $(getconf _NPROCESSORS_ONLN) cores, ${seconds} s simulated per run, sloshsph $("$exe" --version | cut -d' ' -f2-))"
