#!/usr/bin/python3
"""Writes a steady coupled benchmark deck: a block 2 x 1 x 1 of N*2 x N x N C3D8T (or C3D8 for CalculiX)
elements, face x = 0 fixed at theta = 100, film (h = 50, sink 0) on x = 2, pressure 1e3 on y = 1,
thermal expansion on. Dofs: 4 per node.
usage: make_block.py N out.inp [C3D8T|C3D8|C3D8RT] [explicit INCREMENTS]
  explicit INCREMENTS: the same block, loads and material as one *DYNAMIC TEMPERATURE-DISPLACEMENT,
  EXPLICIT step of INCREMENTS fixed increments (DIRECT USER CONTROL: half the element's mechanical
  h / (c_d sqrt 3) and thermal rho c h^2 / (6 k) limits, so the count does not depend on the estimate),
  one output frame at the end (tests/bench/bench_explicit.sh).
"""
import math
import sys

n, path = int(sys.argv[1]), sys.argv[2]
etype = sys.argv[3] if len(sys.argv) > 3 else "C3D8T"
explicit = int(sys.argv[5]) if len(sys.argv) > 5 and sys.argv[4] == "explicit" else 0
nx, ny, nz = 2 * n, n, n
L, H, W = 2.0, 1.0, 1.0
nid = lambda i, j, k: 1 + i + j * (nx + 1) + k * (nx + 1) * (ny + 1)
with open(path, "w") as f:
    f.write("*HEADING\n steady coupled block %dx%dx%d %s\n*NODE, NSET=ALL\n" % (nx, ny, nz, etype))
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                f.write("%d, %.9g, %.9g, %.9g\n" % (nid(i, j, k), L * i / nx, H * j / ny, W * k / nz))
    f.write("*ELEMENT, TYPE=%s, ELSET=BODY\n" % etype)
    e = 1
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                f.write("%d, %d, %d, %d, %d, %d, %d, %d, %d\n" % (e, nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                                                                 nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)))
                e += 1
    f.write("*NSET, NSET=FIXED\n")
    ids = [nid(0, j, k) for k in range(nz + 1) for j in range(ny + 1)]
    for a in range(0, len(ids), 16):
        f.write(", ".join(str(x) for x in ids[a:a + 16]) + "\n")
    f.write("*ELSET, ELSET=HOTEND\n")
    ids = [1 + (nx - 1) + j * nx + k * nx * ny for k in range(nz) for j in range(ny)]
    for a in range(0, len(ids), 16):
        f.write(", ".join(str(x) for x in ids[a:a + 16]) + "\n")
    f.write("*ELSET, ELSET=TOP\n")
    ids = [1 + i + (ny - 1) * nx + k * nx * ny for k in range(nz) for i in range(nx)]
    for a in range(0, len(ids), 16):
        f.write(", ".join(str(x) for x in ids[a:a + 16]) + "\n")
    f.write("*MATERIAL, NAME=STEEL\n*ELASTIC\n 30.0E6, 0.3\n*CONDUCTIVITY\n 10.0\n*DENSITY\n 1000.0\n*SPECIFIC HEAT\n 0.001\n*EXPANSION\n 1.0E-5\n")
    if etype.upper().startswith("SC"):  # a continuum shell: stacks along z, the elements' third direction
        f.write("*SHELL SECTION, ELSET=BODY, MATERIAL=STEEL\n 1.0, 5\n")
    else:
        f.write("*SOLID SECTION, ELSET=BODY, MATERIAL=STEEL\n")
    f.write("*INITIAL CONDITIONS, TYPE=TEMPERATURE\n ALL, 0.0\n")
    if explicit:
        E, nu, rho, c, k, h = 30.0e6, 0.3, 1000.0, 0.001, 10.0, 1.0 / n
        cd = math.sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) / rho)
        dt = 0.5 * min(h / (cd * math.sqrt(3)), rho * c * h * h / (6 * k))
        f.write("*STEP\n*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT, DIRECT USER CONTROL\n %.6e, %.6e\n" % (dt, explicit * dt))
        f.write("*OUTPUT, FIELD, NUMBER INTERVAL=1\n")
    else:
        f.write("*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n 1.0, 1.0\n")
    f.write("*BOUNDARY\n FIXED, 1, 3\n FIXED, 11, 11, 100.0\n*FILM\n HOTEND, F4, 0.0, 50.0\n*DLOAD\n TOP, P5, 1000.0\n")
    f.write("*NODE FILE\n U, NT\n*END STEP\n" if etype == "C3D8" else "*NODE OUTPUT\n U, NT\n*END STEP\n")
