/* Explicit force records: the element forces of an explicit increment from data computed once.
 *
 * Why: an explicit increment evaluates every element's internal force and heat flow once, thousands of
 * times over. In this code's small-strain kinematics the element geometry (Jacobians, spatial gradients,
 * volumes) is that of the reference configuration and never changes, and with temperature-independent
 * properties the conduction R_theta = K_theta theta is linear. The generic kernel (kernels.c) recomputes
 * both at every call, through loops of run-time length sized for the largest family: about 6.5 k flops and
 * 5 us per C3D8T element per increment. A record per element holds what does not change:
 *
 *   header   row, lambda, mu, alpha, lambda + 2 mu, hourglass kappa (two spare)
 *   G        spatial gradients dN_a/dx at each mechanical point, [nq][dim][n]
 *   dV       the points' volumes (thickness or 2 pi r included), [nq]
 *   Nr       N_a / r at each point (axisymmetric: the hoop strain u_r / r), [nq][n]
 *   K        the conduction matrix k int grad N_a . grad N_b dV (full rule), [n][n]
 *   centre   the bulk viscosity's point (full rows; a reduced row's mechanical point is the centre):
 *            gradients [dim][n], volume, N_a / r (axisymmetric)
 *   gamma    the hourglass vectors of a reduced row, [nh][n]
 *
 * and TslElementFastForce evaluates the generic kernel's formulas from it (kernels.c, Mechanics with the
 * isotropic D written out: sigma = lambda tr(eps_mech) m + 2 mu eps_mech; Conduction; the hourglass
 * control of formulations.c; TslElementBulkViscosity), with loops whose lengths are compile-time
 * constants of each row, so the compiler unrolls and vectorises them. Results agree with the generic
 * path to rounding (tests/element/fast_records.c). Memory: C3D8T 2.4 kB, C3D8RT 1.1 kB per element.
 */
#include "element_impl.h"
#include <string.h>

#define HEADER 8

/* Offsets of the record's parts (constants once the row's sizes are). */
typedef struct {
  PetscInt G, dV, Nr, K, Gc, Vc, Nrc, gamma, size;
} Layout;

static inline Layout LayoutOf(PetscInt dim, PetscInt n, PetscInt nq, PetscInt nh, PetscBool axi)
{
  Layout L;
  L.G     = HEADER;
  L.dV    = L.G + nq * n * dim;
  L.Nr    = L.dV + nq;
  L.K     = L.Nr + (axi ? nq * n : 0);
  L.Gc    = L.K + n * n;
  L.Vc    = L.Gc + (nq > 1 ? n * dim : 0);
  L.Nrc   = L.Vc + (nq > 1 ? 1 : 0);
  L.gamma = L.Nrc + (nq > 1 && axi ? n : 0);
  L.size  = L.gamma + nh * n;
  if (nq == 1) L.Gc = L.G, L.Vc = L.dV, L.Nrc = L.Nr; /* the one mechanical point is the centre */
  return L;
}

/* Lanes: the kernel works on TSL_FAST_LANES elements of one row at a time, every real a vector of their
 * values (GCC/Clang vector extensions: the compiler maps them on AVX2 registers in the x86-64-v3 clone, on
 * pairs of SSE2 registers in the baseline one), so each instruction serves the batch's elements alike and
 * the sums over an element's nodes need no horizontal adds or shuffles. A batch's records are interleaved
 * by lane (value k of lane j at rec[k * W + j]); the unknowns and results likewise. */
#define W TSL_FAST_LANES
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi" /* the helpers below are always inlined: no vector crosses a call */
#endif
typedef PetscReal V __attribute__((vector_size(W * sizeof(PetscReal))));
typedef long long VI __attribute__((vector_size(W * sizeof(PetscReal))));

static inline __attribute__((always_inline)) V Ld(const PetscReal *p)
{
  V v;
  memcpy(&v, p, sizeof(v));
  return v;
}
static inline __attribute__((always_inline)) void St(PetscReal *p, V v) { memcpy(p, &v, sizeof(v)); }

/* The forces of one batch (see the file's head). Inlined into each row's function with constant sizes.
 * Gradients are stored by component ([d][a]) and the unknowns split by component first. */
