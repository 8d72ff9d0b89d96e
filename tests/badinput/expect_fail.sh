#!/bin/sh
# usage: expect_fail.sh MPIEXEC NP THERMOSLIDE DECK OUTDIR REGEX [options...]
# Passes when thermoslide exits non-zero within 120 s (no rank left waiting), prints a line matching
# REGEX, and leaves no result files (.h5/.xmf/.csv, final or .part) in OUTDIR.
mpiexec=$1 np=$2 exe=$3 deck=$4 out=$5 regex=$6
shift 6
rm -rf "$out" && mkdir -p "$out"
timeout 120 "$mpiexec" -n "$np" "$exe" "$deck" -o "$out" "$@" > "$out/log" 2>&1
rc=$?
cat "$out/log"
[ $rc -ne 0 ] || { echo "FAIL: exit code 0"; exit 1; }
[ $rc -ne 124 ] || { echo "FAIL: timed out (a rank hung)"; exit 1; }
grep -Eq -e "$regex" "$out/log" || { echo "FAIL: no line matches: $regex"; exit 1; }
left=$(ls "$out" | grep -E '\.(h5|xmf|csv)(\.part)?$')
[ -z "$left" ] || { echo "FAIL: result files left: $left"; exit 1; }
echo "PASS: exit code $rc, message found, no result written"
