#!/usr/bin/python3
"""Rewrite a flat two-block deck of jobs/verification/make_decks.py the way Abaqus/CAE writes a model: parts
and instances (tests/deck, "Parts and instances"; docs/keywords.md).

The blocks are told apart by their ids (the second block's nodes and elements are numbered from 1001). Each
block becomes a *PART numbered from 1 (the second one's ids less 1000), holding its nodes, elements, sets,
surfaces and sections; set names are used qualified by the instance from the assembly and the steps
("Small-1.TOPFACE"), and node ids there become instance labels ("Small-1.31"). The second part is stored
moved: its instance puts it back by a translation and a rotation about z, so the deck's model is the flat
deck's to rounding. Sets that span both blocks (*NODE, NSET=ALL) become assembly sets of the instances' sets.
usage: to_parts.py FLAT.inp OUT.inp [ANGLE_DEGREES]
"""
import math
import sys

src, dst = sys.argv[1], sys.argv[2]
angle = float(sys.argv[3]) if len(sys.argv) > 3 else 90.0
OFF = 1000
INST = ("Large-1", "Small-1")
PART = ("Large", "Small")
T = (5.0, -7.0)  # the second instance's translation; then the rotation by angle about z through the origin


def blocks(lines):
    """(keyword line, data lines) in order; comment lines dropped."""
    out = []
    for l in lines:
        s = l.strip()
        if not s or s.startswith("**"):
            continue
        if s.startswith("*"):
            out.append([s, []])
        else:
            out[-1][1].append(s)
    return out


def param(kw, key):
    for p in kw.split(",")[1:]:
        if "=" in p and p.split("=")[0].strip().upper() == key:
            return p.split("=", 1)[1].strip()
    return None


def which(i):
    return 1 if i > OFF else 0


def local(i):
    return i - OFF if i > OFF else i


with open(src) as f:
    bl = blocks(f.readlines())

part = ([], [])  # the parts' keyword blocks
sets = {}  # name -> part index, or -1 for a set spanning both (node and element sets, surfaces)
rest = []
c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
for kw, data in bl:
    k = kw.split(",")[0].upper()
    if k == "*NODE":
        ids = [int(d.split(",")[0]) for d in data]
        p = which(ids[0])
        name = param(kw, "NSET")
        if name:
            sets[name] = p if sets.get(name, p) == p else -1
        rows = []
        for d in data:
            f = [x.strip() for x in d.split(",")]
            x, y = float(f[1]), float(f[2])
            if p == 1:  # stored at R(-angle) x - T: the instance's translation T, then its rotation R(angle), put it back
                x, y = c * x + s * y - T[0], -s * x + c * y - T[1]
            rows.append("%d, %.17g, %.17g" % (local(int(f[0])), x, y))
        part[p].append(("*Node" + (", nset=%s" % name if name else ""), rows))
    elif k in ("*ELEMENT", "*NSET", "*ELSET"):
        ids = [int(x) for d in data for x in d.split(",") if x.strip()]
        p = which(ids[0])
        assert all(which(i) == p for i in ids), kw
        name = param(kw, "ELSET" if k != "*NSET" else "NSET")
        if name:
            sets[name] = p
        rows = [", ".join(str(local(int(x))) for x in d.split(",") if x.strip()) for d in data]
        part[p].append((kw, rows))
    elif k == "*SURFACE":
        ref = data[0].split(",")[0].strip()
        sets[param(kw, "NAME")] = sets[ref]
        part[sets[ref]].append((kw, data))
    elif k == "*SOLID SECTION":
        part[sets[param(kw, "ELSET")]].append((kw, data))
    elif k != "*HEADING":
        rest.append((kw, data))


def ref(x):
    """a node id or set name of the flat deck, as the assembly and the steps name it"""
    x = x.strip()
    if x.isdigit():
        return "%s.%d" % (INST[which(int(x))], local(int(x)))
    if x in sets and sets[x] >= 0:
        return "%s.%s" % (INST[sets[x]], x)
    return x


out = ["*Heading", " %s, as parts and instances" % src]
for p in (0, 1):
    out.append("*Part, name=%s" % PART[p])
    for kw, rows in part[p]:
        out.append(kw)
        out += [" " + r for r in rows]
    out.append("*End Part")
out.append("*Assembly, name=Assembly")
out += ["*Instance, name=%s, part=%s" % (INST[0], PART[0]), "*End Instance"]
out += ["*Instance, name=%s, part=%s" % (INST[1], PART[1]), " %g, %g, 0." % T, " 0., 0., 0., 0., 0., 1., %g" % angle, "*End Instance"]
for name, p in sets.items():  # sets over both blocks: the instances' halves
    if p < 0:
        out += ["*Nset, nset=%s" % name, " %s.%s, %s.%s" % (INST[0], name, INST[1], name)]
out.append("*End Assembly")
for kw, data in rest:
    k = kw.split(",")[0].upper()
    out.append(kw)
    for d in data:
        f = d.split(",")
        if k == "*EQUATION" and len(f) >= 3:
            f = [ref(x) if i % 3 == 0 else x for i, x in enumerate(f)]
        elif k in ("*BOUNDARY", "*CLOAD", "*CFLUX", "*INITIAL CONDITIONS", "*DLOAD", "*DFLUX", "*FILM", "*DSFLUX", "*SFILM", "*CONTACT PAIR"):
            f = [ref(x) for x in f[:2]] + f[2:] if k == "*CONTACT PAIR" else [ref(f[0])] + f[1:]
        out.append(" " + ", ".join(x.strip() for x in f))
with open(dst, "w") as g:
    g.write("\n".join(out) + "\n")
