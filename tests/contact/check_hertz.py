#!/usr/bin/python3
"""Hertz line contact (decks/make_hertz_deck.py): the contact pressure CPRESS along the punch's arc against the
closed form for the force the job transmits. P (per unit thickness, the whole contact: twice the half model's)
is the reaction of the driven top, -2 sum RF_x there; with two bodies of one steel, plane strain,
E* = E / (2 (1 - nu^2)), the half-width is a = sqrt(4 P R / (pi E*)) and the peak p0 = 2 P / (pi a).
Measured: p0 the CPRESS at y = 0, a from the second moment of the pressure over the secondary nodes,
a^2 = 4 int p y^2 dy / int p dy (exact for the elliptic distribution p0 sqrt(1 - y^2/a^2): insensitive to where
between two nodes the pressure ends), and the force the pressure carries, 2 int p dy, against P.
Tolerances (stated in docs/verification.md): 3 % for a and p0 (the mesh, 0.1 mm at the contact for a of about
1 mm, the finite bodies and the penalty's compliance 1 / K against the elastic a / E*: 1 %), 0.5 % for the
force balance.
usage: check_hertz.py OUTDIR JOB
"""
import math
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, finish

R, E, NU = 50.0, 210000.0, 0.3
r = Result(sys.argv[1], sys.argv[2])
ids, xyz = r.node_ids, r.xyz
rf, cp = r.field("RF"), r.field("CPRESS")[:, 0]
top = [i for i in range(len(ids)) if ids[i] > 10000 and abs(xyz[i, 0] - 50.0) < 1e-9]
P = -2.0 * float(np.sum(rf[top, 0]))
arc = sorted([i for i in range(len(ids)) if ids[i] > 10000 and abs(xyz[i, 0] - 30.0 - (R - math.sqrt(R * R - xyz[i, 1] ** 2))) < 1e-9],
             key=lambda i: xyz[i, 1])
y, p = xyz[arc, 1], cp[arc]
estar = E / (2.0 * (1.0 - NU * NU))
a = math.sqrt(4.0 * P * R / (math.pi * estar))
p0 = 2.0 * P / (math.pi * a)
m0, m2 = np.trapz(p, y), np.trapz(p * y * y, y)
print("force P %.6g N/mm, Hertz: a %.6g mm, p0 %.6g MPa; measured a %.6g, p0 %.6g" % (P, a, p0, math.sqrt(4 * m2 / m0), p[0]))
check("Hertz half-width a (mm)", math.sqrt(4.0 * m2 / m0), a, 0.03 * a)
check("Hertz peak pressure p0 (MPa)", float(p[0]), p0, 0.03 * p0)
check("force carried by CPRESS (N/mm)", 2.0 * m0, P, 0.005 * P)
finish()
