#!/usr/bin/python3
"""FEniCSx (dolfinx 0.5) peer of thermoslide on the steady coupled block benchmark (make_block.py N).

Same problem and discretization as the deck: block [0,2]x[0,1]x[0,1], 2N x N x N trilinear hexahedra (Q1,
i.e. C3D8T nodes and dofs: 4 per node, (2N+1)(N+1)^2 nodes), full 2x2x2 Gauss integration (quadrature
degree 2; exact on this affine mesh), steady, small strain, one-way coupled, solved monolithically as ONE
linear system in the mixed space (vector Q1 u) x (Q1 theta):
  heat:      -div(k grad theta) = 0, k = 10; theta = 100 on x = 0; film on x = 2: q_out = h (theta - 0), h = 50
  mechanics: sigma = lam tr(eps_m) I + 2 mu eps_m, eps_m = eps(u) - alpha (theta - 0) I,
             E = 30e6, nu = 0.3, alpha = 1e-5; u = 0 on x = 0; pressure p = 1e3 on y = 1 (traction -p n)
Solver: KSP fgmres (rtol 1e-10, right preconditioned, i.e. relative to the true initial residual |b|),
PCFIELDSPLIT multiplicative, temperature split first (BoomerAMG), then displacement (GAMG with the 6 rigid
body modes as near null space, block size 3). All of it can be overridden on the command line with the
options prefix -peer_ (splits: -peer_fieldsplit_T_..., -peer_fieldsplit_u_...), e.g. -peer_ksp_view,
-peer_ksp_monitor, -peer_fieldsplit_u_pc_type hypre.

usage: [mpirun -n P] /usr/bin/python3 peer_block.py N OUTDIR [--no-output] [--compare THERMOSLIDE.h5]
                                                             [-peer_... PETSc options]
Writes OUTDIR/peer_blockN.{xdmf,h5} (U and NT, dolfinx.io.XDMFFile) unless --no-output. Prints (rank 0) a
timing table (wall per phase, synchronized by barriers, and CPU time per phase, max over ranks: on a
loaded machine the CPU column is the steadier one), the KSP iterations, dofs, peak RSS (ru_maxrss, max and
sum over ranks), check values (theta and u at the node (2,1,1), max theta, max |u|) and a final
machine-readable line "PEER key=value ...". JIT (FFCx/CFFI) time is reported separately and is not in
"total" (which does include the python/dolfinx import, also reported separately); run once beforehand
(any N, same ranks or not) to fill the FFCx cache (~/.cache/fenics or $XDG_CACHE_HOME/fenics) so that the
JIT row is only a cache load. --compare matches the nodes of a thermoslide result of the same N
(outdir/deck.h5) by coordinates and prints max|difference|/max|value| for NT and U (needs h5py).
"""
import os
import sys
import time

T_START = time.perf_counter()

# ---- command line: N OUTDIR [--no-output] [--compare FILE]; everything else goes to PETSc --------------
if len(sys.argv) < 3 or sys.argv[1].startswith("-"):
    sys.stderr.write(__doc__)
    sys.exit(2)
N, OUTDIR = int(sys.argv[1]), sys.argv[2]
WRITE, COMPARE, petsc_args = True, None, [sys.argv[0]]
_rest = sys.argv[3:]
while _rest:
    a = _rest.pop(0)
    if a == "--no-output":
        WRITE = False
    elif a == "--compare":
        COMPARE = _rest.pop(0)
    else:
        petsc_args.append(a)

import petsc4py  # noqa: E402

petsc4py.init(petsc_args)
from petsc4py import PETSc  # noqa: E402
from mpi4py import MPI  # noqa: E402
import numpy as np  # noqa: E402
import resource  # noqa: E402
import ufl  # noqa: E402
import dolfinx  # noqa: E402
import dolfinx.fem.petsc  # noqa: E402
import dolfinx.io  # noqa: E402
from dolfinx import cpp as _cpp  # noqa: E402
from dolfinx.mesh import CellType, GhostMode  # noqa: E402

comm = MPI.COMM_WORLD
rank = comm.rank
times = {}  # wall time per phase
cpu = {}  # CPU time of this process per phase (a check on a loaded machine, where wall times are noisy)


class Phase:
    """Wall time of a phase, synchronized over the ranks (barrier at both ends), and this rank's CPU time."""

    def __init__(self, name):
        self.name = name

    def __enter__(self):
        comm.Barrier()
        self.t0, self.c0 = time.perf_counter(), time.process_time()

    def __exit__(self, *exc):
        c1 = time.process_time()
        comm.Barrier()
        times[self.name] = times.get(self.name, 0.0) + time.perf_counter() - self.t0
        cpu[self.name] = cpu.get(self.name, 0.0) + c1 - self.c0


