"""Increments end on the corners of the slide amplitude (t = 1 and 2 of step 2) although the increment
size (0.07) does not divide them, and the frictional heat is the spec's: 120 dissipated, 60 absorbed
(LAGRANGE friction: all slip dissipates; the blocks' elastic shear at the two reversals takes ~1e-6).

usage: check_corners.py OUTDIR JOB"""
import sys
import numpy as np

out, job = sys.argv[1], sys.argv[2]
h = np.genfromtxt("%s/%s.csv" % (out, job), delimiter=",", names=True)
ok = True


def check(name, value, expected, tol):
    global ok
    good = abs(value - expected) <= tol
    ok &= good
    print("%s: %.10g (expected %g, tolerance %g) %s" % (name, value, expected, tol, "PASS" if good else "FAIL"))


s2 = h[h["step"] == 2]
for corner in (1.0, 2.0):
    check("step 2 increment ending at the corner t = %g (closest end)" % corner, s2["step_time"][np.argmin(abs(s2["step_time"] - corner))], corner, 1e-12)
check("increments of step 2 not all equal (0.07 does not divide the corners)", float(len(set(np.round(s2["dt"], 12))) > 1), 1.0, 0)
check("total frictional dissipation", h["friction_dissipation_total"][-1], 120.0, 120.0 * 2e-6)
check("heat absorbed by the blocks (eta = 0.5)", h["friction_heat_total"][-1], 60.0, 60.0 * 2e-6)
print("all checks passed" if ok else "SOME CHECKS FAILED")
sys.exit(0 if ok else 1)
