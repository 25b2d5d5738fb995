#!/usr/bin/env bash
# check_run_dir.sh DIR: the run directory holds what the README promises, with the fixed names.
set -eu
d=$1
for f in case.toml run.json summary.json timeseries.csv particles.pvd; do
  [ -s "$d/$f" ] || { echo "missing or empty: $d/$f"; exit 1; }
done
ls "$d"/particles/particles_*.vtu > /dev/null || { echo "no VTU snapshots"; exit 1; }
head -1 "$d/timeseries.csv" | grep -q '^time,' || { echo "first column is not 'time'"; exit 1; }
for c in 'p:y0.02' 'eta:centre' 'F_w' 'F_sw'; do
  head -1 "$d/timeseries.csv" | tr ',' '\n' | grep -qx "$c" || { echo "no column $c"; exit 1; }
done
for k in status steps simulated_time_s wall_time_s fluid_particles wall_particles leaked_particles particle_steps_per_second; do
  grep -q "\"$k\"" "$d/summary.json" || { echo "summary.json lacks $k"; exit 1; }
done
grep -q '"status": "completed"' "$d/summary.json" || { echo "status is not completed"; exit 1; }
# The memory breakdown adds up to the total, and names the largest parts of an ISPH run.
python3 - "$d/summary.json" <<'PY' || exit 1
import json, sys
s = json.load(open(sys.argv[1]))
parts = s["memory_bytes_per_particle_by_part"]
total = s["memory_bytes_per_particle"]
missing = {"particle_arrays", "neighbour_list", "pairs", "ppe_matrix", "multigrid"} - set(parts)
if missing or abs(sum(parts.values()) - total) > 1e-9 * total or not total > 0:
    sys.exit(f"memory breakdown {parts} does not add up to {total} (missing {sorted(missing)})")
PY
grep -q 'VTKFile type="Collection"' "$d/particles.pvd" || { echo "bad pvd"; exit 1; }
echo "run directory ok"
