"""The .xmf of every element family and of mixed meshes read as users read it: by meshio's XDMF time-series reader
(Debian's python3-meshio, with /usr/bin/python3) or by ParaView's two XDMF readers (pvpython). The decks are
make_family_decks.py's, run by run_family_decks.sh into OUTDIR/<deck>/.

Each reader must give, for every deck it can read: the nodes' coordinates (those of /mesh/coordinates), the cells
in the deck's element order with the deck's nodes (ids turned into the file's rows through /mesh/node_ids) in
XDMF's (VTK's) order, which is the dialect's but for the wedges (their base runs the other way round:
XDMF_ORDER), and type, both frames (t = 0.5 and 1) with NT = t (10 + 100 x) and U = 0 at every node and
HFL = (-200 t, 0, 0) in every cell (1e-9). ParaView also measures every cell (vtkCellSizeFilter: its area or
volume from the cell's own node order and shape, so a node order ParaView reads otherwise shows) against the
element's (1e-12).

What meshio cannot read (docs/output.md, "Reading with meshio"), asserted as such so that a meshio that can is
checked instead: a Mixed topology with second-order cells (its Mixed reader has node counts for the linear cell
ids only: KeyError on 34, 36, 37, 38, 40, 48), and wedge15 at all (no "wedge15" in its table of cell dimensions:
KeyError 'wedge15' when it builds the cell block, whatever the file says).

usage: /usr/bin/python3 check_readers.py meshio OUTDIR DECKDIR NAME...
       pvpython check_readers.py paraview OUTDIR DECKDIR NAME...
"""
import os
import sys

import h5py
import numpy as np

MESHIO = {"tri3": "triangle", "tri6": "triangle6", "quad4": "quad", "quad8": "quad8", "tet4": "tetra", "tet10": "tetra10",
          "wedge6": "wedge", "wedge15": "wedge15", "hex8": "hexahedron", "hex20": "hexahedron20"}
VTK = {"tri3": 5, "tri6": 22, "quad4": 9, "quad8": 23, "tet4": 10, "tet10": 24, "wedge6": 13, "wedge15": 26, "hex8": 12, "hex20": 25}
QUADRATIC = {"tri6", "quad8", "tet10", "wedge15", "hex20"}
XDMF_ORDER = {"wedge6": [0, 2, 1, 3, 5, 4], "wedge15": [0, 2, 1, 3, 5, 4, 8, 7, 6, 11, 10, 9, 12, 14, 13]}
failed = []


def report(name, ok, what):
    print("%s: %s %s" % (name, what, "PASS" if ok else "FAIL"))
    if not ok:
        failed.append("%s: %s" % (name, what))


def expected(outdir, deckdir, name):
    """What the files hold: the coordinates, the cells (family, measure, file rows in XDMF's order) in element order."""
    with h5py.File(os.path.join(outdir, name, name + ".h5"), "r") as f:
        xyz, node_ids = f["/mesh/coordinates"][...], f["/mesh/node_ids"][...]
    row = {int(i): r for r, i in enumerate(node_ids)}
    cells = []
    for line in open(os.path.join(deckdir, name + ".cells")):
        fam, size, *ids = line.split()
        rows = [row[int(i)] for i in ids]
        cells.append((fam, float(size), [rows[k] for k in XDMF_ORDER[fam]] if fam in XDMF_ORDER else rows))
    return xyz, cells


def frame_values(x, t):
    return t * (10 + 100 * x), -200.0 * t


def meshio_limitation(cells, err):
    """The reason meshio 5 cannot read this mesh, if it is a known one, else None."""
    fams = {c[0] for c in cells}
    if isinstance(err, KeyError) and err.args == ("wedge15",) and "wedge15" in fams:
        return "meshio has no wedge15 cell (KeyError 'wedge15' in its table of cell dimensions)"
    if isinstance(err, KeyError) and len(fams) > 1 and fams & QUADRATIC and err.args[0] in (34, 36, 37, 38, 40, 48):
        return "meshio's Mixed reader knows the node counts of the linear cell ids only (KeyError %d)" % err.args[0]
    return None


