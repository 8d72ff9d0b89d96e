#!/usr/bin/python3
"""Compares thermoslide's displacements (or temperatures) with CalculiX's printed ones (a .dat file, e.g. the .dat.ref
that CalculiX's test decks come with): the last frame of the HDF5 against the last "displacements" ("temperatures")
block of the .dat (the nodes it prints). Prints the largest difference relative to the largest printed |u| (for NT:
relative to the largest printed |T - T_ref|, T_ref the smallest printed temperature, so that the comparison does not
depend on the temperature scale's origin) and fails above TOL.
usage: compare_ccx_dat.py RESULT.h5 CALCULIX.dat TOL [U|NT]"""
import sys

import h5py
import numpy as np

h5, dat, tol = sys.argv[1], sys.argv[2], float(sys.argv[3])
field = sys.argv[4] if len(sys.argv) > 4 else "U"
header = {"U": "displacements", "NT": "temperatures"}[field]
with h5py.File(h5, "r") as f:
    ids = {int(n): i for i, n in enumerate(f["mesh/node_ids"][:])}
    last = sorted(f["frames"])[-1]
    u = f["frames"][last][field][:]
blocks, cur = [], None
for line in open(dat):
    if header in line:
        cur = {}
        blocks.append(cur)
        continue
    p = line.split()
    if cur is None or not p:
        continue
    if p[0].isdigit() and len(p) >= (2 if field == "NT" else 3):
        cur[int(p[0])] = np.array([float(x) for x in p[1:]])
    else:
        cur = None
if not blocks or not blocks[-1]:
    sys.exit(f"FAIL: no {header} printed in {dat}")
ref = blocks[-1]
base = min(v.min() for v in ref.values()) if field == "NT" else 0.0
scale = max(np.abs(v - base).max() for v in ref.values())
diff = max(np.abs(u[ids[n]][: len(v)] - v).max() for n, v in ref.items())
rel = diff / scale if scale > 0 else diff
print(f"{len(ref)} nodes: largest |{'T - T_min' if field == 'NT' else 'u'}| {scale:.6g}, largest difference {diff:.3g}, relative {rel:.3g} (tolerance {tol:g})")
sys.exit(0 if rel <= tol else 1)
