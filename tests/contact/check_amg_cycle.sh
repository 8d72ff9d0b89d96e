#!/bin/sh
# thermoslide's application of BoomerAMG's V-cycle (src/solve/amg.c) against hypre's own (-tsl_amg_cycle 0):
# the same arithmetic with each level's first Jacobi sweep computed from the zero iterate without a product,
# so the same Newton and linear iterations and the same result files, to the bit (compare_h5.py, tolerance 0).
#   - the steady C3D8T block of tests/bench/make_block.py at N = 8, solved iteratively (-tsl_direct_max_dofs 0):
#     both blocks take the cycle; also with two sweeps on every level (-..._grid_sweeps_all 2: the sweeps after
#     the first are hypre's) and with Jacobi on the coarsest level instead of Gaussian elimination;
#   - the two-block contact deck of make_contact_block.py at N = 12 (contact pattern rebuilt after the first
#     solve, block solves then one cycle per outer iteration): the displacement block takes the cycle, the
#     temperature block (hybrid Gauss-Seidel with contact) keeps hypre's;
# on 1 and 2 ranks; and a smoother the cycle does not cover (symmetric SOR/Jacobi) keeps hypre's application.
# usage: check_amg_cycle.sh THERMOSLIDE MPIEXEC OUTDIR BENCHDIR TOOLSDIR
set -u
exe=$1 mpiexec=$2 out=$3 bench=$4 tools=$5
rm -rf "$out" && mkdir -p "$out" || exit 1
/usr/bin/python3 "$bench/make_block.py" 8 "$out/block.inp" || exit 1
/usr/bin/python3 "$bench/make_contact_block.py" 12 "$out/contact.inp" || exit 1
its() { grep -E "^  step [0-9]+ increment [0-9]+:" "$1" | sed -n 's/.*\(newton [0-9]*\).*\(linear [0-9]*\).*/\1 \2/p' | tr '\n' ' '; }
# the blocks (temperature, displacement) whose -ksp_view shows thermoslide's cycle in any solve
cycled() {
  awk '/temperature block solver/ {b = "temperature"} /displacement block solver/ {b = "displacement"}
       /BoomerAMG V-cycle applied by thermoslide/ {seen[b] = 1}
       END {s = ""; if (seen["temperature"]) s = "temperature"; if (seen["displacement"]) s = s (s ? "+" : "") "displacement"; print s ? s : "none"}' "$1"
}
# run NAME NP DECK BLOCKS-CYCLED OPTIONS...: the default and -tsl_amg_cycle 0, compared
run() {
  name=$1 np=$2 deck=$3 want=$4
  shift 4
  for c in 1 0; do
    $mpiexec -n "$np" "$exe" "$out/$deck.inp" -o "$out/${name}_$c" -ksp_view -tsl_amg_cycle $c "$@" > "$out/${name}_$c.log" 2>&1 ||
      { cat "$out/${name}_$c.log"; exit 1; }
  done
  echo "$name ($np rank(s)): $(its "$out/${name}_1.log")| blocks cycled by thermoslide: $(cycled "$out/${name}_1.log"), with -tsl_amg_cycle 0: $(cycled "$out/${name}_0.log")"
  [ "$(cycled "$out/${name}_1.log")" = "$want" ] || { echo "FAIL: $name: the cycle should be thermoslide's on: $want"; exit 1; }
  [ "$(cycled "$out/${name}_0.log")" = none ] || { echo "FAIL: $name: -tsl_amg_cycle 0 did not keep hypre's cycle"; exit 1; }
  [ -n "$(its "$out/${name}_1.log")" ] || { echo "FAIL: $name: no increment reported"; exit 1; }
  [ "$(its "$out/${name}_1.log")" = "$(its "$out/${name}_0.log")" ] || { echo "FAIL: $name: iterations differ from hypre's cycle"; exit 1; }
  /usr/bin/python3 "$tools/compare_h5.py" "$out/${name}_1/$deck.h5" "$out/${name}_0/$deck.h5" 0 || { echo "FAIL: $name: results differ"; exit 1; }
}
for np in 1 2; do
  run "block_$np" $np block temperature+displacement -tsl_direct_max_dofs 0
  run "contact_$np" $np contact displacement -tsl_partition axis_x
done
run sweeps2 1 block temperature+displacement -tsl_direct_max_dofs 0 -fieldsplit_u_pc_hypre_boomeramg_grid_sweeps_all 2 -fieldsplit_T_pc_hypre_boomeramg_grid_sweeps_all 2
run coarse_jacobi 1 block temperature+displacement -tsl_direct_max_dofs 0 -fieldsplit_u_pc_hypre_boomeramg_relax_type_coarse Jacobi
run ssor 1 block temperature -tsl_direct_max_dofs 0 -fieldsplit_u_pc_hypre_boomeramg_relax_type_all symmetric-SOR/Jacobi
echo "PASS"
