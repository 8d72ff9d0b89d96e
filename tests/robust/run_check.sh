#!/bin/sh
# usage: run_check.sh MPIEXEC NP THERMOSLIDE DECK OUTDIR LOGREGEX PYTHON CHECK [ARGS...] -- [OPTIONS...]
# Runs the deck under a timeout, requires LOGREGEX in the log (the situation the test is about did happen),
# then the check script: CHECK OUTDIR JOB ARGS.
mpiexec=$1 np=$2 exe=$3 deck=$4 out=$5 regex=$6 py=$7 check=$8
shift 8
args=""
while [ $# -gt 0 ] && [ "$1" != "--" ]; do args="$args $1"; shift; done
[ $# -gt 0 ] && shift
job=$(basename "$deck" .inp)
rm -rf "$out" && mkdir -p "$out"
timeout 600 "$mpiexec" -n "$np" "$exe" "$deck" -o "$out" "$@" > "$out/log" 2>&1
rc=$?
cat "$out/log"
[ $rc -eq 0 ] || { echo "FAIL: exit code $rc"; exit 1; }
grep -Eq -e "$regex" "$out/log" || { echo "FAIL: no line matches: $regex"; exit 1; }
"$py" "$check" "$out" "$job" $args
