#!/usr/bin/python3
"""check_frames.py JOB.h5 T1 T2 ... [FIELD:NODE:COMPONENT=V1,V2,...]

Passes when the job's frames are exactly these, at these step times (to 1e-12 of the largest): the frames of an
*OUTPUT, NUMBER INTERVAL= / TIME INTERVAL= step, every one at an output time and none between. With
FIELD:NODE:COMPONENT=V1,V2,..., also the component (0-based) of a node field at the deck's node NODE in each
frame (to 1e-10 of the largest), e.g. U:3:1=0.25,0.5 for a prescribed U2 of node 3 ramped over two frames.
"""
import sys

import h5py

times = [float(a) for a in sys.argv[2:] if "=" not in a]
values = [a for a in sys.argv[2:] if "=" in a]
ok = True
with h5py.File(sys.argv[1], "r") as f:
    frames = [g for _, g in sorted(f["frames"].items())]
    got = [float(g.attrs["time"]) for g in frames]
    print("frame times:", got)
    tol = 1e-12 * max(abs(t) for t in times)
    if len(got) != len(times) or any(abs(a - b) > tol for a, b in zip(got, times)):
        print("FAIL: expected the frame times", times)
        ok = False
    ids = list(f["mesh/node_ids"][()])
    for v in values:
        what, want = v.split("=")
        field, node, comp = what.split(":")
        want = [float(x) for x in want.split(",")]
        have = [float(g[field][()][ids.index(int(node))][int(comp)]) for g in frames]
        print("%s of node %s, component %s:" % (field, node, comp), have)
        if len(have) != len(want) or any(abs(a - b) > 1e-10 * max(abs(x) for x in want) for a, b in zip(have, want)):
            print("FAIL: expected", want)
            ok = False
print("PASS" if ok else "FAILED")
sys.exit(0 if ok else 1)
