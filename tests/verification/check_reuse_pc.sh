#!/bin/sh
# A Jacobian equal bit for bit to the one before it keeps its preconditioner (src/solve/driver.c,
# FormJacobian; docs/running.md "An unchanged Jacobian"). The coupled C3D8T block of tests/bench/make_block.py
# (N = 6: 2 548 unknowns, above the 3D direct-solver default) as a transient step of five fixed increments
# (DIRECT): a linear model at a constant increment, so every Jacobian after the first is the first.
#   - the default (iterative) run, a one-rank LU run and a 2-rank MUMPS run each say so, for at least 4 of
#     their Jacobians;
#   - each equals its run with -tsl_reuse_unchanged_jacobian 0 (the preconditioner built every time) to 1e-8,
#     and the three agree with one another to 1e-8.
# usage: check_reuse_pc.sh THERMOSLIDE MPIEXEC OUTDIR BENCHDIR TOOLSDIR
set -u
exe=$1 mpiexec=$2 out=$3 bench=$4 tools=$5
size=6 && . "$tools/block_case.sh"
sed -i -e 's/^\*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE$/*COUPLED TEMPERATURE-DISPLACEMENT, DIRECT/' -e 's/^ 1.0, 1.0$/ 0.2, 1.0/' "$out/block.inp"
grep -q "DISPLACEMENT, DIRECT" "$out/block.inp" || { echo "FAIL: the transient deck was not written"; exit 1; }
kept() {
  n=$(sed -n 's/^thermoslide: \([0-9]*\) of \([0-9]*\) Jacobians equal to the one before them.*/\1/p' "$out/$1.log")
  echo "$1: ${n:-0} Jacobians kept their preconditioner"
  [ "${n:-0}" -ge 4 ] || { echo "FAIL: $1 kept the preconditioner for ${n:-0} Jacobians, not at least 4"; exit 1; }
}
for c in "iter 1" "lu 1 -tsl_direct_max_dofs 100000" "mumps 2 -tsl_direct_max_dofs 100000"; do
  set -- $c
  case_=$1 ranks=$2 # (run sets name and np)
  shift 2
  run "$case_" "$ranks" "$@"
  run "${case_}_rebuilt" "$ranks" -tsl_reuse_unchanged_jacobian 0 "$@"
  kept "$case_"
  grep -q "Jacobians equal to the one before" "$out/${case_}_rebuilt.log" && { echo "FAIL: ${case_}_rebuilt kept a preconditioner"; exit 1; }
  cmp_h5 "$case_" "${case_}_rebuilt"
done
cmp_h5 lu iter
cmp_h5 mumps lu
echo "PASS"
