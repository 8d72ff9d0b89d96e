#!/usr/bin/python3
"""Rewrites a deck's triangles and wedges as Abaqus/CAE's collapsed quadrilaterals and bricks.

CPE3T a, b, c -> CPE4T a, b, c, c (likewise CPS, CAX) and C3D6T a, b, c, d, e, f -> C3D8T a, b, c, c, d, e, f, f;
the face labels of element surfaces and face loads follow (the triangle's S3 = 3-1 is the quadrilateral's S4 =
4-1, the wedge's S5 = 3-1-4-6 the brick's S6 = 4-1-5-8; the other faces keep their numbers). The element
interpolation is the same (docs/elements.md, "Collapsed elements"), so a job and its collapsed twin must agree.
usage: collapse_deck.py IN.inp OUT.inp
"""
import re
import sys

TYPES = {"CPE3T": ("CPE4T", 3), "CPS3T": ("CPS4T", 3), "CAX3T": ("CAX4T", 3), "C3D6T": ("C3D8T", 5)}
FACE_KEYWORDS = ("*SURFACE", "*DLOAD", "*FILM", "*DFLUX")

src, dst = sys.argv[1], sys.argv[2]
lines, out, block, moved = open(src).read().split("\n"), [], None, None
for line in lines:
    if line.startswith("*") and not line.startswith("**"):
        block = None
        m = re.search(r"TYPE=(\w+)", line, re.I)
        if line.upper().startswith("*ELEMENT") and m and m.group(1).upper() in TYPES:
            new, moved = TYPES[m.group(1).upper()]
            line = line[:m.start(1)] + new + line[m.end(1):]
            block = "element2d" if new != "C3D8T" else "element3d"
        elif line.upper().startswith(FACE_KEYWORDS):
            block = "faces"
    elif block == "element2d" and line.strip():
        f = [x.strip() for x in line.split(",")]
        line = " " + ", ".join(f + [f[3]])
    elif block == "element3d" and line.strip():
        f = [x.strip() for x in line.split(",")]
        line = " " + ", ".join(f[:4] + [f[3]] + f[4:7] + [f[6]])
    elif block == "faces" and moved and line.strip():
        # the moved face's label (S3 / P3 / F3 of a triangle, S5 / P5 / F5 of a wedge) takes the next number
        line = re.sub(r"(,\s*[SPF])%d\b" % moved, lambda g: g.group(1) + str(moved + 1), line)
    out.append(line)
open(dst, "w").write("\n".join(out))
