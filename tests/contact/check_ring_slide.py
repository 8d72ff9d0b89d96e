#!/usr/bin/python3
"""The friction section as rings at r = 1000 (decks/make_ring_decks.py; issue 44, item 7): the job completed (the
caller checks the exit code), the small ring stayed on the large one (no node moved by more than the slide, 1.5,
and a little: a ring thrown 1e10 away in a Newton step had "converged" before), and the friction series' answer:
  dissipation mu F x 6 = 0.2 x 100 x 2 pi (1003) x 2 x 6 = 1 512 488.4 (the history's friction_dissipation_total,
  relative 1e-4: measured -2.9e-6 to -5.4e-6 over the types and meshes; the interface carries the axial load
  whole, and the slip path is the drive's, less the small ring's elastic shear at the reversals),
  absorbed = eta x dissipation (1e-9: the same sum),
  final temperature uniform (spread 1e-3 of the mean) and equal to absorbed / (rho c V) = 15 x dissipation /
  1 512 488.4, V = 2 pi (1003) 8 (1e-4).
With a reference run (REFDIR REFJOB: the full-integration CAX4T on the same mesh), the dissipation and the final
temperatures agree with it to 1e-5 (measured 8e-7).
usage: check_ring_slide.py OUTDIR JOB [REFDIR REFJOB]
"""
import math
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, check_true, finish

outdir, job = sys.argv[1:3]
r = Result(outdir, job)
h = r.history
force = 100.0 * 2 * math.pi * 1003.0 * 2.0
expected = 0.2 * force * 6.0
diss = h["friction_dissipation_total"][-1]
heat = h["friction_heat_total"][-1]
check("%s dissipation (mu F x slip path 6)" % job, diss, expected, 1e-4, relative=True)
check("%s absorbed heat / dissipation (eta)" % job, heat / diss, 0.5, 1e-9, relative=True)
check_true("%s completed the equilibration step" % job, int(h["step"][-1]) == 3 and abs(h["step_time"][-1] - 20.0) < 1e-9,
           "last row: step %d at step time %g" % (int(h["step"][-1]), h["step_time"][-1]))
U = r.field("U")
umax = np.abs(U[:, :2]).max()
check_true("%s largest displacement at the end below 1.6 (the slide's 1.5 and the rings' deformation)" % job, umax < 1.6, "%.6g" % umax)
umax_all = max(np.abs(r.field("U", i)[:, :2]).max() for i in range(len(r.frames)))
check_true("%s largest displacement in any frame below 1.6" % job, umax_all < 1.6, "%.6g" % umax_all)
nt = r.field("NT")[:, 0]
check("%s final temperature spread / mean" % job, (nt.max() - nt.min()) / nt.mean(), 0.0, 1e-3)
check("%s final mean temperature (absorbed / rho c V)" % job, nt.mean(), heat / (2 * math.pi * 1003.0 * 8.0), 1e-4, relative=True)
if len(sys.argv) > 4:
    ref = Result(sys.argv[3], sys.argv[4])
    check("%s dissipation against %s's" % (job, sys.argv[4]), diss, ref.history["friction_dissipation_total"][-1], 1e-5, relative=True)
    check("%s final mean temperature against %s's" % (job, sys.argv[4]), nt.mean(), ref.field("NT")[:, 0].mean(), 1e-5, relative=True)
finish()
