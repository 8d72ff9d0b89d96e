#!/usr/bin/python3
"""Uniform heating by dT = 100 (alpha = 1e-5, E = 30e6, nu = 0.3), free or fully constrained.

free:        zero stress; strain alpha dT in every direction (plane strain: in-plane (1+nu) alpha dT,
             E33 = 0, S33 = -E alpha dT since the out-of-plane strain is held at zero)
constrained: S11 = S22 = S33 = -E alpha dT / (1 - 2 nu) (plane strain, axisymmetric, 3D);
             plane stress S11 = S22 = -E alpha dT / (1 - nu), S33 = 0, E33 = alpha dT (1 + nu)/(1 - nu)
             (the free out-of-plane strain); other strains zero
The history's strain energy (one implicit element pass with the heat balance, docs/running.md) equals
1/2 sigma : eps_mech V: constrained 3 s0 alpha dT / (2 (1 - 2 nu)) per unit volume (plane stress s0 alpha dT /
(1 - nu)), free 0 (plane strain s0 alpha dT / 2 from the held out-of-plane strain), over V = 1 (the unit
square or cube, thickness 1) or 2 pi 1.5 (the axisymmetric ring r in [1, 2], z in [0, 1], the full circumference).
Tolerances: 1e-8 relative to E alpha dT for stress, 1e-10 absolute for strain, 1e-10 relative for the energy
(exact for these elements).
usage: check_expansion.py OUTDIR JOB TYPE free|constrained
"""
import math
import sys

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, finish

outdir, job, typ, kind = sys.argv[1:5]
r = Result(outdir, job)
E, nu, a, dT = 30.0e6, 0.3, 1.0e-5, 100.0
s0 = E * a * dT
S, Eps = r.field("S"), r.field("E")
if kind == "free":
    if typ == "CPE4T":
        es, ss = [(1 + nu) * a * dT] * 2 + [0.0], [0.0, 0.0, -s0]
    elif typ == "CPS4T":
        es, ss = [a * dT] * 2, [0.0, 0.0, 0.0]
    else:
        es, ss = [a * dT] * 3, [0.0, 0.0, 0.0]
else:
    es = [0.0, 0.0, a * dT * (1 + nu) / (1 - nu) if typ == "CPS4T" else 0.0]
    ss = [-s0 / (1 - nu)] * 2 + [0.0] if typ == "CPS4T" else [-s0 / (1 - 2 * nu)] * 3
for c, v in enumerate(ss):
    check("S%d%d (worst element)" % (c + 1, c + 1), max(S[:, c], key=lambda x: abs(x - v)), v, 1e-8 * s0)
for c, v in enumerate(es):
    check("E%d%d (worst element)" % (c + 1, c + 1), max(Eps[:, c], key=lambda x: abs(x - v)), v, 1e-10)
check("S12 (worst element)", max(abs(S[:, 3])), 0.0, 1e-8 * s0)
vol = 3 * math.pi if typ == "CAX4T" else 1.0
if kind == "free":
    density = 0.5 * s0 * a * dT if typ == "CPE4T" else 0.0
else:
    density = s0 * a * dT / (1 - nu) if typ == "CPS4T" else 1.5 * s0 * a * dT / (1 - 2 * nu)
check("strain energy in the history (last row)", r.history["strain_energy"][-1], density * vol, 1e-10 * 1.5 * s0 * a * dT / (1 - 2 * nu) * vol)
finish()
