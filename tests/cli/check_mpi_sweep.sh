#!/usr/bin/env bash
# A sweep spread over 2 MPI ranks (issue: sweeps across machines): both ranks run points, and
# rank 0 writes one frequency_response.csv with every point, as a single-machine sweep does.
set -u
exe=$1 case=$2 dir=$3
rm -rf "$dir"
mpirun --allow-run-as-root --oversubscribe -np 2 "$exe" sweep "$case" --beta 0.9:1.1:3 --threads 1 \
  --set particles.dp=0.02 --set time.end=1.5 --set output.snapshot_interval=0 --out "$dir" 2> "$dir.err" \
  || { echo "FAIL: exit $?"; cat "$dir.err"; exit 1; }
csv="$dir/frequency_response.csv"
[ "$(grep -c ',completed,' "$csv")" = 3 ] || { echo "FAIL: 3 completed rows expected"; cat "$csv"; exit 1; }
grep -q 'sweep\[0/2\]: completed' "$dir.err" && grep -q 'sweep\[1/2\]: completed' "$dir.err" \
  || { echo "FAIL: both ranks should run points"; cat "$dir.err"; exit 1; }
echo "mpi sweep ok"
