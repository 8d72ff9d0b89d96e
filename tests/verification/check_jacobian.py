#!/usr/bin/python3
"""Reads a thermoslide log run with -snes_test_jacobian: every ||J - Jfd||_F/||J||_F must be below 1e-6.

The finite-difference Jacobian is computed by PETSc from the residual alone, so agreement shows that the
analytic Jacobian (element tangents, film, thermal-expansion coupling, constraint rows) is consistent.
usage: check_jacobian.py OUTDIR LOG
"""
import re
import sys

sys.path.insert(0, sys.path[0] + "/../tools")
from tslcheck import check, check_true, finish

ratios = [float(m) for m in re.findall(r"\|\|J - Jfd\|\|_F/\|\|J\|\|_F = ([0-9.eE+-]+)", open(sys.argv[2]).read())]
check_true("Jacobian tests found", len(ratios) > 0, "%d comparisons" % len(ratios))
for i, x in enumerate(ratios):
    check("||J - Jfd||_F/||J||_F, evaluation %d" % (i + 1), x, 0.0, 1e-6)
finish()
