#!/bin/bash
# A job with *RESTART, WRITE, FREQUENCY=3 run whole; then its points after the middle one removed (as if the job had
# been killed there) and the job continued with -tsl_restart: the continuation's results (every frame) and history
# must equal the whole run's, bitwise on one rank, within TOL on two (the two-rank run is not bitwise repeatable
# itself: two whole runs differ by ~1e-13). Then the bad cases: -tsl_restart without any point, a point of another
# model: an error naming it, a non-zero exit. (Another rank count continues: restart_ranks.sh.)
# usage: restart_continue.sh THERMOSLIDE MPIEXEC NP DECK OUTDIR PYTHON COMPARE TOL
set -u
exe=$1 mpiexec=$2 np=$3 deck=$4 out=$5 py=$6 compare=$7 tol=$8
rm -rf "$out" && mkdir -p "$out/whole" || exit 1
sed '0,/^\*[Ss][Tt][Ee][Pp]/s//*RESTART, WRITE, FREQUENCY=3\n&/' "$deck" > "$out/job.inp"
$mpiexec -n "$np" "$exe" "$out/job.inp" -o "$out/whole" > "$out/whole.log" 2>&1 || { cat "$out/whole.log"; echo "FAIL: the whole run"; exit 1; }
n=$(ls "$out"/whole/job.restart.*.h5 | wc -l)
[ "$n" -ge 4 ] || { echo "FAIL: $n restart points written"; exit 1; }
cp -r "$out/whole" "$out/cont"
# keep the first half of the points (in step, increment order)
ls "$out"/cont/job.restart.*.h5 | sed 's/.*job\.restart\.\([0-9]*\)\.\([0-9]*\)\.h5/\1 \2/' | sort -n -k1,1 -k2,2 | tail -n $((n - n / 2)) |
  while read -r s i; do rm "$out/cont/job.restart.$s.$i.h5"; done
$mpiexec -n "$np" "$exe" "$out/job.inp" -o "$out/cont" -tsl_restart > "$out/cont.log" 2>&1 || { cat "$out/cont.log"; echo "FAIL: the continuation"; exit 1; }
grep "continuing from restart point" "$out/cont.log" || { echo "FAIL: the continuation did not say where it continued from"; exit 1; }
"$py" "$compare" "$out/whole/job.h5" "$out/cont/job.h5" "$tol" || { echo "FAIL: the continuation's results differ from the whole run's"; exit 1; }
if [ "$tol" = 0 ]; then cmp "$out/whole/job.csv" "$out/cont/job.csv" || { echo "FAIL: the histories differ"; exit 1; }; fi
[ "$(wc -l < "$out/whole/job.csv")" = "$(wc -l < "$out/cont/job.csv")" ] || { echo "FAIL: history rows lost or duplicated"; exit 1; }
# the latest point corrupted (one value of its solution changed in place) or truncated: it is passed over with a
# warning naming it, and the continuation from the one before it gives the same results
latest=$(ls "$out"/whole/job.restart.*.h5 | sed 's/.*job\.restart\.\([0-9]*\)\.\([0-9]*\)\.h5/\1 \2/' | sort -n -k1,1 -k2,2 | tail -n 1 | tr ' ' .)
for how in corrupted truncated; do
  rm -rf "$out/$how" && cp -r "$out/whole" "$out/$how"
  p="$out/$how/job.restart.$latest.h5"
  if [ $how = corrupted ]; then
    "$py" -c "import h5py, sys; f = h5py.File(sys.argv[1], 'r+'); x = f['X']; v = x[...]; v.flat[len(v.flat) // 2] += 1e-3; x[...] = v" "$p" || exit 1
  else
    truncate -s $(($(stat -c %s "$p") / 2)) "$p"
  fi
  $mpiexec -n "$np" "$exe" "$out/job.inp" -o "$out/$how" -tsl_restart > "$out/$how.log" 2>&1 || { cat "$out/$how.log"; echo "FAIL: the continuation past a $how point"; exit 1; }
  grep -q "warning: restart point .*job.restart.$latest.h5 is not used: " "$out/$how.log" || { cat "$out/$how.log"; echo "FAIL: the $how point was not named"; exit 1; }
  grep "is not used" "$out/$how.log"
  grep -q "continuing from restart point" "$out/$how.log" || { echo "FAIL: no continuation from an earlier point"; exit 1; }
  "$py" "$compare" "$out/whole/job.h5" "$out/$how/job.h5" "$tol" || { echo "FAIL: the continuation past a $how point differs from the whole run"; exit 1; }
done
# another model: the friction coefficient or a node's position changed: an error naming the point, the results kept
for change in '/^\*FRICTION/{n;s/0\.1/0.2/}' '0,/^ 1, 0, 0$/s// 1, 0.001, 0/'; do
  rm -rf "$out/model" && cp -r "$out/whole" "$out/model"
  mkdir -p "$out/changed" && sed "$change" "$out/job.inp" > "$out/changed/job.inp"
  cmp -s "$out/job.inp" "$out/changed/job.inp" && { echo "FAIL: the deck change '$change' changed nothing"; exit 1; }
  if $mpiexec -n "$np" "$exe" "$out/changed/job.inp" -o "$out/model" -tsl_restart > "$out/model.log" 2>&1; then echo "FAIL: a point continued with another model ($change)"; exit 1; fi
  grep -q "restart point .* was written for" "$out/model.log" || { cat "$out/model.log"; echo "FAIL: no clear error for another model ($change)"; exit 1; }
  grep -o "restart point .* was written for.*" "$out/model.log" | head -1
  cmp -s "$out/whole/job.h5" "$out/model/job.h5" || { echo "FAIL: the refused continuation changed the results"; exit 1; }
done
# no point at all: an error, nothing overwritten
mkdir -p "$out/none"
if $mpiexec -n "$np" "$exe" "$out/job.inp" -o "$out/none" -tsl_restart > "$out/none.log" 2>&1; then echo "FAIL: -tsl_restart without a point completed"; exit 1; fi
grep -q "no valid restart point of job job" "$out/none.log" || { cat "$out/none.log"; echo "FAIL: no clear error without a point"; exit 1; }
echo PASS
