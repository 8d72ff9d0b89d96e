#!/bin/sh
# Parts and instances (docs/keywords.md): the spec's friction and conductance series rewritten the way
# Abaqus/CAE writes a model (tests/tools/to_parts.py: two parts numbered from 1, the second stored moved and
# put back by its instance's translation and 90-degree rotation, sets and node labels qualified by the
# instances, a set over both instances in the assembly) must be the flat deck's model: its fields equal the
# flat deck's run to 1e-8 (friction, 1 rank) and 1e-6 (conductance, 2 ranks with the pair split; the flat
# run on 1), node and element ids aside (the second part's ids follow the first part's, not 1001...), and the
# friction series passes its checks. No warning on either parts deck.
# The flat decks' runs are the verification tests' own (FLATDIR/sliding_<series>_cpe4t_np1, their fixtures).
# usage: check_parts.sh THERMOSLIDE MPIEXEC OUTDIR TOOLSDIR JOBSDIR CHECKSDIR FLATDIR
set -u
exe=$1 mpiexec=$2 out=$3 tools=$4 jobs=$5 checks=$6 flat=$7
rm -rf "$out" && mkdir -p "$out" || exit 1
for series in friction conductance; do
  np=1 tol=1e-8
  [ $series = conductance ] && np=2 tol=1e-6
  /usr/bin/python3 "$tools/to_parts.py" "$jobs/sliding_${series}_cpe4t.inp" "$out/parts_$series.inp" || exit 1
  $mpiexec -n $np "$exe" "$out/parts_$series.inp" -o "$out/parts_$series" -tsl_partition axis_y > "$out/parts_$series.log" 2>&1 ||
    { cat "$out/parts_$series.log"; exit 1; }
  grep -i "warning" "$out/parts_$series.log" && { echo "FAIL: a warning on the parts deck"; exit 1; }
  /usr/bin/python3 "$tools/compare_h5.py" "$flat/sliding_${series}_cpe4t_np1/sliding_${series}_cpe4t.h5" "$out/parts_$series/parts_$series.h5" $tol \
    skip=mesh/node_ids skip=mesh/element_ids || { echo "FAIL: the parts deck ($series) is not the flat deck's model"; exit 1; }
done
/usr/bin/python3 "$checks/check_sliding.py" "$out/parts_friction" parts_friction friction || exit 1
echo "PASS"