static inline __attribute__((always_inline)) void Force(const PetscInt dim, const PetscInt n, const PetscInt nq, const PetscInt nh,
                                                        const PetscBool axi, const TslElementFastShape *shape, const PetscReal *rec,
                                                        const PetscReal *u, const PetscReal *ti, const PetscReal *v, const PetscReal *eta,
                                                        const PetscReal *eta2, PetscReal *R, PetscReal *Rv, PetscReal *power, PetscReal *energy)
{
  const PetscInt nd     = dim + 1;
  const Layout   L      = LayoutOf(dim, n, nq, nh, axi);
  const V        lambda = Ld(rec + 1 * W), mu = Ld(rec + 2 * W), alpha = Ld(rec + 3 * W);
  V              U[3][TSL_FAST_MAX_NODES], th[TSL_FAST_MAX_NODES], dth[TSL_FAST_MAX_NODES], F[3][TSL_FAST_MAX_NODES], Fth[TSL_FAST_MAX_NODES];
  V              en[2] = {{0}, {0}};

  for (PetscInt a = 0; a < n; a++) {
    for (PetscInt d = 0; d < dim; d++) U[d][a] = Ld(u + (nd * a + d) * W), F[d][a] = (V){0};
    th[a] = Ld(u + (nd * a + dim) * W), dth[a] = th[a] - Ld(ti + a * W);
  }
  for (PetscInt q = 0; q < nq; q++) {
    const PetscReal *Gx = rec + (L.G + q * n * dim) * W, *Gy = Gx + n * W, *Gz = Gy + n * W, *Nr = rec + (L.Nr + q * n) * W, *Nq = shape->N[q];
    const V          dV = Ld(rec + (L.dV + q) * W);
    V                e[6] = {{0}, {0}, {0}, {0}, {0}, {0}}, s[6], eth = {0}, tr;
    for (PetscInt a = 0; a < n; a++) eth += Nq[a] * dth[a];
    eth *= alpha;
    for (PetscInt a = 0; a < n; a++) {
      const V gx = Ld(Gx + a * W), gy = Ld(Gy + a * W);
      e[0] += gx * U[0][a];
      e[1] += gy * U[1][a];
      e[3] += gy * U[0][a] + gx * U[1][a];
      if (dim == 3) {
        const V gz = Ld(Gz + a * W);
        e[2] += gz * U[2][a];
        e[4] += gz * U[0][a] + gx * U[2][a];
        e[5] += gz * U[1][a] + gy * U[2][a];
      } else if (axi)
        e[2] += Ld(Nr + a * W) * U[0][a];
    }
    tr = e[0] + e[1] + e[2] - 3 * eth;
    for (PetscInt r = 0; r < 3; r++) s[r] = (lambda * tr + 2 * mu * (e[r] - eth)) * dV;
    for (PetscInt r = 3; r < 6; r++) s[r] = mu * e[r] * dV;
    if (energy) /* 1/2 sigma : eps_mech dV, as the generic output (kernels.c, Mechanics) */
      for (PetscInt r = 0; r < 6; r++) en[0] += 0.5 * s[r] * (r < 3 ? e[r] - eth : e[r]);
    for (PetscInt a = 0; a < n; a++) {
      const V gx = Ld(Gx + a * W), gy = Ld(Gy + a * W);
      if (dim == 3) {
        const V gz = Ld(Gz + a * W);
        F[0][a] += gx * s[0] + gy * s[3] + gz * s[4];
        F[1][a] += gy * s[1] + gx * s[3] + gz * s[5];
        F[2][a] += gz * s[2] + gx * s[4] + gy * s[5];
      } else {
        F[0][a] += gx * s[0] + gy * s[3];
        if (axi) F[0][a] += Ld(Nr + a * W) * s[2];
        F[1][a] += gy * s[1] + gx * s[3];
      }
    }
  }
  for (PetscInt a = 0; a < n; a++) Fth[a] = (V){0};
  for (PetscInt b = 0; b < n; b++) { /* K is symmetric: column b times theta_b, contiguous */
    const PetscReal *K = rec + (L.K + b * n) * W;
    for (PetscInt a = 0; a < n; a++) Fth[a] += Ld(K + a * W) * th[b];
  }
  for (PetscInt k = 0; k < nh; k++) {
    const PetscReal *gam   = rec + (L.gamma + k * n) * W;
    const V          kappa = Ld(rec + 5 * W);
    for (PetscInt d = 0; d < dim; d++) {
      V qk = {0};
      for (PetscInt a = 0; a < n; a++) qk += Ld(gam + a * W) * U[d][a];
      if (energy) en[1] += 0.5 * kappa * qk * qk;
      qk *= kappa;
      for (PetscInt a = 0; a < n; a++) F[d][a] += Ld(gam + a * W) * qk;
    }
  }
  for (PetscInt a = 0; a < n; a++) {
    for (PetscInt d = 0; d < dim; d++) St(R + (nd * a + d) * W, F[d][a]);
    St(R + (nd * a + dim) * W, Fth[a]);
  }
  if (energy) St(energy, en[0]), St(energy + W, en[1]);
  if (Rv) { /* lanes without viscosity (eta = eta2 = 0) get zero forces and power */
    const PetscReal *Gc = rec + L.Gc * W, *Nrc = rec + L.Nrc * W;
    const V          Vc = Ld(rec + L.Vc * W), cd = Ld(rec + 4 * W);
    V                rate = {0}, p, neg, gd[3][TSL_FAST_MAX_NODES];
    for (PetscInt a = 0; a < n; a++)
      for (PetscInt d = 0; d < dim; d++) {
        gd[d][a] = Ld(Gc + (d * n + a) * W);
        if (axi && d == 0) gd[d][a] += Ld(Nrc + a * W);
        rate += gd[d][a] * Ld(v + (nd * a + d) * W);
      }
    neg = (V)((VI)rate & (rate < 0)); /* the quadratic term, in compression only */
    p   = Ld(eta) * cd * rate - Ld(eta2) * cd * neg * neg;
    for (PetscInt a = 0; a < n; a++) {
      for (PetscInt d = 0; d < dim; d++) St(Rv + (nd * a + d) * W, p * gd[d][a] * Vc);
      St(Rv + (nd * a + dim) * W, (V){0});
    }
    St(power, p * rate * Vc);
  }
}

