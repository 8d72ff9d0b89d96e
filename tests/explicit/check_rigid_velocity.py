#!/usr/bin/python3
"""A free, unloaded block with a uniform initial velocity v (*INITIAL CONDITIONS, TYPE=VELOCITY) translates
rigidly: u = v t at every node of every frame (1e-10 relative to |v| t), the temperatures stay where they
started, the kinetic energy is 1/2 M |v|^2 in every history row (1e-10 relative; M = rho V), no internal or
viscous energy appears (1e-10 of it) and the balance closes (the initial kinetic energy is booked as work
done before the step, so ETOTAL starts at zero).
usage: check_rigid_velocity.py OUTDIR JOB VX VY VZ MASS THETA
"""
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, finish

outdir, job = sys.argv[1:3]
v = np.array([float(a) for a in sys.argv[3:6]])
mass, theta = float(sys.argv[6]), float(sys.argv[7])
r = Result(outdir, job)
speed = np.linalg.norm(v)
worst, worst_t = 0.0, 0.0
for i in range(len(r.frames)):
    t = float(r.frame(i).attrs["time"])
    if t <= 0:
        continue
    u = r.field("U", i)[:, :3]
    err = np.abs(u - v[None, : u.shape[1]] * t).max() / (speed * t)
    if err >= worst:
        worst, worst_t = err, t
check("largest |u - v t| / (|v| t) over the nodes and frames (worst at t = %g)" % worst_t, worst, 0.0, 1e-10)
check("time of the last frame", float(r.frame(-1).attrs["time"]), 0.1, 1e-12, relative=True)
check("largest |NT - theta_0| at the last frame", np.abs(r.field("NT", -1) - theta).max(), 0.0, 1e-10 * theta)
h = r.history
ke = 0.5 * mass * speed**2
check("largest |ALLKE - 1/2 M v^2| / (1/2 M v^2) over %d rows" % len(h["ALLKE"]), np.abs(h["ALLKE"] - ke).max() / ke, 0.0, 1e-10)
check("largest |ALLIE| / ALLKE", np.abs(h["ALLIE"]).max() / ke, 0.0, 1e-10)
check("largest |ALLVD| / ALLKE", np.abs(h["ALLVD"]).max() / ke, 0.0, 1e-10)
check("largest strain energy / ALLKE", np.abs(h["strain_energy"]).max() / ke, 0.0, 1e-10)
check("ALLWK (the initial kinetic energy, done before the step) / ALLKE", h["ALLWK"][-1] / ke, 1.0, 1e-10, relative=True)
check("energy balance |ETOTAL| / ALLKE", np.abs(h["ETOTAL"]).max() / ke, 0.0, 1e-10)
finish()
