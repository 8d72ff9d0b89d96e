#!/bin/sh
# Inexact Newton (src/solve/driver.c, -tsl_linear_forcing): the later Newton iterations of an increment are
# solved to the forcing term instead of -ksp_rtol, which must save linear iterations without changing the
# answer. The two-block C3D8T contact deck of tests/bench/make_contact_block.py at N = 16 (289 contact nodes,
# 6 200 unknowns, one steady increment, the iterative solver), 1 rank, run with the default forcing and with
# -tsl_linear_forcing 0 (every iteration to -ksp_rtol 1e-10). Iteration counts are exact: the same Newton
# iterations, strictly fewer linear ones; the interface heat equal to 1e-8 relative (the Newton tolerance is
# a 1e-9 reduction per field).
# usage: check_linear_forcing.sh THERMOSLIDE MPIEXEC OUTDIR BENCHDIR
set -u
exe=$1 mpiexec=$2 out=$3 bench=$4
rm -rf "$out" && mkdir -p "$out" || exit 1
/usr/bin/python3 "$bench/make_contact_block.py" 16 "$out/block.inp" || exit 1
for run in forcing exact; do
  opt=""
  [ $run = exact ] && opt="-tsl_linear_forcing 0"
  # shellcheck disable=SC2086
  $mpiexec -n 1 "$exe" "$out/block.inp" -o "$out/$run" $opt > "$out/$run.log" 2>&1 || { cat "$out/$run.log"; exit 1; }
  line=$(grep -E "^  step 1 increment 1:" "$out/$run.log" | tail -1)
  newton=$(echo "$line" | sed -n 's/.*newton \([0-9]*\).*/\1/p') linear=$(echo "$line" | sed -n 's/.*linear \([0-9]*\).*/\1/p')
  [ -n "$newton" ] && [ -n "$linear" ] || { echo "FAIL: no increment line in $out/$run.log"; exit 1; }
  heat=$(/usr/bin/python3 -c 'import csv, sys; print(list(csv.DictReader(open(sys.argv[1])))[-1]["interface_heat"])' "$out/$run/block.csv") || exit 1
  echo "$run: $newton Newton iterations, $linear linear iterations, interface heat $heat"
  eval "newton_$run=$newton linear_$run=$linear heat_$run=$heat"
done
[ "$newton_forcing" = "$newton_exact" ] || { echo "FAIL: the forcing term changed the Newton iterations"; exit 1; }
[ "$linear_forcing" -lt "$linear_exact" ] || { echo "FAIL: no linear iterations saved"; exit 1; }
awk -v a="$heat_forcing" -v b="$heat_exact" 'BEGIN {d = a - b; if (d < 0) d = -d; s = b < 0 ? -b : b; printf "heat relative difference %.2e (at most 1e-8)\n", d / s; exit !(d <= 1e-8 * s)}' ||
  { echo "FAIL: the forcing term changed the interface heat"; exit 1; }
echo "PASS"