/* One function per row, each cloned for x86-64-v3 (AVX2, FMA) beside the baseline build where the
 * compiler can: the loader picks the clone the machine runs (GCC function multi-versioning), so a Debian
 * build stays portable and still uses the wide registers. */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define CLONES
#endif
#define FORCE_ROW(name, dim, n, nq, nh, axi)                                                                                                         \
  CLONES static void name(const TslElementFastShape *sh, const PetscReal *rec, const PetscReal *u, const PetscReal *ti, const PetscReal *v,          \
                          const PetscReal *eta, const PetscReal *eta2, PetscReal *R, PetscReal *Rv, PetscReal *power, PetscReal *energy)             \
  {                                                                                                                                                  \
    Force(dim, n, nq, nh, axi, sh, rec, u, ti, v, eta, eta2, R, Rv, power, energy);                                                                  \
  }
FORCE_ROW(Hex8Full, 3, 8, 8, 0, PETSC_FALSE)
FORCE_ROW(Hex8Reduced, 3, 8, 1, 4, PETSC_FALSE)
FORCE_ROW(Quad4Full, 2, 4, 4, 0, PETSC_FALSE)
FORCE_ROW(Quad4Reduced, 2, 4, 1, 1, PETSC_FALSE)
FORCE_ROW(Quad4FullAxi, 2, 4, 4, 0, PETSC_TRUE)
FORCE_ROW(Quad4ReducedAxi, 2, 4, 1, 1, PETSC_TRUE)
FORCE_ROW(Tet4Full, 3, 4, 1, 0, PETSC_FALSE)
FORCE_ROW(Tet10Full, 3, 10, 4, 0, PETSC_FALSE)
FORCE_ROW(Wedge6Full, 3, 6, 6, 0, PETSC_FALSE)
FORCE_ROW(Tri3Full, 2, 3, 1, 0, PETSC_FALSE)
FORCE_ROW(Tri6Full, 2, 6, 3, 0, PETSC_FALSE)
FORCE_ROW(Quad8Full, 2, 8, 9, 0, PETSC_FALSE)
FORCE_ROW(Tri3FullAxi, 2, 3, 1, 0, PETSC_TRUE)
FORCE_ROW(Tri6FullAxi, 2, 6, 3, 0, PETSC_TRUE)
FORCE_ROW(Quad8FullAxi, 2, 8, 9, 0, PETSC_TRUE)

