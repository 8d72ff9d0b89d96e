#!/usr/bin/python3
"""Uniform heating by dT = 100 (alpha = 1e-5, E = 30e6, nu = 0.3), free or fully constrained.

free:        zero stress; strain alpha dT in every direction (plane strain: in-plane (1+nu) alpha dT,
             E33 = 0, S33 = -E alpha dT since the out-of-plane strain is held at zero)
constrained: S11 = S22 = S33 = -E alpha dT / (1 - 2 nu) (plane strain, axisymmetric, 3D);
             plane stress S11 = S22 = -E alpha dT / (1 - nu), S33 = 0, E33 = alpha dT (1 + nu)/(1 - nu)
             (the free out-of-plane strain); other strains zero
Tolerances: 1e-8 relative to E alpha dT for stress, 1e-10 absolute for strain (exact for these elements).
usage: check_expansion.py OUTDIR JOB TYPE free|constrained
"""
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
finish()
