#!/usr/bin/python3
"""The *STATIC runs reading coupled.h5 (make_decks.py) against the coupled run itself.

same    static.inp: every frame at the source's times; U, S, E and NT equal to the coupled run's to 1e-10 of each
        field's largest value (the plate's stress follows its temperature alone, and the temperatures are the file's)
fine    static_fine.inp: at the source's times the same; between them NT is the mean of the two neighbouring frames
        (interpolated in time; before the first frame, of the initial 0 and the first frame), 1e-12
one     static_one.inp: one frame (BSTEP=2, BINC=8) as the step's ramped target: at the end U, S and NT equal the
        source's last frame (1e-10), at step time 0.5 NT is half of it
usage: check_sequential.py SOURCE_DIR DIR JOB same|fine|one"""
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, check_true, finish

src_dir, out, job, case = sys.argv[1:5]
c, r = Result(src_dir, "coupled"), Result(out, job)
check_true("same nodes in both files", np.array_equal(c.node_ids, r.node_ids))


def frames(res):
    return [(float(res.h5["/frames/" + f].attrs["time"]), f) for f in res.frames]


cf, rf = frames(c), frames(r)
print("source frames %d, these %d" % (len(cf), len(rf)))


def same_fields(fc, fr, what, names=("U", "S", "E", "NT"), tol=1e-10):
    for name in names:
        a, b = c.h5["/frames/%s/%s" % (fc, name)][...], r.h5["/frames/%s/%s" % (fr, name)][...]
        scale = max(np.abs(a).max(), 1e-300)
        check("%s: %s, largest difference / largest value" % (what, name), float(np.abs(a - b).max() / scale), 0.0, tol)


if case in ("same", "fine"):
    ctimes = np.array([t for t, _ in cf])
    matched = 0
    for t, f in rf:
        k = int(np.argmin(np.abs(ctimes - t)))
        if abs(ctimes[k] - t) <= 1e-9 * ctimes.max():
            same_fields(cf[k][1], f, "t = %g" % t)
            matched += 1
        else:  # between the source's frames k0 < t < k1 (or before the first: from the initial temperature 0)
            k1 = int(np.searchsorted(ctimes, t))
            t0, T0 = (ctimes[k1 - 1], c.h5["/frames/%s/NT" % cf[k1 - 1][1]][...]) if k1 > 0 else (0.0, 0.0 * c.h5["/frames/%s/NT" % cf[0][1]][...])
            t1, T1 = ctimes[k1], c.h5["/frames/%s/NT" % cf[k1][1]][...]
            w = (t - t0) / (t1 - t0)
            want = (1 - w) * T0 + w * T1
            check("t = %g: NT interpolated between the source's %g and %g (w = %.3f), worst / largest" % (t, t0, t1, w),
                  float(np.abs(r.h5["/frames/%s/NT" % f][...] - want).max() / np.abs(T1).max()), 0.0, 1e-12)
    check_true("every source frame matched", matched == len(cf), "%d of %d" % (matched, len(cf)))
else:
    last = cf[-1][1]
    same_fields(last, rf[-1][1], "end of the ramp vs the source's last frame", ("U", "S", "NT"))
    half = [f for t, f in rf if abs(t - 0.5) < 1e-12]
    check_true("a frame at step time 0.5", len(half) == 1)
    check("t = 0.5: NT = half the frame's, worst / largest", float(np.abs(r.h5["/frames/%s/NT" % half[0]][...] - 0.5 * c.h5["/frames/%s/NT" % last][...]).max()
          / np.abs(c.h5["/frames/%s/NT" % last][...]).max()), 0.0, 1e-12)
finish()
