#!/bin/sh
# check_bad.sh PROGRAM DECK EXPECTED: passes when PROGRAM DECK exits non-zero and its output contains
# EXPECTED (a fixed string, typically "error: deck.inp:LINE: message").
prog=$1 deck=$2 expected=$3
out=$("$prog" "$deck" 2>&1)
status=$?
printf '%s\n' "$out"
if [ $status -eq 0 ]; then echo "FAIL: $prog $deck exited 0"; exit 1; fi
if ! printf '%s\n' "$out" | grep -qF -- "$expected"; then echo "FAIL: expected output to contain: $expected"; exit 1; fi
echo "PASS: exit $status and message found"
