#!/usr/bin/python3
"""box.inp on a Gmsh mesh: S11 = -100, S22 = S33 = S12 = 0, u1 = -100 x / E and theta = 50 x / k at every node and
point, to 1e-8 of the field's scale (the patch-test solution is exact in every family: a wrong node order, face
label or orientation from gmsh2inp.py breaks it). usage: check_box.py OUTDIR JOB"""
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, finish

E, k, p, q = 30.0e6, 10.0, 100.0, 50.0  # u1 = -p L / E on HOT (L = 2)
r = Result(*sys.argv[1:3])
x = r.xyz[:, 0]
check("nodes on the box (x extent)", float(x.max() - x.min()), 2.0, 1e-12)
check("theta - q x / k, worst (relative to q L / k)", float(np.abs(r.field("NT").ravel() - q * x / k).max()) / (q * 2 / k), 0.0, 1e-8)
u = r.field("U")
check("u1 + p x / E, worst (relative to p L / E)", float(np.abs(u[:, 0] + p * x / E).max()) / (p * 2 / E), 0.0, 1e-8)
s = r.field("S")
check("S11 + p, worst (relative to p)", float(np.abs(s[:, 0] + p).max()) / p, 0.0, 1e-8)
check("S22, S33, S12, S13, S23, worst (relative to p)", float(np.abs(s[:, 1:]).max()) / p, 0.0, 1e-8)
finish()
