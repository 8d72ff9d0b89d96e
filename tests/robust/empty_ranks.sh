#!/bin/bash
# Ranks that hold no element: a model with no more elements than ranks puts one element on each of the first
# ranks and nothing on the others (src/mesh/distribute.c), which must still take part in every collective call
# (assembly, contact exchange, solver, output) and change nothing. Each deck runs on 1 rank and on NP ranks; the
# HDF5 results must agree to TOL (compare_h5.py: relative to each dataset's largest value).
# usage: empty_ranks.sh THERMOSLIDE MPIEXEC OUTDIR TOOLS DECK:NP:TOL...
set -u
exe=$1 mpiexec=$2 out=$3 tools=$4
shift 4
rm -rf "$out" && mkdir -p "$out" || exit 1
fail=0
for spec in "$@"; do
  deck=${spec%%:*} rest=${spec#*:} np=${spec#*:} np=${np%%:*} tol=${rest#*:}
  b=$(basename "$deck" .inp) dir=$(dirname "$deck")
  for n in 1 "$np"; do
    if ! (cd "$dir" && timeout 300 $mpiexec -n "$n" "$exe" "$b.inp" -o "$out/${b}_np$n" > "$out/${b}_np$n.log" 2>&1); then
      tail -5 "$out/${b}_np$n.log"
      echo "$b on $n ranks: FAIL (the run)"
      fail=1
      continue 2
    fi
  done
  printf "%s, %s ranks against 1: " "$b" "$np"
  /usr/bin/python3 "$tools/compare_h5.py" "$out/${b}_np1/$b.h5" "$out/${b}_np$np/$b.h5" "$tol" | tail -1
  [ "${PIPESTATUS[0]}" = 0 ] || fail=1
done
[ $fail = 0 ] && echo PASS || echo FAIL
exit $fail
