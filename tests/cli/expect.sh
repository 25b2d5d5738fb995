#!/usr/bin/env bash
# expect.sh CODE REGEX -- command...: runs the command, passes if it exits with CODE and its
# stderr+stdout match the extended regex REGEX. Used by the command-line tests.
set -u
want=$1; pattern=$2; shift 2
[ "$1" = "--" ] && shift
out=$("$@" 2>&1); got=$?
if [ "$got" != "$want" ]; then
  echo "exit code $got, expected $want; output:"; echo "$out"; exit 1
fi
if ! grep -Eq -- "$pattern" <<<"$out"; then
  echo "output does not match /$pattern/:"; echo "$out"; exit 1
fi
echo "ok: exit $got, output matches /$pattern/"