comm.Barrier()
times["import"] = time.perf_counter() - T_START

# ---- solver defaults (a user's -peer_... option wins) ------------------------------------------------
PREFIX = "peer_"
DEFAULTS = [
    ("ksp_type", "fgmres"),
    ("ksp_rtol", "1e-10"),
    ("ksp_atol", "1e-50"),
    ("ksp_max_it", "1000"),
    ("ksp_gmres_restart", "100"),
    ("pc_type", "fieldsplit"),
    ("pc_fieldsplit_type", "multiplicative"),
    # temperature: one BoomerAMG V-cycle
    ("fieldsplit_T_ksp_type", "preonly"),
    ("fieldsplit_T_pc_type", "hypre"),
    ("fieldsplit_T_pc_hypre_type", "boomeramg"),
    ("fieldsplit_T_pc_hypre_boomeramg_coarsen_type", "HMIS"),
    ("fieldsplit_T_pc_hypre_boomeramg_interp_type", "ext+i"),
    ("fieldsplit_T_pc_hypre_boomeramg_agg_nl", "1"),
    # displacement: one smoothed-aggregation GAMG V-cycle with the rigid body modes
    ("fieldsplit_u_ksp_type", "preonly"),
    ("fieldsplit_u_pc_type", "gamg"),
    ("fieldsplit_u_pc_gamg_type", "agg"),
    ("fieldsplit_u_pc_gamg_agg_nsmooths", "1"),
    ("fieldsplit_u_pc_gamg_threshold", "0.02"),
    ("fieldsplit_u_pc_gamg_square_graph", "1"),
    ("fieldsplit_u_mg_levels_ksp_type", "chebyshev"),
    ("fieldsplit_u_mg_levels_pc_type", "jacobi"),
    ("fieldsplit_u_mg_levels_ksp_max_it", "2"),
]
opts = PETSc.Options()
for k, v in DEFAULTS:
    if not opts.hasName(PREFIX + k):
        opts.setValue(PREFIX + k, v)

# ---- mesh -------------------------------------------------------------------------------------------
with Phase("mesh"):
    mesh = dolfinx.mesh.create_box(comm, [np.array([0.0, 0.0, 0.0]), np.array([2.0, 1.0, 1.0])], [2 * N, N, N],
                                   CellType.hexahedron, ghost_mode=GhostMode.none)
    tdim = mesh.topology.dim
    fdim = tdim - 1

# ---- UFL problem ------------------------------------------------------------------------------------
cell = mesh.ufl_cell()
Ue = ufl.VectorElement("Lagrange", cell, 1)
Te = ufl.FiniteElement("Lagrange", cell, 1)
ME = ufl.MixedElement([Ue, Te])
QDEG = 2  # 2x2x2 Gauss points on the hexahedra, 2x2 on faces: C3D8T's full integration

with Phase("jit"):
    (ufcx_element, ufcx_dofmap), module, _ = dolfinx.jit.ffcx_jit(comm, ME)
    if WRITE:
        dolfinx.jit.ffcx_jit(comm, Ue)  # the vector Q1 space u is written from (created in "output")

