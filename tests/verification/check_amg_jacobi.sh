#!/bin/sh
# Weighted-Jacobi smoothing of the blocks' BoomerAMG with a weight per level (src/solve/split.c JacobiWeights,
# docs/running.md "Solvers"; the displacement block, and the temperature block of a model without contact): omega_l = s / (1.1 lambda_l), lambda_l the level's largest
# eigenvalue of D^-1 A estimated by ten Lanczos steps and capped by Gershgorin's bound, s =
# -tsl_amg_jacobi_scale (1.6). The steady coupled C3D8T block of tests/bench/make_block.py (N = 12, 16 900
# unknowns, iterative):
#   - the default run weights the levels of both blocks (-ksp_view lists the weights; -info gives the
#     displacement block's finest weight and estimate, whose product times 1.1 is s to 1e-3) and its
#     smoother is Jacobi without CF ordering;
#   - its results equal those of the previous smoothers (-tsl_amg_jacobi_scale 0: Chebyshev on the
#     displacement, hybrid Gauss-Seidel on the temperature) to 1e-8, on 1 rank and on 2;
#   - another scale (1.2) scales the finest weight by 1.2 / 1.6 (the same hierarchy, the same estimate);
#   - a user's own -fieldsplit_u_pc_hypre_boomeramg_relax_weight_all is left alone (only the temperature
#     block's weights listed).
# usage: check_amg_jacobi.sh THERMOSLIDE MPIEXEC OUTDIR BENCHDIR TOOLSDIR
set -u
exe=$1 mpiexec=$2 out=$3 bench=$4 tools=$5
size=12 && . "$tools/block_case.sh"
its() { sed -n 's/.*newton [0-9]*  linear \([0-9]*\).*/\1/p' "$out/$1.log" | tail -1; }
finest() { sed -n 's/.*fieldsplit_u_ BoomerAMG Jacobi weights on [0-9]* levels, finest \([0-9.e+-]*\) (lambda \([0-9.e+-]*\)).*/\1 \2/p' "$out/$1.log" | head -1; }
run jacobi_1 1 -ksp_view -info
run cheby_1 1 -tsl_amg_jacobi_scale 0 -ksp_view
run jacobi_2 2
run scaled_1 1 -tsl_amg_jacobi_scale 1.2 -info
run user_1 1 -fieldsplit_u_pc_hypre_boomeramg_relax_weight_all 0.5 -ksp_view
echo "displacement cycles: Jacobi $(its jacobi_1) (2 ranks $(its jacobi_2)), Chebyshev $(its cheby_1); finest weight and estimate: $(finest jacobi_1)"
nw() { grep -c "BoomerAMG Jacobi weights per level" "$out/$1.log"; }
[ "$(nw jacobi_1)" = 2 ] || { echo "FAIL: not both blocks' per-level weights in -ksp_view"; exit 1; }
grep -q "Relax down *Jacobi" "$out/jacobi_1.log" || { echo "FAIL: the default smoother is not Jacobi"; exit 1; }
grep -q "Not using CF-relaxation" "$out/jacobi_1.log" || { echo "FAIL: CF-ordered Jacobi sweeps by default"; exit 1; }
grep -q "Relax down *Chebyshev" "$out/cheby_1.log" || { echo "FAIL: -tsl_amg_jacobi_scale 0 did not keep Chebyshev"; exit 1; }
grep -q "Relax down *symmetric-SOR/Jacobi" "$out/cheby_1.log" || { echo "FAIL: -tsl_amg_jacobi_scale 0 did not keep hybrid Gauss-Seidel on the temperature"; exit 1; }
[ "$(nw cheby_1)" = 0 ] || { echo "FAIL: weights listed without Jacobi smoothing"; exit 1; }
[ "$(nw user_1)" = 1 ] || { echo "FAIL: the user's relax weight was overridden"; exit 1; }
set -- $(finest jacobi_1) $(finest scaled_1)
[ $# = 4 ] || { echo "FAIL: no finest-level weight in -info"; exit 1; }
awk -v w=$1 -v l=$2 -v w2=$3 -v l2=$4 'BEGIN {
  p = 1.1 * w * l; r = w2 / w
  printf "1.1 x weight x estimate: %.4f (scale 1.6); weight ratio at scale 1.2: %.4f (0.75)\n", p, r
  exit !(p > 1.6 * (1 - 1e-3) && p < 1.6 * (1 + 1e-3) && l == l2 && r > 0.75 * (1 - 1e-6) && r < 0.75 * (1 + 1e-6) && p * 1.1 < 2) }' ||
  { echo "FAIL: the finest level's weight is not scale / (1.1 x estimate)"; exit 1; }
cmp_h5 jacobi_1 cheby_1
cmp_h5 jacobi_2 jacobi_1
cmp_h5 scaled_1 jacobi_1
cmp_h5 user_1 jacobi_1
echo "PASS"
