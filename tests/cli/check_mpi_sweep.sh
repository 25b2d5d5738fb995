#!/usr/bin/env bash
# A sweep spread over 2 MPI ranks (issue: sweeps across machines):
#  1. both ranks run points, and rank 0 writes one frequency_response.csv with every point, equal
#     to the single-process sweep's (every column but the wall time; same thread count, so the
#     numbers are bitwise the same);
#  2. the same without a shared file system: rank 1 runs in its own mount namespace with a private
#     tmpfs over the sweep folder (as on a second machine, the path exists but is another disk),
#     so rank 0 can only learn rank 1's point through MPI. Its frequency_response.csv must still be
#     complete and equal, and rank 1's point folder on rank 0's side holds only the summary.json
#     that came over MPI (no timeseries.csv: that stayed on "the other machine").
# Usage: check_mpi_sweep.sh EXE CASE DIR [shared|private] (default: both). `private` exits 77
# (ctest: skipped, shown as such) where no mount namespace can be made (not root, no CAP_SYS_ADMIN).
set -u
exe=$1 case=$2 dir=$3 mode=${4:-both}
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$dir"
mkdir -p "$dir"
args=(sweep "$case" --beta 0.9:1.1:3 --threads 1 --set particles.dp=0.02 --set time.end=1.5
  --set output.snapshot_interval=0)
mpi=(mpirun --allow-run-as-root --oversubscribe -np 2)
fail() { echo "FAIL: $*"; exit 1; }

# The columns that must agree: all but the wall time and the run folder.
same_results() {
  /usr/bin/python3 - "$1" "$2" <<'EOF'
import csv, sys
def rows(p):
    with open(p) as f:
        return [{k: v for k, v in r.items() if k not in ("wall_time_s", "run_dir")} for r in csv.DictReader(f)]
a, b = rows(sys.argv[1]), rows(sys.argv[2])
sys.exit(0 if a == b and len(a) == 3 else 1)
EOF
}

"$exe" "${args[@]}" --out "$dir/single" 2> "$dir/single.err" || fail "single-process sweep exit $?: $(cat "$dir/single.err")"

if [ "$mode" != private ]; then
  "${mpi[@]}" "$exe" "${args[@]}" --out "$dir/shared" 2> "$dir/shared.err" || fail "mpi sweep exit $?: $(cat "$dir/shared.err")"
  csv="$dir/shared/frequency_response.csv"
  [ "$(grep -c ',completed,' "$csv")" = 3 ] || fail "3 completed rows expected: $(cat "$csv")"
  grep -q 'sweep\[0/2\]: completed' "$dir/shared.err" && grep -q 'sweep\[1/2\]: completed' "$dir/shared.err" \
    || fail "both ranks should run points: $(cat "$dir/shared.err")"
  same_results "$dir/single/frequency_response.csv" "$csv" || fail "2-rank sweep differs from the single-process one"
  echo "mpi sweep ok (shared file system)"
fi
[ "$mode" = shared ] && exit 0

# Without a shared file system (needs root for the mount namespace).
if ! unshare --mount true 2> /dev/null; then
  echo "SKIPPED: cannot make a mount namespace (unshare --mount) to stand for a second machine"
  exit 77
fi
mkdir -p "$dir/private"
"${mpi[@]}" "$here/private_disk_for_rank.sh" 1 "$dir/private" "$exe" "${args[@]}" --out "$dir/private" \
  2> "$dir/private.err" || fail "mpi sweep without shared files exit $?: $(cat "$dir/private.err")"
csv="$dir/private/frequency_response.csv"
same_results "$dir/single/frequency_response.csv" "$csv" || fail "sweep without shared files differs: $(cat "$csv")"
[ -f "$dir/private/beta_1.0000/summary.json" ] || fail "rank 1's summary did not reach rank 0"
[ ! -e "$dir/private/beta_1.0000/timeseries.csv" ] || fail "rank 1 wrote to rank 0's disk: the test did not separate them"
[ -f "$dir/private/beta_0.9000/timeseries.csv" ] || fail "rank 0's own point lacks its time series"
echo "mpi sweep ok (no shared file system)"
