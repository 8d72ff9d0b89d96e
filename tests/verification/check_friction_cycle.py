#!/usr/bin/python3
"""sliding_friction_cycle_{lagrange,penalty}_cpe4t (issue 8, items 7 and 8): the friction series' blocks
under a pressure of 75 (normal force 150 on area 2), mu = 0.2, slid +1.25, -2.5, +1.25 over step 2
(amplitude breakpoints at 1 and 3 s), then left to equilibrate (adiabatic, rho c = 1, area 8).

Frictional dissipation = mu * p * area * slip path. The path the solver sees is the one between its
increments: an increment that straddles a reversal of the amplitude moves the block by the net amount
only, so the path is taken from the increments' step times (printed next to the continuous path 5).
  lagrange  all relative motion dissipates: mu p A path within 0.1 %
  penalty   the elastic slip of each stick phase (at most SLIP TOLERANCE 0.005 x facet 0.5 = 2.5e-3,
            five times over: start, two reversals of 2 x 2.5e-3) stores energy instead: between
            -1 % and 0 of mu p A path (the spec: the automatic penalty under-estimates by about 0.7 %)
Heat absorbed = eta (0.5) x dissipation (1e-6); final temperatures uniform = absorbed / 8 (0.1 %);
energy balance of every increment within 1e-6 of the largest heat rate.
usage: check_friction_cycle.py OUTDIR JOB lagrange|penalty
"""
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, check_true, finish

outdir, job, law = sys.argv[1:4]
r = Result(outdir, job)
h = r.history
mu, force = 0.2, 75.0 * 2.0

t = np.concatenate([[0.0], h["step_time"][h["step"] == 2]])
u = 1.25 * np.interp(t, [0.0, 1.0, 3.0, 4.0], [0.0, 1.0, -1.0, 0.0])
path = float(np.abs(np.diff(u)).sum())
print("slip path between increments %.6g (continuous 5), %d increments in step 2" % (path, len(t) - 1))
expected = mu * force * path
dissipated = h["friction_dissipation_total"][-1]
if law == "lagrange":
    check("frictional dissipation = mu p A path", dissipated, expected, 1e-3, relative=True)
else:
    check_true("frictional dissipation within [-1 %, 0] of mu p A path (penalty elastic slip)", 0.99 * expected <= dissipated <= expected * (1 + 1e-6),
               "%.6g vs %.6g (%.3f %%)" % (dissipated, expected, 100 * (dissipated / expected - 1)))
check("heat absorbed = 0.5 x dissipation", h["friction_heat_total"][-1], 0.5 * dissipated, 1e-6, relative=True)
nt = r.field("NT")[:, 0]
check("final temperature, coldest node = absorbed / 8", nt.min(), h["friction_heat_total"][-1] / 8.0, 1e-3, relative=True)
check("final temperature, hottest node = absorbed / 8", nt.max(), h["friction_heat_total"][-1] / 8.0, 1e-3, relative=True)
scale = max(abs(h["friction_dissipation_rate"]).max(), 1e-300)
check("worst energy balance residual over all increments", abs(h["balance_residual"]).max(), 0.0, 1e-6 * scale)
finish()
