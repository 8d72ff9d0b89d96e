#!/usr/bin/python3
"""Temperature-dependent material tables (jobs/verification/conduction_tables_cpe4t.inp, see
make_decks.temperature_tables):
  step 1  steady conduction with k(theta) = 10 + 0.2 theta: nodal temperatures on the Kirchhoff profile
          10 theta + 0.1 theta^2 = 2000 x (worst error < 1e-3 of 100; the element quadrature of k(theta)
          is not exact), heat through the bar RFL = 2000 x 0.1 = 200 (1e-3)
  step 2  a flux 500 x area 0.1 for 1 s into an insulated bar with c(theta) = 1 + theta / 200: the heat
          stored from the nodal temperatures, sum rho V_a (e(theta_a) - e(theta_a at the start)) with
          e(theta) = theta + theta^2 / 400 up to 200 and 300 + 2 (theta - 200) beyond (c keeps its last
          value; the bar ends near 335) and V_a the lumped nodal areas, = 50 (1e-5 relative: what the Newton
          floor leaves, each increment's temperature residual below 1e-8 of the job's largest (step 1's, 5.7e3),
          summed over the bar's 82 nodes and the step's 1 s: sqrt(82) x 5.7e-5 x 1 / 50 = 1e-5; measured
          2e-8, 1e-13 before the increments started from the extrapolated state, whose last Newton step lands
          nearer the floor)
usage: check_tables.py OUTDIR JOB
"""
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, finish

outdir, job = sys.argv[1:3]
r = Result(outdir, job)
x = r.xyz[:, 0]
f1 = r.frame_of_step(1)
nt1 = r.field("NT", f1)[:, 0]
exact = (-10 + np.sqrt(100 + 800 * x)) / 0.2
check("step 1 nodal temperature vs the Kirchhoff profile, worst", float(np.max(np.abs(nt1 - exact))), 0.0, 0.1)
rfl = r.field("RFL", f1)[:, 0]
check("step 1 heat entering at theta = 100 (RFL, x = 1)", float(rfl[np.abs(x - 1) < 1e-12].sum()), 200.0, 1e-3, relative=True)

nt2 = r.field("NT")[:, 0]
cell = 0.025 * 0.1
ncell = np.where((np.abs(x) < 1e-12) | (np.abs(x - 1) < 1e-12), 1, 2)
va = ncell * cell / 4
e = lambda t: np.where(t <= 200.0, t + t * t / 400.0, 300.0 + 2.0 * (t - 200.0))  # c constant beyond the table
check("step 2 heat stored with c(theta) (from NT) = flux x area x time", float(np.sum(va * (e(nt2) - e(nt1)))), 50.0, 1e-5, relative=True)
finish()
