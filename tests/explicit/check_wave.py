#!/usr/bin/python3
"""Step load F on the end of a free bar (explicit): behind the front u(x, t) = v (t - x / c), with the
bar speed c = sqrt(E / rho) = 100 (nu = 0: the plane-strain dilatational speed is the same) and the
particle velocity v = F / (rho c A) = 1 (F = 1, A = 0.01 x 1). A straight line fitted to u(x) at the last
frame (t = 0.007) over 0.05 < x < 0.55, away from the load point and the front's ringing, gives the
front position x_f = c t where it reaches zero, so c = x_f / t (tolerance 2 %) and v from its slope
(2 %). The energy balance closes (|ETOTAL| < 1e-6 max energy), kinetic and strain energy share the
work equally (1/2 of ALLWK each, 2 %), ALLIE is the elements' strain energy (3 %: ALLIE lags the state by half an increment and the front rings).
With a mass scale factor s (third argument, default 1) the speed is c / sqrt(s) and v = F / (s rho c' A).
usage: check_wave.py OUTDIR JOB [MASS_SCALE]
"""
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, finish

outdir, job = sys.argv[1:3]
r = Result(outdir, job)
E, rho, F, A = 1.0e4, 1.0 * (float(sys.argv[3]) if len(sys.argv) > 3 else 1.0), 1.0, 0.01
c, v = (E / rho) ** 0.5, F / (rho * (E / rho) ** 0.5 * A)
t = float(r.frame(-1).attrs["time"])
x, u = r.xyz[:, 0], r.field("U", -1)[:, 0]
sel = (x > 0.05) & (x < 0.8 * c * t - 0.05)
slope, icpt = np.polyfit(x[sel], u[sel], 1)
check("front speed from the displacement profile at t = %g" % t, -icpt / slope / t, c, 0.02, relative=True)
check("particle velocity behind the front", -slope * c, v, 0.02, relative=True)
h = r.history
emax = max(h["ALLWK"].max(), 1e-30)
check("energy balance |ETOTAL| / max ALLWK", abs(h["ETOTAL"]).max() / emax, 0.0, 1e-6)
check("ALLKE / ALLWK at the end", h["ALLKE"][-1] / h["ALLWK"][-1], 0.5, 0.02, relative=True)
check("ALLIE against the elements' strain energy", h["ALLIE"][-1], h["strain_energy"][-1], 0.03, relative=True)
finish()
