#!/usr/bin/python3
"""Writes the SI steel plate of the per-field convergence tests: 0.2 x 0.1 x 0.01 m of NX x NY x 1 C3D8T,
E = 2.1e11 Pa and k = 50 W/m K falling with temperature (tables: Newton iterates), clamped at x = 0, a flux
Q = 100 W/m^2 into the face x = 0 and a film h = 0.05 W/m^2 K (sink 20) on the top face z = 0.01, initially
at 20. The Biot number h L / k is 2e-4, so the plate heats almost uniformly: its mean temperature follows
C dT/dt = q A_q - h A_f (T - 20) (check_si_plate.py). The mechanical residuals are of order E alpha dT A ~ 1e5
N, the thermal ones of order 1 W.
usage: make_si_plate.py OUT.inp transient|steady"""
import sys

path, kind = sys.argv[1], sys.argv[2]
nx, ny = 10, 5
L, H, W = 0.2, 0.1, 0.01
nid = lambda i, j, k: 1 + i + j * (nx + 1) + k * (nx + 1) * (ny + 1)
rows = lambda ids: "".join(", ".join(map(str, ids[a:a + 16])) + "\n" for a in range(0, len(ids), 16))
with open(path, "w") as f:
    f.write("*HEADING\nSI steel plate, %s (tests/verification/decks/make_si_plate.py)\n*NODE, NSET=ALL\n" % kind)
    for k in range(2):
        for j in range(ny + 1):
            for i in range(nx + 1):
                f.write("%d, %.9g, %.9g, %.9g\n" % (nid(i, j, k), L * i / nx, H * j / ny, W * k))
    f.write("*ELEMENT, TYPE=C3D8T, ELSET=PLATE\n")
    for j in range(ny):
        for i in range(nx):
            f.write("%d, %d, %d, %d, %d, %d, %d, %d, %d\n" % (1 + i + j * nx, nid(i, j, 0), nid(i + 1, j, 0), nid(i + 1, j + 1, 0), nid(i, j + 1, 0),
                                                            nid(i, j, 1), nid(i + 1, j, 1), nid(i + 1, j + 1, 1), nid(i, j + 1, 1)))
    f.write("*NSET, NSET=CLAMPED\n" + rows([nid(0, j, k) for k in range(2) for j in range(ny + 1)]))
    f.write("*ELSET, ELSET=FLUXED\n" + rows([1 + j * nx for j in range(ny)]))
    f.write("*ELSET, ELSET=FILMED\n" + rows(list(range(1, nx * ny + 1))))
    f.write("*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3, 0.\n1.5e11, 0.3, 500.\n*CONDUCTIVITY\n50., 0.\n30., 500.\n")
    f.write("*DENSITY\n7850.\n*SPECIFIC HEAT\n460.\n*EXPANSION\n1.2e-5\n")
    f.write("*SOLID SECTION, ELSET=PLATE, MATERIAL=STEEL\n*INITIAL CONDITIONS, TYPE=TEMPERATURE\nALL, 20.\n")
    if kind == "steady":
        f.write("*STEP, INC=100\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n1., 1.\n")
    else:  # five time constants C / (h A_f) = 7.2e5 s in 40 increments
        f.write("*STEP, INC=100\n*COUPLED TEMPERATURE-DISPLACEMENT\n9.0e4, 3.6e6, 9.0e4, 9.0e4\n")
    f.write("*BOUNDARY\nCLAMPED, 1, 3, 0.\n*DFLUX\nFLUXED, S6, 100.\n*FILM\nFILMED, F2, 20., 0.05\n*END STEP\n")
