#!/usr/bin/python3
"""Checks of the incompatible-mode decks (make_decks.py):

cantilever KIND  step 1 (end couple M = 1): every tip node's deflection = M L^2 / (2 E' I), exact for the bubbles
                 (a pure-bending field is in their space), 1e-6; step 2 (tip shear P = 1): the tip's mean
                 deflection against Timoshenko's P L^3 / (3 E' I) + P L / (5/6 G A) within 1 %. E' = E / (1 - nu^2)
                 in plane strain, E otherwise (3D sides free). KIND locks (the full-integration C3D8): both
                 deflections below 0.7 of that (0.65 measured: shear locking), the bubbles' work shown by the contrast.
patch KIND       every element's S equal to D (A_sym - eps_th I) and E to A_sym (in-plane) within 1e-9 of |S|
usage: check.py OUTDIR JOB cantilever|cantilever_locks|patch strain|stress|3d|axi"""
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
sys.path.insert(0, sys.path[0])
from tslcheck import Result, check, check_true, finish
from make_decks import A, ALPHA, DT, E, NU

outdir, job, case, kind = sys.argv[1:5]
r = Result(outdir, job)
G = E / (2 * (1 + NU))
if case.startswith("cantilever"):
    L, h, M, P = 10.0, 1.0, 1.0, 1.0
    Ep = E / (1 - NU * NU) if kind == "strain" else E
    I = h ** 3 / 12
    x = r.xyz[:, 0]
    tip = np.isclose(x, L)
    couple = -M * L * L / (2 * Ep * I)  # the top fibres stretched: the tip goes down
    shear = P * L ** 3 / (3 * Ep * I) + P * L / (5.0 / 6.0 * G * h)
    v1 = r.field("U", r.frame_of_step(1))[tip, 1]
    v2 = r.field("U", r.frame_of_step(2))[tip, 1].mean()
    print("tip deflection / beam: couple %.6f, shear %.6f" % (v1.mean() / couple, v2 / shear))
    if case == "cantilever":
        check("end couple: every tip node's deflection / M L^2 / (2 E' I), worst", float(np.abs(v1 / couple - 1).max()), 0.0, 1e-6)
        check("tip shear: deflection / Timoshenko", float(v2 / shear), 1.0, 0.01)
    else:
        check_true("the full-integration brick locks: couple deflection below 0.7 of the beam's", v1.mean() / couple < 0.7, "%.4f" % (v1.mean() / couple))
        check_true("and the shear deflection", v2 / shear < 0.7, "%.4f" % (v2 / shear))
else:
    lam, mu = E * NU / ((1 + NU) * (1 - 2 * NU)), G
    eth = ALPHA * DT
    if kind == "axi":  # (r, z, theta): u_r = A00 r, u_z = A11 z
        eps = np.array([A[0][0], A[1][1], A[0][0], 0, 0, 0])
    else:
        d = 3 if kind == "3d" else 2
        Am = np.zeros((3, 3))
        Am[:d, :d] = np.array(A)[:d, :d]
        eps = np.array([Am[0, 0], Am[1, 1], Am[2, 2], Am[0, 1] + Am[1, 0], Am[0, 2] + Am[2, 0], Am[1, 2] + Am[2, 1]])
    em = eps - eth * np.array([1, 1, 1, 0, 0, 0])
    if kind == "stress":  # sigma_33 = 0: eps_33 free
        em[2] = -NU / (1 - NU) * (em[0] + em[1])
        eps[2] = em[2] + eth
    tr = em[:3].sum()
    s = np.array([lam * tr + 2 * mu * em[0], lam * tr + 2 * mu * em[1], lam * tr + 2 * mu * em[2], mu * em[3], mu * em[4], mu * em[5]])
    S, Ee = r.field("S"), r.field("E")
    scale = np.abs(s).max()
    print("expected S", s)
    check("every element's S - D (A_sym - eps_th I), worst / |S|", float(np.abs(S - s).max() / scale), 0.0, 1e-9)
    check("every element's E - A_sym (11, 22, 12), worst / |E|", float(np.abs(Ee[:, [0, 1, 3]] - eps[[0, 1, 3]]).max() / np.abs(eps).max()), 0.0, 1e-9)
finish()
