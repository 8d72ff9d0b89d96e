"""Reads <job>.xmf as ParaView-style readers do (meshio's XDMF time-series reader, h5py underneath)
and checks mesh, times and field values against the closed-form figures of mesh_fixture.h.
With a second .h5, also checks that both files hold identical datasets (1 rank vs n ranks).

usage: read_meshio.py JOB.xmf [OTHER.h5]
"""
import sys

import h5py
import meshio
import numpy as np


def value(frame, field, item, comp):
    return frame * 100000 + field * 10000 + 10 * item + comp + (0.25 if field % 2 else -0.125)


def expected(frame, field, n, ncomp):
    item, comp = np.meshgrid(np.arange(n), np.arange(ncomp), indexing="ij")
    return value(frame, field, item, comp)


def check_series(xmf):
    with meshio.xdmf.TimeSeriesReader(xmf) as reader:
        points, cells = reader.read_points_cells()
        nnode = points.shape[0]
        assert points.shape == (nnode, 3), points.shape
        ncell = sum(len(c.data) for c in cells)
        kinds = {c.type for c in cells}
        assert kinds == {"quad", "triangle"}, kinds
        assert reader.num_steps == 2, reader.num_steps
        for k in range(reader.num_steps):
            frame = k + 1
            t, point_data, cell_data = reader.read_data(k)
            assert t == 0.5 * frame, t
            assert np.array_equal(point_data["NT"], expected(frame, 1, nnode, 1))
            assert np.array_equal(point_data["U"], expected(frame, 2, nnode, 3))
            s = np.concatenate(cell_data["S"])  # split per cell block, in file order
            assert np.array_equal(s, expected(frame, 3, ncell, 6))
            assert ("V" in point_data) == (frame == 2)
            if frame == 2:
                assert np.array_equal(point_data["V"], expected(frame, 4, nnode, 2))
    print(f"{xmf}: {nnode} nodes, {ncell} cells, 2 frames read by meshio: PASS")


def datasets(h5):
    out = {}

    def visit(name, obj):  # returning anything but None would stop the walk
        if isinstance(obj, h5py.Dataset):
            out[name] = obj

    h5.visititems(visit)
    return out


def compare(a_path, b_path):
    with h5py.File(a_path, "r") as a, h5py.File(b_path, "r") as b:
        da, db = datasets(a), datasets(b)
        assert sorted(da) == sorted(db), (sorted(da), sorted(db))
        for name in da:
            assert da[name].dtype == db[name].dtype, name
            assert np.array_equal(da[name][()], db[name][()]), name
        for g in a["frames"]:
            assert dict(a["frames"][g].attrs) == dict(b["frames"][g].attrs), g
    print(f"{a_path} and {b_path}: {len(da)} identical datasets: PASS")


if __name__ == "__main__":
    check_series(sys.argv[1])
    if len(sys.argv) > 2:
        compare(sys.argv[1][: -len(".xmf")] + ".h5", sys.argv[2])
