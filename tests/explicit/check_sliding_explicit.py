#!/usr/bin/python3
"""The spec's sliding series as explicit steps (jobs/verification/sliding_*_explicit_*_cpe4t.inp, written by
make_decks.py --explicit; docs/explicit.md, "Contact"): a 2 x 0.25 block (node ids > 1000) pressed with 200
on a 6 x 1.25 block fixed at its bottom, rho c = 1, total area 8.

friction (PRESS, SLIDE, EQUILIBRATE): the slide's slip path 6 under mu N = 0.1 x 200 dissipates 120 (ALLFD
and the history's friction_dissipation_total), of which eta = 0.5 heats the blocks: 60 absorbed, and after
the resting step every node at 60 / 8 = 7.5; each within 1 %.
conductance (HEAT, SLIDE, STEADY, DOUBLE PRESSURE, SLIDE OFF): at the end of the long "steady" periods
(steps 3 and 4, transient steps long enough) the film takes out what the flux brings in (200) within 1 %;
after the slide-off the small block is isothermal (spread below 1 % of its mean) and no heat crosses the
interface.
Both: the energy balance ETOTAL = ALLKE + ALLIE + ALLCW - ALLWK - ALLMW within 1e-6 of the largest
energy in every history row; quasi-static: ALLKE against ALLIE and ALLWK printed (the prescribed slide moves
the 500-mass block rigidly, so ALLKE is the block's 1/2 M v^2 and ALLIE, the elastic energy of blocks
pressed by 100 with E = 3e7, is tiny: the figure that tells inertia did not matter is the kinetic energy left
when the slide has stopped, checked below 1 % of the frictional work).
usage: check_sliding_explicit.py OUTDIR JOB friction|conductance
"""
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, check_true, finish

outdir, job, series = sys.argv[1:4]
r = Result(outdir, job)
h, ids = r.history, r.node_ids
small = ids > 1000


def last_row(step):
    return np.nonzero(h["step"] == step)[0][-1]


scale = max(abs(h[k]).max() for k in ("ALLKE", "ALLIE", "ALLWK", "ALLCW"))
check("energy balance |ETOTAL| over all rows / largest energy", abs(h["ETOTAL"]).max() / scale, 0.0, 1e-6)
moving = h["ALLIE"] > 0
print("quasi-static: largest ALLKE %.4g, ALLIE at that row %.4g (ALLKE / ALLIE %.3g), largest ALLKE / ALLWK %.3g"
      % (h["ALLKE"].max(), h["ALLIE"][np.argmax(h["ALLKE"])], h["ALLKE"].max() / max(h["ALLIE"][np.argmax(h["ALLKE"])], 1e-300),
         (h["ALLKE"][moving] / np.maximum(abs(h["ALLWK"][moving]), 1e-300)).max()))

if series == "friction":
    s2 = last_row(2)
    print("at the end of the slide: ALLKE %.4g ALLIE %.4g ALLWK %.4g ALLFD %.6g ALLCW %.6g" % tuple(h[k][s2] for k in ("ALLKE", "ALLIE", "ALLWK", "ALLFD", "ALLCW")))
    check("kinetic energy left when the slide has stopped / ALLFD", h["ALLKE"][s2] / h["ALLFD"][s2], 0.0, 0.01)
    check("frictional dissipation ALLFD after the slide", h["ALLFD"][s2], 120.0, 0.01, relative=True)
    check("frictional dissipation, end of the job", h["friction_dissipation_total"][-1], 120.0, 0.01, relative=True)
    check("heat absorbed by the blocks (eta = 0.5)", h["friction_heat_total"][-1], 60.0, 0.01, relative=True)
    nt = r.field("NT")[:, 0]
    check("final temperature, coldest node (60 / 8)", nt.min(), 7.5, 0.01, relative=True)
    check("final temperature, hottest node (60 / 8)", nt.max(), 7.5, 0.01, relative=True)
    finish()

for step in (3, 4):
    i = last_row(step)
    print("step %d end: heat in %.6g, film heat out %.6g, interface %.6g, stored %.4g" % (step, h["heat_in"][i], h["film_heat_out"][i], h["interface_heat"][i], h["stored_heat_rate"][i]))
    check("step %d (steady period) film heat out = flux in" % step, h["film_heat_out"][i], h["heat_in"][i], 0.01, relative=True)
    check("step %d flux in (100 x 2)" % step, h["heat_in"][i], 200.0, 1e-6, relative=True)
nt = r.field("NT")[:, 0][small]
check("slide-off: small block isothermal, spread / mean", (nt.max() - nt.min()) / abs(nt.mean()), 0.0, 0.01)
check("slide-off: heat across the interface / 200", abs(h["interface_heat"][-1]) / 200.0, 0.0, 1e-6)
check_true("slide-off: every secondary node open", abs(r.field("CPRESS")[:, 0]).max() == 0.0, "largest CPRESS %g" % abs(r.field("CPRESS")[:, 0]).max())
finish()
