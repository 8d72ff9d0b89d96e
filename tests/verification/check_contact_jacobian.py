#!/usr/bin/python3
"""-snes_test_jacobian with contact active (jobs/verification/contact_jacobian_cpe4t.inp): step 1 sticks,
step 2 slips, step 3 opens (with radiation across the gap); pressure-dependent conductance, radiation
and frictional heating are all in play. Every ||J - Jfd||/||J|| must be below 1e-6, except the first
evaluation of step 3: an increment that follows a slipping one starts exactly on the Coulomb yield
surface (|tau| = mu p, zero slip), a kink where a finite-difference Jacobian has no meaning.
The contact status of the secondary nodes in each step's output must be stick (1), slip (2), open (0).
usage: check_contact_jacobian.py OUTDIR LOG
"""
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check_contact_jacobian_log, check_true, finish

outdir, log = sys.argv[1:3]
check_contact_jacobian_log(log)
r = Result(outdir, "contact_jacobian_cpe4t")
sec = [i for i in range(len(r.node_ids)) if r.node_ids[i] in (101, 102)]
for s, want, name in ((1, 1, "stick"), (2, 2, "slip"), (3, 0, "open")):
    st = r.field("CSTATUS", r.frame_of_step(s))[sec, 0]
    check_true("step %d contact status %s" % (s, name), bool(np.all(st == want)), "(CSTATUS %s)" % st.tolist())
q = r.field("HFLA", r.frame_of_step(3))[sec, 0]
check_true("step 3 heat still crosses the open gap by radiation", bool(np.all(np.abs(q) > 0)), "(HFLA %s)" % q.tolist())
finish()
