#!/usr/bin/python3
"""A free bar (E 1e4, nu 0, rho 1: c = 100; length 1, 50 CPE4T elements, 0.02 x 1 section) given the initial
velocity -v0 = -5 (*INITIAL CONDITIONS, TYPE=VELOCITY) strikes a wall at x = 0 (the wall nodes' dof 1 held by
*BOUNDARY, which wins over their initial velocity). Behind the compression front x < c t the bar is at rest
under the stress -rho c v0 = -500; until the front reaches the free end (t = 0.01) nothing else happens.
Checks:
 - the boundary condition won at the wall: the log says so (2 dofs), U1 = 0 there in every frame, and ALLWK
   stays the initial kinetic energy 1/2 M v0^2 of the free nodes (0.2475: a held node that kept its -5 would
   make the support do work);
 - the energy balance closes (|ETOTAL| < 1e-9 of ALLWK) and ALLVD >= 0 in every row;
 - the mean stress behind the front at the last frame (0.1 < x < c t - 0.1) is -rho c v0 (2 %);
 - the peak overshoot max(-S11) / (rho c v0) - 1 over the elements and frames is printed; with a reference
   run (the same deck with b2 = 0, whose output lies beside this one: OUTDIR with JOB replaced by REF_JOB, so
   the run on as many ranks) it must be at most 0.6 of the reference's, with more viscous work.
usage: check_impact.py OUTDIR JOB [REF_JOB]
"""
import os
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, check_true, finish

RHO, C, V0, MASS = 1.0, 100.0, 5.0, 0.02


def overshoot(r):
    peak = max((-r.field("S", i)[:, 0]).max() for i in range(len(r.frames)))
    return peak / (RHO * C * V0) - 1


outdir, job = sys.argv[1:3]
r = Result(outdir, job)
log = open(outdir + ".log").read()
check_true("log: the wall's prescribed dofs keep their boundary condition", "; 2 prescribed dofs keep their boundary condition instead" in log)
x = r.xyz[:, 0]
wall = np.abs(x) < 1e-12
check("largest |U1| at the wall over the frames", max(np.abs(r.field("U", i)[wall, 0]).max() for i in range(len(r.frames))), 0.0, 0.0)
h = r.history
ke0 = 0.5 * MASS * (1 - 0.5 / 50) * V0**2  # the two wall nodes (a quarter of an element each) are held
check("ALLWK = initial kinetic energy of the free nodes (every row)", np.abs(h["ALLWK"] - ke0).max(), 0.0, 1e-12 * ke0)
check("energy balance |ETOTAL| / ALLWK", np.abs(h["ETOTAL"]).max() / ke0, 0.0, 1e-9)
check("smallest ALLVD", min(h["ALLVD"].min(), 0.0), 0.0, 0.0)
t = float(r.frame(-1).attrs["time"])
cells = r.elements()
xc = np.array([x[c].mean() for c in cells])
behind = (xc > 0.1) & (xc < C * t - 0.1)
check("mean S11 behind the front at t = %g (%d elements)" % (t, behind.sum()), r.field("S", -1)[behind, 0].mean(), -RHO * C * V0, 0.02, relative=True)
peak = overshoot(r)
print("peak overshoot of the compressive stress behind the front: %.4f" % peak)
if len(sys.argv) > 3:
    ref_job = sys.argv[3]
    ref_dir = os.path.join(os.path.dirname(outdir), os.path.basename(outdir).replace(job, ref_job))
    ref = Result(ref_dir, ref_job)
    peak_ref = overshoot(ref)
    print("reference (%s): peak overshoot %.4f, ALLVD %.6g" % (ref_dir, peak_ref, ref.history["ALLVD"][-1]))
    check("peak overshoot / the reference's (b2 = 0)", peak / peak_ref, 0.0, 0.6)
    check_true("more viscous work than the reference", h["ALLVD"][-1] > ref.history["ALLVD"][-1],
               "ALLVD %.6g > %.6g" % (h["ALLVD"][-1], ref.history["ALLVD"][-1]))
finish()
