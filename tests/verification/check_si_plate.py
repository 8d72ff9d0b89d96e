#!/usr/bin/python3
"""The SI plate of make_si_plate.py: its mean temperature at every frame against the energy balance of the
whole plate, C (T_n - T_n-1) / dt = q A_q - h A_f (T_n - 20) (backward Euler, as the transient step
integrates it; steady: q A_q = h A_f (T - 20)), within 1e-3 of the rise: the plate's own temperature
differences are of the order of the Biot number, 2e-4 of the rise.
usage: check_si_plate.py OUTDIR JOB transient|steady [HEAT]  (HEAT: the heat unit's factor, transform_deck.py)"""
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, finish

out, job, kind = sys.argv[1:4]
heat = float(sys.argv[4]) if len(sys.argv) > 4 else 1.0
r = Result(out, job)
C = 7850.0 * 460.0 * 0.2 * 0.1 * 0.01 * heat   # J/K (in the deck's heat unit)
Q = 100.0 * 0.1 * 0.01 * heat                 # W into x = 0
G = 0.05 * 0.2 * 0.1 * heat                    # W/K out through the film
rise = Q / G
theta, t_prev, worst = 20.0, 0.0, 0.0
for i in range(len(r.frames)):
    t = float(r.frame(i).attrs["time"])
    if kind == "steady":
        theta = 20.0 + rise
    else:
        dt = t - t_prev
        theta = (theta + dt / C * (Q + G * 20.0)) / (1 + dt * G / C)
        t_prev = t
    worst = max(worst, abs(r.field("NT", i).mean() - theta) / rise)
check("mean temperature against the plate's energy balance at %d frames (worst, / rise %g)" % (len(r.frames), rise), worst, 0.0, 1e-3)
finish()