def check_meshio(outdir, deckdir, name):
    import meshio

    xyz, cells = expected(outdir, deckdir, name)
    xmf = os.path.join(outdir, name, name + ".xmf")
    try:
        with meshio.xdmf.TimeSeriesReader(xmf) as r:
            points, blocks = r.read_points_cells()
            frames = [r.read_data(k) for k in range(r.num_steps)]
    except Exception as err:  # a reader's failure: known, or a failure of the test
        why = meshio_limitation(cells, err)
        report(name, why is not None, "meshio cannot read it: %s" % (why or repr(err)))
        return
    got = [(b.type, list(c)) for b in blocks for c in b.data]
    want = [(MESHIO[f], rows) for f, _, rows in cells]
    report(name, np.array_equal(points, xyz), "meshio: %d points at the file's coordinates" % len(points))
    report(name, got == want, "meshio: %d cells, types %s, with the deck's nodes in XDMF's order" % (len(got), sorted({b.type for b in blocks})))
    report(name, [t for t, _, _ in frames] == [0.5, 1.0], "meshio: frames at t = 0.5, 1")
    for t, pd, cd in frames:
        nt, hx = frame_values(xyz[:, 0], t)
        hfl = np.concatenate(cd["HFL"])
        ok = np.abs(pd["NT"][:, 0] - nt).max() <= 1e-9 * 110 and np.abs(pd["U"]).max() == 0
        ok = ok and hfl.shape == (len(cells), 3) and np.abs(hfl - [hx, 0, 0]).max() <= 1e-9 * 200
        report(name, bool(ok), "meshio: frame t = %g: NT = t (10 + 100 x), U = 0, HFL = (-200 t, 0, 0)" % t)


def check_paraview(outdir, deckdir, name):
    from paraview import simple
    from paraview import servermanager
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter

    xyz, cells = expected(outdir, deckdir, name)
    xmf = os.path.join(outdir, name, name + ".xmf")
    for label, make in (("XDMF Reader", lambda: simple.XDMFReader(FileNames=[xmf])), ("Xdmf3 Reader", lambda: simple.Xdmf3ReaderT(FileName=[xmf]))):
        reader = make()
        times = list(reader.TimestepValues)
        report(name, times == [0.5, 1.0], "%s: frames at t = %s" % (label, times))
        for t in times:
            reader.UpdatePipeline(t)
            grid = servermanager.Fetch(reader)
            if grid.IsA("vtkMultiBlockDataSet"):  # a reader that wraps the grid in a block
                grid = grid.GetBlock(0)
            ncell = grid.GetNumberOfCells()
            pts = vtk_to_numpy(grid.GetPoints().GetData())
            conn = [[grid.GetCell(c).GetPointId(k) for k in range(grid.GetCell(c).GetNumberOfPoints())] for c in range(ncell)]
            types = [grid.GetCellType(c) for c in range(ncell)]
            ok = np.array_equal(pts, xyz) and conn == [rows for _, _, rows in cells] and types == [VTK[f] for f, _, _ in cells]
            sizes = vtkCellSizeFilter()
            sizes.SetInputData(grid)
            sizes.Update()
            out = sizes.GetOutput()
            measure = vtk_to_numpy(out.GetCellData().GetArray("Area" if out.GetCell(0).GetCellDimension() == 2 else "Volume"))
            ok_size = np.abs(measure - [s for _, s, _ in cells]).max() <= 1e-12
            nt, hx = frame_values(xyz[:, 0], t)
            pnt = vtk_to_numpy(grid.GetPointData().GetArray("NT")).reshape(-1)
            hfl = vtk_to_numpy(grid.GetCellData().GetArray("HFL"))
            ok_val = np.abs(pnt - nt).max() <= 1e-9 * 110 and np.abs(hfl - [hx, 0, 0]).max() <= 1e-9 * 200
            report(name, bool(ok and ok_size and ok_val),
                   "%s t = %g: %d points, %d cells of VTK types %s with the deck's nodes in XDMF's order, measures %s, NT and HFL" %
                   (label, t, len(pts), ncell, sorted(set(types)), " ".join("%.6g" % m for m in measure)))
        simple.Delete(reader)


mode, outdir, deckdir, names = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
for n in names:
    (check_meshio if mode == "meshio" else check_paraview)(outdir, deckdir, n)
print("%s: %d decks, %s" % (mode, len(names), "FAILED: " + "; ".join(failed) if failed else "all checks passed"))
sys.exit(1 if failed else 0)
