#!/bin/bash
# A job with *RESTART, WRITE (FREQUENCY=2, or the RESTART given) interrupted in its sliding step (step 2) and continued with -tsl_restart,
# in both ways a batch job ends early:
#   stop  SIGUSR1 to mpirun (a wall-time warning): the job writes a point at its last converged increment and exits
#         with 138; the continuation starts there;
#   kill  SIGKILL to one rank (a lost node, an out-of-memory kill): nothing is written at the end; the continuation
#         starts from the latest periodic point and extends the killed run's frames and history (its .part files).
# Each continuation's results (every frame) and history must equal the uninterrupted run's: bitwise on one rank,
# within TOL of each field's largest value on more (MUMPS's parallel factorisation is not bitwise repeatable).
# RESTART: the *RESTART line put before the first step (default: FREQUENCY=2); WAIT: the log line the interruption
# waits for (default: step 2's second increment). CONT_NP (environment): continue on that many ranks instead of NP,
# reading the point by node, element and face (restart.c, NaturalMap, LoadState); TOL is then that of two whole runs
# on the two counts, which differ too (the solvers' sums in another order).
# usage: restart_interrupt.sh THERMOSLIDE MPIEXEC NP DECK OUTDIR PYTHON COMPARE TOL [RESTART [WAIT]]
set -u
exe=$1 mpiexec=$2 np=$3 deck=$4 out=$5 py=$6 compare=$7 tol=$8
cnp=${CONT_NP:-$np}
restart=${9:-*RESTART, WRITE, FREQUENCY=2} wait_for=${10:-step 2 increment 2:}
rm -rf "$out" && mkdir -p "$out/whole" || exit 1
job=$(basename "$deck" .inp)
awk -v line="$restart" '!done && toupper($0) ~ /^\*STEP/ {print line; done = 1} {print}' "$deck" > "$out/$job.inp"
$mpiexec -n "$np" "$exe" "$out/$job.inp" -o "$out/whole" > "$out/whole.log" 2>&1 || { cat "$out/whole.log"; echo "FAIL: the whole run"; exit 1; }

# interrupt HOW DIR: starts the job, waits for its second increment of step 2, interrupts it; sets rc
interrupt() {
  local how=$1 dir=$2 pid
  mkdir -p "$dir"
  $mpiexec -n "$np" "$exe" "$out/$job.inp" -o "$dir" > "$dir.log" 2>&1 &
  pid=$!
  for _ in $(seq 1 6000); do grep -q "$wait_for" "$dir.log" 2> /dev/null && break; kill -0 $pid 2> /dev/null || break; sleep 0.01; done
  if [ "$how" = stop ]; then
    kill -USR1 $pid 2> /dev/null
  else
    # the last rank's process (a child of mpirun)
    kill -KILL "$(pgrep -P $pid | tail -n 1)" 2> /dev/null
  fi
  wait $pid
  rc=$?
}

fail=0
for how in stop kill; do
  dir=$out/$how
  interrupt $how "$dir"
  if [ $rc = 0 ]; then echo "FAIL: $how: the job ended before it was interrupted"; fail=1; continue; fi
  if [ $how = stop ]; then
    [ $rc = 138 ] || { cat "$dir.log"; echo "FAIL: stop: exit status $rc, expected 138 (128 + SIGUSR1)"; fail=1; continue; }
    grep -q "restart point .*(SIGUSR1)" "$dir.log" || { cat "$dir.log"; echo "FAIL: stop: no restart point written on the signal"; fail=1; continue; }
  else
    ls "$dir/$job.h5.part" > /dev/null 2>&1 || { echo "FAIL: kill: the killed run left no $job.h5.part"; fail=1; continue; }
  fi
  last=$(grep -o "step [0-9]* increment [0-9]*:" "$dir.log" | tail -n 1)
  $mpiexec -n "$cnp" "$exe" "$out/$job.inp" -o "$dir" -tsl_restart > "$dir.cont.log" 2>&1 || { cat "$dir.cont.log"; echo "FAIL: $how: the continuation"; fail=1; continue; }
  if [ "$cnp" != "$np" ]; then
    grep -q "the point was written on $np ranks" "$dir.cont.log" || { cat "$dir.cont.log"; echo "FAIL: $how: the continuation on $cnp ranks did not say it read a point of $np"; fail=1; continue; }
  fi
  from=$(grep -o "continuing from restart point .*: step [0-9]* increment [0-9]*" "$dir.cont.log" | sed 's/.*: //')
  echo "$how: interrupted after ${last%:} on $np ranks, continued from $from on $cnp"
  "$py" "$compare" "$out/whole/$job.h5" "$dir/$job.h5" "$tol" || { echo "FAIL: $how: the continuation's results differ from the whole run's"; fail=1; }
  if [ "$tol" = 0 ]; then cmp "$out/whole/$job.csv" "$dir/$job.csv" || { echo "FAIL: $how: the histories differ"; fail=1; }; fi
  [ "$(wc -l < "$out/whole/$job.csv")" = "$(wc -l < "$dir/$job.csv")" ] || { echo "FAIL: $how: history rows lost or duplicated"; fail=1; }
  ls "$dir"/*.part "$dir"/*.interrupted.* > /dev/null 2>&1 && { ls "$dir"; echo "FAIL: $how: the interrupted run's files are left beside the results"; fail=1; }
done
[ $fail = 0 ] && echo PASS
exit $fail
