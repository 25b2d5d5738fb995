#!/usr/bin/env bash
# check_all_cases.sh EXE CASES_DIR SCRATCH: every case shipped in cases/ is accepted and takes
# its first steps (two steps of 1 ms; no settling, no snapshots), so a change of the case format
# or of a default cannot silently break a shipped case.
set -u
exe=$1; cases=$2; scratch=$3
status=0; n=0
for f in "$cases"/*.toml; do
  n=$((n + 1))
  out="$scratch/all_cases_$(basename "$f" .toml)"
  rm -rf "$out"
  if ! "$exe" run "$f" --out "$out" --quiet --threads 1 --set time.end=0.002 --set output.sample_interval=0.001 \
      --set output.snapshot_interval=0 --set time.settle=0 > "$scratch/all_cases.log" 2>&1; then
    echo "FAILED: $f"; cat "$scratch/all_cases.log"; status=1
  fi
  rm -rf "$out"
done
[ $status = 0 ] && echo "ok: all $n cases start"
exit $status
