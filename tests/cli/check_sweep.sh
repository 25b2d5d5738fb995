#!/usr/bin/env bash
# `sloshsph sweep` contract (issue: screens and sweeps): frequency_response.csv with the fixed
# columns, one row per point; a re-run skips finished points; a sweep directory reused with other
# settings is refused (exit 2); failing points are reported, the sweep goes on, and exits 3;
# ranged --set keys sweep any parameter.
set -u
exe=$1 case=$2 dir=$3
rm -rf "$dir"
common=(--set particles.dp=0.02 --set time.end=1.5 --set output.snapshot_interval=0 --threads 1 --jobs 2)
fail() { echo "FAIL: $*"; exit 1; }

"$exe" sweep "$case" --beta 0.9:1.1:3 "${common[@]}" --out "$dir/ok" 2> "$dir.err1" || fail "sweep exit $?: $(cat "$dir.err1")"
csv="$dir/ok/frequency_response.csv"
head -1 "$csv" | grep -q '^beta,omega,eta_max,eta_min,F_sw_max,F_sw_min,energy_per_cycle,status,' || fail "header: $(head -1 "$csv")"
[ "$(grep -c ',completed,' "$csv")" = 3 ] || fail "3 completed rows expected: $(cat "$csv")"
for b in 0.9000 1.0000 1.1000; do [ -f "$dir/ok/beta_$b/summary.json" ] || fail "no run directory for beta $b"; done
grep -q '3 done, 0 running, 0 left' "$dir.err1" || fail "progress: $(cat "$dir.err1")"

"$exe" sweep "$case" --beta 0.9:1.1:3 "${common[@]}" --out "$dir/ok" 2> "$dir.err2" || fail "re-run exit $?"
grep -q '3 of 3 points already finished, skipped' "$dir.err2" || fail "re-run did not skip: $(cat "$dir.err2")"

"$exe" sweep "$case" --beta 0.9:1.1:3 "${common[@]}" --set time.end=2 --out "$dir/ok" 2> "$dir.err3"
[ $? = 2 ] || fail "reuse with other settings should exit 2"
grep -q 'different case' "$dir.err3" || fail "message: $(cat "$dir.err3")"

"$exe" sweep "$case" --beta 0.95,1.05 "${common[@]}" --set run.max_speed_factor=1e-6 --out "$dir/bad" 2> "$dir.err4"
[ $? = 3 ] || fail "failing points should give exit 3"
[ "$(grep -c ',failed,' "$dir/bad/frequency_response.csv")" = 2 ] || fail "2 failed rows expected"
grep -q 'FAILED' "$dir.err4" || fail "failures not reported"
# A parameter sweep: ranged --set keys (amplitude as a list, depth as A:B:N) without --beta, each
# point at the case's own frequency ratio; one column set:<key> per swept key, every combination.
"$exe" sweep "$case" "${common[@]}" --set excitation.amplitude=0.003,0.006 --set fill.depth=0.12:0.14:2 \
  --out "$dir/params" 2> "$dir.err5" || fail "parameter sweep exit $?: $(cat "$dir.err5")"
csv="$dir/params/frequency_response.csv"
head -1 "$csv" | grep -q ',set:excitation.amplitude,set:fill.depth,wall_time_s,run_dir$' || fail "header: $(head -1 "$csv")"
[ "$(grep -c ',completed,' "$csv")" = 4 ] || fail "4 completed rows expected: $(cat "$csv")"
grep -q '^1,.*,0.006,0.14,[^,]*,excitation.amplitude_0.006__fill.depth_0.14$' "$csv" || fail "row: $(cat "$csv")"
point="$dir/params/excitation.amplitude_0.006__fill.depth_0.14/case.toml"
grep -q '^depth = 0.14' "$point" && grep -q '^amplitude = 0.006' "$point" || fail "the point's case: $(cat "$point")"
"$exe" sweep "$case" "${common[@]}" --set excitation.amplitude=0.003:0.006:0 --out "$dir/params_bad" 2> "$dir.err6"
[ $? = 2 ] && grep -q "key 'excitation.amplitude'.*point count N" "$dir.err6" || fail "bad range: $(cat "$dir.err6")"
echo "sweep contract ok"
