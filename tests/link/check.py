#!/usr/bin/python3
"""Checks of the link decks (make_decks.py): steady (theta = 100 s / L, RFL = -25 and +25), source (theta = q s (L - s)
/ (2 k), the ends' RFL = -q A L in all), fin (the far node's RFL = -k A theta_j / 2, the sum of RFL zero); every
temperature 1e-9 of its scale. usage: check.py OUTDIR JOB steady|source|fin"""
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, finish

out, job, case = sys.argv[1:4]
r = Result(out, job)
K, A, L = 50.0, 0.01, 2.0
T, R = r.field("NT")[:, 0], r.field("RFL")[:, 0]
if case in ("steady", "source"):
    s = np.linalg.norm(r.xyz - r.xyz[np.argmin(r.node_ids)], axis=1)
    want = 100 * s / L if case == "steady" else 1000.0 * s * (L - s) / (2 * K)
    check("theta along the link against the closed form, worst / scale", float(np.abs(T - want).max() / np.abs(want).max()), 0.0, 1e-9)
    if case == "steady":
        check("heat in at the hot end (RFL)", float(R.max()), K * A * 100 / L, 1e-9, relative=True)
        check("heat out at the cold end (RFL)", float(R.min()), -K * A * 100 / L, 1e-9, relative=True)
    else:
        check("heat out at the ends = q A L", float(R.sum()), -1000.0 * A * L, 1e-9, relative=True)
else:
    j, far = list(r.node_ids).index(6), list(r.node_ids).index(20)
    check("heat through the fin = k A theta_j / 2", float(R[far]), -K * A * T[j] / 2.0, 1e-9, relative=True)
    check("sum of RFL (steady, no other heat)", float(R.sum()), 0.0, 1e-9 * float(np.abs(R).max()))
finish()
