#!/bin/bash
# A deck on a mesh from Gmsh, as a user builds it: gmsh meshes GEO (GMSH_OPTIONS, e.g. "-2 -setnumber ORDER 2"), writing
# MESH (its .msh, or with "-format inp" Gmsh's own Abaqus export), jobs/tools/gmsh2inp.py turns it into OUT/mesh.inp
# (TOOL_OPTIONS), the deck DECK (which *INCLUDEs mesh.inp) is copied to OUT/JOB.inp and run on NP ranks, then CHECK
# reads OUT/JOB.h5 (CHECK_ARGS after OUT JOB).
# usage: run_gmsh_case.sh EXE MPIEXEC NP GEO "GMSH_OPTIONS" MESHNAME "TOOL_OPTIONS" DECK OUT JOB CHECK [CHECK_ARGS...]
set -eu
exe=$1 mpiexec=$2 np=$3 geo=$4 gopts=$5 meshname=$6 topts=$7 deck=$8 out=$9 job=${10} check=${11}
shift 11
root=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$out" && mkdir -p "$out"
# shellcheck disable=SC2086
gmsh $gopts "$geo" -o "$out/$meshname" > "$out/gmsh.log" 2>&1 || { cat "$out/gmsh.log"; exit 1; }
# shellcheck disable=SC2086
/usr/bin/python3 "$root/jobs/tools/gmsh2inp.py" "$out/$meshname" "$out/mesh.inp" $topts
cp "$deck" "$out/$job.inp"
rc=0
"$mpiexec" -n "$np" "$exe" "$out/$job.inp" -o "$out" > "$out/$job.log" 2>&1 || rc=$?
cat "$out/$job.log"
[ $rc -eq 0 ] || exit $rc
/usr/bin/python3 "$check" "$out" "$job" "$@"
