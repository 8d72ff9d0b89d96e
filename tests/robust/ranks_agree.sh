#!/bin/bash
# Results that do not depend on the number of ranks: each deck runs on 1 rank and on NP ranks, and the HDF5
# results must agree to TOL (compare_h5.py: relative to each field's largest value; FLOORS, e.g. RF=1e3, for
# fields that are round-off). Used for ranks that hold no element (a model with no more elements than ranks puts
# one element on each of the first ranks and nothing on the others, src/mesh/distribute.c; they must still take
# part in every collective call) and for more ranks than the 2 of the rest of the suite (contact exchanges with
# several neighbours).
# usage: ranks_agree.sh THERMOSLIDE MPIEXEC OUTDIR TOOLS DECK:NP:TOL[:FLOORS] ... [-- OPTIONS for every run]
set -u
exe=$1 mpiexec=$2 out=$3 tools=$4
shift 4
specs=() opts=()
while [ $# -gt 0 ] && [ "$1" != -- ]; do specs+=("$1"); shift; done
[ $# -gt 0 ] && shift && opts=("$@")
rm -rf "$out" && mkdir -p "$out" || exit 1
fail=0
for spec in "${specs[@]}"; do
  IFS=: read -r deck np tol floors <<< "$spec"
  b=$(basename "$deck" .inp) dir=$(dirname "$deck")
  for n in 1 "$np"; do
    if ! (cd "$dir" && timeout 300 $mpiexec -n "$n" "$exe" "$b.inp" -o "$out/${b}_np$n" "${opts[@]}" > "$out/${b}_np$n.log" 2>&1); then
      tail -5 "$out/${b}_np$n.log"
      echo "$b on $n ranks: FAIL (the run)"
      fail=1
      continue 2
    fi
  done
  printf "%s, %s ranks against 1: " "$b" "$np"
  /usr/bin/python3 "$tools/compare_h5.py" "$out/${b}_np1/$b.h5" "$out/${b}_np$np/$b.h5" "$tol" $floors | tail -1
  [ "${PIPESTATUS[0]}" = 0 ] || fail=1
done
[ $fail = 0 ] && echo PASS || echo FAIL
exit $fail
