#!/usr/bin/python3
"""Explicit transient conduction (forward Euler, lumped capacity) in the slab of
jobs/verification/conduction_transient_cpe4t.inp, against the series solution and against the implicit
(backward Euler) run of that deck: kappa = 10, face x = 0 held at 100 from t = 0, x = 1 insulated.
Checks: nodal error against the series at t = 0.01 and 0.03 (0.5 and 0.3 of 100: the mesh's error only,
the explicit increment is 40x below the implicit one); the explicit and the implicit temperatures at
t = 0.03 agree within 1 % of the 100 range (backward Euler's O(dt) error: 0.5 at most there); the heat
balance of every history row closes (heat in through the prescribed face = heat stored, 1e-9 relative).
usage: check_conduction.py OUTDIR JOB IMPLICIT_OUTDIR IMPLICIT_JOB
"""
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, finish, slab_series

outdir, job, idir, ijob = sys.argv[1:5]
r, ri = Result(outdir, job), Result(idir, ijob)
kappa, L = 10.0, 1.0


def exact(x, t):
    return slab_series(x, t, kappa, L)


times = [float(r.frame(i).attrs["time"]) for i in range(len(r.frames))]
for target, tol in ((0.01, 0.5), (0.03, 0.3)):
    i = min(range(len(times)), key=lambda j: abs(times[j] - target))
    nt = r.field("NT", i)[:, 0]
    err = max(abs(nt[j] - exact(r.xyz[j, 0], times[i])) for j in range(len(nt)))
    check("explicit: max nodal error against the series at t = %.4g" % times[i], err, 0.0, tol)
check("explicit and implicit end times", times[-1], float(ri.frame(-1).attrs["time"]), 1e-12)
diff = abs(r.field("NT", -1)[:, 0] - ri.field("NT", -1)[:, 0]).max()
check("explicit - implicit temperatures at t = 0.03 (of 100)", diff, 0.0, 1.0)
h = r.history
check("heat balance: worst |balance| / stored rate", abs(h["balance_residual"]).max() / abs(h["stored_heat_rate"]).max(), 0.0, 1e-9)
finish()
