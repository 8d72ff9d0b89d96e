#!/bin/bash
# A job with *RESTART, WRITE (FREQUENCY=2, or the RESTART given) run whole on NPA ranks; its points after the middle
# one removed (as if the job had been killed there) and the job continued with -tsl_restart on NPB ranks: the point
# is read by node, element and face (restart.c, NaturalMap and LoadState). The continuation's results (every frame)
# must agree with the whole run's within TOL of each field's largest value, its history have the same rows. The
# tolerance is that of two whole runs on NPA and NPB ranks, which differ too (the solvers' sums in another order).
# TOL=refused: the continuation must stop with an error saying the point continues on NPA ranks only (an explicit
# step's point), the earlier run's results and points untouched.
# usage: restart_ranks.sh THERMOSLIDE MPIEXEC NPA NPB DECK OUTDIR PYTHON COMPARE TOL [RESTART]
set -u
exe=$1 mpiexec=$2 npa=$3 npb=$4 deck=$5 out=$6 py=$7 compare=$8 tol=$9
restart=${10:-*RESTART, WRITE, FREQUENCY=2}
rm -rf "$out" && mkdir -p "$out/whole" || exit 1
job=$(basename "$deck" .inp)
awk -v line="$restart" '!done && toupper($0) ~ /^\*STEP/ {print line; done = 1} {print}' "$deck" > "$out/$job.inp"
$mpiexec -n "$npa" "$exe" "$out/$job.inp" -o "$out/whole" > "$out/whole.log" 2>&1 || { cat "$out/whole.log"; echo "FAIL: the whole run on $npa ranks"; exit 1; }
n=$(ls "$out"/whole/"$job".restart.*.h5 | wc -l)
[ "$n" -ge 4 ] || { echo "FAIL: $n restart points written"; exit 1; }
cp -r "$out/whole" "$out/cont"
ls "$out"/cont/"$job".restart.*.h5 | sed 's/.*\.restart\.\([0-9]*\)\.\([0-9]*\)\.h5/\1 \2/' | sort -n -k1,1 -k2,2 | tail -n $((n - n / 2)) |
  while read -r s i; do rm "$out/cont/$job.restart.$s.$i.h5"; done
if [ "$tol" = refused ]; then
  cp -r "$out/cont" "$out/before"
  if $mpiexec -n "$npb" "$exe" "$out/$job.inp" -o "$out/cont" -tsl_restart > "$out/cont.log" 2>&1; then echo "FAIL: the point of $npa ranks continued on $npb"; exit 1; fi
  grep -q "continues on the rank count it was written with ($npa)" "$out/cont.log" || { cat "$out/cont.log"; echo "FAIL: no clear error"; exit 1; }
  grep -o "restart point .*" "$out/cont.log" | head -1
  diff -r "$out/before" "$out/cont" > /dev/null || { echo "FAIL: the refused continuation changed the earlier run's files"; exit 1; }
  echo PASS
  exit 0
fi
$mpiexec -n "$npb" "$exe" "$out/$job.inp" -o "$out/cont" -tsl_restart > "$out/cont.log" 2>&1 || { cat "$out/cont.log"; echo "FAIL: the continuation on $npb ranks"; exit 1; }
grep "continuing from restart point" "$out/cont.log" || { echo "FAIL: the continuation did not say where it continued from"; exit 1; }
grep -q "the point was written on $npa ranks" "$out/cont.log" || { cat "$out/cont.log"; echo "FAIL: the continuation did not say it read a point of $npa ranks"; exit 1; }
"$py" "$compare" "$out/whole/$job.h5" "$out/cont/$job.h5" "$tol" || { echo "FAIL: the continuation on $npb ranks differs from the whole run on $npa"; exit 1; }
[ "$(wc -l < "$out/whole/$job.csv")" = "$(wc -l < "$out/cont/$job.csv")" ] || { echo "FAIL: history rows lost or duplicated"; exit 1; }
echo PASS
