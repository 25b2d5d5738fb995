#!/usr/bin/env bash
# Interruption and resume (issue: hard to break). An uninterrupted run and a run stopped by
# SIGINT part-way then resumed must write the same timeseries.csv (bitwise-equal state gives
# the same printed numbers) and the same response; the stopped run exits 4 with a checkpoint.
set -u
exe=$1 case=$2 dir=$3
shift 3  # further arguments: extra options for both runs (they come last, so they win)
rm -rf "$dir"; mkdir -p "$dir"
common=(--set particles.dp=0.02 --set time.end=2 --set output.snapshot_interval=0.5 --threads 1 --quiet "$@")
fail() { echo "FAIL: $*"; exit 1; }

"$exe" run "$case" "${common[@]}" --checkpoint-every 0.25 --out "$dir/full" || fail "full run exit $?"
[ -e "$dir/full/checkpoint.bin" ] && fail "a completed run keeps no checkpoint"

"$exe" run "$case" "${common[@]}" --checkpoint-every 0.25 --out "$dir/cut" &
pid=$!
# Wait until the run has written at least one periodic checkpoint, then interrupt it. Up to 10
# minutes (under the sanitizers the settle alone took more than the 30 s this once allowed, and
# the signal then arrived before any checkpoint), or until the run has ended by itself.
for _ in $(seq 1 12000); do
  [ -e "$dir/cut/checkpoint.bin" ] && break
  kill -0 $pid 2> /dev/null || break
  sleep 0.05
done
# While the run goes on, a second process in its directory is refused at once (exit 2, before any
# set-up) and changes nothing: a resume, and a run with --force, which would empty the directory.
# The run is stopped (SIGSTOP) meanwhile: it keeps its lock and cannot end between the attempts.
kill -STOP $pid 2> /dev/null
case $(ps -o stat= -p $pid 2> /dev/null) in
  T*)
    # `status` names the process that holds the lock.
    "$exe" status "$dir/cut" > "$dir/status_running.txt" || fail "status exit $?"
    grep -q "running (pid $pid)" "$dir/status_running.txt" || fail "status of a running run: $(cat "$dir/status_running.txt")"
    "$exe" resume "$dir/cut" --threads 1 --quiet 2> "$dir/busy_resume.err"; busy_resume=$?
    "$exe" run "$case" "${common[@]}" --force --out "$dir/cut" 2> "$dir/busy_run.err"; busy_run=$?
    kill -CONT $pid
    for attempt in resume run; do
      err="$dir/busy_$attempt.err"; code_var=busy_$attempt
      [ "${!code_var}" = 2 ] || fail "$attempt in the directory of a running run should exit 2, got ${!code_var}: $(cat "$err")"
      grep -q "is running in this run directory" "$err" || fail "$attempt beside a running run, message: $(cat "$err")"
    done
    [ -s "$dir/cut/timeseries.csv" ] || fail "the refused run --force emptied the running run's directory";;
  *) kill -CONT $pid 2> /dev/null; echo "note: the run ended before the second process was tried; the lock was not checked";;
esac
kill -INT $pid; wait $pid; code=$?
if [ $code = 0 ]; then echo "note: the run finished before the interrupt arrived"; else
  [ $code = 4 ] || fail "interrupted run should exit 4, got $code"
  grep -q '"status": "interrupted"' "$dir/cut/summary.json" || fail "summary should say interrupted"
  [ -s "$dir/cut/checkpoint.bin" ] || fail "no checkpoint after SIGINT"
  "$exe" status "$dir/cut" | grep -q "interrupted, resumable" || fail "status after SIGINT: $("$exe" status "$dir/cut")"
  "$exe" resume "$dir/cut" --threads 1 --quiet 2> "$dir/resume.err" || fail "resume exit $?: $(cat "$dir/resume.err")"
  grep -q "completed cut in" "$dir/resume.err" || fail "the resumed run is named after its directory: $(cat "$dir/resume.err")"
fi
"$exe" status "$dir" > "$dir/status_done.txt" || fail "status of the folder, exit $?"
[ "$(grep -c " completed " "$dir/status_done.txt")" = 2 ] || fail "status of both runs: $(cat "$dir/status_done.txt")"
cmp "$dir/full/timeseries.csv" "$dir/cut/timeseries.csv" || fail "time series differ after resume"
cmp "$dir/full/particles.pvd" "$dir/cut/particles.pvd" || fail "snapshot index differs after resume"
grep '"response"' -A200 "$dir/full/summary.json" | grep -v wall | head -60 > "$dir/r1"
grep '"response"' -A200 "$dir/cut/summary.json" | grep -v wall | head -60 > "$dir/r2"
cmp "$dir/r1" "$dir/r2" || fail "response differs after resume"
"$exe" resume "$dir/full" 2> "$dir/err2"; [ $? = 2 ] || fail "resuming a completed run should exit 2"
grep -q "no checkpoint.bin" "$dir/err2" || fail "message: $(cat "$dir/err2")"
echo "resume ok"
