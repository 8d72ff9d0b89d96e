#!/usr/bin/python3
"""Renumbers a deck's nodes and elements by a random permutation, as a mesh generator or a merge of parts
may number them: every reference moves with its node or element, so the model is the same and only its
ids (and their order in the file) differ.

usage: renumber_deck.py IN.inp OUT.inp MAP.txt [SEED]
MAP.txt gets one line per node ("node OLD NEW") and per element ("elem OLD NEW"), for compare_h5.py's
renumbered= option. References renumbered: *NODE, *ELEMENT (ids and connectivity), *NSET and *ELSET
(GENERATE ranges expanded), *SURFACE (TYPE=ELEMENT faces, TYPE=NODE nodes), *EQUATION terms, and the leading
node or element of *BOUNDARY, *CLOAD, *CFLUX, *INITIAL CONDITIONS, *DLOAD, *DFLUX, *FILM, *RADIATE data
lines. A keyword outside this list that names a node or element by number is refused (exit 2), so a test
never runs a model other than the one it meant.
"""
import random
import sys

NODE_FIRST = ("*BOUNDARY", "*CLOAD", "*CFLUX", "*INITIAL CONDITIONS")
ELEM_FIRST = ("*DLOAD", "*DFLUX", "*FILM", "*RADIATE")
# keywords whose data lines name no node or element by number
PLAIN = ("*HEADING", "*MATERIAL", "*ELASTIC", "*CONDUCTIVITY", "*DENSITY", "*SPECIFIC HEAT", "*EXPANSION", "*SOLID SECTION",
         "*SHELL SECTION", "*SURFACE INTERACTION", "*FRICTION", "*GAP CONDUCTANCE", "*GAP RADIATION", "*GAP HEAT GENERATION",
         "*SURFACE BEHAVIOR", "*CONTACT PAIR", "*AMPLITUDE", "*STEP", "*END STEP", "*COUPLED TEMPERATURE-DISPLACEMENT",
         "*DYNAMIC TEMPERATURE-DISPLACEMENT", "*STATIC", "*NODE OUTPUT", "*ELEMENT OUTPUT", "*OUTPUT", "*NODE PRINT", "*EL PRINT",
         "*NODE FILE", "*EL FILE", "*CONTACT OUTPUT", "*CONTACT PRINT", "*CONTACT FILE", "*PHYSICAL CONSTANTS", "*CONTROLS",
         "*BULK VISCOSITY", "*FIXED MASS SCALING", "*VARIABLE MASS SCALING", "*ORIENTATION")


def options(line):
    f = [x.strip() for x in line.split(",")]
    return f[0].upper(), dict((x.split("=", 1)[0].upper(), x.split("=", 1)[1].upper() if "=" in x else "") for x in f[1:] if x)


def main():
    src, dst, mapfile = sys.argv[1:4]
    seed = int(sys.argv[4]) if len(sys.argv) > 4 else 1
    lines = open(src).read().splitlines()
    nodes, elems, kw = [], [], None
    for line in lines:
        if line.startswith("**"):
            continue
        if line.startswith("*"):
            kw = options(line)[0]
        elif line.strip() and kw == "*NODE":
            nodes.append(int(line.split(",")[0]))
        elif line.strip() and kw == "*ELEMENT":
            elems.append(int(line.split(",")[0]))
    rng = random.Random(seed)
    pn, pe = nodes[:], elems[:]
    rng.shuffle(pn)
    rng.shuffle(pe)
    nm, em = dict(zip(nodes, pn)), dict(zip(elems, pe))
    num = lambda x: x.strip().lstrip("-").isdigit()

    out, block, kw, opts, eq_left = [], [], None, {}, 0

    def flush():
        if kw in ("*NODE", "*ELEMENT"):
            block.sort(key=lambda l: int(l.split(",")[0]))
        out.extend(block)
        del block[:]

    for line in lines:
        if line.startswith("**") or not line.strip():
            out.append(line)
            continue
        if line.startswith("*"):
            flush()
            kw, opts = options(line)
            eq_left = 0
            gen = "GENERATE" in opts and kw in ("*NSET", "*ELSET")
            out.append(line.replace(", GENERATE", "").replace(",GENERATE", "") if gen else line)
            continue
        f = [x.strip() for x in line.split(",")]
        if kw == "*NODE":
            f[0] = str(nm[int(f[0])])
        elif kw == "*ELEMENT":
            f = [str(em[int(f[0])])] + [str(nm[int(x)]) for x in f[1:] if x]
        elif kw in ("*NSET", "*ELSET"):
            m = nm if kw == "*NSET" else em
            if "GENERATE" in opts:
                a, b = int(f[0]), int(f[1])
                s = int(f[2]) if len(f) > 2 and f[2] else 1
                ids = [str(m[i]) for i in range(a, b + 1, s)]
                block.extend(", ".join(ids[k:k + 16]) for k in range(0, len(ids), 16))
                continue
            f = [str(m[int(x)]) if num(x) else x for x in f if x]
        elif kw == "*SURFACE":
            m = nm if opts.get("TYPE") == "NODE" else em
            if num(f[0]):
                f[0] = str(m[int(f[0])])
        elif kw == "*EQUATION":
            if eq_left == 0:
                eq_left = int(f[0])
            else:
                for k in range(0, len(f) - 2, 3):
                    if num(f[k]):
                        f[k] = str(nm[int(f[k])])
                eq_left -= len([x for x in f if x]) // 3
        elif kw in NODE_FIRST:
            if num(f[0]):
                f[0] = str(nm[int(f[0])])
        elif kw in ELEM_FIRST:
            if num(f[0]):
                f[0] = str(em[int(f[0])])
        elif kw not in PLAIN:
            sys.stderr.write("renumber_deck.py: %s: keyword %s is not handled\n" % (src, kw))
            sys.exit(2)
        block.append(", ".join(f))
    flush()
    open(dst, "w").write("\n".join(out) + "\n")
    with open(mapfile, "w") as m:
        m.writelines("node %d %d\n" % (a, b) for a, b in nm.items())
        m.writelines("elem %d %d\n" % (a, b) for a, b in em.items())


main()
