#!/usr/bin/python3
"""contact_steady_touching_cpe4t: the conductance series' blocks, exactly touching at the start, solved
steady from the first step (issue 8, item 2). Flux 100 on the small block's top (area 2), film h = 10,
sink 0 on a unit area of the large block's bottom, pressure-dependent gap conductance.

  1, 2  thermal equilibrium: flux in = heat across the interface = film heat out = 200, 1e-6 relative
  1, 2  the film face's mean temperature = 200 / (h area) = 20 (nodal mean of a linear field over the
        two film elements: 1 %)
  1, 2  the interface law node by node: HFLA = k(CPRESS) (theta_main - theta_secondary), 1e-6 relative
  1, 2  temperatures symmetric about x = 3 (1e-6 of the largest)
  2     doubling the pressure lowers k from about 20 to about 5: the mean interface drop grows by the
        ratio of the area-averaged conductances (1 %)
usage: check_steady_touching.py OUTDIR JOB
"""
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, finish

outdir, job = sys.argv[1:3]
r = Result(outdir, job)
ids, xyz, h = r.node_ids, r.xyz, r.history
small = ids > 1000
large = ~small


def k_table(p):
    return np.interp(p, [100.0, 200.0], [20.0, 5.0])


drops, kmean = {}, {}
for step in (1, 2):
    row = [i for i in range(len(h["step"])) if h["step"][i] == step][-1]
    f = r.frame_of_step(step)
    check("step %d flux in = 200" % step, h["heat_in"][row], 200.0, 1e-6, relative=True)
    check("step %d heat across the interface = flux in" % step, abs(h["interface_heat"][row]), h["heat_in"][row], 1e-6, relative=True)
    check("step %d film heat out = flux in" % step, h["film_heat_out"][row], h["heat_in"][row], 1e-6, relative=True)
    nt, u = r.field("NT", f)[:, 0], r.field("U", f)
    film = [i for i in range(len(ids)) if large[i] and abs(xyz[i, 1]) < 1e-9 and 2.5 - 1e-9 <= xyz[i, 0] <= 3.5 + 1e-9]
    film = sorted(film, key=lambda i: xyz[i, 0])
    mean = (0.5 * nt[film[0]] + nt[film[1]] + 0.5 * nt[film[2]]) / 2.0
    check("step %d film face mean temperature = 200 / (h A)" % step, mean, 20.0, 0.01, relative=True)
    key = {(bool(small[i]), round(xyz[i, 0], 9), round(xyz[i, 1], 9)): i for i in range(len(ids))}
    mirror = max(abs(nt[i] - nt[key[(bool(small[i]), round(6.0 - xyz[i, 0], 9), round(xyz[i, 1], 9))]]) for i in range(len(ids)))
    check("step %d temperatures symmetric about x = 3 (worst mirror difference)" % step, mirror, 0.0, 1e-6 * abs(nt).max())
    cp, q = r.field("CPRESS", f)[:, 0], r.field("HFLA", f)[:, 0]
    y0 = xyz[small, 1].min()
    sec = sorted([i for i in range(len(ids)) if small[i] and abs(xyz[i, 1] - y0) < 1e-9], key=lambda i: xyz[i, 0])
    top = sorted([i for i in range(len(ids)) if large[i] and abs(xyz[i, 1] - y0) < 1e-9], key=lambda i: xyz[i, 0])
    tm = np.interp([xyz[i, 0] + u[i, 0] for i in sec], [xyz[i, 0] + u[i, 0] for i in top], nt[top])
    ts = nt[sec]
    expected = k_table(cp[sec]) * (tm - ts)
    check("step %d interface law node by node (HFLA vs law, worst relative)" % step, np.abs(q[sec] - expected).max() / np.abs(expected).max(), 0.0, 1e-6)
    w = np.array([0.5 if k in (0, len(sec) - 1) else 1.0 for k in range(len(sec))])
    drops[step] = float(np.sum(w * (ts - tm)) / np.sum(w))
    kmean[step] = float(np.sum(w * k_table(cp[sec])) / np.sum(w))
check("step 2 / step 1 mean drop = ratio of mean conductances", drops[2] / drops[1], kmean[1] / kmean[2], 0.01, relative=True)
finish()
