#!/usr/bin/python3
"""gmsh2inp: a Gmsh mesh (.msh, any format meshio reads, or Gmsh's own Abaqus .inp export) as the mesh part of a
thermoslide deck: *NODE, *ELEMENT with coupled temperature-displacement types, and a set per physical group.

    /usr/bin/python3 jobs/tools/gmsh2inp.py MESH OUT.inp [--kind strain|stress|axi] [--type CELL=TYPE ...]
                                            [--first-id GROUP=ID ...] [--scale S]

Physical groups become, by their dimension (the mesh's own dimension d: the highest among its cells):
- d (bodies): an *ELEMENT block per cell type and group, ELSET=<name>, and an *NSET of the group's nodes;
- d - 1 (faces in 3D, lines in 2D): an element-face *SURFACE, TYPE=ELEMENT, NAME=<name> (each facet matched to
  the body element it bounds and written as that element's face label S1, S2, ... in the dialect's numbering),
  and an *NSET of its nodes; a facet no body element has raises an error naming the group;
- lower (points, or lines in 3D): an *NSET of their nodes.
Bodies' cells outside every physical group are written with ELSET=UNGROUPED; every element is in the ELSET EALL,
every node in the NSET NALL. From Gmsh's .inp export the physical groups are its named ELSETs (Gmsh writes every elementary
entity as an ELSET too, PointN/LineN/SurfaceN/VolumeN: those are skipped).

Element types by cell (2D: --kind strain (default), stress or axi):
  triangle CPE3T/CPS3T/CAX3T, triangle6 CPE6MT/CPS6MT/CAX6MT, quad CPE4T/CPS4T/CAX4T, quad8 CPE8T/CPS8T/CAX8T,
  tetra C3D4T, tetra10 C3D10MT, wedge C3D6T, wedge15 C3D15T, hexahedron C3D8T, hexahedron20 C3D20T;
  --type CELL=TYPE replaces one (e.g. quad=CPE4RT, hexahedron=C3D8RT). 9-, 18- and 27-node cells (Gmsh's default
  second order for quadrangles, prisms, hexahedra: set Mesh.SecondOrderIncomplete = 1) are refused.
Each body cell is turned to positive orientation (2D: counter-clockwise in the x-y plane; 3D: positive volume),
the node order as the dialect numbers it (meshio already gives the VTK order, which is the dialect's for every
type above). Ids: nodes and elements are numbered 1, 2, ... in meshio's order, except that --first-id GROUP=ID
numbers the nodes and elements of body group GROUP from ID on (its nodes first reached by it; to keep an
existing deck's ids, e.g. the verification decks' small block from 1001). --scale multiplies the coordinates.
The output holds the mesh part only: *INCLUDE it from a deck that adds materials, sections (ELSET=<group>),
interactions and steps.
"""
import argparse
import re
import sys

import numpy as np

try:
    import meshio
except ImportError:  # Debian's python3-meshio, through /usr/bin/python3
    sys.exit("gmsh2inp: needs meshio (Debian: apt-get install python3-meshio; run with /usr/bin/python3)")

DIM = {"line": 1, "line3": 1, "triangle": 2, "triangle6": 2, "quad": 2, "quad8": 2, "tetra": 3, "tetra10": 3,
       "wedge": 3, "wedge15": 3, "hexahedron": 3, "hexahedron20": 3, "vertex": 0,
       "quad9": 2, "wedge18": 3, "hexahedron27": 3}
TYPES_2D = {"triangle": "%s3T", "triangle6": "%s6MT", "quad": "%s4T", "quad8": "%s8T"}
KIND = {"strain": "CPE", "stress": "CPS", "axi": "CAX"}
TYPES_3D = {"tetra": "C3D4T", "tetra10": "C3D10MT", "wedge": "C3D6T", "wedge15": "C3D15T", "hexahedron": "C3D8T",
            "hexahedron20": "C3D20T"}
