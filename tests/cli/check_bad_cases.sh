#!/usr/bin/env bash
# check_bad_cases.sh BAD_DIR SCRATCH COUNT: after the bad-case tests (tests/cli/CMakeLists.txt),
# checks that none of them left a run directory in SCRATCH, and that every case file of
# BAD_DIR is in the corpus (COUNT tests), so a file added without its test is noticed.
set -u
bad=$1; scratch=$2; count=$3
status=0
shopt -s nullglob
for d in "$scratch"/bad[0-9] "$scratch"/bad_*; do
  echo "a rejected case left a run directory behind: $d"; status=1
done
files=("$bad"/*.toml)
if [ "${#files[@]}" != "$count" ]; then
  echo "bad_cases/ holds ${#files[@]} case files but $count tests use them: wire each file as a test"; status=1
fi
[ $status = 0 ] && echo "ok: ${#files[@]} bad cases, no run directory left behind"
exit $status
