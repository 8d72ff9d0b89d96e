#!/usr/bin/python3
"""*DAMPING in an explicit step (decks/damping_oscillators_cpe4t.inp): two one-element oscillators, each
m u'' + c u' + k u = 0 with k = lambda + 2 mu (a unit square in uniaxial strain), m = rho / 2 (its top nodes' lumped
masses), released at u = 0, u' = v0 = 1: u(t) = v0 / omega_d exp(-zeta omega t) sin(omega_d t), omega_d =
omega sqrt(1 - zeta^2). Element 1's *DAMPING, ALPHA gives c = alpha m, zeta = alpha / (2 omega); element 2's BETA
gives c = beta k, zeta = beta omega / 2; both 0.05 here.

Tolerance (derived): the damping force of an explicit increment is c v_{n-1/2}, half an increment late, which acts
as a mass m - c h / 2: the frequency rises by zeta omega h / 2 (3.7e-5 at h = 2e-6), a phase error of 7e-4 rad over
the three periods run, and the decay by zeta omega h (its amplitude error 7e-5); central differences' own
(omega h)^2 / 24 is 1e-7. So every frame's u is checked within 2e-3 of the first amplitude v0 / omega (three times
the bound); the undamped answer lies up to 0.85 of it away by the end. The energy balance closes to round-off (the
damping's work in ALLVD): |ETOTAL| < 1e-9 of the energy released, and ALLVD is the energy the oscillators lost.
With LOG and UNDAMPED_LOG (the same deck without *DAMPING): the stable increment is the undamped one times
sqrt(1 + xi^2) - xi at the element's highest mode omega_e = 2 / dt_e, xi = alpha / (2 omega_e) or beta omega_e / 2,
the smaller of the two elements' (1e-4: the log's five digits).
usage: check_damping.py OUTDIR JOB [LOG UNDAMPED_LOG]
"""
import math
import re
import sys

import numpy as np

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import Result, check, check_true, finish

outdir, job = sys.argv[1:3]
E, nu, rho, v0 = 2.0e5, 0.3, 1.0, 1.0
alpha, beta = 73.38, 1.3628e-4
M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))  # lambda + 2 mu
k, m = M, rho / 2
omega = math.sqrt(k / m)
r = Result(outdir, job)
ids = list(r.node_ids)
amp = v0 / omega
for name, tops, zeta in (("ALPHA", (3, 4), alpha / (2 * omega)), ("BETA", (13, 14), beta * omega / 2)):
    wd = omega * math.sqrt(1 - zeta * zeta)
    rows = [ids.index(n) for n in tops]
    err, undamped, tend = 0.0, 0.0, 0.0
    for i in range(len(r.frames)):
        t = float(r.frame(i).attrs["time"])
        u = r.field("U", i)[rows, 1]
        exact = v0 / wd * math.exp(-zeta * omega * t) * math.sin(wd * t)
        err = max(err, abs(u - exact).max())
        undamped = max(undamped, abs(v0 / omega * math.sin(omega * t) - exact))
        tend = t
    print("%s: zeta %.6f, omega %.4f, %d frames to t = %g" % (name, zeta, omega, len(r.frames), tend))
    check("%s: largest |u - u_exact| / (v0 / omega)" % name, err / amp, 0.0, 2e-3)
    check_true("%s: the undamped answer lies far off" % name, undamped / amp > 0.5, "%.3f of v0 / omega" % (undamped / amp))
h = r.history
e0 = 2 * 0.5 * (2 * rho / 4) * v0 * v0  # two oscillators, each two top nodes of mass rho / 4 at v0
check("energy balance |ETOTAL| / energy released", np.abs(h["ETOTAL"]).max() / e0, 0.0, 1e-9)
check("ALLVD + ALLKE + ALLIE at the end / the released energy", (h["ALLVD"][-1] + h["ALLKE"][-1] + h["ALLIE"][-1]) / e0, 1.0, 1e-6)
check_true("ALLVD grows (the damping dissipates)", bool(np.all(np.diff(h["ALLVD"]) >= -1e-15 * e0)) and h["ALLVD"][-1] > 0.5 * e0,
           "ALLVD %.6g of %.6g" % (h["ALLVD"][-1], e0))
if len(sys.argv) > 4:
    pat = re.compile(r"stable increment ([0-9.eE+-]+) .*mechanical ([0-9.eE+-]+) at element")
    (damped,), (undamped_dt,) = ([float(mm.group(2)) for mm in map(pat.search, open(f)) if mm][:1] for f in sys.argv[3:5])
    f = lambda xi: math.sqrt(1 + xi * xi) - xi
    expect = undamped_dt * min(f(alpha * undamped_dt / 4), f(beta / undamped_dt))
    print("undamped element limit %.4e: xi %.4f (ALPHA), %.4f (BETA)" % (undamped_dt, alpha * undamped_dt / 4, beta / undamped_dt))
    check("mechanical limit with *DAMPING / expected", damped / expect, 1.0, 1e-4)
finish()
