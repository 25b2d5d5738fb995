#!/usr/bin/env bash
# SIGINT while the fluid settles (time.settle, before t = 0 and before the run directory exists):
# the run stops within a few steps with exit code 4 and a message, and writes nothing.
set -u
exe=$1 case=$2 dir=$3
rm -rf "$dir" "$dir.err"
"$exe" run "$case" --out "$dir" --threads 1 --set particles.dp=0.02 --set time.settle=200 2> "$dir.err" &
pid=$!
sleep 2
kill -INT "$pid"
start=$(date +%s)
wait "$pid"
code=$? waited=$(( $(date +%s) - start ))
[ "$code" = 4 ] || { echo "FAIL: exit $code, expected 4: $(cat "$dir.err")"; exit 1; }
[ "$waited" -le 5 ] || { echo "FAIL: took $waited s to stop after SIGINT"; exit 1; }
grep -q 'interrupted while the fluid settled' "$dir.err" || { echo "FAIL: message: $(cat "$dir.err")"; exit 1; }
[ ! -e "$dir" ] || { echo "FAIL: a run directory was written"; ls -la "$dir"; exit 1; }
echo "settle interrupt ok: exit 4 after $waited s, nothing written"
