#!/usr/bin/python3
"""The collapsed patch against the proper one and against the exact answer (make_decks.py).

Both meshes pass the patch test: U and NT at every node are the boundary's linear fields (the free centre node
too), E and HFL are uniform (the strain given, -k grad theta with k = 50), and the two meshes' S, E and HFL agree
element by element to round-off (the same elements in the same order). Tolerances: 1e-12 relative to the
fields' scale.
usage: check_collapsed.py PROPER_OUTDIR PROPER_JOB COLLAPSED_OUTDIR COLLAPSED_JOB 2d|3d|ax
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from tslcheck import Result, check, finish

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_decks import fields  # noqa: E402  (the decks' fields)

pdir, pjob, cdir, cjob, variant = sys.argv[1:6]
dim = 3 if variant == "3d" else 2
STRAIN, GRAD = fields(variant)
proper, collapsed = Result(pdir, pjob), Result(cdir, cjob)
for name, r in (("proper", proper), ("collapsed", collapsed)):
    x = r.xyz[:, :dim]
    u, nt = r.field("U")[:, :dim], r.field("NT").reshape(-1)
    uex = x @ np.array(STRAIN)[:dim, :dim].T
    tex = 10 + x @ np.array(GRAD[:dim])
    check("%s: max |U - exact| / 1e-3" % name, float(np.max(np.abs(u - uex))) / 1e-3, 0.0, 1e-12)
    check("%s: max |NT - exact| / 10" % name, float(np.max(np.abs(nt - tex))) / 10, 0.0, 1e-12)
    hfl = r.field("HFL")[:, :dim]
    check("%s: max |HFL + k grad theta| / 250" % name, float(np.max(np.abs(hfl + 50 * np.array(GRAD[:dim])))) / 250, 0.0, 1e-12)
    if variant == "ax":  # the hoop strain u_r / r = c at every point, the axis too
        check("%s: max |E33 - c| / 1e-3" % name, float(np.max(np.abs(r.field("E")[:, 2] - STRAIN[0][0]))) / 1e-3, 0.0, 1e-12)
    eps = r.field("E")
    check("%s: max |E11 - 1e-3| / 1e-3" % name, float(np.max(np.abs(eps[:, 0] - STRAIN[0][0]))) / 1e-3, 0.0, 1e-12)
for f in ("S", "E", "HFL"):
    a, b = proper.field(f), collapsed.field(f)
    scale = max(float(np.max(np.abs(a))), 1e-30)
    check("%s: collapsed against proper, max difference / max |%s|" % (f, f), float(np.max(np.abs(a - b))) / scale, 0.0, 1e-12)
finish()
