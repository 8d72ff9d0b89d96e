#!/usr/bin/python3
"""Checks of the plasticity decks (make_decks.py):

uniaxial   at every frame the axial stress, plastic strain and PEEQ against the 1D Mises model with isotropic
           hardening sigma_y = 200 + 1000 p driven by the frame's axial strain (the pulled face's displacement over the
           unit length): for piecewise-linear hardening the radial return is exact, so 1e-8 of the yield stress; the
           other stress components below 1e-8 of it
adiabatic  no heat leaves: the final uniform temperature = 0.9 ALLPD / (rho c V) (1e-8), ALLPD = int sigma_y dp at the
           final PEEQ (1e-8; the _soft deck: the stress at the end is the table's yield stress at the final PEEQ and
           temperature, 1e-8, and ALLPD lies between the integrals of the cold and the hot curves)
uniaxial_kinematic, adiabatic_kinematic  the same with linear kinematic hardening (C = 1000): the 1D surface |sigma - a|
           = 200 moved by the back stress a = C eps_p (the reverse yield at a - 200, the Bauschinger offset)
usage: check.py OUTDIR JOB uniaxial[_kinematic]|adiabatic[_kinematic]|adiabatic_soft AXIS"""
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, check_true, finish

outdir, job, case, axis = sys.argv[1:5]
r = Result(outdir, job)
axis = int(axis)  # 0: x (3D), 1: z (the ring)
E, S0, H, RHO, C = 200000.0, 200.0, 1000.0, 1.0, 2.0
sy = lambda p: S0 + H * min(p, 0.5)
coord = r.xyz[:, axis]
pulled = np.isclose(coord, coord.max())
frames = range(len(r.frames))

if case in ("uniaxial", "uniaxial_kinematic"):
    kin = case == "uniaxial_kinematic"
    eps_p, p, a, worst, worst_other, iso = 0.0, 0.0, 0.0, 0.0, 0.0, [0.0, 0.0]
    for k in frames:
        eps = float(r.field("U", k)[pulled, axis].mean()) / (coord.max() - coord.min())
        trial = E * (eps - eps_p)
        if kin:  # the surface |sigma - a| = S0 moved by a = H eps_p (H = 1000 the back stress's modulus C)
            if abs(trial - a) > S0:
                dp = (abs(trial - a) - S0) / (E + H)
                eps_p += np.sign(trial - a) * dp
                a += H * np.sign(trial - a) * dp
                p += dp
        elif abs(trial) > sy(p):  # 1D return: |trial| - E dp = sigma_y(p + dp), linear in dp below p = 0.5
            dp = (abs(trial) - sy(p)) / (E + H)
            eps_p += np.sign(trial) * dp
            p += dp
        s = E * (eps - eps_p)
        t = E * (eps - iso[0])  # the isotropic model beside it: how far the kinematic answer is from it
        if abs(t) > sy(iso[1]):
            dq = (abs(t) - sy(iso[1])) / (E + H)
            iso = [iso[0] + np.sign(t) * dq, iso[1] + dq]
        S, PE, PQ = r.field("S", k)[0], r.field("PE", k)[0], r.field("PEEQ", k)[0, 0]
        worst = max(worst, abs(S[axis] - s) / S0, abs(PE[axis] - eps_p) * E / S0, abs(PQ - p) * E / S0)
        worst_other = max(worst_other, max(abs(S[c]) for c in range(6) if c != axis) / S0)
    print("%d frames, final strain %.4g, stress %.6g, PEEQ %.6g" % (len(r.frames), eps, s, p))
    check("stress, plastic strain and PEEQ against the 1D model, worst (of sigma_y0)", worst, 0.0, 1e-8)
    check("the other stress components, worst (of sigma_y0)", worst_other, 0.0, 1e-8)
    check_true("loading, unloading and reverse yield all seen", p > 0.02 and eps < 0, "PEEQ %.4g" % p)
    if kin:  # the Bauschinger offset: the reverse yield at a - S0, so the end differs from the isotropic answer
        si = E * (eps - iso[0])
        print("back stress %.6g; final stress %.6g (isotropic hardening: %.6g)" % (a, s, si))
        check_true("the kinematic answer is not the isotropic one (Bauschinger offset)", abs(s - si) > 0.05 * S0, "%.6g vs %.6g" % (s, si))
else:
    h = r.history
    theta = r.field("NT", -1)[:, 0]
    V = 1.0 if axis == 0 else np.pi * ((11.0) ** 2 - 10.0 ** 2)
    allpd = float(h["ALLPD"][-1])
    check("the temperature is uniform (spread of the mean)", float(np.ptp(theta) / abs(theta.mean())), 0.0, 1e-10)
    check("final temperature = 0.9 ALLPD / (rho c V)", float(theta.mean()), 0.9 * allpd / (RHO * C * V), 1e-8, relative=True)
    pq = float(r.field("PEEQ", -1)[0, 0])
    if case in ("adiabatic", "adiabatic_kinematic"):  # monotone: int (S0 + C p) dp as with the isotropic line
        check("ALLPD = int sigma_y dp at the final PEEQ", allpd, (S0 * pq + 0.5 * H * pq * pq) * V, 1e-8, relative=True)
    else:  # sigma_y = (1 - w) (200 + 1000 p) + w (100 + 500 p), w = theta / 50
        w = theta.mean() / 50.0
        q = float(np.sqrt(0.5 * ((lambda s: (s[0] - s[1]) ** 2 + (s[1] - s[2]) ** 2 + (s[2] - s[0]) ** 2 + 6 * (s[3] ** 2 + s[4] ** 2 + s[5] ** 2))(r.field("S", -1)[0]))))
        check("Mises stress at the end = the table's yield stress at the final PEEQ and temperature", q, (1 - w) * (200 + 1000 * pq) + w * (100 + 500 * pq), 1e-8,
              relative=True)
        check_true("ALLPD between the integrals of the hot and the cold curves", 0.5 * (100 * pq + 250 * pq * pq) <= allpd <= 200 * pq + 500 * pq * pq,
                   "%.6g" % allpd)
    print("final PEEQ %.6g, temperature %.6g, ALLPD %.6g" % (pq, theta.mean(), allpd))
finish()