with Phase("fe_setup"):
    # the function space from the compiled element (what dolfinx.fem.FunctionSpace does, minus its JIT)
    ffi = module.ffi
    cpp_element = _cpp.fem.FiniteElement(ffi.cast("uintptr_t", ffi.addressof(ufcx_element)))
    cpp_dofmap = _cpp.fem.create_dofmap(comm, ffi.cast("uintptr_t", ffi.addressof(ufcx_dofmap)), mesh.topology,
                                        cpp_element)
    cpp_mesh = getattr(mesh, "_mesh", mesh)  # dolfinx 0.5.x: the python Mesh may wrap the C++ one
    W = dolfinx.fem.FunctionSpace(mesh, ME, _cpp.fem.FunctionSpace(cpp_mesh, cpp_element, cpp_dofmap))

    # boundary facets: x = 0 (support, theta = 100), x = 2 (film, tag 1), y = 1 (pressure, tag 2)
    f_x0 = dolfinx.mesh.locate_entities_boundary(mesh, fdim, lambda x: np.isclose(x[0], 0.0))
    f_x2 = dolfinx.mesh.locate_entities_boundary(mesh, fdim, lambda x: np.isclose(x[0], 2.0))
    f_y1 = dolfinx.mesh.locate_entities_boundary(mesh, fdim, lambda x: np.isclose(x[1], 1.0))
    fac = np.hstack([f_x2, f_y1]).astype(np.int32)
    tag = np.hstack([np.full(len(f_x2), 1, np.int32), np.full(len(f_y1), 2, np.int32)])
    order = np.argsort(fac)
    mt = dolfinx.mesh.meshtags(mesh, fdim, fac[order], tag[order])

    # Sub-spaces collapsed: temperature and the x component of u (scalar collapses are cheap; dolfinx 0.5's
    # collapse of the blocked u sub-space W.sub(0) costs 0.12 s at N=16 but several s at N=32, superlinear:
    # FEniCS/dolfinx#3282, so it is not used here).
    V_T, map_T = W.sub(1).collapse()
    V_x, map_x = W.sub(0).sub(0).collapse()
    # Dirichlet conditions on x = 0: theta = 100, u = 0 (per component, constant values)
    bcs = [dolfinx.fem.dirichletbc(PETSc.ScalarType(100.0), dolfinx.fem.locate_dofs_topological(W.sub(1), fdim, f_x0),
                                   W.sub(1))]
    for i in range(3):
        Wi = W.sub(0).sub(i)
        bcs.append(dolfinx.fem.dirichletbc(PETSc.ScalarType(0.0), dolfinx.fem.locate_dofs_topological(Wi, fdim, f_x0),
                                           Wi))

    # Field index sets (global numbering of W, owned dofs only; PCFIELDSPLIT wants them sorted). dolfinx
    # numbers the 4 dofs of a node u_x, u_y, u_z, theta consecutively in W, so the sorted u dofs are
    # node-interleaved (x,y,z per node) and the u split has block size 3.
    imap = W.dofmap.index_map
    assert W.dofmap.index_map_bs == 1
    n_own, first = imap.size_local, imap.local_range[0]
    own_T = np.sort(np.asarray(map_T[:V_T.dofmap.index_map.size_local]))
    is_theta = np.zeros(n_own, dtype=bool)
    is_theta[own_T] = True
    own_u = np.flatnonzero(~is_theta).astype(np.int64)
    nloc_u = own_u.size
    own_x = np.asarray(map_x[:V_x.dofmap.index_map.size_local])
    x_order = np.argsort(own_x)
    assert nloc_u == 3 * own_x.size and np.array_equal(own_x[x_order], own_u[0::3]), "u dofs not (x,y,z) per node"
    assert np.all(own_u[1::3] == own_u[0::3] + 1) and np.all(own_u[2::3] == own_u[0::3] + 2)
    is_u = PETSc.IS().createGeneral((first + own_u).astype(PETSc.IntType), comm=comm)
    is_u.setBlockSize(3)
    is_T = PETSc.IS().createGeneral((first + own_T).astype(PETSc.IntType), comm=comm)

    # near null space of the u block: the 6 rigid body modes at the nodes, in is_u's order
    xyz = V_x.tabulate_dof_coordinates()[:own_x.size][x_order]
    modes = []
    for m in range(6):
        blk = np.zeros((xyz.shape[0], 3), dtype=PETSc.ScalarType)
        if m < 3:
            blk[:, m] = 1.0  # translations
        elif m == 3:  # rotations about z, x, y
            blk[:, 0], blk[:, 1] = -xyz[:, 1], xyz[:, 0]
        elif m == 4:
            blk[:, 1], blk[:, 2] = -xyz[:, 2], xyz[:, 1]
        else:
            blk[:, 0], blk[:, 2] = xyz[:, 2], -xyz[:, 0]
        vec = PETSc.Vec().createMPI((nloc_u, PETSc.DECIDE), bsize=3, comm=comm)
        vec.setArray(blk.ravel())
        modes.append(vec)
    dolfinx.la.orthonormalize(modes)
    assert dolfinx.la.is_orthonormal(modes, eps=1e-10)
    nearnull = PETSc.NullSpace().create(vectors=modes, comm=comm)
    is_u.compose("nearnullspace", nearnull)  # PCFIELDSPLIT puts it on the u sub-matrix

    # forms
    u, T = ufl.TrialFunctions(W)
    v, s = ufl.TestFunctions(W)
    c = lambda val: dolfinx.fem.Constant(mesh, PETSc.ScalarType(val))  # noqa: E731
    E, nu, alpha, k, h, p = c(30e6), c(0.3), c(1e-5), c(10.0), c(50.0), c(1e3)
    T_sink = c(0.0)  # film sink temperature; the reference (initial) temperature of the expansion is 0 too
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    mu = E / (2 * (1 + nu))
    I3 = ufl.Identity(3)
    eps = ufl.sym(ufl.grad(u))
    sigma = lam * ufl.tr(eps) * I3 + 2 * mu * eps - (3 * lam + 2 * mu) * alpha * T * I3  # T_ref = 0
    n = ufl.FacetNormal(mesh)
    md = {"quadrature_degree": QDEG}
    dx = ufl.Measure("dx", domain=mesh, metadata=md)
    ds = ufl.Measure("ds", domain=mesh, subdomain_data=mt, metadata=md)
    a_ufl = ((ufl.inner(sigma, ufl.sym(ufl.grad(v))) + k * ufl.inner(ufl.grad(T), ufl.grad(s))) * dx
             + h * T * s * ds(1))
    L_ufl = -p * ufl.inner(n, v) * ds(2) + h * T_sink * s * ds(1)