typedef void (*ForceFn)(const TslElementFastShape *, const PetscReal *, const PetscReal *, const PetscReal *, const PetscReal *, const PetscReal *,
                        const PetscReal *, PetscReal *, PetscReal *, PetscReal *, PetscReal *);

/* The rows: which (family, formulation, kinematics) have a record, and its sizes. */
typedef struct {
  const TslGeometry    *geom;
  const TslFormulation *form;
  TslKinematics         kin;
  PetscInt              nq, nh;
  ForceFn               force;
} FastRow;

static const FastRow Rows[] = {
    {&TslGeomHex8, &TslFormFull, TSL_KIN_SOLID3D, 8, 0, Hex8Full},
    {&TslGeomHex8, &TslFormReduced, TSL_KIN_SOLID3D, 1, 4, Hex8Reduced},
    {&TslGeomQuad4, &TslFormFull, TSL_KIN_PLANE_STRAIN, 4, 0, Quad4Full},
    {&TslGeomQuad4, &TslFormReduced, TSL_KIN_PLANE_STRAIN, 1, 1, Quad4Reduced},
    {&TslGeomQuad4, &TslFormFull, TSL_KIN_AXISYMMETRIC, 4, 0, Quad4FullAxi},
    {&TslGeomQuad4, &TslFormReduced, TSL_KIN_AXISYMMETRIC, 1, 1, Quad4ReducedAxi},
    {&TslGeomTet4, &TslFormFull, TSL_KIN_SOLID3D, 1, 0, Tet4Full},
    {&TslGeomTet10, &TslFormModified, TSL_KIN_SOLID3D, 4, 0, Tet10Full}, /* modified: lumping and pressure faces differ, not the force */
    {&TslGeomWedge6, &TslFormFull, TSL_KIN_SOLID3D, 6, 0, Wedge6Full},
    {&TslGeomTri3, &TslFormFull, TSL_KIN_PLANE_STRAIN, 1, 0, Tri3Full},
    {&TslGeomTri6, &TslFormModified, TSL_KIN_PLANE_STRAIN, 3, 0, Tri6Full},
    {&TslGeomQuad8, &TslFormFull, TSL_KIN_PLANE_STRAIN, 9, 0, Quad8Full},
    {&TslGeomTri3, &TslFormFull, TSL_KIN_AXISYMMETRIC, 1, 0, Tri3FullAxi},
    {&TslGeomTri6, &TslFormModified, TSL_KIN_AXISYMMETRIC, 3, 0, Tri6FullAxi},
    {&TslGeomQuad8, &TslFormFull, TSL_KIN_AXISYMMETRIC, 9, 0, Quad8FullAxi},
};

static PetscInt RowOf(const TslElementType *t)
{
  for (PetscInt r = 0; r < (PetscInt)(sizeof(Rows) / sizeof(Rows[0])); r++)
    if (Rows[r].geom == t->geom && Rows[r].form == t->form && Rows[r].kin == t->kin && t->nextra == 0 &&
        t->form->quadrature(t->geom)->n == Rows[r].nq) /* the row's compile-time point count is the rule's */
      return r;
  return -1;
}

static Layout RowLayout(PetscInt r)
{
  const FastRow *row = &Rows[r];
  return LayoutOf(row->geom->dim, row->geom->nnode, row->nq, row->nh, TslKinematicsRowGet(row->kin)->revolve);
}

PetscBool TslElementFastShapeGet(const TslElementType *t, TslElementFastShape *shape)
{
  const PetscInt       r = RowOf(t);
  const TslQuadrature *quad;
  PetscReal            dN[TSL_MAX_ELEM_NODES * 3], N[TSL_MAX_ELEM_NODES];

  shape->row = r, shape->size = 0;
  if (r < 0 || RowLayout(r).size > TSL_FAST_MAX_SIZE) return PETSC_FALSE;
  shape->size = RowLayout(r).size;
  quad = t->form->quadrature(t->geom);
  for (PetscInt q = 0; q < quad->n; q++) {
    t->geom->shape(quad->xi[q], N, dN);
    for (PetscInt a = 0; a < t->geom->nnode; a++) shape->N[q][a] = N[a];
  }
  return PETSC_TRUE;
}

