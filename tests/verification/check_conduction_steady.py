#!/usr/bin/python3
"""Steady 1D conduction: theta = 100 at the inner face, film h = 50 (sink 0) at the outer face, k = 10.

Plane and 3D (x from 0 to 1): theta(x) = 100 - q x / k, q = 100 / (1/k + 1/h); bilinear/trilinear
elements reproduce a linear field exactly, so nodal values must match to solver tolerance (1e-6).
Axisymmetric (r from 1 to 2): theta = 100 + B ln r, B = -h*100 / (k/ro + h ln ro); the total heat
2 pi k |B| H is checked to 1e-3 (discretisation of the log profile), nodal values to 0.1 (of 100).
In every case the heat entering through the prescribed temperatures must leave through the film:
reaction heat = film heat out to 1e-8 relative, and the balance residual vanishes.
usage: check_conduction_steady.py OUTDIR JOB TYPE
"""
import math
import sys

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, finish

outdir, job, typ = sys.argv[1:4]
r = Result(outdir, job)
nt = r.field("NT")[:, 0]
k, h, H = 10.0, 50.0, 0.2
if typ == "CAX4T":
    ri, ro = 1.0, 2.0
    B = -h * 100.0 / (k / ro + h * math.log(ro / ri))
    exact = [100.0 + B * math.log(x / ri) for x in r.xyz[:, 0]]
    err = max(abs(a - b) for a, b in zip(nt, exact))
    check("max nodal error vs log profile", err, 0.0, 0.1)
    Q = -2.0 * math.pi * k * B * H
    check("total heat through the cylinder", r.history["film_heat_out"][-1], Q, 1e-3, relative=True)
else:
    q = 100.0 / (1.0 / k + 1.0 / h)
    exact = [100.0 - q * x / k for x in r.xyz[:, 0]]
    err = max(abs(a - b) for a, b in zip(nt, exact))
    check("max nodal error vs linear profile", err, 0.0, 1e-6)
    area = H * (0.2 if typ == "C3D8T" else 1.0)
    check("film heat out = q * area", r.history["film_heat_out"][-1], q * area, 1e-8, relative=True)
    hfl = r.field("HFL")[:, 0]
    check("element heat flux HFL1 = q (worst element)", max(abs(x - q) for x in hfl), 0.0, 1e-6 * q)
check("reaction heat = film heat out", r.history["reaction_heat"][-1], r.history["film_heat_out"][-1], 1e-8, relative=True)
check("energy balance residual", r.history["balance_residual"][-1], 0.0, 1e-8 * abs(r.history["film_heat_out"][-1]))
finish()
