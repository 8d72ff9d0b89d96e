#!/bin/bash
# The element catalogue benchmark: one steady coupled solve (make_family_block.py: a 2 x 1 rectangle or
# ring section, a 2 x 1 x 1 block) per representative type of each family and formulation, on a mesh
# refined twice, 1 rank, -log_view. Prints per type and size: elements, dofs, Jacobian assembly and
# residual time per element per evaluation (SNESJacobianEval, SNESFunctionEval: time / count /
# elements), the linear iterations of the one Newton step, and the total time (PETSc's). Then, for the
# quadratic types, the linear iterations with thermoslide's default BoomerAMG options and with two
# alternatives (ST7, AGG0 below) side by side. Figures only, never pass/fail. Takes 3-4 minutes on 1 core.
# usage: bench_elements.sh THERMOSLIDE [OUTDIR] [TYPE...]     (default: every type of the list below)
set -u
exe=$1 out=${2:-$PWD/bench-elements-out}
shift 2 || shift $#
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
rm -f "$out"/*.inp "$out"/*.inp.size "$out"/*.log

# type and its three sizes N (cells 2N x N [x N]): the largest ~1e5 dofs, a few seconds each
sizes_of() {
  case $1 in
    C3D10MT) echo 3 6 12 ;;
    C3D*) echo 6 12 24 ;;
    C*6MT | C*8T) echo 16 32 64 ;;
    *) echo 32 64 128 ;;
  esac
}
types=${*:-CPE3T CPE4T CPE4RT CPE6MT CPE8T CAX4T CAX8T CGAX8T CPEG8T C3D4T C3D6T C3D8T C3D8RT C3D10MT}
quadratic="CPE6MT CPE8T C3D10MT"
# BoomerAMG alternatives for the displacement block, compared with the defaults on the quadratic types
# (docs/running.md): a higher strong threshold (fewer connections count as strong, so more coarse
# points: the fastest in 2D) and no aggressive coarsening (fewest iterations, but operator complexity 2-2.5 instead of 1.2-1.6)
ST7="-fieldsplit_u_pc_hypre_boomeramg_strong_threshold 0.7"
AGG0="-fieldsplit_u_pc_hypre_boomeramg_agg_nl 0"

# parse LOG ELEMS: sets jac res its total from a job log with -log_view
parse() {
  its=$(grep -oE "newton [0-9]+  linear [0-9]+" "$1" | tail -1 | awk '{print $4}')
  total=$(awk '/^Time \(sec\):/ {print $3}' "$1")
  # event line: name count ratio time ...; microseconds per element per evaluation
  jac=$(awk -v e="$2" '$1 == "SNESJacobianEval" {printf "%.2f", 1e6 * $4 / $2 / e}' "$1")
  res=$(awk -v e="$2" '$1 == "SNESFunctionEval" {printf "%.2f", 1e6 * $4 / $2 / e}' "$1")
}

# run TYPE N TAG [options...]: writes the deck (once) and $out/TYPE_N.TAG.log; sets elems dofs jac res its total
run() {
  local typ=$1 n=$2 tag=$3 deck log
  shift 3
  deck=$out/${typ}_$n.inp log=$out/${typ}_$n.$tag.log
  [ -f "$deck" ] || /usr/bin/python3 "$here/make_family_block.py" "$typ" "$n" "$deck" > "$deck.size" || return 1
  read -r elems dofs < "$deck.size"
  if ! mpirun -n 1 "$exe" "$deck" -o "$out/res" -log_view "$@" > "$log" 2>&1; then
    echo "run failed: $log" >&2
    tail -3 "$log" >&2
    return 1
  fi
  parse "$log" "$elems"
}

echo "Steady coupled block, 1 rank: Jacobian and residual evaluation per element (us), linear iterations, total time (s)"
printf "%-8s %5s %8s %8s %8s %8s %6s %8s\n" type N elements dofs jac_us res_us linear time_s
for t in $types; do
  for n in $(sizes_of "$t"); do
    run "$t" "$n" default || continue
    printf "%-8s %5d %8d %8d %8s %8s %6s %8.2f\n" "$t" "$n" "$elems" "$dofs" "$jac" "$res" "$its" "$total"
  done
done

echo
echo "Quadratic types: linear iterations (total time s) with thermoslide's defaults, ST7 = $ST7, AGG0 = $AGG0"
printf "%-8s %5s %8s %14s %14s %14s\n" type N dofs default ST7 AGG0
for t in $quadratic; do
  case " $types " in *" $t "*) ;; *) continue ;; esac
  for n in $(sizes_of "$t"); do
    [ -f "$out/${t}_$n.default.log" ] || run "$t" "$n" default || continue
    read -r elems dofs < "$out/${t}_$n.inp.size"
    parse "$out/${t}_$n.default.log" "$elems"
    d=$(printf "%s (%.2f)" "$its" "$total")
    # shellcheck disable=SC2086
    run "$t" "$n" st7 $ST7 || continue
    s7=$(printf "%s (%.2f)" "$its" "$total")
    # shellcheck disable=SC2086
    run "$t" "$n" agg0 $AGG0 || continue
    printf "%-8s %5d %8d %14s %14s %14s\n" "$t" "$n" "$dofs" "$d" "$s7" "$(printf "%s (%.2f)" "$its" "$total")"
  done
done
