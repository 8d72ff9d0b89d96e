#!/usr/bin/python3
"""Decks of the heat-transfer link tests (DC1D2, DC1D3; CMakeLists.txt here), *HEAT TRANSFER steps:

  steady_dc1d2.inp   10 DC1D2 along a line of length 2 in 3D, skew (direction (1, 2, 2) / 3) and far from the origin,
                     cross-section 0.01 (the *SOLID SECTION value), k = 50, held at 0 and 100 at its ends: theta = 100
                     s / L at every node, the heat through it k A 100 / L = 25 (RFL at the ends)
  source_dc1d3.inp   4 DC1D3 in the plane (2D coordinates), a uniform body flux q = 1000 (BF), both ends at 0: theta =
                     q s (L - s) / (2 k), exact for quadratic links; the ends take q A L out (RFL)
  fin_dc2d4.inp      a DC2D4 plate (thickness 0.1) held at 100 on its left, a DC1D2 fin (length 2) from its right edge
                     to a node at 0: the heat through the fin k A theta_j / 2 (theta_j at the junction), the heat balance
  jacobian_dc1d2.inp the steady link with k falling with temperature and a nodal flux: the tangent by finite differences
usage: make_decks.py [OUTDIR]"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
K, AREA, L = 50.0, 0.01, 2.0


def line(n_el, order, origin, direction, two_d=False):
    nn = n_el * order + 1
    nodes = [(i + 1, [origin[d] + L * i / (nn - 1) * direction[d] for d in range(3)]) for i in range(nn)]
    elems = [(e + 1, [1 + order * e, 1 + order * e + order] + ([1 + order * e + 1] if order == 2 else [])) for e in range(n_el)]
    fmt = (lambda x: ", ".join("%.15g" % v for v in x[:2])) if two_d else (lambda x: ", ".join("%.15g" % v for v in x))
    return ("*NODE, NSET=NALL\n" + "".join(" %d, %s\n" % (i, fmt(x)) for i, x in nodes) +
            "*ELEMENT, TYPE=DC1D%d, ELSET=BAR\n" % (order + 1) + "".join(" %d, %s\n" % (e, ", ".join(str(v) for v in c)) for e, c in elems) +
            "*NSET, NSET=END0\n 1\n*NSET, NSET=END1\n %d\n" % nn)


def material(k_table=False):
    k = " 50.0, 0.0\n 25.0, 100.0\n" if k_table else " 50.0\n"
    return ("*MATERIAL, NAME=CU\n*CONDUCTIVITY\n" + k + "*DENSITY\n 8900.0\n*SPECIFIC HEAT\n 385.0\n"
            "*SOLID SECTION, ELSET=BAR, MATERIAL=CU\n %g\n*INITIAL CONDITIONS, TYPE=TEMPERATURE\n NALL, 0.0\n" % AREA)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "decks")
    skew = [1 / 3.0, 2 / 3.0, 2 / 3.0]
    decks = {
        "steady_dc1d2": "*HEADING\n A skew DC1D2 link held at 0 and 100\n" + line(10, 1, [1000.0, 2000.0, -500.0], skew) + material() +
                        "*STEP\n*HEAT TRANSFER, STEADY STATE\n 1.0, 1.0\n*BOUNDARY\n END0, 11, 11, 0.0\n END1, 11, 11, 100.0\n*END STEP\n",
        "source_dc1d3": "*HEADING\n A DC1D3 link in the plane with a uniform body flux\n" + line(4, 2, [3.0, -1.0, 0.0], [0.6, 0.8, 0.0], True) +
                        material() + "*STEP\n*HEAT TRANSFER, STEADY STATE\n 1.0, 1.0\n*BOUNDARY\n END0, 11, 11, 0.0\n END1, 11, 11, 0.0\n"
                        "*DFLUX\n BAR, BF, 1000.0\n*END STEP\n",
        "fin_dc2d4": "*HEADING\n A DC2D4 plate held at 100 on its left, a DC1D2 fin from its right edge to a node held at 0\n"
                     "*NODE, NSET=NALL\n" + "".join(" %d, %g, %g\n" % (1 + i + 3 * j, 0.5 * i, 0.5 * j) for j in range(3) for i in range(3)) +
                     " 20, 3.0, 0.5\n*ELEMENT, TYPE=DC2D4, ELSET=PLATE\n 1, 1, 2, 5, 4\n 2, 2, 3, 6, 5\n 3, 4, 5, 8, 7\n 4, 5, 6, 9, 8\n"
                     "*ELEMENT, TYPE=DC1D2, ELSET=BAR\n 10, 6, 20\n*NSET, NSET=LEFT\n 1, 4, 7\n"
                     "*SOLID SECTION, ELSET=PLATE, MATERIAL=CU\n 0.1\n" + material() +
                     "*STEP\n*HEAT TRANSFER, STEADY STATE\n 1.0, 1.0\n*BOUNDARY\n LEFT, 11, 11, 100.0\n 20, 11, 11, 0.0\n*END STEP\n",
        "jacobian_dc1d2": "*HEADING\n The link's tangent: k(theta) and a nodal flux\n" + line(4, 1, [0.0, 0.0, 0.0], skew) + material(True) +
                          "*STEP\n*HEAT TRANSFER, STEADY STATE\n 1.0, 1.0\n*BOUNDARY\n END0, 11, 11, 0.0\n*CFLUX\n 3, 11, 20.0\n END1, 11, 5.0\n*END STEP\n",
    }
    for name, text in decks.items():
        with open(os.path.join(out, name + ".inp"), "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