# corner positions of each face S1, S2, ... as the dialect numbers them
FACES = {
    "triangle": [(0, 1), (1, 2), (2, 0)],
    "quad": [(0, 1), (1, 2), (2, 3), (3, 0)],
    "tetra": [(0, 1, 2), (0, 3, 1), (1, 3, 2), (2, 3, 0)],
    "wedge": [(0, 1, 2), (3, 5, 4), (0, 3, 4, 1), (1, 4, 5, 2), (2, 5, 3, 0)],
    "hexahedron": [(0, 1, 2, 3), (4, 7, 6, 5), (0, 4, 5, 1), (1, 5, 6, 2), (2, 6, 7, 3), (3, 7, 4, 0)],
}
LINEAR = {"triangle6": "triangle", "quad8": "quad", "tetra10": "tetra", "wedge15": "wedge", "hexahedron20": "hexahedron"}
NCORNER = {"triangle": 3, "quad": 4, "tetra": 4, "wedge": 6, "hexahedron": 8}
# the node permutation that reverses a cell's orientation (corners, then the midside nodes that follow them)
FLIP = {
    "triangle": [0, 2, 1], "triangle6": [0, 2, 1, 5, 4, 3],
    "quad": [0, 3, 2, 1], "quad8": [0, 3, 2, 1, 7, 6, 5, 4],
    "tetra": [0, 2, 1, 3], "tetra10": [0, 2, 1, 3, 6, 5, 4, 7, 9, 8],
    "wedge": [0, 2, 1, 3, 5, 4], "wedge15": [0, 2, 1, 3, 5, 4, 8, 7, 6, 11, 10, 9, 12, 14, 13],
    "hexahedron": [0, 3, 2, 1, 4, 7, 6, 5],
    "hexahedron20": [0, 3, 2, 1, 4, 7, 6, 5, 11, 10, 9, 8, 15, 14, 13, 12, 16, 19, 18, 17],
}
GMSH_ENTITY_SET = re.compile(r"^(Point|Line|Curve|Surface|Volume)\d+$")


def fail(msg):
    sys.exit("gmsh2inp: " + msg)


def orientation(ctype, x):
    """Signed measure of a cell from its corner coordinates x (2D: area in the x-y plane; 3D: the volume of the
    tetrahedron of its first corners, which has the cell's sign for every convex cell)."""
    lin = LINEAR.get(ctype, ctype)
    if DIM[lin] == 2:
        c = x[:NCORNER[lin], :2]
        return 0.5 * np.sum(c[:, 0] * np.roll(c[:, 1], -1) - np.roll(c[:, 0], -1) * c[:, 1])
    a = {"tetra": (0, 1, 2, 3), "wedge": (0, 1, 2, 3), "hexahedron": (0, 1, 3, 4)}[lin]
    return np.linalg.det(np.array([x[a[1]] - x[a[0]], x[a[2]] - x[a[0]], x[a[3]] - x[a[0]]]))


def groups_of(mesh, is_inp):
    """{name: [(block, cell indices)]} of every physical group."""
    out = {}
    for name, per_block in (mesh.cell_sets or {}).items():
        if name.startswith("gmsh:") or (is_inp and GMSH_ENTITY_SET.match(name)):
            continue
        members = [(b, np.asarray(idx, dtype=int)) for b, idx in enumerate(per_block) if idx is not None and len(idx)]
        if members:
            out[name] = members
    if not out and "gmsh:physical" in mesh.cell_data:  # older meshio: physical tags without names
        for b, tags in enumerate(mesh.cell_data["gmsh:physical"]):
            for t in np.unique(tags):
                out.setdefault("PHYS%d" % t, []).append((b, np.nonzero(tags == t)[0]))
    return out