with Phase("jit"):
    a_form = dolfinx.fem.form(a_ufl)
    L_form = dolfinx.fem.form(L_ufl)

# ---- assembly ---------------------------------------------------------------------------------------
with Phase("assembly"):
    A = dolfinx.fem.petsc.assemble_matrix(a_form, bcs=bcs)
    A.assemble()
    b = dolfinx.fem.petsc.assemble_vector(L_form)
    dolfinx.fem.petsc.apply_lifting(b, [a_form], bcs=[bcs])
    b.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
    dolfinx.fem.petsc.set_bc(b, bcs)

# ---- solver -----------------------------------------------------------------------------------------
w = dolfinx.fem.Function(W)
with Phase("solver_setup"):
    ksp = PETSc.KSP().create(comm)
    ksp.setOptionsPrefix(PREFIX)
    ksp.setOperators(A)
    pc = ksp.getPC()
    pc.setType("fieldsplit")
    pc.setFieldSplitIS(("T", is_T), ("u", is_u))  # temperature first
    ksp.setFromOptions()
    ksp.setUp()
    if pc.getType() == "fieldsplit":  # build the AMG hierarchies of the splits here, not in the first solve
        for sub in pc.getFieldSplitSubKSP():
            sub.setUp()
    ksp.setUpOnBlocks()

with Phase("solve"):
    ksp.solve(b, w.vector)
    w.x.scatter_forward()
its = ksp.getIterationNumber()
reason = ksp.getConvergedReason()
rnorm = ksp.getResidualNorm()

# ---- output -----------------------------------------------------------------------------------------
with Phase("output"):
    if WRITE:
        # u: interpolated (an exact copy, same nodes) into a vector Q1 space; theta: the collapse map
        uh = dolfinx.fem.Function(dolfinx.fem.FunctionSpace(mesh, Ue), name="U")
        uh.interpolate(w.sub(0))
        Th = dolfinx.fem.Function(V_T, name="NT")
        Th.x.array[:] = w.x.array[map_T]
        if rank == 0:
            os.makedirs(OUTDIR, exist_ok=True)
        comm.Barrier()
        with dolfinx.io.XDMFFile(comm, os.path.join(OUTDIR, "peer_block%d.xdmf" % N), "w") as xf:
            xf.write_mesh(mesh)
            xf.write_function(uh)
            xf.write_function(Th)

T_END = time.perf_counter()

# ---- check values: theta and u at the corner node (2,1,1), extremes ----------------------------------
xT = V_T.tabulate_dof_coordinates()[:V_T.dofmap.index_map.size_local]
uT = w.x.array[np.asarray(map_T[:xT.shape[0]])]
xU = V_x.tabulate_dof_coordinates()[:own_x.size]
uU = np.stack([w.x.array[own_x + i] for i in range(3)], axis=1)
probe = None
iT = np.flatnonzero(np.linalg.norm(xT - [2.0, 1.0, 1.0], axis=1) < 1e-10)
iU = np.flatnonzero(np.linalg.norm(xU - [2.0, 1.0, 1.0], axis=1) < 1e-10)
if len(iT) and len(iU):
    probe = (float(uT[iT[0]]), *[float(x) for x in uU[iU[0]]])
probe = [pr for pr in comm.allgather(probe) if pr is not None][0]
max_T = comm.allreduce(float(uT.max(initial=-np.inf)), op=MPI.MAX)
max_u = comm.allreduce(float(np.linalg.norm(uU, axis=1).max(initial=0.0)), op=MPI.MAX)

cpu_max = {k: comm.allreduce(v, op=MPI.MAX) for k, v in sorted(cpu.items())}
rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0  # MB (Linux: ru_maxrss in KiB)
rss_max = comm.allreduce(rss, op=MPI.MAX)
rss_sum = comm.allreduce(rss, op=MPI.SUM)
ndofs = imap.size_global

