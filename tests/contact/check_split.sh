#!/bin/sh
# thermoslide's field split (src/solve/split.c), the default preconditioner, against PETSc's own field split
# (-pc_type fieldsplit) with the same options: the same arithmetic with the displacement block held once, so
# the same Newton and linear iterations and the same results to 1e-12 (compare_h5.py; measured: identical).
# The two-block C3D8T contact deck of tests/bench/make_contact_block.py at N = 12 (169 contact nodes; the
# contact pairing changes after the first solve, so the Jacobian's pattern is rebuilt in place and the
# blocks extracted again), on 1 and 2 ranks; both with -tsl_block_solves 0 ("ours"), since PETSc's split has
# no block solves, and ours with -tsl_amg_jacobi_scale 0, since PETSc's split keeps BoomerAMG's Chebyshev
# smoothing. Then the default ("blocks": the first solve, before the contact couples the fields, is block
# triangular and its blocks are solved by CG; weighted-Jacobi smoothing with per-level weights, shown by
# -ksp_view) and -pc_fieldsplit_type additive (no coupling update) reach the same Newton iterations and
# interface heat to 1e-8 relative; -pc_type tslsplit, the split's registered type, is the default bit for bit.
# usage: check_split.sh THERMOSLIDE MPIEXEC OUTDIR BENCHDIR TOOLSDIR
set -u
exe=$1 mpiexec=$2 out=$3 bench=$4 tools=$5
rm -rf "$out" && mkdir -p "$out" || exit 1
/usr/bin/python3 "$bench/make_contact_block.py" 12 "$out/block.inp" || exit 1
its() { grep -E "^  step 1 increment 1:" "$1" | tail -1 | sed -n 's/.*newton \([0-9]*\).*linear \([0-9]*\).*/\1 \2/p'; }
heat() { /usr/bin/python3 -c 'import csv, sys; print(list(csv.DictReader(open(sys.argv[1])))[-1]["interface_heat"])' "$1"; }
for np in 1 2; do
  for run in ours petsc additive blocks named; do
    opt="-tsl_block_solves 0 -tsl_amg_jacobi_scale 0"
    [ $run = petsc ] && opt="-pc_type fieldsplit"
    [ $run = additive ] && opt="-pc_fieldsplit_type additive -tsl_block_solves 0 -tsl_amg_jacobi_scale 0"
    [ $run = blocks ] && opt=""
    [ $run = named ] && opt="-pc_type tslsplit"
    # shellcheck disable=SC2086
    $mpiexec -n $np "$exe" "$out/block.inp" -o "$out/${run}_$np" -tsl_partition axis_x -ksp_view $opt > "$out/${run}_$np.log" 2>&1 ||
      { cat "$out/${run}_$np.log"; exit 1; }
    echo "$np rank(s), $run: Newton, linear iterations $(its "$out/${run}_$np.log"), interface heat $(heat "$out/${run}_$np/block.csv")"
  done
  grep -q "thermoslide field split (multiplicative)" "$out/ours_$np.log" || { echo "FAIL: the default is not thermoslide's split"; exit 1; }
  grep -q "type: tslsplit" "$out/ours_$np.log" || { echo "FAIL: -ksp_view does not name the split's PC type"; exit 1; }
  /usr/bin/python3 "$tools/compare_h5.py" "$out/named_$np/block.h5" "$out/blocks_$np/block.h5" 0 || { echo "FAIL: -pc_type tslsplit is not the default"; exit 1; }
  grep -q "type: hypre" "$out/ours_$np.log" || { echo "FAIL: no hypre displacement block in -ksp_view"; exit 1; }
  grep -q "type: fieldsplit" "$out/petsc_$np.log" || { echo "FAIL: -pc_type fieldsplit did not give PETSc's split"; exit 1; }
  grep -q "thermoslide field split (additive)" "$out/additive_$np.log" || { echo "FAIL: -pc_fieldsplit_type additive not taken"; exit 1; }
  [ "$(its "$out/ours_$np.log")" = "$(its "$out/petsc_$np.log")" ] || { echo "FAIL: iterations differ from PETSc's field split"; exit 1; }
  /usr/bin/python3 "$tools/compare_h5.py" "$out/ours_$np/block.h5" "$out/petsc_$np/block.h5" 1e-12 || exit 1
  grep -q "block-triangular operator" "$out/blocks_$np.log" || { echo "FAIL: no block solves in the default run's -ksp_view"; exit 1; }
  grep -q "BoomerAMG Jacobi weights per level" "$out/blocks_$np.log" || { echo "FAIL: no per-level Jacobi weights in the default run's -ksp_view"; exit 1; }
  grep -q "Relax down *Chebyshev" "$out/ours_$np.log" || { echo "FAIL: -tsl_amg_jacobi_scale 0 did not keep Chebyshev smoothing"; exit 1; }
  for run in additive blocks; do
    [ "$(its "$out/${run}_$np.log" | cut -d' ' -f1)" = "$(its "$out/ours_$np.log" | cut -d' ' -f1)" ] || { echo "FAIL: $run: Newton iterations differ"; exit 1; }
    awk -v a="$(heat "$out/${run}_$np/block.csv")" -v b="$(heat "$out/ours_$np/block.csv")" -v r=$run \
      'BEGIN {d = a - b; if (d < 0) d = -d; s = b < 0 ? -b : b; printf "%s: heat relative difference %.2e (at most 1e-8)\n", r, d / s; exit !(d <= 1e-8 * s)}' ||
      { echo "FAIL: $run changed the interface heat"; exit 1; }
  done
done
echo "PASS"
