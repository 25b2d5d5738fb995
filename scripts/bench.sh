#!/usr/bin/env bash
# Throughput benchmark (docs/performance.md, issue 8): runs each case for a short simulated time
# at 1 and 2 OpenMP threads, one after the other, and prints a markdown table of particle-steps
# per second, wall seconds per simulated second, threads and memory, read from each run's
# summary.json. Cases: the hydrostatic tank (dp = 5 mm), the Tait tank without screens (dp = 5
# mm), the Tait tank with two Ergun screens at dp = 7 mm and 5 mm, and with --large a
# 200,000-particle tank at rest (2 m x 1 m of water, dp = 3.16 mm, dt = 0.05 dp as
# bench/bench_stages.cpp's sized tank) for 0.0063 s (40 steps) whatever SECONDS says (about a
# minute on one thread with the default multigrid preconditioner; with
# SLOSHSPH_BENCH_SET='scheme.preconditioner="jacobi"' about 5,000 iterations a step and hours).
# SLOSHSPH_BENCH_SET adds space-separated KEY=VALUE overrides to every run (to compare options).
# Usage: scripts/bench.sh [SIMULATED_SECONDS] [--large] (default 2 s). Needs a build (scripts/build.sh).
# The machine should be otherwise idle: compare ratios measured in one run of this script.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
exe=${SLOSHSPH_BUILD_DIR:-$root/build}/app/sloshsph
seconds=2
large=false
for a in "$@"; do
  case "$a" in
    --large) large=true ;;
    *) seconds=$a ;;
  esac
done
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# label | case file | simulated seconds | extra --set arguments (space-separated KEY=VALUE)
runs=(
  "hydrostatic|hydrostatic.toml|$seconds|"
  "tld_no_screens|tld_no_screens.toml|$seconds|"
  "tait_screens_7mm|tait2005_screens.toml|$seconds|"
  "tait_screens_5mm|tait2005_screens.toml|$seconds|particles.dp=0.005"
)
if $large; then
  runs+=("tank_200k|hydrostatic.toml|0.0063|tank.length=2.0 tank.height=1.5 fill.depth=1.0 particles.dp=0.0031623 time.dt=0.000158 probes.pressure=[] scheme.solver_max_iterations=20000 output.sample_interval=0.002")
fi
echo "| case | dp (m) | particles | threads | particle-steps/s | wall s per simulated s | steps | scheme memory (B/particle) | peak resident (MB) |"
echo "|---|---|---|---|---|---|---|---|---|"
for r in "${runs[@]}"; do
  IFS='|' read -r label file secs extra <<< "$r"
  sets=(--set time.end="$secs" --set output.snapshot_interval=0)
  for kv in $extra ${SLOSHSPH_BENCH_SET:-}; do sets+=(--set "$kv"); done
  for t in 1 2; do
    d="$out/${label}_$t"
    OMP_NUM_THREADS=$t "$exe" run "$root/cases/$file" --out "$d" --threads "$t" --quiet "${sets[@]}" >/dev/null 2>&1
    /usr/bin/python3 - "$d/summary.json" "$label" "$t" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
n = s["fluid_particles"] + s["wall_particles"]
print(f"| {sys.argv[2]} | {s['dp_m']:g} | {n} | {sys.argv[3]} | {s['particle_steps_per_second']:.3g} "
      f"| {s['wall_seconds_per_simulated_second']:.3g} | {s['steps']} | {s['memory_bytes_per_particle']:.0f} "
      f"| {s.get('peak_resident_memory_bytes', 0) / 1e6:.1f} |")
PY
  done
done
echo
echo "($(date -u +%Y-%m-%d), $(getconf _NPROCESSORS_ONLN) cores, ${seconds} s simulated per run, sloshsph $("$exe" --version | cut -d' ' -f2-))"