# ---- optional comparison with a thermoslide result --------------------------------------------------
cmp_line = ""
if COMPARE:
    allxT, allT = comm.gather(xT, root=0), comm.gather(uT, root=0)
    allxU, allu = comm.gather(xU, root=0), comm.gather(uU, root=0)
    if rank == 0:
        import h5py

        with h5py.File(COMPARE, "r") as f:
            X = f["mesh/coordinates"][:]
            fr = f["frames"][sorted(f["frames"].keys())[-1]]
            U_ts, T_ts = fr["U"][:], fr["NT"][:].ravel()
        key = lambda x: np.lexsort(np.round(x * 8 * N).T)  # noqa: E731 (nodes on a lattice of step 1/N)
        ib = key(X)
        xp, Tp = np.vstack(allxT), np.hstack(allT)
        ia = key(xp)
        assert len(ia) == len(ib) and np.allclose(xp[ia], X[ib], atol=1e-9), "node sets differ (theta)"
        dT = np.abs(Tp[ia] - T_ts[ib]).max() / np.abs(T_ts).max()
        xp, up = np.vstack(allxU), np.vstack(allu)
        ia = key(xp)
        assert len(ia) == len(ib) and np.allclose(xp[ia], X[ib], atol=1e-9), "node sets differ (u)"
        dU = np.abs(up[ia] - U_ts[ib]).max() / np.abs(U_ts).max()
        cmp_line = "compare %s: max|dNT|/max|NT| %.3e  max|dU|/max|U| %.3e" % (COMPARE, dT, dU)

if rank == 0:
    total = T_END - T_START - times["jit"]
    rows = [("import (python, dolfinx, petsc4py)", times["import"]),
            ("mesh (create_box + distribute)", times["mesh"]),
            ("fe setup (dofmap, BCs, ISs, near null space)", times["fe_setup"]),
            ("assembly (matrix + rhs, lifting, BCs)", times["assembly"]),
            ("solver setup (KSP/PC, AMG hierarchies)", times["solver_setup"]), ("solve (KSP)", times["solve"]),
            ("output (XDMF/HDF5)" + ("" if WRITE else " - disabled"), times["output"]),
            ("total (wall, excluding JIT)", total), ("JIT (FFCx/CFFI, or cache load)", times["jit"])]
    print("peer_block N=%d ranks=%d dofs=%d (nodes %d) hexahedra %d, quadrature degree %d" %
          (N, comm.size, ndofs, ndofs // 4, 2 * N ** 3, QDEG))
    print("KSP %s/PC %s: %d iterations, reason %d, final residual %.3e" %
          (ksp.getType(), pc.getType(), its, reason, rnorm))
    print("  %-48s %9s   %s" % ("phase", "wall", "cpu (max over ranks)"))
    for (name, t), ph in zip(rows, ["import", "mesh", "fe_setup", "assembly", "solver_setup", "solve", "output", None,
                                    "jit"]):
        print("  %-48s %9.3f s %s" % (name, t, " %8.3f s" % cpu_max[ph] if ph in cpu_max else ""))
    print("  %-48s %9.1f MB max/rank, %.1f MB sum" % ("peak RSS", rss_max, rss_sum))
    print("check: theta(2,1,1) %.10g  u(2,1,1) %.10g %.10g %.10g  max theta %.10g  max|u| %.10g" %
          (probe[0], probe[1], probe[2], probe[3], max_T, max_u))
    if cmp_line:
        print(cmp_line)
    print("PEER n=%d ranks=%d dofs=%d its=%d reason=%d import=%.4f mesh=%.4f fe_setup=%.4f jit=%.4f assembly=%.4f "
          "solver_setup=%.4f solve=%.4f output=%.4f total=%.4f total_excl_import=%.4f rss_max_mb=%.1f "
          "rss_sum_mb=%.1f theta_211=%.10g uy_211=%.10g max_theta=%.10g max_u=%.10g cpu_assembly=%.4f "
          "cpu_solver_setup=%.4f cpu_solve=%.4f" %
          (N, comm.size, ndofs, its, reason, times["import"], times["mesh"], times["fe_setup"], times["jit"],
           times["assembly"], times["solver_setup"], times["solve"], times["output"], total, total - times["import"],
           rss_max, rss_sum, probe[0], probe[2], max_T, max_u, cpu_max["assembly"], cpu_max["solver_setup"],
           cpu_max["solve"]))
    sys.stdout.flush()
if reason < 0:
    sys.exit(1)
