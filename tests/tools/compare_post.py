#!/usr/bin/python3
"""POST OUTPUT check: every frame of POST.h5 against the frame of ORIG.h5 with the same step and increment, each field
within TOL of its largest value in the original frame; every original frame at a restart point must be recovered. FIELDS (environment, names separated by spaces): the post
frames hold exactly these fields (a POST OUTPUT deck's own requests), each checked against the original's.
usage: compare_post.py ORIG.h5 POST.h5 TOL [POINTS_DIR JOB]"""
import os
import re
import sys

import h5py
import numpy as np

orig, post, tol = h5py.File(sys.argv[1], "r"), h5py.File(sys.argv[2], "r"), float(sys.argv[3])
by_key = {(int(g.attrs["step"]), int(g.attrs["increment"])): g for g in orig["frames"].values()}
fail, worst, n = 0, 0.0, 0
for name, g in post["frames"].items():
    key = (int(g.attrs["step"]), int(g.attrs["increment"]))
    if key not in by_key:
        print("post frame %s (step %d increment %d): no frame of the original run there" % ((name,) + key))
        fail = 1
        continue
    o = by_key[key]
    only = os.environ.get("FIELDS", "").split()
    if only and sorted(g.keys()) != sorted(only):
        print("step %d increment %d: fields %s, expected %s" % (key + (sorted(g.keys()), sorted(only))))
        fail = 1
    if abs(float(g.attrs["time"]) - float(o.attrs["time"])) > 1e-12 * max(1.0, abs(float(o.attrs["time"]))):
        print("step %d increment %d: time %g, the original's %g" % (key + (g.attrs["time"], o.attrs["time"])))
        fail = 1
    for f in o:
        if only and f not in only:
            continue
        if f not in g:
            print("step %d increment %d: field %s not recovered" % (key + (f,)))
            fail = 1
            continue
        a, b = np.asarray(o[f], float), np.asarray(g[f], float)
        scale = max(np.max(np.abs(a)), 1e-300)
        d = float(np.max(np.abs(a - b))) / scale if a.size else 0.0
        worst = max(worst, d)
        if d > tol:
            print("step %d increment %d: %s differs by %.3e of its largest value" % (key + (f, d)))
            fail = 1
    n += 1
if len(sys.argv) > 5:  # every point's frame recovered
    pat = re.compile(re.escape(sys.argv[5]) + r"\.restart\.(\d+)\.(\d+)\.h5$")
    want = {(int(m.group(1)), int(m.group(2))) for m in map(pat.match, os.listdir(sys.argv[4])) if m}
    got = {(int(g.attrs["step"]), int(g.attrs["increment"])) for g in post["frames"].values()}
    if want - got:
        print("points without a recovered frame: %s" % sorted(want - got))
        fail = 1
print("%d post frames against the original run's: largest difference %.3e of a field's largest value (tolerance %.1e) %s" % (n, worst, tol, "FAIL" if fail else "PASS"))
sys.exit(fail)
