#!/usr/bin/python3
"""A bar stretched statically by 0.001 (implicit step 1), released free-free (explicit step 2): the
elongation e(t) = u(x = L) - u(x = 0) is periodic with the fundamental period 2 L / c = 0.02 (c = 100, the
bar speed; nu = 0). The period is measured between the first and third zero crossings of e(t) in the frames
(every 2e-4) and checked within 1 %; the amplitude returns to 0.001 after one period (5 %: the peak of the triangle wave is a corner that the mesh's dispersion rounds, 2.5 % low with 100 elements); the energy
balance closes (|ETOTAL| < 1e-6 of the strain energy released) and no momentum appears (rigid motion of
the centre below 1e-3 of the stretch).
usage: check_vibration.py OUTDIR JOB
"""
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, finish

outdir, job = sys.argv[1:3]
r = Result(outdir, job)
L, c, d0 = 1.0, 100.0, 0.001
x = r.xyz[:, 0]
left, right = np.isclose(x, 0.0), np.isclose(x, L)
idx = [i for i in range(len(r.frames)) if int(r.frame(i).attrs["step"]) == 2]
t = np.array([float(r.frame(i).attrs["time"]) for i in idx]) - 1.0
e = np.array([r.field("U", i)[right, 0].mean() - r.field("U", i)[left, 0].mean() for i in idx])
cross = [t[k] - e[k] * (t[k + 1] - t[k]) / (e[k + 1] - e[k]) for k in range(len(e) - 1) if e[k] * e[k + 1] < 0]
check("zero crossings of the elongation found", len(cross), 3, 0.5)
if len(cross) >= 3:
    check("period between the first and third crossing", cross[2] - cross[0], 2 * L / c, 0.01, relative=True)
k = int(np.argmin(abs(t - 2 * L / c)))
check("elongation after one period (t = %g)" % t[k], e[k], d0, 0.05, relative=True)
centre = np.array([r.field("U", i)[:, 0].mean() for i in idx])
check("rigid motion of the centre / stretch", abs(centre - centre[0]).max() / d0, 0.0, 1e-3)
h = r.history
step2 = h["step"] == 2
check("energy balance |ETOTAL| / strain energy released", abs(h["ETOTAL"][step2]).max() / h["ALLWK"][step2].max(), 0.0, 1e-6)
finish()
