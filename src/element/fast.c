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

/* The force of one element (see the file's head). Inlined into each row's function with constant sizes.
 * Gradients are stored by component ([d][a]) and the unknowns split by component first, so that every sum
 * over the nodes is over contiguous arrays of constant length: what the vectoriser needs. */
static inline __attribute__((always_inline)) void Force(const PetscInt dim, const PetscInt n, const PetscInt nq, const PetscInt nh,
                                                        const PetscBool axi, const TslElementFastShape *shape, const PetscReal *rec,
                                                        const PetscReal *u, const PetscReal *ti, const PetscReal *v, PetscReal eta, PetscReal eta2,
                                                        PetscReal *R, PetscReal *Rv, PetscReal *power, PetscReal *energy)
{
  const PetscInt  nd     = dim + 1;
  const Layout    L      = LayoutOf(dim, n, nq, nh, axi);
  const PetscReal lambda = rec[1], mu = rec[2], alpha = rec[3];
  PetscReal       U[3][TSL_FAST_MAX_NODES], th[TSL_FAST_MAX_NODES], dth[TSL_FAST_MAX_NODES], F[3][TSL_FAST_MAX_NODES], Fth[TSL_FAST_MAX_NODES];

  for (PetscInt a = 0; a < n; a++) {
    for (PetscInt d = 0; d < dim; d++) U[d][a] = u[nd * a + d], F[d][a] = 0;
    th[a] = u[nd * a + dim], dth[a] = th[a] - ti[a];
  }
  for (PetscInt q = 0; q < nq; q++) {
    const PetscReal *Gx = rec + L.G + q * n * dim, *Gy = Gx + n, *Gz = Gy + n, *Nr = rec + L.Nr + q * n, *Nq = shape->N[q], dV = rec[L.dV + q];
    PetscReal        e[6] = {0, 0, 0, 0, 0, 0}, s[6], eth = 0, tr;
    for (PetscInt a = 0; a < n; a++) eth += Nq[a] * dth[a];
    eth *= alpha;
    for (PetscInt a = 0; a < n; a++) {
      e[0] += Gx[a] * U[0][a];
      e[1] += Gy[a] * U[1][a];
      e[3] += Gy[a] * U[0][a] + Gx[a] * U[1][a];
      if (dim == 3) {
        e[2] += Gz[a] * U[2][a];
        e[4] += Gz[a] * U[0][a] + Gx[a] * U[2][a];
        e[5] += Gz[a] * U[1][a] + Gy[a] * U[2][a];
      } else if (axi)
        e[2] += Nr[a] * U[0][a];
    }
    tr = e[0] + e[1] + e[2] - 3 * eth;
    for (PetscInt r = 0; r < 3; r++) s[r] = (lambda * tr + 2 * mu * (e[r] - eth)) * dV;
    for (PetscInt r = 3; r < 6; r++) s[r] = mu * e[r] * dV;
    if (energy) /* 1/2 sigma : eps_mech dV, as the generic output (kernels.c, Mechanics) */
      for (PetscInt r = 0; r < 6; r++) energy[0] += 0.5 * s[r] * (r < 3 ? e[r] - eth : e[r]);
    for (PetscInt a = 0; a < n; a++) {
      if (dim == 3) {
        F[0][a] += Gx[a] * s[0] + Gy[a] * s[3] + Gz[a] * s[4];
        F[1][a] += Gy[a] * s[1] + Gx[a] * s[3] + Gz[a] * s[5];
        F[2][a] += Gz[a] * s[2] + Gx[a] * s[4] + Gy[a] * s[5];
      } else {
        F[0][a] += Gx[a] * s[0] + Gy[a] * s[3] + (axi ? Nr[a] * s[2] : 0);
        F[1][a] += Gy[a] * s[1] + Gx[a] * s[3];
      }
    }
  }
  for (PetscInt a = 0; a < n; a++) Fth[a] = 0;
  for (PetscInt b = 0; b < n; b++) { /* K is symmetric: column b times theta_b, contiguous */
    const PetscReal *K = rec + L.K + b * n;
    for (PetscInt a = 0; a < n; a++) Fth[a] += K[a] * th[b];
  }
  for (PetscInt k = 0; k < nh; k++) {
    const PetscReal *gam = rec + L.gamma + k * n;
    for (PetscInt d = 0; d < dim; d++) {
      PetscReal qk = 0;
      for (PetscInt a = 0; a < n; a++) qk += gam[a] * U[d][a];
      if (energy) energy[1] += 0.5 * rec[5] * qk * qk;
      qk *= rec[5];
      for (PetscInt a = 0; a < n; a++) F[d][a] += gam[a] * qk;
    }
  }
  for (PetscInt a = 0; a < n; a++) {
    for (PetscInt d = 0; d < dim; d++) R[nd * a + d] = F[d][a];
    R[nd * a + dim] = Fth[a];
  }
  *power = 0;
  if ((eta > 0 || eta2 > 0) && Rv) {
    const PetscReal *Gc = rec + L.Gc, *Nrc = rec + L.Nrc, Vc = rec[L.Vc];
    PetscReal        rate = 0, p;
    for (PetscInt a = 0; a < n; a++)
      for (PetscInt d = 0; d < dim; d++) rate += (Gc[d * n + a] + (axi && d == 0 ? Nrc[a] : 0)) * v[nd * a + d];
    p = eta * rec[4] * rate;
    if (rate < 0) p -= eta2 * rec[4] * rate * rate; /* the quadratic term, in compression only */
    for (PetscInt a = 0; a < n; a++) {
      for (PetscInt d = 0; d < dim; d++) Rv[nd * a + d] = p * (Gc[d * n + a] + (axi && d == 0 ? Nrc[a] : 0)) * Vc;
      Rv[nd * a + dim] = 0;
    }
    *power = p * rate * Vc;
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
                          PetscReal eta, PetscReal eta2, PetscReal *R, PetscReal *Rv, PetscReal *power, PetscReal *energy)                           \
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

typedef void (*ForceFn)(const TslElementFastShape *, const PetscReal *, const PetscReal *, const PetscReal *, const PetscReal *, PetscReal, PetscReal,
                        PetscReal *, PetscReal *, PetscReal *, PetscReal *);

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

  shape->row = r;
  if (r < 0) return PETSC_FALSE;
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

void TslElementFastForce(const TslElementFastShape *shape, const PetscReal rec[], const PetscReal u[], const PetscReal ti[], const PetscReal v[],
                         PetscReal eta, PetscReal eta2, PetscReal R[], PetscReal Rv[], PetscReal *power)
{
  Rows[shape->row].force(shape, rec, u, ti, v, eta, eta2, R, Rv, power, NULL);
}

void TslElementFastEnergy(const TslElementFastShape *shape, const PetscReal rec[], const PetscReal u[], const PetscReal ti[], PetscReal *strain,
                          PetscReal *hourglass)
{
  PetscReal R[TSL_MAX_ELEM_DOF], w, energy[2] = {0, 0};

  Rows[shape->row].force(shape, rec, u, ti, NULL, 0, 0, R, NULL, &w, energy);
  *strain = energy[0], *hourglass = energy[1];
}