PetscInt TslElementFastSize(const TslElementInput *in)
{
  const PetscInt r = RowOf(in->type);
  if (r < 0 || TslMaterialIsTemperatureDependent(in->sec->mat)) return 0;
  return RowLayout(r).size;
}

/* Gradients (and N_a / r) of point p into G[dim][n] (and Nr[n]). */
static void StorePoint(const TslElementPoint *p, PetscInt n, PetscInt dim, PetscBool axi, PetscReal G[], PetscReal Nr[])
{
  for (PetscInt a = 0; a < n; a++) {
    for (PetscInt d = 0; d < dim; d++) G[d * n + a] = p->dNdx[a][d];
    if (axi) Nr[a] = p->N[a] / p->x[0];
  }
}

PetscBool TslElementFastBuild(const TslElementInput *in, PetscReal rec[])
{
  const TslElementType *t = in->type;
  const TslGeometry    *g = t->geom;
  const PetscInt        r = RowOf(t), n = g->nnode, dim = g->dim;
  const PetscBool       axi    = TslKinematicsRowGet(t->kin)->revolve;
  const TslQuadrature  *quad   = t->form->quadrature(g);
  PetscReal             xi0[3] = {0, 0, 0}; /* the centre: the corners' centroid, as TslElementBulkViscosity's */
  Layout                L;
  TslMaterialPoint      mp;
  TslElementPoint       p;
  PetscReal             lambda, mu;

  if (r < 0) return PETSC_FALSE;
  for (PetscInt a = 0; a < g->ncorner; a++)
    for (PetscInt d = 0; d < g->dim; d++) xi0[d] += g->node_xi[a][d] / g->ncorner;
  L = RowLayout(r);
  for (PetscInt i = 0; i < L.size; i++) rec[i] = 0;
  TslMaterialEval(in->sec->mat, 0, &mp);
  TslElementLame(&mp, &lambda, &mu);
  rec[0] = (PetscReal)r, rec[1] = lambda, rec[2] = mu, rec[3] = mp.alpha, rec[4] = lambda + 2 * mu;
  for (PetscInt q = 0; q < quad->n; q++) {
    if (!TslElementPointEvaluate(t, in->sec, in->x, quad->xi[q], quad->w[q], &p)) return PETSC_FALSE;
    StorePoint(&p, n, dim, axi, &rec[L.G + q * n * dim], &rec[L.Nr + q * n]);
    rec[L.dV + q] = p.dV;
  }
  for (PetscInt q = 0; q < g->full.n; q++) { /* conduction: the full rule in every formulation */
    if (!TslElementPointEvaluate(t, in->sec, in->x, g->full.xi[q], g->full.w[q], &p)) return PETSC_FALSE;
    for (PetscInt a = 0; a < n; a++)
      for (PetscInt b = 0; b < n; b++) {
        PetscReal kab = 0;
        for (PetscInt d = 0; d < dim; d++) kab += p.dNdx[a][d] * p.dNdx[b][d];
        rec[L.K + a * n + b] += mp.k * kab * p.dV;
      }
  }
  /* the centre: the bulk viscosity's point and the hourglass control's (xi = 0 for quad4 and hex8) */
  if (!TslElementPointEvaluate(t, in->sec, in->x, xi0, g->ref_volume, &p)) return PETSC_FALSE;
  if (quad->n > 1) {
    StorePoint(&p, n, dim, axi, &rec[L.Gc], &rec[L.Nrc]);
    rec[L.Vc] = p.dV;
  }
  if (Rows[r].nh) {
    PetscReal gamma[4][TSL_MAX_ELEM_NODES], bb;
    PetscInt  nh = TslElementHourglassBase(in, &p, gamma, &bb);
    if (nh != Rows[r].nh) return PETSC_FALSE;
    rec[5] = TslElementHourglassKappa(mu, p.dV, bb);
    for (PetscInt k = 0; k < nh; k++)
      for (PetscInt a = 0; a < n; a++) rec[L.gamma + k * n + a] = gamma[k][a];
  }
  return PETSC_TRUE;
}

