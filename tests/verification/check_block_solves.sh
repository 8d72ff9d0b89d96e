#!/bin/sh
# Block solves (src/solve/split.c, docs/running.md "Block solves"): a model without contact has a block-
# triangular Jacobian (the temperature rows hold no displacement entries), and the default split then solves
# the temperature block and the displacement block by CG to the outer tolerance, so the outer FGMRES converges
# in one iteration. The steady coupled C3D8T block of tests/bench/make_block.py (N = 10, 10 164 unknowns):
#   - the default run says so in -ksp_view, its outer solve takes 1 iteration, and the job's "linear" count is
#     the displacement block's CG iterations (AMG cycles, more than 5);
#   - its results equal -tsl_block_solves 0 (one cycle per outer iteration) to 1e-8, on 1 rank and 2;
#   - a displacement CG capped at 3 iterations (-fieldsplit_u_ksp_max_it 3) fails, the split falls back to
#     one cycle per block (-info says so) and the outer FGMRES still converges to the same results (1e-8);
#     so does a temperature CG capped at 2 (-fieldsplit_T_ksp_max_it 2), which fails before the coupling
#     product, so that the coupling block, not extracted under block solves, is extracted there, on 2 ranks.
# usage: check_block_solves.sh THERMOSLIDE MPIEXEC OUTDIR BENCHDIR TOOLSDIR
set -u
exe=$1 mpiexec=$2 out=$3 bench=$4 tools=$5
size=10 && . "$tools/block_case.sh"
run blocks_1 1 -ksp_view -ksp_converged_reason
run cycles_1 1 -tsl_block_solves 0 -ksp_converged_reason
run blocks_2 2 -ksp_converged_reason
run capped_1 1 -fieldsplit_u_ksp_max_it 3 -info -ksp_converged_reason
run capped_t_2 2 -fieldsplit_T_ksp_max_it 2 -info -ksp_converged_reason
grep -q "block-triangular operator: each block solved by CG" "$out/blocks_1.log" || { echo "FAIL: no block solves in -ksp_view"; exit 1; }
outer=$(grep "^  Linear solve converged" "$out/blocks_1.log" | sed -n 's/.*iterations \([0-9]*\).*/\1/p' | head -1)
lin=$(sed -n 's/.*newton [0-9]*  linear \([0-9]*\).*/\1/p' "$out/blocks_1.log" | tail -1)
echo "block solves: outer iterations $outer, displacement cycles $lin; one cycle per outer iteration: $(sed -n 's/.*newton [0-9]*  linear \([0-9]*\).*/\1/p' "$out/cycles_1.log" | tail -1)"
[ "$outer" = 1 ] || { echo "FAIL: the outer solve took $outer iterations, not 1"; exit 1; }
[ "$lin" -gt 5 ] || { echo "FAIL: the job's linear count ($lin) is not the displacement block's cycles"; exit 1; }
cmp_h5 blocks_1 cycles_1
cmp_h5 blocks_2 blocks_1
grep -q "block solve by CG failed" "$out/capped_1.log" || { echo "FAIL: the capped CG did not fall back"; exit 1; }
grep -q "Linear solve converged" "$out/capped_1.log" || { echo "FAIL: the outer solve did not converge after the fallback"; exit 1; }
cmp_h5 capped_1 blocks_1
grep -q "temperature block solve by CG failed" "$out/capped_t_2.log" || { echo "FAIL: the capped temperature CG did not fall back"; exit 1; }
grep -q "Linear solve converged" "$out/capped_t_2.log" || { echo "FAIL: the outer solve did not converge after the temperature fallback"; exit 1; }
cmp_h5 capped_t_2 blocks_2
echo "PASS"
