#!/bin/bash
# Results that do not depend on how the deck numbers its nodes and elements, nor on the order they are held in
# memory (-tsl_mesh_order, src/mesh/distribute.c): each deck runs as written on 1 rank with its elements and nodes
# held in id order (-tsl_mesh_order input), and renumbered at random (tests/tools/renumber_deck.py, every
# reference moved with its node or element) on NP ranks in the default locality order; the HDF5 results, row
# by row of the same node or element, must agree to TOL (compare_h5.py renumbered=; FLOORS as there).
# usage: renumbered.sh THERMOSLIDE MPIEXEC OUTDIR TOOLS DECK:NP:TOL[:FLOORS] ...
set -u
exe=$1 mpiexec=$2 out=$3 tools=$4
shift 4
rm -rf "$out" && mkdir -p "$out" || exit 1
fail=0
for spec in "$@"; do
  IFS=: read -r deck np tol floors <<< "$spec"
  b=$(basename "$deck" .inp) dir=$(dirname "$deck")
  /usr/bin/python3 "$tools/renumber_deck.py" "$deck" "$out/${b}_r.inp" "$out/$b.map" 7 || { echo "$b: FAIL (renumbering)"; fail=1; continue; }
  cp "$dir"/*.inc "$out"/ 2> /dev/null
  if ! (cd "$dir" && timeout 300 $mpiexec -n 1 "$exe" "$b.inp" -o "$out/$b" -tsl_mesh_order input > "$out/$b.log" 2>&1) ||
    ! (cd "$out" && timeout 300 $mpiexec -n "$np" "$exe" "${b}_r.inp" -o "$out/${b}_r" > "$out/${b}_r.log" 2>&1); then
    tail -5 "$out/$b.log" "$out/${b}_r.log"
    echo "$b: FAIL (the run)"
    fail=1
    continue
  fi
  printf "%s renumbered, on %s ranks, against as written on 1: " "$b" "$np"
  /usr/bin/python3 "$tools/compare_h5.py" "$out/$b/$b.h5" "$out/${b}_r/${b}_r.h5" "$tol" $floors "renumbered=$out/$b.map" | tail -1
  [ "${PIPESTATUS[0]}" = 0 ] || fail=1
done
[ $fail = 0 ] && echo PASS || echo FAIL
exit $fail
