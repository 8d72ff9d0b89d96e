#!/usr/bin/python3
"""Compares every dataset of two thermoslide .h5 files (e.g. a 1-rank and a 2-rank run).

usage: compare_h5.py A.h5 B.h5 [rtol] [FIELD=floor ...] [skip=PREFIX ...]
A dataset agrees when max|a - b| <= rtol * max(M, floor), M the largest magnitude of that field over
all frames of the job: a heat flux that has decayed to round-off in the last frame is compared with
the fluxes the job produced, not with itself.
A field that is physically zero (reactions of a free body) is only round-off; FIELD=floor gives the
magnitude it is compared against (e.g. RF=1e4 for forces of order 1e4 elsewhere in the model).
skip=PREFIX leaves out the datasets whose path starts with PREFIX (skip=mesh: the same cells numbered
otherwise, e.g. continuum shells with another stack direction); skipfield=NAME those of field NAME in every
frame (skipfield=S: element averages over integration points that two rules place differently).
renumbered=MAP.txt: B is the model of A with its nodes and elements renumbered (tests/tools/renumber_deck.py
writes MAP.txt): B's node and element rows are compared with A's rows of the same node or element, and the
datasets that are ids or connectivity (mesh/node_ids, mesh/element_ids, mesh/topology, mesh/connectivity) are left out.
"""
import sys

import h5py
import numpy as np


def datasets(f):
    out = {}
    f.visititems(lambda name, obj: out.__setitem__(name, obj[...]) if isinstance(obj, h5py.Dataset) else None)
    return out


a, b = datasets(h5py.File(sys.argv[1], "r")), datasets(h5py.File(sys.argv[2], "r"))
rtol = float(sys.argv[3]) if len(sys.argv) > 3 else 1e-8
skips = [kv.split("=", 1)[1] for kv in sys.argv[4:] if kv.startswith("skip=")]
skipfields = [kv.split("=", 1)[1] for kv in sys.argv[4:] if kv.startswith("skipfield=")]
floors = dict((kv.split("=")[0], float(kv.split("=")[1])) for kv in sys.argv[4:] if not kv.startswith(("skip=", "skipfield=", "renumbered=")))
renumbered = [kv.split("=", 1)[1] for kv in sys.argv[4:] if kv.startswith("renumbered=")]
if renumbered:
    nmap, emap = {}, {}
    for line in open(renumbered[0]):
        kind, old, new = line.split()
        (nmap if kind == "node" else emap)[int(old)] = int(new)
    skips += ["mesh/node_ids", "mesh/element_ids", "mesh/topology", "mesh/connectivity"]
    # B's row of each of A's nodes (elements): A's id, renumbered, found among B's ids
    rows = []
    for ids, m in (("mesh/node_ids", nmap), ("mesh/element_ids", emap)):
        where = dict((int(i), r) for r, i in enumerate(b[ids]))
        rows.append((len(a[ids]), np.array([where[m[int(i)]] for i in a[ids]], dtype=int)))
    for name in list(b):
        if any(name.startswith(p) for p in skips) or np.ndim(b[name]) == 0:
            continue
        for n, perm in rows:
            if b[name].shape[0] == n:
                b[name] = b[name][perm]
                break
a = dict((k, v) for k, v in a.items() if not any(k.startswith(p) for p in skips) and k.split("/")[-1] not in skipfields)
b = dict((k, v) for k, v in b.items() if not any(k.startswith(p) for p in skips) and k.split("/")[-1] not in skipfields)
bad = sorted(set(a) ^ set(b))
if bad:
    print("datasets present in only one file: %s" % bad)
    sys.exit(1)
magnitude = {}
for name, x in a.items():
    field = name.split("/")[-1]
    magnitude[field] = max(magnitude.get(field, 0.0), float(np.abs(np.asarray(x, dtype=float)).max()) if np.size(x) else 0.0)
# every dataset is compared (the first one over the tolerance need not be the worst): the worst is reported
worst, worst_name, failed = 0.0, "", 0
for name in sorted(a):
    x, y = np.asarray(a[name], dtype=float), np.asarray(b[name], dtype=float)
    if x.shape != y.shape:
        print("%s: shapes differ %s vs %s FAIL" % (name, x.shape, y.shape))
        sys.exit(1)
    scale = max(magnitude[name.split("/")[-1]], floors.get(name.split("/")[-1], 1e-300))
    rel = (np.abs(x - y).max() / scale) if x.size else 0.0
    if rel > worst:
        worst, worst_name = rel, name
    if rel > rtol:
        failed += 1
        if failed <= 5:
            print("%s: relative difference %.3e > %.1e" % (name, rel, rtol))
if failed:
    print("%d of %d datasets differ by more than %.1e; the largest: %s, %.3e FAIL" % (failed, len(a), rtol, worst_name, worst))
    sys.exit(1)
print("%d datasets agree; largest relative difference %.3e (%s; tolerance %.1e) PASS" % (len(a), worst, worst_name or "all equal", rtol))