void TslElementFastInterleave(PetscInt size, PetscInt lane, const PetscReal rec[], PetscReal batch[])
{
  for (PetscInt k = 0; k < size; k++) batch[k * W + lane] = rec[k];
}

void TslElementFastForceBatch(const TslElementFastShape *shape, const PetscReal rec[], const PetscReal u[], const PetscReal ti[], const PetscReal v[],
                              const PetscReal eta[], const PetscReal eta2[], PetscReal R[], PetscReal Rv[], PetscReal power[])
{
  if (!Rv)
    for (PetscInt j = 0; j < W; j++) power[j] = 0;
  Rows[shape->row].force(shape, rec, u, ti, v, eta, eta2, R, Rv, power, NULL);
}

void TslElementFastEnergyBatch(const TslElementFastShape *shape, const PetscReal rec[], const PetscReal u[], const PetscReal ti[], PetscReal strain[],
                               PetscReal hourglass[])
{
  PetscReal R[TSL_MAX_ELEM_DOF * W], energy[2 * W];

  Rows[shape->row].force(shape, rec, u, ti, NULL, NULL, NULL, R, NULL, NULL, energy);
  for (PetscInt j = 0; j < W; j++) strain[j] = energy[j], hourglass[j] = energy[W + j];
}

/* One element: its record and data copied into every lane of a batch (tests and benchmarks; the explicit
 * loop calls the batch functions). */
typedef struct {
  PetscReal rec[TSL_FAST_MAX_SIZE * W], u[TSL_MAX_ELEM_DOF * W], ti[TSL_FAST_MAX_NODES * W], v[TSL_MAX_ELEM_DOF * W], R[TSL_MAX_ELEM_DOF * W],
    Rv[TSL_MAX_ELEM_DOF * W];
} Single;

static void SingleFill(const TslElementFastShape *shape, const PetscReal rec[], const PetscReal u[], const PetscReal ti[], const PetscReal v[],
                       Single *s)
{
  const FastRow *row = &Rows[shape->row];
  const PetscInt n = row->geom->nnode, nd = n * (row->geom->dim + 1);

  for (PetscInt j = 0; j < W; j++) {
    TslElementFastInterleave(RowLayout(shape->row).size, j, rec, s->rec);
    TslElementFastInterleave(nd, j, u, s->u);
    TslElementFastInterleave(n, j, ti, s->ti);
    if (v) TslElementFastInterleave(nd, j, v, s->v);
  }
}

void TslElementFastForce(const TslElementFastShape *shape, const PetscReal rec[], const PetscReal u[], const PetscReal ti[], const PetscReal v[],
                         PetscReal eta, PetscReal eta2, PetscReal R[], PetscReal Rv[], PetscReal *power)
{
  Single         s;
  const FastRow *row = &Rows[shape->row];
  const PetscInt nd  = row->geom->nnode * (row->geom->dim + 1);
  const PetscBool bv = (eta > 0 || eta2 > 0) && Rv ? PETSC_TRUE : PETSC_FALSE;
  PetscReal      e1[W], e2[W], w[W];

  for (PetscInt j = 0; j < W; j++) e1[j] = eta, e2[j] = eta2;
  SingleFill(shape, rec, u, ti, bv ? v : NULL, &s);
  TslElementFastForceBatch(shape, s.rec, s.u, s.ti, bv ? s.v : NULL, e1, e2, s.R, bv ? s.Rv : NULL, w);
  for (PetscInt i = 0; i < nd; i++) {
    R[i] = s.R[i * W];
    if (bv) Rv[i] = s.Rv[i * W];
  }
  *power = w[0];
}

void TslElementFastEnergy(const TslElementFastShape *shape, const PetscReal rec[], const PetscReal u[], const PetscReal ti[], PetscReal *strain,
                          PetscReal *hourglass)
{
  Single    s;
  PetscReal se[W], hg[W];

  SingleFill(shape, rec, u, ti, NULL, &s);
  TslElementFastEnergyBatch(shape, s.rec, s.u, s.ti, se, hg);
  *strain = se[0], *hourglass = hg[0];
}
