#!/usr/bin/python3
"""Transient conduction into a slab 0 < x < L = 1, initially at 0, face x = 0 held at 100 from t = 0,
x = L insulated; diffusivity kappa = k / (rho c) = 10 / (1000 * 0.001) = 10.

theta(x, t) = 100 [1 - sum_n 4/((2n+1) pi) sin((2n+1) pi x / 2L) exp(-(2n+1)^2 pi^2 kappa t / 4L^2)]
Backward Euler (dt = 5e-4, Fourier step 0.005) on 40 elements: the nodal error is checked at Fourier
numbers ~0.1 and 0.3 with tolerances 1.0 and 0.5 (of 100): backward Euler's O(dt) error is largest
early, when the profile is steep (halving dt halves it); the energy balance residual of every increment is
checked against 1e-6 of the heat stored.
usage: check_conduction_transient.py OUTDIR JOB
"""
import sys

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, finish, slab_series

outdir, job = sys.argv[1:3]
r = Result(outdir, job)
kappa, L = 10.0, 1.0


def exact(x, t):
    return slab_series(x, t, kappa, L)


times = [float(r.frame(i).attrs["time"]) for i in range(len(r.frames))]
for target, tol in ((0.01, 1.0), (0.03, 0.5)):
    i = min(range(len(times)), key=lambda j: abs(times[j] - target))
    nt = r.field("NT", i)[:, 0]
    err = max(abs(nt[j] - exact(r.xyz[j, 0], times[i])) for j in range(len(nt)))
    check("max nodal error at t = %.4g (Fourier %.2g)" % (times[i], kappa * times[i]), err, 0.0, tol)
stored = abs(r.history["stored_heat_rate"]).max()
check("worst energy balance residual over increments", abs(r.history["balance_residual"]).max(), 0.0, 1e-6 * stored)
finish()
