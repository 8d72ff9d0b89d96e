#!/bin/sh
# usage: keep_result.sh MPIEXEC NP THERMOSLIDE GOOD_DECK BAD_DECK OUTDIR
# Both decks have the same job name. The good run writes results; the bad run must fail and leave
# every byte of them in place, with no temporary files behind.
mpiexec=$1 np=$2 exe=$3 good=$4 bad=$5 out=$6
job=$(basename "$good" .inp)
rm -rf "$out" && mkdir -p "$out"
"$mpiexec" -n "$np" "$exe" "$good" -o "$out" > "$out/good.log" 2>&1 || { cat "$out/good.log"; echo "FAIL: good run"; exit 1; }
before=$(cd "$out" && md5sum "$job.h5" "$job.xmf" "$job.csv")
timeout 120 "$mpiexec" -n "$np" "$exe" "$bad" -o "$out" > "$out/bad.log" 2>&1 && { echo "FAIL: bad run exited 0"; exit 1; }
cat "$out/bad.log"
after=$(cd "$out" && md5sum "$job.h5" "$job.xmf" "$job.csv")
[ "$before" = "$after" ] || { echo "FAIL: earlier results changed"; exit 1; }
[ -z "$(ls "$out" | grep '\.part')" ] || { echo "FAIL: temporary files left"; exit 1; }
echo "PASS: earlier results intact"
