"""Reading thermoslide results and printing verification checks (used by tests and the demo).

Each check prints one line `name: value (expected E, tolerance T) PASS|FAIL`; `finish()` exits non-zero
if any failed. Uses Debian's python3-h5py and python3-numpy only.
"""
import csv
import math
import sys

import h5py
import numpy as np

_failed = []


class Result:
    """The .h5 and .csv of one job."""

    def __init__(self, outdir, job):
        self.h5 = h5py.File("%s/%s.h5" % (outdir, job), "r")
        self.xyz = self.h5["/mesh/coordinates"][...]
        self.node_ids = self.h5["/mesh/node_ids"][...]
        self.frames = sorted(self.h5["/frames"].keys())
        with open("%s/%s.csv" % (outdir, job)) as f:
            rows = list(csv.DictReader(f))
        self.history = {k: np.array([float(r[k]) for r in rows]) for k in rows[0]} if rows else {}

    def frame(self, index=-1):
        return self.h5["/frames/" + self.frames[index]]

    def field(self, name, index=-1):
        return self.frame(index)[name][...]

    def frame_of_step(self, step, last=True):
        """Index of the last (or first) frame written in a step."""
        idx = [i for i, f in enumerate(self.frames) if int(self.h5["/frames/" + f].attrs["step"]) == step]
        return idx[-1] if last else idx[0]

    def elements(self):
        """Connectivity (natural node indices) of each element from the Mixed topology."""
        topo, out, k = self.h5["/mesh/topology"][...], [], 0
        sizes = {4: 3, 5: 4, 6: 4, 8: 6, 9: 8, 36: 6, 37: 8, 38: 10, 48: 20}
        while k < len(topo):
            n = sizes[int(topo[k])]
            out.append(topo[k + 1:k + 1 + n])
            k += 1 + n
        return out


def check(name, value, expected, tol, relative=False):
    """|value - expected| <= tol (absolute) or <= tol*|expected| (relative)."""
    err = abs(value - expected)
    bound = tol * abs(expected) if relative else tol
    ok = bool(err <= bound) and np.isfinite(value)
    kind = "relative " if relative else ""
    print("%s: %.10g (expected %.10g, %stolerance %.3g) %s" % (name, value, expected, kind, tol, "PASS" if ok else "FAIL"))
    if not ok:
        _failed.append(name)
    return ok


def check_true(name, ok, detail=""):
    print("%s: %s %s" % (name, detail, "PASS" if ok else "FAIL"))
    if not ok:
        _failed.append(name)


def check_contact_jacobian_log(log):
    """The ||J - Jfd||/||J|| ratios of -snes_test_jacobian in a job log, step by step: every one below 1e-6
    in steps 1, 2, 3 (stick, slip, open), except the first evaluation of step 3, which starts exactly on
    the Coulomb yield surface (a kink where a finite-difference Jacobian means nothing)."""
    import re
    step, seen = 0, {}
    for line in open(log):
        m = re.match(r"step (\d+) \(", line)
        if m:
            step = int(m.group(1))
        m = re.search(r"\|\|J - Jfd\|\|_F/\|\|J\|\|_F = ([0-9.eE+-]+)", line)
        if m:
            seen.setdefault(step, []).append(float(m.group(1)))
    check_true("Jacobian comparisons in all three steps", sorted(seen) == [1, 2, 3], "%s" % {k: len(v) for k, v in seen.items()})
    for s, ratios in sorted(seen.items()):
        for k, x in enumerate(ratios):
            if s == 3 and k == 0:
                print("step 3 evaluation 1: %.3g (on the yield surface, not checked)" % x)
                continue
            check("step %d evaluation %d ||J - Jfd||/||J||" % (s, k + 1), x, 0.0, 1e-6)


def finish():
    if _failed:
        print("FAILED checks: %s" % ", ".join(_failed))
        sys.exit(1)
    print("all checks passed")
    sys.exit(0)


def slab_series(x, t, kappa, L=1.0, theta=100.0):
    """Slab 0 < x < L initially at 0, face x = 0 held at theta from t = 0, x = L insulated:
    theta [1 - sum_n 4/((2n+1) pi) sin((2n+1) pi x / 2L) exp(-(2n+1)^2 pi^2 kappa t / 4L^2)]."""
    s = 0.0
    for n in range(200):
        m = (2 * n + 1) * math.pi / (2 * L)
        s += 4.0 / ((2 * n + 1) * math.pi) * math.sin(m * x) * math.exp(-m * m * kappa * t)
    return theta * (1.0 - s)
