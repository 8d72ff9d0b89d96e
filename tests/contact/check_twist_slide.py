#!/usr/bin/python3
"""Frictional sliding with circumferential slip (decks/contact_twist_slide_*, make_decks.py): an inner ring
pressed on an outer one (interface r = 1.25, LAGRANGE friction mu = 0.1, eta = 0.5) and driven by a slide
of magnitude 1 at the interface: axially, circumferentially (phi = 0.8) or both (0.6 axial, 0.8
circumferential).

  every job   energy balance of every increment (1e-6 of the largest dissipation rate); heat absorbed
              = eta x dissipation (1e-3)
  twist       the interface force N = sum CPRESS x area (area of a secondary node: its tributary length on
              the interface times 2 pi 1.25; trapezoid weights for line2 faces, Simpson for line3), averaged
              over the frames of the slide; dissipation = mu N x circumferential path 1.25 x 0.8 (0.5 %)
  twist, combined  the accumulated slip CSLIP (length of the slip vector) of every secondary node = 1
              (0.5 %). (The twist and its moment reaction are not among the outputs yet, so the moment on
              the held face is not checked.)
  axial       dissipation = mu N x 1 (0.5 %)
  combined    the slip magnitude is the axial job's: heat generated = the axial job's (0.5 %)

usage: check_twist_slide.py OUTDIR_AXIAL JOB_AXIAL OUTDIR_TWIST JOB_TWIST OUTDIR_COMBINED JOB_COMBINED
"""
import re
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, finish

MU, ETA, RC, PHI = 0.1, 0.5, 1.25, 0.8
jobs = dict(zip(("axial", "twist", "combined"), (Result(sys.argv[1 + 2 * k], sys.argv[2 + 2 * k]) for k in range(3))))
quadratic = bool(re.search(r"_cgax[68]", sys.argv[2]))


def normal_force(r):
    """Mean over the slide's frames of sum CPRESS x area over the secondary nodes (inner ring, r = 1.25)."""
    ids, xyz = r.node_ids, r.xyz
    sec = sorted([i for i in range(len(ids)) if ids[i] > 1000 and abs(xyz[i, 0] - RC) < 1e-9], key=lambda i: xyz[i, 1])
    dz = xyz[sec[-1], 1] - xyz[sec[0], 1]
    n = len(sec)
    if quadratic:
        w = np.array([1.0 if k in (0, n - 1) else (4.0 if k % 2 else 2.0) for k in range(n)]) * dz / (3 * (n - 1))
    else:
        w = np.array([0.5 if k in (0, n - 1) else 1.0 for k in range(n)]) * dz / (n - 1)
    frames = [i for i, f in enumerate(r.frames) if int(r.h5["/frames/" + f].attrs["step"]) == 2]
    forces = [float(np.sum(r.field("CPRESS", i)[sec, 0] * w) * 2 * np.pi * RC) for i in frames]
    print("interface force N over the slide: %.6g to %.6g" % (min(forces), max(forces)))
    return float(np.mean(forces))


for name, r in jobs.items():
    h = r.history
    scale = max(abs(h["friction_dissipation_rate"]).max(), 1e-300)
    check("%s: worst energy balance residual over all increments" % name, abs(h["balance_residual"]).max(), 0.0, 1e-6 * scale)
    check("%s: heat absorbed = eta x dissipation" % name, h["friction_heat_total"][-1], ETA * h["friction_dissipation_total"][-1], 1e-3, relative=True)

r = jobs["twist"]
N = normal_force(r)
dis = r.history["friction_dissipation_total"][-1]
check("twist: dissipation = mu N x circumferential path 1.25 x 0.8", dis, MU * N * RC * PHI, 5e-3, relative=True)
for name in ("twist", "combined"):
    r = jobs[name]
    sec = [i for i in range(len(r.node_ids)) if r.node_ids[i] > 1000 and abs(r.xyz[i, 0] - RC) < 1e-9]
    cslip = r.field("CSLIP")[sec, 0]
    check("%s: accumulated slip CSLIP of every secondary node, smallest = path 1" % name, cslip.min(), 1.0, 5e-3, relative=True)
    check("%s: accumulated slip CSLIP of every secondary node, largest = path 1" % name, cslip.max(), 1.0, 5e-3, relative=True)

r = jobs["axial"]
N = normal_force(r)
check("axial: dissipation = mu N x axial path 1", r.history["friction_dissipation_total"][-1], MU * N * 1.0, 5e-3, relative=True)
check("combined (0.6 axial, 0.8 circumferential): heat = the axial job's", jobs["combined"].history["friction_heat_total"][-1],
      jobs["axial"].history["friction_heat_total"][-1], 5e-3, relative=True)
finish()
