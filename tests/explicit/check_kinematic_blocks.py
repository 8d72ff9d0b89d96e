#!/usr/bin/python3
"""3D kinematic contact in an explicit step (decks/kinematic_blocks_c3d8t.inp: a 0.1-thick C3D8T block
pressed by 100 onto a base block, MECHANICAL CONSTRAINT=KINEMATIC, gap conductance on pressure; docs/explicit.md):
- the energy balance closes (|ETOTAL| below 1e-6 of the largest energy in every history row);
- the kinematic contact does no net positive work beyond the scheme's error (ALLCW >= -1e-6 of the largest
  energy in every row: closing a gap removes the approach velocity; with the gaps closed to round-off the first
  touch books a small negative work that is first order in the increment, -6.7e-9 / -4.3e-9 / -2.4e-9 / -1.2e-9
  at -tsl_explicit_safety 0.9 / 0.45 / 0.225 / 0.1125, 2.2e-7 of the largest energy at the default, while the
  step's ALLCW itself moves by 7e-4 between the first two of those increments: docs/explicit.md, open problem 3);
- no secondary node in contact (CPRESS > 0) penetrates the base's top face (interpolated bilinearly over the
  base's top nodes, a structured grid in x and z) by more than 1e-8: the corrector's passes close the rough
  penetration of this impact within the increment (docs/explicit.md, "Kinematic contact"; measured: none,
  every node within 1e-7 above the face; one pass left 4.5e-6 at the block's corners, and the deck's
  penalty would allow p_max / eps_n = 1.1e-3).
usage: check_kinematic_blocks.py OUTDIR JOB
"""
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, check_true, finish

r = Result(*sys.argv[1:3])
h = r.history
scale = max(abs(h[k]).max() for k in ("ALLKE", "ALLIE", "ALLWK", "ALLCW"))
check("energy balance |ETOTAL| over all rows / largest energy", abs(h["ETOTAL"]).max() / scale, 0.0, 1e-6)
check_true("contact work ALLCW >= -1e-6 of the largest energy in every row", (h["ALLCW"] >= -1e-6 * scale).all(),
           "smallest %g (%.2g of the largest energy)" % (h["ALLCW"].min(), h["ALLCW"].min() / scale))

xyz, u, cp = r.xyz, r.field("U"), r.field("CPRESS")[:, 0]
sec = np.nonzero(cp > 0)[0]
y0 = xyz[sec[0], 1]
top = np.nonzero((abs(xyz[:, 1] - y0) < 1e-9) & (cp == 0) & ~np.isin(np.arange(len(cp)), sec))[0]
xs, zs = np.unique(np.round(xyz[top, 0], 9)), np.unique(np.round(xyz[top, 2], 9))
Y = np.full((len(xs), len(zs)), np.nan)
for n in top:
    Y[np.searchsorted(xs, round(xyz[n, 0], 9)), np.searchsorted(zs, round(xyz[n, 2], 9))] = xyz[n, 1] + u[n, 1]
pen = []
for n in sec:
    x, z = xyz[n, 0] + u[n, 0], xyz[n, 2] + u[n, 2]
    i = min(max(np.searchsorted(xs, x) - 1, 0), len(xs) - 2)
    k = min(max(np.searchsorted(zs, z) - 1, 0), len(zs) - 2)
    a, b = (x - xs[i]) / (xs[i + 1] - xs[i]), (z - zs[k]) / (zs[k + 1] - zs[k])
    ym = (1 - a) * (1 - b) * Y[i, k] + a * (1 - b) * Y[i + 1, k] + (1 - a) * b * Y[i, k + 1] + a * b * Y[i + 1, k + 1]
    pen.append(ym - (xyz[n, 1] + u[n, 1]))
print("%d secondary nodes in contact, CPRESS %.4g .. %.4g; base top face: %d x %d nodes" % (len(sec), cp[sec].min(), cp[sec].max(), len(xs), len(zs)))
check("largest penetration", max(max(pen), 0.0), 0.0, 1e-8)
finish()
