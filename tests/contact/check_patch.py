#!/usr/bin/python3
"""Contact patch test (decks/make_patch_decks.py): a uniform pressure 100 and a uniform heat flux through a
non-matching interface (5 vs 3 CPE4T across). Surface-to-surface (OUTDIR_S2S): CPRESS at every secondary
node, S22 in every element of both blocks, HFLA at every secondary node and the heat flux HFL2 in every
element of both blocks uniform and equal to the exact values (100, 1428.571...) within 1e-8 relative; the
heat across the interface equals q x its area. Node-to-surface on the same deck (OUTDIR_N2S) cannot do this:
its worst errors are printed, and the test requires them to be above 1e-3 (the point of the option).
The 3D decks (C3D8T, 3 x 3 vs 4 x 5 across an interface of area 1) are checked the same way; NSEC is the
number of secondary nodes on the interface (4 in 2D, the default; 30 in 3D). AREA is the interface's area
(default 1; the CAX4T rings of make_patch_decks.py --axi: 3 pi = 9.42477796...).
usage: check_patch.py OUTDIR_S2S JOB_S2S OUTDIR_N2S JOB_N2S [NSEC [AREA]]
"""
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, check_true, finish

Q = 100.0 / (0.5 / 50 * 2 + 1 / 20.0)  # k = 50 over 0.5 in each block, gap conductance 20: 1428.571...


AREA = float(sys.argv[6]) if len(sys.argv) > 6 else 1.0


def errors(outdir, job):
    r = Result(outdir, job)
    ids, xyz = r.node_ids, r.xyz
    sec = [i for i in range(len(ids)) if ids[i] > 1000 and abs(xyz[i, 1] - 0.5) < 1e-12]
    cp, q = r.field("CPRESS")[:, 0], r.field("HFLA")[:, 0]
    s, hfl = r.field("S"), r.field("HFL")
    return (len(sec), float(np.max(np.abs(cp[sec] - 100.0))) / 100.0, float(np.max(np.abs(s[:, 1] + 100.0))) / 100.0,
            float(np.max(np.abs(q[sec] + Q))) / Q, float(np.max(np.abs(hfl[:, 1] + Q))) / Q, abs(r.history["interface_heat"][-1] + Q * AREA) / (Q * AREA))


s2s = errors(*sys.argv[1:3])
n2s = errors(*sys.argv[3:5])
nsec = int(sys.argv[5]) if len(sys.argv) > 5 else 4
check_true("secondary nodes on the interface (%d)" % nsec, s2s[0] == nsec, "(%d)" % s2s[0])
names = ["CPRESS at the secondary nodes", "S22 in both blocks", "HFLA at the secondary nodes", "heat flux HFL2 in both blocks",
         "heat across the interface"]
for k, name in enumerate(names):
    print("%s, worst relative error: surface-to-surface %.3g, node-to-surface %.3g" % (name, s2s[k + 1], n2s[k + 1]))
    check("surface-to-surface: %s, worst relative error" % name, s2s[k + 1], 0.0, 1e-8)
check_true("node-to-surface does not transmit the uniform pressure (worst CPRESS error > 1e-3)", n2s[1] > 1e-3, "(%.3g)" % n2s[1])
finish()
