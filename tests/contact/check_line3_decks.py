#!/usr/bin/python3
"""Checks of the line3 contact decks (tests/contact/decks/).

uniform OUTDIR JOB      contact_line3_uniform_*: two stacked blocks of one material, matched meshes, pressure
                        100 and heat flux 10 on top, steady state. Every secondary node (the upper block's
                        bottom, corners and midsides: 7) is in contact with CPRESS = 100 and HFLA = -10 (heat
                        from the secondary into the main block), and the temperature jump across the
                        interface is q / k(100) = 10 / 20 = 0.5 at every node, all within 1e-6 relative:
                        the exact uniform state is the discrete one only if the contact areas are the
                        consistent weights of the face (1/6, 2/3, 1/6; in axisymmetry int N_a 2 pi r ds), as
                        the face loads on top are; the heat crossing the interface equals the heat put in.
jacobian OUTDIR JOB     contact_line3_jacobian_cpe8t, run with -snes_test_jacobian (log OUTDIR.log): every
                        ||J - Jfd||/||J|| below 1e-6 except the first evaluation of step 3 (an increment after
                        a slipping one starts on the Coulomb yield surface, a kink for finite differences);
                        the secondary nodes (corners and midside) stick in step 1, slip in 2, are open in 3.
"""
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, check_contact_jacobian_log, check_true, finish

mode, outdir, job = sys.argv[1:4]
r = Result(outdir, job)
ids, xyz = r.node_ids, r.xyz

if mode == "uniform":
    sec = [i for i in range(len(ids)) if ids[i] > 1000 and abs(xyz[i, 1] - 1.0) < 1e-12]
    main = {round(xyz[i, 0], 9): i for i in range(len(ids)) if ids[i] < 1000 and abs(xyz[i, 1] - 1.0) < 1e-12}
    cp, q, nt = r.field("CPRESS")[:, 0], r.field("HFLA")[:, 0], r.field("NT")[:, 0]
    nsec = 4 if job.endswith("4t") else 7  # line2: 4 corners; line3: 4 corners and 3 midsides
    check_true("secondary nodes on the interface", len(sec) == nsec, "(%d of %d)" % (len(sec), nsec))
    check("contact pressure, worst node (corner or midside)", float(np.max(np.abs(cp[sec] - 100.0))), 0.0, 1e-6 * 100.0)
    check("contact heat flux HFLA, worst node", float(np.max(np.abs(q[sec] + 10.0))), 0.0, 1e-6 * 10.0)
    jump = [nt[i] - nt[main[round(xyz[i, 0], 9)]] for i in sec]
    check("temperature jump theta_s - theta_m = q / k(p), worst node", float(np.max(np.abs(np.array(jump) - 0.5))), 0.0, 1e-6 * 0.5)
    print("CPRESS at the secondary nodes by x: %s" % " ".join("%.9g" % cp[i] for i in sorted(sec, key=lambda i: xyz[i, 0])))
    h = r.history
    check("heat across the interface = heat in", abs(h["interface_heat"][-1]), h["heat_in"][-1], 1e-6, relative=True)
elif mode == "jacobian":
    check_contact_jacobian_log(outdir + ".log")
    sec = [i for i in range(len(ids)) if abs(xyz[i, 1] - 0.9999) < 1e-9]
    check_true("secondary nodes (2 corners, 1 midside)", len(sec) == 3, "(%d)" % len(sec))
    for s, want, name in ((1, 1, "stick"), (2, 2, "slip"), (3, 0, "open")):
        st = r.field("CSTATUS", r.frame_of_step(s))[sec, 0]
        check_true("step %d contact status %s" % (s, name), bool(np.all(st == want)), "(CSTATUS %s)" % st.tolist())
    qs = r.field("HFLA", r.frame_of_step(3))[sec, 0]
    check_true("step 3 heat still crosses the open gap by radiation", bool(np.all(np.abs(qs) > 0)), "(HFLA %s)" % qs.tolist())
else:
    sys.exit("unknown mode %s" % mode)
finish()
