#!/usr/bin/python3
"""A model moved by (DX, DY) and re-expressed in a length unit SCALE times smaller (transform_deck.py: N, m
-> kN, mm with SCALE = 1000, energy, time and temperature units unchanged) must give the same answer:

  U / SCALE = U of the reference, NT equal, CPRESS * SCALE^3 equal   (last frame of every step)
  frictional dissipation and heat totals, interface heat, film heat out equal (per increment history)

within RTOL of each field's largest value (1- vs 2-rank agreement of penalty contact is 1e-6: the Newton
residual stops at the round-off floor, so two equivalent runs agree to that level and not to 1e-12).
With HEAT and FORCE (transform_deck.py: heat numbers times HEAT, force numbers times FORCE) the
CPRESS, dissipation and heat totals of the re-expressed run are divided by them before the comparison.
usage: check_invariance.py REF_OUTDIR REF_JOB OUTDIR JOB DX DY SCALE RTOL [HEAT FORCE]
"""
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, check_true, finish

ref_dir, ref_job, out_dir, job = sys.argv[1:5]
dx, dy, s, rtol = (float(v) for v in sys.argv[5:9])
heat, force = (float(v) for v in sys.argv[9:11]) if len(sys.argv) > 10 else (1.0, 1.0)
a, b = Result(ref_dir, ref_job), Result(out_dir, job)

order_a, order_b = np.argsort(a.node_ids), np.argsort(b.node_ids)
check_true("same nodes", np.array_equal(a.node_ids[order_a], b.node_ids[order_b]))
moved = a.xyz[order_a, :2] * s + np.array([dx, dy])
check("coordinates moved and scaled as asked (worst, relative)", np.abs(b.xyz[order_b, :2] - moved).max() / np.abs(moved).max(), 0.0, 1e-14)

steps = sorted(set(int(v) for v in a.history["step"]))
fields = tuple(f for f in (("U", 1.0 / s), ("NT", 1.0), ("CPRESS", s**3 / force)) if f[0] in a.frame(a.frame_of_step(steps[0])))  # no CPRESS without contact
# each field against its largest value over the run (a step where a field is still round-off, like the
# temperatures before any heat, would otherwise compare noise with noise)
largest = {n: max(np.abs(a.field(n, a.frame_of_step(st))).max() for st in steps) for n, f in fields}
for step in steps:
    fa, fb = a.frame_of_step(step), b.frame_of_step(step)
    for name, factor in fields:
        va, vb = a.field(name, fa)[order_a], b.field(name, fb)[order_b] * factor
        scale = max(largest[name], 1e-300)
        check("step %d %s%s (worst difference / largest value)" % (step, name, " / scale" if name == "U" and s != 1 else " * scale^3" if name == "CPRESS" and s != 1 else ""),
              np.abs(vb - va).max() / scale, 0.0, rtol)

for col, unit in (("friction_dissipation_total", force), ("friction_heat_total", heat)):
    va, vb = a.history[col][-1], b.history[col][-1] / unit
    check("final %s" % col, vb, va, rtol, relative=True)
for step in steps:
    ia = [i for i in range(len(a.history["step"])) if a.history["step"][i] == step][-1]
    ib = [i for i in range(len(b.history["step"])) if b.history["step"][i] == step][-1]
    for col in ("interface_heat", "film_heat_out", "heat_in"):
        va, vb = a.history[col][ia], b.history[col][ib] / heat
        scale = max(abs(a.history["friction_dissipation_rate"]).max(), abs(a.history["heat_in"]).max(), 1e-300)
        check("step %d end %s" % (step, col), abs(vb - va) / scale, 0.0, rtol)
print("increments: reference %d, moved and scaled %d; Newton iterations %d and %d" %
      (len(a.history["step"]), len(b.history["step"]), a.history["newton_its"].sum(), b.history["newton_its"].sum()))
finish()
