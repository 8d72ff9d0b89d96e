#!/bin/bash
# Decks we did not write: CalculiX's restart pair (package calculix-ccx-test). beamwrite.inp (a cantilever,
# NLGEOM static step, *RESTART, WRITE, FREQUENCY=1) runs; beamread.inp (*RESTART, READ, STEP=1 and a second step
# loading the free end, *NODE FILE and *EL FILE without data lines) continues it with -oldjob. The second step's
# displacements must equal CalculiX's own (beamread.dat.ref, its last displacement table) within TOL of the largest.
# usage: restart_calculix_beam.sh THERMOSLIDE MPIEXEC NP OUTDIR PYTHON TOL
set -u
exe=$1 mpiexec=$2 np=$3 out=$4 py=$5 tol=$6
ccx=/usr/share/doc/calculix-ccx-test/examples/test
rm -rf "$out" && mkdir -p "$out" || exit 1
zcat "$ccx/beamwrite.inp.gz" > "$out/beamwrite.inp" || exit 1
$mpiexec -n "$np" "$exe" "$out/beamwrite.inp" -o "$out/w" > "$out/w.log" 2>&1 || { cat "$out/w.log"; echo "FAIL: beamwrite"; exit 1; }
$mpiexec -n "$np" "$exe" "$ccx/beamread.inp" -oldjob "$out/w/beamwrite" -o "$out/r" > "$out/r.log" 2>&1 || { cat "$out/r.log"; echo "FAIL: beamread"; exit 1; }
"$py" - "$out/r/beamread.h5" "$ccx/beamread.dat.ref.gz" "$tol" << 'PY'
import gzip, sys
import h5py
import numpy as np
f = h5py.File(sys.argv[1], "r")
frames = f["frames"]
last = frames[sorted(frames)[-1]]
if int(last.attrs["step"]) != 2 or "U" not in last:
    sys.exit("FAIL: the last frame is step %d with %s, expected step 2 with U" % (int(last.attrs["step"]), sorted(last)))
U, pos = np.asarray(last["U"]), {n: k for k, n in enumerate(np.asarray(f["mesh/node_ids"]))}
lines = gzip.open(sys.argv[2], "rt").read().splitlines()
i = [k for k, l in enumerate(lines) if "displacements" in l][-1]
ref = {}
for l in lines[i + 2:]:
    p = l.split()
    if len(p) != 4:
        break
    ref[int(p[0])] = np.array([float(x) for x in p[1:]])
umax = max(np.max(np.abs(v)) for v in ref.values())
d = max(np.max(np.abs(U[pos[n]] - v)) for n, v in ref.items()) / umax
ok = d <= float(sys.argv[3])
print("beamread step 2: %d nodes' displacements against CalculiX's: largest difference %.3e of the largest %.6g (tolerance %s) %s"
      % (len(ref), d, umax, sys.argv[3], "PASS" if ok else "FAIL"))
sys.exit(0 if ok else 1)
PY
