#!/bin/bash
# The batch scripts of jobs/cluster (docs/running.md, "Restart"), run as Slurm and PBS would run them, with srun,
# scontrol, mpirun and qsub standing in: the job is stopped by SIGUSR1 in its sliding step, the script queues it
# again (scontrol requeue / qsub of its own copy with OUT and the count), the requeued job continues with
# -tsl_restart in the same output directory and ends with the uninterrupted run's results and history. Then the
# two cases where it must not queue again: a job stopped without a new point since its start, and one whose
# allowance (MAX_REQUEUE) is used.
# usage: batch_requeue.sh THERMOSLIDE MPIEXEC SOURCE_DIR OUTDIR PYTHON COMPARE TOL
set -u
exe=$1 mpiexec=$2 src=$3 out=$4 py=$5 compare=$6 tol=$7
rm -rf "$out" && mkdir -p "$out/bin" || exit 1
deck=$out/friction.inp
sed '0,/^\*[Ss][Tt][Ee][Pp]/s//*RESTART, WRITE, FREQUENCY=2\n&/' "$src/jobs/verification/sliding_friction_cpe4t.inp" > "$deck"
$mpiexec -n 2 "$exe" "$deck" -o "$out/whole" > "$out/whole.log" 2>&1 || { cat "$out/whole.log"; echo "FAIL: the whole run"; exit 1; }

# the stand-ins: srun and mpirun run the job on 2 ranks as $out/mode says (stop: SIGUSR1 at step 2 increment 3;
# run: to its end; 138: exit at once as a stopped job would); scontrol and qsub record their arguments
ln -s "$exe" "$out/bin/thermoslide"
cat > "$out/bin/launch" << EOS
#!/bin/bash
mode=\$(cat "$out/mode")
[ "\$mode" = 138 ] && exit 138
"$mpiexec" -n 2 "\$@" > "$out/launch.log" 2>&1 &
pid=\$!
if [ "\$mode" = stop ]; then
  for _ in \$(seq 1 6000); do grep -q "step 2 increment 3:" "$out/launch.log" && break; kill -0 \$pid 2> /dev/null || break; sleep 0.01; done
  kill -USR1 \$pid
fi
wait \$pid
rc=\$?
cat "$out/launch.log"
exit \$rc
EOS
printf '#!/bin/bash\nexec "%s/bin/launch" "$@"\n' "$out" > "$out/bin/srun"
printf '#!/bin/bash\nshift 2\nexec "%s/bin/launch" "$@"\n' "$out" > "$out/bin/mpirun" # drops -n N
printf '#!/bin/bash\necho "$@" >> "%s/scontrol.calls"\n' "$out" > "$out/bin/scontrol"
printf '#!/bin/bash\necho "$@" >> "%s/qsub.calls"\n' "$out" > "$out/bin/qsub"
chmod +x "$out/bin/"*
export PATH=$out/bin:$PATH
unset OUT MAX_REQUEUE REQUEUED SLURM_RESTART_COUNT
fail=0
check_result() { # DIR LOG WHAT
  grep -q "continuing from restart point" "$2" || { cat "$2"; echo "FAIL: $3: the requeued job did not continue from a point"; fail=1; }
  "$py" "$compare" "$out/whole/friction.h5" "$1/friction.h5" "$tol" || { echo "FAIL: $3: the results differ from the whole run's"; fail=1; }
  [ "$(wc -l < "$out/whole/friction.csv")" = "$(wc -l < "$1/friction.csv")" ] || { echo "FAIL: $3: history rows lost or duplicated"; fail=1; }
}

# Slurm: the same job id, and so the same directory, after the requeue; SLURM_RESTART_COUNT counts the requeues
mkdir -p "$out/slurm" && cd "$out/slurm" || exit 1
echo stop > "$out/mode"
SLURM_JOB_ID=4242 bash "$src/jobs/cluster/thermoslide.slurm" "$deck" > first.log 2>&1
rc=$?
[ $rc = 138 ] || { cat first.log; echo "FAIL: slurm: the stopped job's exit status $rc, expected 138"; fail=1; }
[ "$(cat "$out/scontrol.calls" 2> /dev/null)" = "requeue 4242" ] || { cat first.log; echo "FAIL: slurm: the stopped job was not requeued"; fail=1; }
echo run > "$out/mode"
SLURM_JOB_ID=4242 SLURM_RESTART_COUNT=1 bash "$src/jobs/cluster/thermoslide.slurm" "$deck" > second.log 2>&1 || { cat second.log; echo "FAIL: slurm: the requeued job"; fail=1; }
check_result results-4242 second.log slurm
echo 138 > "$out/mode"
rm -f "$out/scontrol.calls"
SLURM_JOB_ID=4242 SLURM_RESTART_COUNT=2 bash "$src/jobs/cluster/thermoslide.slurm" "$deck" > third.log 2>&1
grep -q "stopped without a new restart point since the start; not queued again" third.log && [ ! -e "$out/scontrol.calls" ] || { cat third.log; echo "FAIL: slurm: a job stopped without progress was queued again"; fail=1; }
SLURM_JOB_ID=4243 SLURM_RESTART_COUNT=5 bash "$src/jobs/cluster/thermoslide.slurm" "$deck" > fourth.log 2>&1
grep -q "not queued again: 5 requeues (MAX_REQUEUE) are used" fourth.log && [ ! -e "$out/scontrol.calls" ] || { cat fourth.log; echo "FAIL: slurm: queued again beyond MAX_REQUEUE"; fail=1; }

# PBS: a new job id on each submission; the script submits its own copy with OUT and the count
mkdir -p "$out/pbs" && cd "$out/pbs" || exit 1
printf 'n1\nn1\n' > nodes
echo stop > "$out/mode"
PBS_O_WORKDIR=$PWD PBS_JOBID=77.server PBS_NODEFILE=$PWD/nodes DECK=$deck bash "$src/jobs/cluster/thermoslide.pbs" > first.log 2>&1
rc=$?
[ $rc = 138 ] || { cat first.log; echo "FAIL: pbs: the stopped job's exit status $rc, expected 138"; fail=1; }
calls=$(cat "$out/qsub.calls" 2> /dev/null)
[ "$calls" = "-v DECK=$deck,OUT=results-77,MAX_REQUEUE=5,REQUEUED=1 results-77/thermoslide.pbs" ] || { cat first.log; echo "FAIL: pbs: qsub called as '$calls'"; fail=1; }
echo run > "$out/mode"
PBS_O_WORKDIR=$PWD PBS_JOBID=78.server PBS_NODEFILE=$PWD/nodes DECK=$deck OUT=results-77 REQUEUED=1 bash results-77/thermoslide.pbs > second.log 2>&1 || { cat second.log; echo "FAIL: pbs: the submitted-again job"; fail=1; }
check_result results-77 second.log pbs
[ $fail = 0 ] && echo PASS
exit $fail
