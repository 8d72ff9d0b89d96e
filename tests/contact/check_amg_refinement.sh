#!/bin/sh
# The linear iterations of a contact problem under refinement (issue 10: AMG that keeps its iteration count
# as the mesh is refined, here with contact). The two-block C3D8T deck of tests/bench/make_contact_block.py
# (a thin block pressed on a base through a penalty node-to-surface pair with gap conductance, one steady
# increment) at N = 16 and N = 32 (289 and 1 089 contact nodes, 6 200 and 22 584 unknowns), 1 rank, the
# default solver. Iteration counts are exact, so the check is too: FGMRES iterations per Newton iteration
# may grow by at most 1.2x for the halved mesh size. With the lean hierarchy of the contact-free models they
# doubled (50 -> 99); with the contact models' defaults (src/solve/driver.c) 19 -> 20. Every Newton iteration
# is solved to -ksp_rtol here (-tsl_linear_forcing 0), so that the counts measure the preconditioner alone.
# usage: check_amg_refinement.sh THERMOSLIDE MPIEXEC OUTDIR BENCHDIR
set -u
exe=$1 mpiexec=$2 out=$3 bench=$4
rm -rf "$out" && mkdir -p "$out" || exit 1
for n in 16 32; do
  /usr/bin/python3 "$bench/make_contact_block.py" $n "$out/block$n.inp" || exit 1
  $mpiexec -n 1 "$exe" "$out/block$n.inp" -o "$out/block$n" -tsl_linear_forcing 0 > "$out/block$n.log" 2>&1 || { cat "$out/block$n.log"; exit 1; }
  line=$(grep -E "^  step 1 increment 1:" "$out/block$n.log" | tail -1)
  newton=$(echo "$line" | sed -n 's/.*newton \([0-9]*\).*/\1/p') linear=$(echo "$line" | sed -n 's/.*linear \([0-9]*\).*/\1/p')
  [ -n "$newton" ] && [ -n "$linear" ] || { echo "FAIL: no increment line in $out/block$n.log"; exit 1; }
  per=$(awk -v l=$linear -v n=$newton 'BEGIN {print l / n}')
  [ $n = 16 ] && per16=$per || per32=$per
  printf "N = %d: %d Newton iterations, %d linear iterations, %.1f per Newton iteration\n" $n $newton $linear $per
done
ratio=$(awk -v a=$per32 -v b=$per16 'BEGIN {print a / b}')
printf "growth for the halved mesh size: %.2f (at most 1.2)\n" $ratio
awk -v r=$ratio 'BEGIN {exit !(r <= 1.2)}' || { echo "FAIL: the linear iterations grow with the mesh"; exit 1; }
echo "PASS"
