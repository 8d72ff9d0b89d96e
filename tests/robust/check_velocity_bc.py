#!/usr/bin/python3
"""*BOUNDARY, TYPE=VELOCITY in an explicit step: the prescribed node's U1 in every frame equals the integral of
its velocity amplitude, here the tabular displacement through (T0 + t_i, a_i), held at the last value after it
(the velocity amplitude ends at 0). usage: check_velocity_bc.py RESULT.h5 NODE T0 t0 a0 t1 a1 ... (tolerance 1e-9)"""
import sys

import h5py
import numpy as np

f = h5py.File(sys.argv[1], "r")
node, t0 = int(sys.argv[2]), float(sys.argv[3])
pts = [float(x) for x in sys.argv[4:]]
tt, aa = np.array(pts[0::2]) + t0, np.array(pts[1::2])
i = list(f["mesh/node_ids"][:]).index(node)
worst, n = 0.0, 0
for name in sorted(f["frames"].keys()):
    t = f["frames/" + name].attrs["time"]
    if t < tt[0]:
        continue
    expect = np.interp(t, tt, aa)
    worst = max(worst, abs(f["frames/" + name + "/U"][i][0] - expect))
    n += 1
print(f"node {node}: U1 against the velocity's integral in {n} frames: largest difference {worst:.3e} (at most 1e-9)")
sys.exit(0 if n > 10 and worst <= 1e-9 else 1)