def set_lines(keyword, name, ids):
    ids = sorted(set(int(i) for i in ids))
    rows = [", ".join(str(i) for i in ids[k:k + 16]) for k in range(0, len(ids), 16)]
    return "*%s, %s=%s\n" % (keyword, keyword, name) + "".join(" %s\n" % r for r in rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("mesh")
    ap.add_argument("out")
    ap.add_argument("--kind", choices=sorted(KIND), default="strain", help="2D: plane strain, plane stress or axisymmetric")
    ap.add_argument("--type", action="append", default=[], metavar="CELL=TYPE", help="element type for a meshio cell type")
    ap.add_argument("--first-id", action="append", default=[], metavar="GROUP=ID", help="number a body group's nodes and elements from ID")
    ap.add_argument("--scale", type=float, default=1.0)
    a = ap.parse_args()

    try:
        mesh = meshio.read(a.mesh)
    except Exception as e:  # meshio raises many kinds: report the file and the reason
        fail("%s: cannot read the mesh (%s)" % (a.mesh, e))
    is_inp = a.mesh.lower().endswith(".inp")
    cells = [(c.type, np.asarray(c.data, dtype=int)) for c in mesh.cells]
    dims = [DIM.get(t, -1) for t, _ in cells]
    for t, _ in cells:
        if t not in DIM:
            fail("%s: cell type %s is not supported" % (a.mesh, t))
    dim = max(dims)
    if dim < 2:
        fail("%s: no 2D or 3D cells" % a.mesh)
    pts = np.asarray(mesh.points, dtype=float) * a.scale
    if dim == 2 and pts.shape[1] > 2 and np.any(np.abs(pts[:, 2]) > 1e-12 * max(1.0, np.abs(pts).max())):
        fail("%s: a 2D mesh must lie in the plane z = 0" % a.mesh)
    types = dict((t, (v % KIND[a.kind]) if dim == 2 else v) for t, v in (TYPES_2D if dim == 2 else TYPES_3D).items())
    for spec in a.type:
        cell, _, typ = spec.partition("=")
        if cell not in types or not typ:
            fail("--type %s: give CELL=TYPE with CELL one of %s" % (spec, ", ".join(sorted(types))))
        types[cell] = typ.upper()
    groups = groups_of(mesh, is_inp)
    body_blocks = [b for b, d in enumerate(dims) if d == dim]
    for b in body_blocks:
        if cells[b][0] not in types:
            fail("%s: %d-node cells (%s) are not supported: second order from Gmsh needs Mesh.SecondOrderIncomplete = 1"
                 % (a.mesh, cells[b][1].shape[1], cells[b][0]))

    # orientation: every body cell positive
    for b in body_blocks:
        t, conn = cells[b]
        for k in range(len(conn)):
            s = orientation(t, pts[conn[k]])
            if s == 0.0:
                fail("%s: a degenerate %s cell (block %d, cell %d)" % (a.mesh, t, b, k))
            if s < 0.0:
                conn[k] = conn[k][FLIP[t]]

    # ids: the --first-id groups first, then the rest from 1 in meshio's order
    node_id = np.zeros(len(pts), dtype=int)
    elem_id = {b: np.zeros(len(cells[b][1]), dtype=int) for b in body_blocks}
    used_nodes = np.zeros(len(pts), dtype=bool)
    for b in body_blocks:
        used_nodes[cells[b][1].ravel()] = True
    taken_e, taken_n = set(), set()
    for spec in a.first_id:
        name, _, first = spec.partition("=")
        if name not in groups or not first.isdigit() or int(first) < 1:
            fail("--first-id %s: give GROUP=ID with GROUP a body group (%s)" % (spec, ", ".join(sorted(groups))))
        nid = eid = int(first)
        for b, idx in groups[name]:
            if b not in elem_id:
                fail("--first-id %s: %s is not a body group" % (spec, name))
            for k in idx:
                if elem_id[b][k] == 0:
                    elem_id[b][k] = eid
                    taken_e.add(eid)
                    eid += 1
                for n in cells[b][1][k]:
                    if node_id[n] == 0:
                        node_id[n] = nid
                        taken_n.add(nid)
                        nid += 1
    nxt = 1
    for n in np.nonzero(used_nodes)[0]:
        if node_id[n] == 0:
            while nxt in taken_n:
                nxt += 1
            node_id[n] = nxt
            nxt += 1
    nxt = 1
    for b in body_blocks:
        for k in range(len(elem_id[b])):
            if elem_id[b][k] == 0:
                while nxt in taken_e:
                    nxt += 1
                elem_id[b][k] = nxt
                nxt += 1
    if len(set(node_id[used_nodes])) != int(used_nodes.sum()):
        fail("--first-id: the ids of two groups overlap; choose first ids further apart")

    # facets of the body cells, by their sorted corner ids: (block, cell, face label)
    facet = {}
    for b in body_blocks:
        t, conn = cells[b]
        lin = LINEAR.get(t, t)
        for k, c in enumerate(conn):
            for f, corners in enumerate(FACES[lin]):
                facet.setdefault(tuple(sorted(c[list(corners)])), []).append((b, k, f + 1))

    ncomp = 3 if dim == 3 else 2
    out = ["** written by gmsh2inp.py from %s: %d nodes, %d elements\n" % (a.mesh, int(used_nodes.sum()),
                                                                          sum(len(cells[b][1]) for b in body_blocks))]
    out.append("*NODE, NSET=NALL\n")
    order = np.nonzero(used_nodes)[0]
    order = order[np.argsort(node_id[order])]
    out += [" %d, %s\n" % (node_id[n], ", ".join("%.17g" % v for v in pts[n, :ncomp])) for n in order]
    body_group = {}  # (block, cell) -> first body group naming it
    for name, members in groups.items():
        for b, idx in members:
            if dims[b] == dim:
                for k in idx:
                    body_group.setdefault((b, int(k)), name)
    for b in body_blocks:
        t, conn = cells[b]
        # one *ELEMENT block per (cell type, body group) in the order of the ids
        by_set = {}
        for k in range(len(conn)):
            by_set.setdefault(body_group.get((b, k), "UNGROUPED"), []).append(k)
        for name, ks in by_set.items():
            ks.sort(key=lambda k: elem_id[b][k])
            out.append("*ELEMENT, TYPE=%s, ELSET=%s\n" % (types[t], name))
            out += [" %d, %s\n" % (elem_id[b][k], ", ".join(str(node_id[n]) for n in conn[k])) for k in ks]
    for name in sorted(groups):
        members = groups[name]
        gdim = max(dims[b] for b, _ in members)
        nodes = set(node_id[n] for b, idx in members for n in cells[b][1][idx].ravel())
        if gdim == dim:
            # a body group named by an ELSET on its *ELEMENT lines; cells already in another group's block
            ids = [elem_id[b][k] for b, idx in members if dims[b] == dim for k in idx if body_group[(b, int(k))] != name]
            if ids:
                out.append(set_lines("ELSET", name, ids))
        elif gdim == dim - 1:
            faces = {}
            for b, idx in members:
                t = cells[b][0]
                lin = LINEAR.get(t, t)
                nc = 2 if DIM[lin] == 1 else NCORNER.get(lin, 0)
                for k in idx:
                    key = tuple(sorted(cells[b][1][k][:nc]))
                    if key not in facet:
                        fail("%s: physical group %s: a facet (nodes %s) bounds no %dD cell" % (a.mesh, name, ", ".join(
                            str(node_id[n]) if node_id[n] else "?" for n in key), dim))
                    for bb, kk, f in facet[key]:
                        faces.setdefault(f, []).append(elem_id[bb][kk])
            for f in sorted(faces):
                out.append(set_lines("ELSET", "%s_S%d" % (name, f), faces[f]))
            out.append("*SURFACE, NAME=%s, TYPE=ELEMENT\n" % name + "".join(" %s_S%d, S%d\n" % (name, f, f) for f in sorted(faces)))
        nodes.discard(0)
        if nodes:
            out.append(set_lines("NSET", name, nodes))
    out.append(set_lines("ELSET", "EALL", [elem_id[b][k] for b in body_blocks for k in range(len(cells[b][1]))]))
    with open(a.out, "w") as fh:
        fh.write("".join(out))
    print("gmsh2inp: %s -> %s: %d nodes, %d elements (%s), %d groups" % (
        a.mesh, a.out, int(used_nodes.sum()), sum(len(cells[b][1]) for b in body_blocks),
        ", ".join(sorted(set(types[cells[b][0]] for b in body_blocks))), len(groups)))


if __name__ == "__main__":
    main()
