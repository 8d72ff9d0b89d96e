/* Coupled temperature-displacement kernels, for every type in the catalogue: patch-type checks
 * (rigid motion, free thermal expansion, constrained expansion, linear temperature), volumes, tangent
 * against central differences of the residual, face loads, body forces, heat change and inverted elements; a continuum
 * shell's STACK DIRECTION (its element renumbered). */
#include <string.h>
#include "check.h"

typedef struct {
  const TslElementType *type;
  TslMaterial           mat;
  TslElementSection     sec;
  PetscReal             x[TSL_MAX_ELEM_NODES * 3], u[TSL_MAX_ELEM_DOF], u_old[TSL_MAX_ELEM_DOF], theta_init[TSL_MAX_ELEM_NODES];
  TslElementInput       in, in_old;
  PetscReal             shift; /* capacity rate factor (backward Euler 1/dt; 0 steady) */
  PetscReal             E, nu, k, rho, c;
} Case;

static const PetscReal ALPHA = 1e-3, THETA0 = 20;

static void Constant(TslPropertyTable *t, PetscReal v0, PetscReal v1)
{
  t->n           = 1;
  t->value[0][0] = v0, t->value[0][1] = v1;
}

/* Every property linear in temperature between 0 and 40 (the tangent checks' temperatures lie inside). */
static void TemperatureDependent(Case *c)
{
  const PetscReal f[TSL_NPROP][2] = {{0.7, 0.9}, {0.5, 0.8}, {1, 1}, {0.6, 0.7}, {0.5, 0.75}};
  for (PetscInt k = 0; k < TSL_NPROP; k++) {
    TslPropertyTable *t = &c->mat.prop[k];
    t->n                = 2;
    t->theta[0] = 0, t->theta[1] = 40;
    t->value[1][0] = t->value[0][0] * f[k][1];
    t->value[1][1] = t->value[0][1] * (k == TSL_PROP_ELASTIC ? 1.2 : 1);
    t->value[0][0] *= f[k][0];
  }
}

/* eps_33 = 0: plane strain, and generalized plane strain with its reference node at rest */
static PetscBool PlaneStrainLike(const TslElementType *t)
{
  return t->kin == TSL_KIN_PLANE_STRAIN || t->kin == TSL_KIN_GENERALIZED_PLANE_STRAIN;
}

static PetscBool IsAxi(const TslElementType *t)
{
  return t->kin == TSL_KIN_AXISYMMETRIC || t->kin == TSL_KIN_AXISYMMETRIC_TWIST;
}

/* Reference coordinate d of node a mapped onto [0, 1]: the [-1, 1] directions are halved, the simplex
 * directions kept. */
static PetscReal UnitCoordinate(const TslGeometry *g, PetscInt a, PetscInt d)
{
  PetscReal lo = 0;
  for (PetscInt b = 0; b < g->nnode; b++) lo = PetscMin(lo, g->node_xi[b][d]);
  return lo < 0 ? 0.5 * (g->node_xi[a][d] + 1) : g->node_xi[a][d];
}

/* Unit element (reference element mapped onto [0,1] in every direction), shifted to r in [1,2] for axisymmetry;
 * distortion > 0 moves every node by a fixed pseudo-random amount of that size. */
static void CaseSetUp(Case *c, const TslElementType *type, PetscReal distortion)
{
  const TslGeometry *g = type->geom;

  c->type = type;
  c->E = 200e3, c->nu = 0.3, c->k = 10, c->rho = 2, c->c = 3;
  PetscCallAbort(PETSC_COMM_SELF, PetscMemzero(&c->mat, sizeof(c->mat)));
  Constant(&c->mat.prop[TSL_PROP_ELASTIC], c->E, c->nu);
  Constant(&c->mat.prop[TSL_PROP_CONDUCTIVITY], c->k, 0);
  Constant(&c->mat.prop[TSL_PROP_DENSITY], c->rho, 0);
  Constant(&c->mat.prop[TSL_PROP_SPECIFIC_HEAT], c->c, 0);
  Constant(&c->mat.prop[TSL_PROP_EXPANSION], ALPHA, 0);
  c->sec = (TslElementSection){&c->mat, 0.5, 0, 0, 0};
  for (PetscInt a = 0; a < g->nnode; a++) {
    for (PetscInt d = 0; d < 3; d++) c->x[3 * a + d] = d < type->dim ? UnitCoordinate(g, a, d) + distortion * PetscSinReal(3.1 * a + 1.3 * d + 0.7) : 0;
    if (IsAxi(type)) c->x[3 * a] += 1;
    c->theta_init[a] = THETA0;
    for (PetscInt i = 0; i < type->ndof; i++) c->u[type->ndof * a + i] = c->u_old[type->ndof * a + i] = i == type->ndof - 1 ? THETA0 : 0;
  }
  /* extra nodes (the reference node of generalized plane strain): away from the element, at rest */
  for (PetscInt a = g->nnode; a < TslElementTypeNodes(type); a++) {
    c->x[3 * a] = 0.3, c->x[3 * a + 1] = -0.2, c->x[3 * a + 2] = 0;
    c->theta_init[a] = THETA0;
    for (PetscInt i = 0; i < type->ndof; i++) c->u[type->ndof * a + i] = c->u_old[type->ndof * a + i] = 0;
  }
  c->in       = (TslElementInput){.type = type, .sec = &c->sec, .x = c->x, .u = c->u, .theta_init = c->theta_init};
  c->in_old   = c->in;
  c->in_old.u = c->u_old;
  c->shift    = 0;
}

/* What the implicit solver assembles for an element: internal force and heat flow, plus
 * shift (Q - Q_old) with the implicit heat content (lumped, or consistent for second-order families), so that
 * the tangent check covers its capacity matrix. */
static PetscErrorCode Residual(Case *c, PetscReal R[], PetscReal K[], PetscBool *inv)
{
  const PetscInt ndof = c->type->ndof, n = c->type->geom->nnode, nd = TslElementTypeNodes(c->type) * ndof;
  PetscReal      Q[TSL_MAX_ELEM_NODES], Qo[TSL_MAX_ELEM_NODES], C[TSL_MAX_ELEM_NODES * TSL_MAX_ELEM_NODES];

  PetscFunctionBeginUser;
  PetscCall(TslElementInternal(&c->in, R, K, inv));
  if (*inv || c->shift == 0) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(TslElementHeatContent(&c->in, Q, C));
  PetscCall(TslElementHeatContent(&c->in_old, Qo, NULL));
  for (PetscInt a = 0; a < n; a++) {
    const PetscInt row = ndof * a + ndof - 1;
    R[row] += c->shift * (Q[a] - Qo[a]);
    if (K)
      for (PetscInt b = 0; b < n; b++) K[row * nd + ndof * b + ndof - 1] += c->shift * C[a * n + b];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* S, E, HFL of the element. */
static PetscErrorCode Output(Case *c, PetscReal S[6], PetscReal E[6], PetscReal H[3])
{
  TslElementResult res;

  PetscFunctionBeginUser;
  PetscCall(TslElementOutput(&c->in, &res));
  for (PetscInt r = 0; r < 6; r++) S[r] = res.S[r], E[r] = res.E[r];
  for (PetscInt d = 0; d < 3; d++) H[d] = res.HFL[d];
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscInt NDof(const Case *c)
{
  return TslElementTypeNodes(c->type) * c->type->ndof;
}

/* Max |R| over the rows of the family's nodes (an extra node's rows carry the out-of-plane force of
 * generalized plane strain, a reaction when its dofs are held). */
static PetscReal MaxRow(const Case *c, const PetscReal R[], PetscBool theta_rows)
{
  PetscReal m = 0;
  for (PetscInt i = 0; i < c->type->geom->nnode * c->type->ndof; i++)
    if ((i % c->type->ndof == c->type->ndof - 1) == theta_rows) m = PetscMax(m, PetscAbsReal(R[i]));
  return m;
}

static PetscErrorCode CheckRigidMotion(TestLog *log, Case *c)
{
  const PetscInt dim = c->type->dim, ndof = c->type->ndof;
  PetscReal      R[TSL_MAX_ELEM_DOF];
  PetscBool      inv;

  PetscFunctionBeginUser;
  /* translation (axial only for axisymmetry: a radial shift strains the hoop direction) */
  for (PetscInt a = 0; a < c->type->geom->nnode; a++)
    for (PetscInt i = 0; i < dim; i++) c->u[ndof * a + i] = (IsAxi(c->type) && i == 0) ? 0 : 0.01 * (i + 1);
  PetscCall(Residual(c, R, NULL, &inv));
  Check(log, MaxRow(c, R, PETSC_FALSE), 0, 1e-9, "%s rigid translation max|R_u|", c->type->name);
  if (c->type->kin == TSL_KIN_AXISYMMETRIC_TWIST) {
    /* a rigid rotation about the axis: the same twist phi at every node */
    for (PetscInt a = 0; a < c->type->geom->nnode; a++) c->u[ndof * a + dim] = 0.02;
    PetscCall(Residual(c, R, NULL, &inv));
    Check(log, MaxRow(c, R, PETSC_FALSE), 0, 1e-9, "%s rigid twist max|R_u|", c->type->name);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckThermalPatch(TestLog *log, Case *c, PetscBool constrained)
{
  const TslElementType *t   = c->type;
  const PetscInt        dim = t->dim, ndof = t->ndof;
  const PetscReal       E = c->E, nu = c->nu, dT = 15;
  PetscReal             R[TSL_MAX_ELEM_DOF], S[6], Eps[6], H[3], Sx[6] = {0}, Ex[6] = {0}, stretch = ALPHA * dT;
  PetscBool             inv;

  PetscFunctionBeginUser;
  if (!constrained) {
    /* free expansion; plane strain keeps eps_33 = 0, so it expands (1 + nu) alpha dT in-plane and
     * carries sigma_33 = -E alpha dT */
    if (PlaneStrainLike(t)) stretch *= 1 + nu, Sx[2] = -E * ALPHA * dT;
    for (PetscInt i = 0; i < 3; i++) Ex[i] = (i < dim || !PlaneStrainLike(t)) ? stretch : 0;
  } else if (t->kin == TSL_KIN_CONTINUUM_SHELL) {
    /* the undistorted element (stack direction z): plane stress in x-y, sigma_zz = -E_t alpha dT with the
     * default thickness modulus E_t = 2 G */
    Sx[0] = Sx[1] = -E * ALPHA * dT / (1 - nu);
    Sx[2]         = -E * ALPHA * dT / (1 + nu);
  } else {
    const PetscReal s = t->kin == TSL_KIN_PLANE_STRESS ? -E * ALPHA * dT / (1 - nu) : -E * ALPHA * dT / (1 - 2 * nu);
    for (PetscInt i = 0; i < 3; i++) Sx[i] = (t->kin == TSL_KIN_PLANE_STRESS && i == 2) ? 0 : s;
    if (t->kin == TSL_KIN_PLANE_STRESS) Ex[2] = ALPHA * dT * (1 + nu) / (1 - nu);
  }
  for (PetscInt a = 0; a < t->geom->nnode; a++) {
    for (PetscInt i = 0; i < dim; i++) c->u[ndof * a + i] = constrained ? 0 : stretch * c->x[3 * a + i];
    c->u[ndof * a + ndof - 1] = THETA0 + dT;
  }
  PetscCall(Residual(c, R, NULL, &inv));
  PetscCall(Output(c, S, Eps, H));
  for (PetscInt r = 0; r < 6; r++) {
    Check(log, S[r], Sx[r], 1e-9 * E * ALPHA * dT, "%s %s expansion S%" PetscInt_FMT, t->name, constrained ? "constrained" : "free", r + 1);
    Check(log, Eps[r], Ex[r], 1e-12, "%s %s expansion E%" PetscInt_FMT, t->name, constrained ? "constrained" : "free", r + 1);
  }
  if (!constrained) Check(log, MaxRow(c, R, PETSC_FALSE), 0, 1e-9, "%s free expansion max|R_u|", t->name);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* theta = g.x + 5 is reproduced exactly by isoparametric elements, so HFL = -k g on any shape. */
static PetscErrorCode CheckLinearTemperature(TestLog *log, Case *c)
{
  const PetscInt  dim = c->type->dim, ndof = c->type->ndof;
  const PetscReal g[3] = {3, -2, 1.5};
  PetscReal       S[6], Eps[6], H[3], K[TSL_MAX_ELEM_DOF * TSL_MAX_ELEM_DOF], R[TSL_MAX_ELEM_DOF], kone = 0, kthu = 0;
  PetscBool       inv;

  PetscFunctionBeginUser;
  for (PetscInt a = 0; a < c->type->geom->nnode; a++) {
    c->u[ndof * a + ndof - 1] = 5;
    for (PetscInt d = 0; d < dim; d++) c->u[ndof * a + ndof - 1] += g[d] * c->x[3 * a + d];
  }
  PetscCall(Output(c, S, Eps, H));
  for (PetscInt d = 0; d < 3; d++) Check(log, H[d], d < dim ? -c->k * g[d] : 0, 1e-10, "%s linear theta HFL%" PetscInt_FMT, c->type->name, d + 1);
  /* steady: a uniform temperature conducts nothing, and the thermal rows do not see displacement */
  PetscCall(Residual(c, R, K, &inv));
  for (PetscInt i = ndof - 1; i < NDof(c); i += ndof) {
    PetscReal s = 0;
    for (PetscInt j = ndof - 1; j < NDof(c); j += ndof) s += K[i * NDof(c) + j];
    kone = PetscMax(kone, PetscAbsReal(s));
    for (PetscInt j = 0; j < NDof(c); j++)
      if (j % ndof != ndof - 1) kthu = PetscMax(kthu, PetscAbsReal(K[i * NDof(c) + j]));
  }
  Check(log, kone, 0, 1e-10, "%s steady max|K_tt . 1|", c->type->name);
  Check(log, kthu, 0, 0, "%s max|K_theta_u|", c->type->name);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Expected volume of the undistorted unit element: its area (or volume) times the thickness 0.5 in plane,
 * or 2 pi r_c with r_c the centroid radius (the mean of the corners for these shapes). */
static PetscReal UnitVolume(const Case *c)
{
  const TslGeometry *g = c->type->geom;
  PetscReal          V = g->ref_volume, rc = 0;

  for (PetscInt d = 0; d < g->dim; d++) {
    PetscReal lo = 0;
    for (PetscInt b = 0; b < g->nnode; b++) lo = PetscMin(lo, g->node_xi[b][d]);
    if (lo < 0) V *= 0.5;
  }
  for (PetscInt a = 0; a < g->ncorner; a++) rc += c->x[3 * a] / g->ncorner;
  switch (c->type->kin) {
  case TSL_KIN_PLANE_STRAIN:
  case TSL_KIN_GENERALIZED_PLANE_STRAIN:
  case TSL_KIN_PLANE_STRESS:
    return V * (c->sec.thickness > 0 ? c->sec.thickness : 1);
  case TSL_KIN_AXISYMMETRIC:
  case TSL_KIN_AXISYMMETRIC_TWIST:
    return V * 2 * PETSC_PI * rc;
  default:
    return V;
  }
}

/* Outward area vector of a flat face from its corners (2D: the edge times thickness or 2 pi r at its
 * middle; 3D: half the sum of the corners' cross products). */
static void FaceAreaVector(const Case *c, PetscInt f, PetscReal A[3])
{
  const TslGeometry *g = c->type->geom, *fg = g->face_geom[f];
  const PetscInt    *fn = g->face_node[f], nc = fg->ncorner;

  for (PetscInt d = 0; d < 3; d++) A[d] = 0;
  if (c->type->dim == 2) {
    const PetscReal *p = &c->x[3 * fn[0]], *q = &c->x[3 * fn[1]];
    const PetscReal  m = IsAxi(c->type) ? 2 * PETSC_PI * 0.5 * (p[0] + q[0]) : c->sec.thickness;
    A[0] = (q[1] - p[1]) * m, A[1] = -(q[0] - p[0]) * m;
    return;
  }
  for (PetscInt i = 0; i < nc; i++) {
    const PetscReal *p = &c->x[3 * fn[i]], *q = &c->x[3 * fn[(i + 1) % nc]];
    A[0] += 0.5 * (p[1] * q[2] - p[2] * q[1]);
    A[1] += 0.5 * (p[2] * q[0] - p[0] * q[2]);
    A[2] += 0.5 * (p[0] * q[1] - p[1] * q[0]);
  }
}

/* The element as Abaqus/CAE writes a triangle or a wedge at a sweep's axis (docs/elements.md, "Collapsed
 * elements"): a quadrilateral's face S3 (nodes 3-4, with 7) or a brick's face S5 (3-4-8-7, with 11, 15, 19, 20)
 * collapsed onto one edge, node 3 onto 4 and 7 onto 8 (their midsides with them, 19 onto 20). The nodes keep their
 * unknowns apart here: the checks hold for any values, the repeated id of a deck makes them one. Returns
 * PETSC_FALSE for a family that is not a quadrilateral or a brick. */
static PetscBool Collapse(Case *c)
{
  const TslGeometry *g = c->type->geom;
  const PetscInt    *v;
  PetscInt           to[4][2], n = 0;

  if (!((g->dim == 2 && g->ncorner == 4) || (g->dim == 3 && g->ncorner == 8))) return PETSC_FALSE;
  if (g->dim == 2) {
    v        = g->face_node[2]; /* 3, 4 (, 7) */
    to[n][0] = v[0], to[n++][1] = v[1];
    if (g->face_nnode[2] > 2) to[n][0] = v[2], to[n++][1] = v[1];
  } else {
    v        = g->face_node[4]; /* 3, 4, 8, 7 (, 11, 20, 15, 19) */
    to[n][0] = v[0], to[n++][1] = v[1];
    to[n][0] = v[3], to[n++][1] = v[2];
    if (g->face_nnode[4] > 4) { /* the midsides of the collapsed edges go with them (11 -> 4, 15 -> 8) */
      c->x[3 * v[4] + 0] = c->x[3 * v[1] + 0], c->x[3 * v[4] + 1] = c->x[3 * v[1] + 1], c->x[3 * v[4] + 2] = c->x[3 * v[1] + 2];
      c->x[3 * v[6] + 0] = c->x[3 * v[2] + 0], c->x[3 * v[6] + 1] = c->x[3 * v[2] + 1], c->x[3 * v[6] + 2] = c->x[3 * v[2] + 2];
      to[n][0] = v[7], to[n++][1] = v[5]; /* 19 -> 20 */
    }
  }
  for (PetscInt k = 0; k < n; k++)
    for (PetscInt d = 0; d < 3; d++) c->x[3 * to[k][0] + d] = c->x[3 * to[k][1] + d];
  return PETSC_TRUE;
}

/* HRZ lumping of the full quadratic triangle and tetrahedron (CPE6T, C3D10T), straight-sided: V_a = V int N_a^2 /
 * sum_b int N_b^2 is V/19 at the tri6 corners and 16V/57 at its midside nodes, V/36 at the tet10 corners and 4V/27
 * at its midside nodes (closed form: int L^4 = 2!4!/6! A ..., docs/elements.md); the lumping rule must be exact
 * for N_a^2 to give them. */
static PetscErrorCode CheckExactLumping(TestLog *log, Case *c)
{
  const TslGeometry *g   = c->type->geom;
  const PetscBool    tri = (PetscBool)(g->nnode == 6);
  PetscReal          vol[TSL_MAX_ELEM_NODES], V = 0;

  PetscFunctionBeginUser;
  PetscCall(TslElementNodalVolume(&c->in, vol));
  for (PetscInt a = 0; a < g->nnode; a++) V += vol[a];
  for (PetscInt a = 0; a < g->nnode; a++) {
    const PetscReal want = a < g->ncorner ? (tri ? 1.0 / 19 : 1.0 / 36) : (tri ? 16.0 / 57 : 4.0 / 27);
    Check(log, vol[a] / V, want, 1e-13, "%s HRZ lumped weight of node %" PetscInt_FMT " / V", c->type->name, a + 1);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckVolumeAndHeat(TestLog *log, Case *c)
{
  const PetscInt ndof = c->type->ndof, n = c->type->geom->nnode;
  PetscReal      vol[TSL_MAX_ELEM_NODES], V = 0, dQ, Rs[TSL_MAX_ELEM_DOF], Rt[TSL_MAX_ELEM_DOF], cap = 0;
  PetscBool      inv;

  PetscFunctionBeginUser;
  PetscCall(TslElementNodalVolume(&c->in, vol));
  for (PetscInt a = 0; a < n; a++) V += vol[a];
  Check(log, V, UnitVolume(c), 1e-12, "%s element volume", c->type->name);
  c->sec.thickness = 0;
  PetscCall(TslElementNodalVolume(&c->in, vol));
  V = 0;
  for (PetscInt a = 0; a < n; a++) V += vol[a];
  Check(log, V, UnitVolume(c), 1e-12, "%s element volume with thickness 0 (taken as 1)", c->type->name);
  c->sec.thickness = 0.5;
  /* stored heat: rho c V dtheta, and the capacity part of the residual is that over dt */
  for (PetscInt a = 0; a < n; a++) c->u[ndof * a + ndof - 1] = c->u_old[ndof * a + ndof - 1] + 2;
  {
    PetscReal Q[TSL_MAX_ELEM_NODES], Qo[TSL_MAX_ELEM_NODES], M[TSL_MAX_ELEM_NODES], mass = 0;
    PetscCall(TslElementLumped(&c->in, Q, NULL, M));
    PetscCall(TslElementLumped(&c->in_old, Qo, NULL, NULL));
    dQ = 0;
    for (PetscInt a = 0; a < n; a++) dQ += Q[a] - Qo[a], mass += M[a];
    Check(log, mass, c->rho * UnitVolume(c), 1e-9, "%s lumped mass", c->type->name);
  }
  for (PetscInt a = 0; a < n; a++) Check(log, vol[a] > 0, 1, 0, "%s lumped weight of node %" PetscInt_FMT " positive", c->type->name, a + 1);
  Check(log, dQ, c->rho * c->c * UnitVolume(c) * 2, 1e-9, "%s heat change", c->type->name);
  PetscCall(Residual(c, Rs, NULL, &inv));
  c->shift = 10;
  PetscCall(Residual(c, Rt, NULL, &inv));
  c->shift = 0;
  for (PetscInt i = ndof - 1; i < NDof(c); i += ndof) cap += (Rt[i] - Rs[i]) / 10;
  Check(log, cap, dQ, 1e-9, "%s capacity residual * dt = heat change", c->type->name);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Radiation to an ambient of 12 with sigma eps = 5.67e-8 * 0.7 on the Celsius scale (absolute zero -273.15):
 * at the tests' temperatures (20 +- 10) its tangent 4 sigma eps (theta - theta_Z)^3 is about 4, near the film's 7. */
static const TslFaceLoadValue RADIATION = {5.67e-8 * 0.7, 12.0, -273.15};

/* The element residual (face == 0) or a film or radiation (kind) on one face alone (face > 0), so that the
 * small face Jacobian is not hidden behind the stiffness in a relative comparison. */
static PetscErrorCode PartResidual(Case *c, PetscInt face, TslFaceLoadKind kind, PetscReal R[], PetscReal K[])
{
  const PetscInt nd  = NDof(c);
  PetscBool      inv = PETSC_FALSE;

  PetscFunctionBeginUser;
  if (face == 0)
    PetscCall(Residual(c, R, K, &inv));
  else {
    for (PetscInt i = 0; i < nd; i++) R[i] = 0;
    if (K)
      for (PetscInt i = 0; i < nd * nd; i++) K[i] = 0;
    PetscCall(TslElementFaceLoad(&c->in, kind, face, kind == TSL_FACE_FILM ? &(TslFaceLoadValue){7.0, 12.0, 0} : &RADIATION, R, K, NULL));
  }
  PetscCheck(!inv, PETSC_COMM_SELF, PETSC_ERR_PLIB, "unexpected inverted element");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* K against central differences of R on a distorted element with a transient capacity term, block by
 * block (u-u, u-theta, theta-u, theta-theta), each relative to the largest entry of its block. */
static PetscErrorCode CheckTangent(TestLog *log, Case *c, PetscInt face, TslFaceLoadKind kind)
{
  const char        *what = kind == TSL_FACE_FILM ? "film" : "radiation";
  static const char *block_name[2][2] = {{"uu", "u-theta"}, {"theta-u", "theta-theta"}};
  const PetscInt     nd = NDof(c), ndof = c->type->ndof;
  PetscReal          K[TSL_MAX_ELEM_DOF * TSL_MAX_ELEM_DOF], R[TSL_MAX_ELEM_DOF], Rp[TSL_MAX_ELEM_DOF], Rm[TSL_MAX_ELEM_DOF];
  PetscReal          kmax[2][2] = {{0}}, err[2][2] = {{0}};

  PetscFunctionBeginUser;
  c->shift = 10;
  for (PetscInt i = 0; i < nd; i++) c->u[i] = (i % ndof == ndof - 1) ? THETA0 + 10 * PetscSinReal(1.1 * i + 0.3) : 0.01 * PetscCosReal(2.3 * i + 0.1);
  PetscCall(PartResidual(c, face, kind, R, K));
  for (PetscInt j = 0; j < nd; j++) {
    const PetscReal save = c->u[j], h = 1e-6 * PetscMax(1, PetscAbsReal(save));
    c->u[j] = save + h;
    PetscCall(PartResidual(c, face, kind, Rp, NULL));
    c->u[j] = save - h;
    PetscCall(PartResidual(c, face, kind, Rm, NULL));
    c->u[j] = save;
    for (PetscInt i = 0; i < nd; i++) {
      const PetscInt bi = i % ndof == ndof - 1, bj = j % ndof == ndof - 1;
      err[bi][bj]  = PetscMax(err[bi][bj], PetscAbsReal((Rp[i] - Rm[i]) / (2 * h) - K[i * nd + j]));
      kmax[bi][bj] = PetscMax(kmax[bi][bj], PetscAbsReal(K[i * nd + j]));
    }
  }
  c->shift = 0;
  for (PetscInt bi = 0; bi < 2; bi++)
    for (PetscInt bj = 0; bj < 2; bj++) {
      /* blocks that are exactly zero (theta-u; all but theta-theta for a film or radiation) compare absolutely */
      const PetscReal scale = kmax[bi][bj] > 0 ? kmax[bi][bj] : 1;
      if (face > 0)
        Check(log, err[bi][bj] / scale, 0, 1e-6, "%s %s on S%" PetscInt_FMT " tangent %s block vs central differences (relative)", c->type->name,
              what, face, block_name[bi][bj]);
      else
        Check(log, err[bi][bj] / scale, 0, 1e-6, "%s tangent %s block vs central differences (relative)", c->type->name, block_name[bi][bj]);
    }
  if (face > 0) Check(log, kmax[1][1] > 0, 1, 0, "%s %s on S%" PetscInt_FMT " has a theta-theta tangent", c->type->name, what, face);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Unit element: outward normal of face f is the direction from the element centre to the face centre,
 * and the face area is 1 times thickness or 2 pi r at the face centre. */
static PetscErrorCode CheckFaceLoads(TestLog *log, Case *c)
{
  const TslGeometry *g   = c->type->geom;
  const PetscInt     dim = c->type->dim, ndof = c->type->ndof, nd = NDof(c);
  const PetscReal    p = 3, q = 5, h = 4, sink = 12, theta = 50;
  PetscReal          R[TSL_MAX_ELEM_DOF], heat;

  PetscFunctionBeginUser;
  for (PetscInt a = 0; a < g->nnode; a++) c->u[ndof * a + ndof - 1] = theta;
  for (PetscInt f = 0; f < g->nface; f++) {
    PetscReal Avec[3], area, force[3] = {0, 0, 0}, sumt = 0;
    FaceAreaVector(c, f, Avec);
    area = PetscSqrtReal(Avec[0] * Avec[0] + Avec[1] * Avec[1] + Avec[2] * Avec[2]);
    for (PetscInt i = 0; i < nd; i++) R[i] = 0;
    PetscCall(TslElementFaceLoad(&c->in, TSL_FACE_PRESSURE, f + 1, &(TslFaceLoadValue){p, 0, 0}, R, NULL, NULL));
    for (PetscInt a = 0; a < g->nnode; a++)
      for (PetscInt i = 0; i < dim; i++) force[i] -= R[ndof * a + i];
    for (PetscInt i = 0; i < dim; i++)
      Check(log, force[i], -p * Avec[i], 1e-12, "%s S%" PetscInt_FMT " pressure force %" PetscInt_FMT, c->type->name, f + 1, i + 1);

    for (PetscInt i = 0; i < nd; i++) R[i] = 0;
    PetscCall(TslElementFaceLoad(&c->in, TSL_FACE_FLUX, f + 1, &(TslFaceLoadValue){q, 0, 0}, R, NULL, &heat));
    sumt = 0;
    for (PetscInt i = ndof - 1; i < nd; i += ndof) sumt += R[i];
    Check(log, heat, q * area, 1e-12, "%s S%" PetscInt_FMT " flux heat", c->type->name, f + 1);
    Check(log, sumt, -q * area, 1e-12, "%s S%" PetscInt_FMT " flux residual sum", c->type->name, f + 1);

    for (PetscInt i = 0; i < nd; i++) R[i] = 0;
    PetscCall(TslElementFaceLoad(&c->in, TSL_FACE_FILM, f + 1, &(TslFaceLoadValue){h, sink, 0}, R, NULL, &heat));
    sumt = 0;
    for (PetscInt i = ndof - 1; i < nd; i += ndof) sumt += R[i];
    Check(log, heat, -h * (theta - sink) * area, 1e-10, "%s S%" PetscInt_FMT " film heat", c->type->name, f + 1);
    Check(log, sumt, h * (theta - sink) * area, 1e-10, "%s S%" PetscInt_FMT " film residual sum", c->type->name, f + 1);

    /* radiation at a uniform temperature: q = sigma eps [(theta - theta_Z)^4 - (theta_a - theta_Z)^4] over the area */
    {
      const PetscReal ta = theta - RADIATION.zero, sa = RADIATION.sink - RADIATION.zero;
      const PetscReal qr = RADIATION.value * (ta * ta * ta * ta - sa * sa * sa * sa);
      for (PetscInt i = 0; i < nd; i++) R[i] = 0;
      PetscCall(TslElementFaceLoad(&c->in, TSL_FACE_RADIATION, f + 1, &RADIATION, R, NULL, &heat));
      sumt = 0;
      for (PetscInt i = ndof - 1; i < nd; i += ndof) sumt += R[i];
      CheckRel(log, heat, -qr * area, 1e-12, 0, "%s S%" PetscInt_FMT " radiation heat", c->type->name, f + 1);
      CheckRel(log, sumt, qr * area, 1e-12, 0, "%s S%" PetscInt_FMT " radiation residual sum", c->type->name, f + 1);
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* int over the undistorted unit element (no thickness, no 2 pi r) of prod_d u_d^p[d], u the coordinates
 * on [0, 1] (UnitCoordinate): on the ns simplex directions prod p_d! / (sum p_d + ns)!, on the others
 * 1 / (p_d + 1). */
static PetscReal UnitMonomial(const TslGeometry *g, const PetscInt p[3])
{
  PetscReal v = 1, fact = 1;
  PetscInt  ns = 0, sum = 0;

  for (PetscInt d = 0; d < g->dim; d++) {
    PetscReal lo = 0;
    for (PetscInt b = 0; b < g->nnode; b++) lo = PetscMin(lo, g->node_xi[b][d]);
    if (lo < 0) {
      v /= p[d] + 1;
      continue;
    }
    ns++, sum += p[d];
    for (PetscInt k = 2; k <= p[d]; k++) v *= k;
  }
  for (PetscInt k = 2; k <= sum + ns; k++) fact *= k;
  return v / fact;
}

/* Body flux q on the undistorted unit element: the heat is q V, the loads sum to -q V, and they are the
 * consistent ones, -q int N_a dV: since sum_a N_a f(x_a) = f for every f of total degree <= the family's
 * order, sum_a R_a f(x_a) = -q int f dV for those f (closed form, UnitMonomial), wherever the full rule
 * integrates f dV exactly (degree + 1 for the r of axisymmetric types). The lumped capacity weights fail
 * this at degree 2 (HRZ on quad8, sub-elements on tri6 and tet10); for linear families they are the same
 * numbers, which is checked too. */
static PetscErrorCode CheckBodyFlux(TestLog *log, Case *c)
{
  const TslGeometry *g   = c->type->geom;
  const PetscInt     dim = c->type->dim, ndof = c->type->ndof, nd = NDof(c), th = ndof - 1;
  const PetscBool    axi = IsAxi(c->type);
  const PetscReal    q = 5, scale = axi ? 2 * PETSC_PI : (dim == 2 ? c->sec.thickness : 1);
  const PetscInt     degree = PetscMin(g->order, g->full.degree - (axi ? 1 : 0));
  PetscReal          R[TSL_MAX_ELEM_DOF], heat, sum = 0, vol[TSL_MAX_ELEM_NODES];

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < nd; i++) R[i] = 0;
  PetscCall(TslElementFaceLoad(&c->in, TSL_BODY_FLUX, 0, &(TslFaceLoadValue){q, 0, 0}, R, NULL, &heat));
  for (PetscInt a = 0; a < g->nnode; a++) sum += R[ndof * a + th];
  Check(log, heat, q * UnitVolume(c), 1e-12, "%s body flux heat", c->type->name);
  Check(log, sum, -q * UnitVolume(c), 1e-12, "%s body flux residual sum", c->type->name);
  for (PetscInt a = g->nnode; a < TslElementTypeNodes(c->type); a++)
    for (PetscInt i = 0; i < ndof; i++) Check(log, R[ndof * a + i], 0, 0, "%s body flux on extra node %" PetscInt_FMT, c->type->name, a + 1);
  /* monomials p of total degree 1..degree in the unit coordinates u = x - (1, 0, 0) (axisymmetric) or x */
  for (PetscInt k = 1; k < (dim == 3 ? 27 : 9); k++) {
    const PetscInt p[3]   = {k % 3, (k / 3) % 3, k / 9};
    PetscReal      moment = 0, exact;
    if (p[0] + p[1] + p[2] > degree) continue;
    for (PetscInt a = 0; a < g->nnode; a++) {
      PetscReal f = 1;
      for (PetscInt d = 0; d < dim; d++) f *= PetscPowRealInt(c->x[3 * a + d] - (axi && d == 0 ? 1 : 0), p[d]);
      moment += R[ndof * a + th] * f;
    }
    if (axi) { /* dV = 2 pi r dA, r = u_0 + 1 */
      const PetscInt p1[3] = {p[0] + 1, p[1], p[2]};
      exact                = UnitMonomial(g, p1) + UnitMonomial(g, p);
    } else
      exact = UnitMonomial(g, p);
    Check(log, moment, -q * scale * exact, 1e-12, "%s body flux moment u^(%" PetscInt_FMT ",%" PetscInt_FMT ",%" PetscInt_FMT ")", c->type->name,
          p[0], p[1], p[2]);
  }
  if (g->order > 1) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(TslElementNodalVolume(&c->in, vol));
  for (PetscInt a = 0; a < g->nnode; a++)
    Check(log, R[ndof * a + th], -q * vol[a], 1e-12, "%s body flux on node %" PetscInt_FMT " = the lumped capacity weight", c->type->name, a + 1);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Body forces (*DLOAD GRAV, CENTRIF) on the undistorted unit element. Gravity rho g n: the nodal forces are the
 * consistent ones, -rho g n_i int N_a dV, checked as the body flux's are, through the moments sum_a R_ai f(x_a)
 * = -rho g n_i int f dV of the monomials the family interpolates (where the full rule integrates f dV exactly);
 * nothing on the temperature rows or the extra nodes. Centrifugal rho omega^2 r_perp about an axis through the
 * origin (z; the symmetry axis y of axisymmetric types): the forces sum to -rho omega^2 int r_perp dV, where the
 * full rule integrates it exactly. Neither depends on the unknowns: displacements and temperatures moved (with
 * temperature-dependent properties) change nothing, since rho is taken at the initial temperature. */
static PetscErrorCode CheckBodyForce(TestLog *log, Case *c)
{
  const TslGeometry *g   = c->type->geom;
  const PetscInt     dim = c->type->dim, ndof = c->type->ndof, nd = NDof(c), th = ndof - 1;
  const PetscBool    axi = IsAxi(c->type);
  const PetscReal    gr = 9.81, w2 = 4, scale = axi ? 2 * PETSC_PI : (dim == 2 ? c->sec.thickness : 1);
  const PetscReal    n3[3] = {0.36, -0.48, 0.8}, n2[3] = {0.6, -0.8, 0}, *n = dim == 3 ? n3 : n2;
  const PetscReal    grav[6] = {n[0], n[1], n[2], 0, 0, 0}, spin[6] = {0, 0, 0, 0, axi ? 1 : 0, axi ? 0 : 1};
  const PetscInt     degree = PetscMin(g->order, g->full.degree - (axi ? 1 : 0));
  PetscReal          R[TSL_MAX_ELEM_DOF], R2[TSL_MAX_ELEM_DOF], force[3], diff = 0;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < nd; i++) R[i] = 0;
  PetscCall(TslElementBodyForce(&c->in, TSL_BODY_GRAV, gr, grav, R, force));
  for (PetscInt i = 0; i < dim; i++)
    Check(log, force[i], c->rho * gr * n[i] * UnitVolume(c), 1e-12, "%s gravity total %" PetscInt_FMT, c->type->name, i + 1);
  for (PetscInt a = 0; a < TslElementTypeNodes(c->type); a++)
    for (PetscInt i = a < g->nnode ? th : 0; i < ndof; i++)
      Check(log, R[ndof * a + i], 0, 0, "%s gravity on node %" PetscInt_FMT " slot %" PetscInt_FMT, c->type->name, a + 1, i);
  for (PetscInt k = 0; k < (dim == 3 ? 27 : 9); k++) {
    const PetscInt p[3] = {k % 3, (k / 3) % 3, k / 9};
    if (p[0] + p[1] + p[2] > degree) continue;
    for (PetscInt i = 0; i < dim; i++) {
      PetscReal moment = 0, exact;
      for (PetscInt a = 0; a < g->nnode; a++) {
        PetscReal f = 1;
        for (PetscInt d = 0; d < dim; d++) f *= PetscPowRealInt(c->x[3 * a + d] - (axi && d == 0 ? 1 : 0), p[d]);
        moment += R[ndof * a + i] * f;
      }
      if (axi) {
        const PetscInt p1[3] = {p[0] + 1, p[1], p[2]};
        exact                = UnitMonomial(g, p1) + UnitMonomial(g, p);
      } else
        exact = UnitMonomial(g, p);
      Check(log, moment, -c->rho * gr * n[i] * scale * exact, 1e-12,
            "%s gravity moment %" PetscInt_FMT " u^(%" PetscInt_FMT ",%" PetscInt_FMT ",%" PetscInt_FMT ")", c->type->name, i + 1, p[0], p[1], p[2]);
    }
  }
  /* centrifugal: int r_perp_i dV, r_perp = (x, y, 0) about z, (r, 0, 0) about the symmetry axis */
  if (g->full.degree >= (axi ? 2 : 1)) {
    PetscReal sum[3] = {0, 0, 0};
    for (PetscInt i = 0; i < nd; i++) R[i] = 0;
    PetscCall(TslElementBodyForce(&c->in, TSL_BODY_CENTRIF, w2, spin, R, force));
    for (PetscInt a = 0; a < g->nnode; a++)
      for (PetscInt i = 0; i < dim; i++) sum[i] += R[ndof * a + i];
    for (PetscInt i = 0; i < (axi ? 1 : 2); i++) {
      const PetscInt  e0[3] = {0, 0, 0}, e1[3] = {i == 0, i == 1, 0}, e2[3] = {2, 0, 0};
      const PetscReal moment = axi ? UnitMonomial(g, e2) + 2 * UnitMonomial(g, e1) + UnitMonomial(g, e0) : UnitMonomial(g, e1);
      Check(log, force[i], c->rho * w2 * scale * moment, 1e-12, "%s centrifugal total %" PetscInt_FMT, c->type->name, i + 1);
      Check(log, sum[i], -force[i], 1e-12, "%s centrifugal nodal sum %" PetscInt_FMT, c->type->name, i + 1);
    }
    for (PetscInt i = axi ? 1 : 2; i < dim; i++) Check(log, force[i], 0, 1e-12, "%s centrifugal along the axis %" PetscInt_FMT, c->type->name, i + 1);
  }
  /* no unknown enters: move every unknown, make the properties depend on temperature, the same forces */
  for (PetscInt i = 0; i < nd; i++) R[i] = R2[i] = 0;
  TemperatureDependent(c);
  PetscCall(TslElementBodyForce(&c->in, TSL_BODY_GRAV, gr, grav, R, NULL));
  for (PetscInt i = 0; i < nd; i++) c->u[i] += i % ndof == th ? 15 : 1e-3 * PetscSinReal(1.7 * i);
  PetscCall(TslElementBodyForce(&c->in, TSL_BODY_GRAV, gr, grav, R2, NULL));
  for (PetscInt i = 0; i < nd; i++) diff = PetscMax(diff, PetscAbsReal(R2[i] - R[i]));
  Check(log, diff, 0, 0, "%s gravity independent of the unknowns", c->type->name);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Second-order types under a linear temperature theta = THETA0 + g.x (free expansion): the stress-free
 * displacement is quadratic, u_i = s [(g.x) x_i - g_i |x|^2 / 2] with s = alpha (3D, plane stress) or
 * (1 + nu) alpha (plane strain, in-plane); axisymmetric with g along z only (u_r = s g z r,
 * u_z = s g (z^2 - r^2) / 2). The element must reproduce it exactly: no force, no in-plane stress. */
static PetscErrorCode CheckQuadraticExpansion(TestLog *log, Case *c)
{
  const TslElementType *t   = c->type;
  const PetscInt        dim = t->dim, ndof = t->ndof;
  PetscReal             g[3] = {0.4, -0.3, 0.2}, R[TSL_MAX_ELEM_DOF], S[6], Eps[6], H[3], s = ALPHA, smax = 0;
  PetscBool             inv;

  PetscFunctionBeginUser;
  if (IsAxi(t)) g[0] = 0;
  if (PlaneStrainLike(t)) s *= 1 + c->nu;
  for (PetscInt a = 0; a < t->geom->nnode; a++) {
    const PetscReal *x = &c->x[3 * a];
    PetscReal        gx = 0, xx = 0;
    for (PetscInt d = 0; d < dim; d++) gx += g[d] * x[d], xx += x[d] * x[d];
    for (PetscInt i = 0; i < dim; i++) c->u[ndof * a + i] = s * (gx * x[i] - 0.5 * g[i] * xx);
    c->u[ndof * a + ndof - 1] = THETA0 + gx;
  }
  PetscCall(Residual(c, R, NULL, &inv));
  PetscCall(Output(c, S, Eps, H));
  for (PetscInt r = 0; r < 6; r++)
    if (!(PlaneStrainLike(t) && r == 2)) smax = PetscMax(smax, PetscAbsReal(S[r]));
  Check(log, MaxRow(c, R, PETSC_FALSE) / (c->E * ALPHA), 0, 1e-10, "%s quadratic free expansion under linear theta max|R_u| / (E alpha)", t->name);
  Check(log, smax / (c->E * ALPHA), 0, 1e-10, "%s quadratic free expansion max|S| / (E alpha)", t->name);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A uniform pressure must push every node of the face inward (positive nodal forces), which contact and
 * lumped loads rely on; the plain tet10 face would give zero corner forces. The serendipity quad8 face of
 * hex20 (C3D20T, C3D20RT) is the known exception: its consistent corner forces pull outward (-1/12 of the
 * total each on a flat parallelogram, the midsides +1/3), which is why contact is refused on it; there the
 * midsides must push inward, the corners pull outward and their sum be the face's area. The expanded S8RT
 * (hex20 with its pressure on the face's six triangles) pushes every node inward. */
static PetscErrorCode CheckPositivePressure(TestLog *log, Case *c)
{
  const TslGeometry *g = c->type->geom;
  const PetscInt     dim = c->type->dim, ndof = c->type->ndof, nd = NDof(c);
  PetscReal          R[TSL_MAX_ELEM_DOF];

  PetscFunctionBeginUser;
  for (PetscInt f = 0; f < g->nface; f++) {
    PetscReal       A[3], worst = PETSC_MAX_REAL, corner = -PETSC_MAX_REAL, sum = 0, a2 = 0;
    /* the expanded S8RT takes its pressure on the linear pieces (FaceRuleSub): every node inward there */
    const PetscBool serendipity = (PetscBool)(dim == 3 && g->face_geom[f]->nnode == 8 && !TslElementTypeSubdividedFace(c->type, f));
    FaceAreaVector(c, f, A);
    for (PetscInt i = 0; i < dim; i++) a2 += A[i] * A[i];
    for (PetscInt i = 0; i < nd; i++) R[i] = 0;
    PetscCall(TslElementFaceLoad(&c->in, TSL_FACE_PRESSURE, f + 1, &(TslFaceLoadValue){1.0, 0, 0}, R, NULL, NULL));
    for (PetscInt k = 0; k < g->face_nnode[f]; k++) {
      PetscReal fn = 0;
      for (PetscInt i = 0; i < dim; i++) fn += R[ndof * g->face_node[f][k] + i] * A[i];
      sum += fn;
      if (serendipity && k < 4)
        corner = PetscMax(corner, fn);
      else
        worst = PetscMin(worst, fn);
    }
    Check(log, worst > 0, 1, 0, "%s S%" PetscInt_FMT " uniform pressure pushes every %sface node inward", c->type->name, f + 1,
          serendipity ? "midside " : "");
    if (serendipity) {
      Check(log, corner < 0, 1, 0, "%s S%" PetscInt_FMT " uniform pressure pulls the serendipity face's corners outward", c->type->name, f + 1);
      Check(log, sum / a2, 1, 1e-12, "%s S%" PetscInt_FMT " uniform pressure's nodal forces sum to the face area", c->type->name, f + 1);
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Uniform torsion of a twist element: phi = c z (u_theta = c r z) is an equilibrium state without body
 * force, with gamma_z-theta = c r and nothing else: S23 = mu c r averaged over the points (the centroid
 * radius for these symmetric rules), every other stress zero. */
static PetscErrorCode CheckTorsion(TestLog *log, Case *c)
{
  const TslElementType *t = c->type;
  const PetscInt        ndof = t->ndof;
  const PetscReal       cz = 0.01, mu = c->E / (2 * (1 + c->nu));
  PetscReal             S[6], Eps[6], H[3], rbar = 0;

  PetscFunctionBeginUser;
  for (PetscInt a = 0; a < t->geom->nnode; a++) c->u[ndof * a + 2] = cz * c->x[3 * a + 1];
  for (PetscInt a = 0; a < t->geom->ncorner; a++) rbar += c->x[3 * a] / t->geom->ncorner;
  PetscCall(Output(c, S, Eps, H));
  for (PetscInt r = 0; r < 6; r++)
    Check(log, S[r], r == 5 ? mu * cz * rbar : 0, 1e-9 * mu * cz * rbar, "%s uniform torsion S%" PetscInt_FMT, t->name, r + 1);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Generalized plane strain: the reference node's U3 = e t (t the thickness) strains every point by
 * eps_33 = e with the in-plane displacements held: S11 = S22 = lambda e, S33 = (lambda + 2 mu) e, E33 = e;
 * turning the bounding planes by UR1 = w instead gives eps_33 = w (y - Y0) / t at the points (their
 * average: the centroid's y for these symmetric rules). */
static PetscErrorCode CheckReferenceNode(TestLog *log, Case *c)
{
  const TslElementType *t = c->type;
  const PetscInt        ndof = t->ndof, r = t->geom->nnode;
  const PetscReal       e = 1e-3, w = 2e-3, th = c->sec.thickness, lambda = c->E * c->nu / ((1 + c->nu) * (1 - 2 * c->nu)), mu = c->E / (2 * (1 + c->nu));
  PetscReal             S[6], Eps[6], H[3], yc = 0;

  PetscFunctionBeginUser;
  for (PetscInt a = 0; a < t->geom->nnode; a++) c->u[ndof * a + ndof - 1] = THETA0 + 0 * c->theta_init[a];
  c->u[ndof * r + 0] = e * th;
  PetscCall(Output(c, S, Eps, H));
  Check(log, Eps[2], e, 1e-12, "%s reference node U3: E33", t->name);
  Check(log, S[0], lambda * e, 1e-9 * c->E * e, "%s reference node U3: S11", t->name);
  Check(log, S[2], (lambda + 2 * mu) * e, 1e-9 * c->E * e, "%s reference node U3: S33", t->name);
  c->u[ndof * r + 0] = 0;
  c->u[ndof * r + 1] = w;
  for (PetscInt a = 0; a < t->geom->ncorner; a++) yc += c->x[3 * a + 1] / t->geom->ncorner;
  PetscCall(Output(c, S, Eps, H));
  Check(log, Eps[2], w * (yc - c->x[3 * r + 1]) / th, 1e-12, "%s reference node UR1: E33 at the centroid's lever arm", t->name);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckInverted(TestLog *log, Case *c)
{
  PetscReal R[TSL_MAX_ELEM_DOF];
  PetscBool inv;

  PetscFunctionBeginUser;
  /* mirror in the second coordinate: clockwise / left-handed numbering */
  for (PetscInt a = 0; a < c->type->geom->nnode; a++) c->x[3 * a + 1] *= -1;
  PetscCall(Residual(c, R, NULL, &inv));
  Check(log, inv, PETSC_TRUE, 0, "%s mirrored element reported inverted", c->type->name);
  for (PetscInt a = 0; a < c->type->geom->nnode; a++) c->x[3 * a + 1] *= -1;
  PetscCall(Residual(c, R, NULL, &inv));
  Check(log, inv, PETSC_FALSE, 0, "%s unit element not inverted", c->type->name);
  if (IsAxi(c->type)) {
    for (PetscInt a = 0; a < c->type->geom->nnode; a++) c->x[3 * a] -= 1.5; /* r in [-0.5, 0.5] */
    PetscCall(Residual(c, R, NULL, &inv));
    Check(log, inv, PETSC_TRUE, 0, "%s element across the axis reported invalid", c->type->name);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A continuum shell's STACK DIRECTION: the distorted element renumbered so that its stack (the third
 * reference direction) becomes the first (node a' of the new numbering is the old node at (xi, eta, zeta) =
 * (eta', zeta', xi'), a cyclic change that keeps the orientation), with STACK DIRECTION=1, gives the same
 * residual node by node as the original with the default 3, and the same energies. Types that can stack
 * along their first direction only (hex8). */
static PetscErrorCode CheckStackDirection(TestLog *log, Case *c)
{
  const TslElementType *t = c->type;
  const TslGeometry    *g = t->geom;
  const PetscInt        n = g->nnode, ndof = t->ndof;
  PetscInt              perm[TSL_MAX_ELEM_NODES];
  PetscReal         x[TSL_MAX_ELEM_NODES * 3], u[TSL_MAX_ELEM_DOF], ti[TSL_MAX_ELEM_NODES], R[TSL_MAX_ELEM_DOF], Rp[TSL_MAX_ELEM_DOF], d = 0, m = 0;
  PetscReal         en[4], enp[4];
  PetscBool         inv, invp;
  TslElementSection sec1 = c->sec;
  TslElementInput   in1;

  PetscFunctionBeginUser;
  if (!TslElementTypeStackAllowed(t, 0)) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt a = 0; a < n; a++) {
    perm[a] = -1;
    for (PetscInt b = 0; b < n; b++)
      if (g->node_xi[b][0] == g->node_xi[a][1] && g->node_xi[b][1] == g->node_xi[a][2] && g->node_xi[b][2] == g->node_xi[a][0]) perm[a] = b;
    CheckTrue(log, (PetscBool)(perm[a] >= 0), "%s stack direction: node %d has an image", t->name, (int)a);
    if (perm[a] < 0) PetscFunctionReturn(PETSC_SUCCESS);
  }
  for (PetscInt a = 0; a < n; a++) { /* some displacement and temperature field on the distorted element */
    for (PetscInt i = 0; i < ndof; i++)
      c->u[ndof * a + i] = i == ndof - 1 ? THETA0 + 3 * PetscSinReal(1.1 * a) : 1e-3 * PetscSinReal(2.1 * a + 0.7 * i + 0.3);
  }
  for (PetscInt a = 0; a < n; a++) {
    for (PetscInt k = 0; k < 3; k++) x[3 * a + k] = c->x[3 * perm[a] + k];
    for (PetscInt i = 0; i < ndof; i++) u[ndof * a + i] = c->u[ndof * perm[a] + i];
    ti[a] = c->theta_init[perm[a]];
  }
  sec1.shell_stack = 1;
  in1              = (TslElementInput){.type = t, .sec = &sec1, .x = x, .u = u, .theta_init = ti};
  PetscCall(TslElementInternalEnergy(&c->in, R, NULL, &inv, en));
  PetscCall(TslElementInternalEnergy(&in1, Rp, NULL, &invp, enp));
  for (PetscInt a = 0; a < n; a++)
    for (PetscInt i = 0; i < ndof; i++)
      d = PetscMax(d, PetscAbsReal(Rp[ndof * a + i] - R[ndof * perm[a] + i])), m = PetscMax(m, PetscAbsReal(R[ndof * a + i]));
  CheckAtMost(log, d / m, 1e-13, "%s STACK DIRECTION=1 on the renumbered element: residual against the default's", t->name);
  Check(log, enp[0], en[0], 1e-13 * en[0], "%s STACK DIRECTION=1: strain energy", t->name);
  Check(log, enp[1], en[1], 1e-13 * en[0], "%s STACK DIRECTION=1: hourglass energy", t->name);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A heat-transfer row (DC...) against the coupled row of its family and measure: at the same nodal temperatures (the
 * coupled row's displacements zero), with temperature-dependent properties and a transient capacity term, the DC
 * row's residual and tangent are the coupled row's temperature rows and temperature-temperature block, for the
 * conduction with the capacity and for a film and radiation on each face (1e-13 of the largest entry). */
static PetscErrorCode CheckHeatCounterpart(TestLog *log, const TslElementType *dc, const TslElementType *cp)
{
  static Case     h, m;
  static PetscReal Rh[TSL_MAX_ELEM_DOF], Kh[TSL_MAX_ELEM_DOF * TSL_MAX_ELEM_DOF], Rm[TSL_MAX_ELEM_DOF], Km[TSL_MAX_ELEM_DOF * TSL_MAX_ELEM_DOF];
  const PetscInt  n = dc->geom->nnode, nm = cp->ndof, th = nm - 1, ndm = n * nm;

  PetscFunctionBeginUser;
  for (PetscInt face = 0; face <= dc->geom->nface; face++)
    for (PetscInt k = 0; k < (face ? 2 : 1); k++) {
      const TslFaceLoadKind kind = k ? TSL_FACE_RADIATION : TSL_FACE_FILM;
      PetscReal             dr = 0, rmax = 0, dk = 0, kmax = 0;
      CaseSetUp(&h, dc, 0.08);
      CaseSetUp(&m, cp, 0.08);
      TemperatureDependent(&h);
      TemperatureDependent(&m);
      h.shift = m.shift = 10;
      for (PetscInt a = 0; a < n; a++) h.u[a] = m.u[nm * a + th] = THETA0 + 10 * PetscSinReal(1.1 * a + 0.3);
      PetscCall(PartResidual(&h, face, kind, Rh, Kh));
      PetscCall(PartResidual(&m, face, kind, Rm, Km));
      for (PetscInt a = 0; a < n; a++) {
        dr = PetscMax(dr, PetscAbsReal(Rh[a] - Rm[nm * a + th])), rmax = PetscMax(rmax, PetscAbsReal(Rh[a]));
        for (PetscInt b = 0; b < n; b++)
          dk = PetscMax(dk, PetscAbsReal(Kh[a * n + b] - Km[(nm * a + th) * ndm + nm * b + th])), kmax = PetscMax(kmax, PetscAbsReal(Kh[a * n + b]));
      }
      char what[48] = "conduction and capacity";
      if (face) PetscCall(PetscSNPrintf(what, sizeof(what), "%s on S%" PetscInt_FMT, k ? "radiation" : "film", face));
      Check(log, dr / PetscMax(rmax, 1e-300), 0, 1e-13, "%s %s: residual = %s's temperature rows (relative)", dc->name, what, cp->name);
      Check(log, dk / PetscMax(kmax, 1e-300), 0, 1e-13, "%s %s: tangent = %s's theta-theta block (relative)", dc->name, what, cp->name);
    }
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  TestLog log = {0, 0};
  Case    c;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  for (PetscInt t = 0; t < TslElementTypeCount(); t++) {
    const TslElementType *type = TslElementTypeGet(t);
    printf("---- %s: %s\n", type->name, type->description);
    if (TslElementTypeHeatOnly(type)) {
      /* the coupled row of the same family, measure and full integration (the dialect's or CalculiX's name) */
      static const char *pair[][2] = {{"DC2D3", "CPE3T"}, {"DC2D4", "CPE4T"},  {"DC2D6", "CPE6T"},  {"DC2D8", "CPE8T"},  {"DCAX3", "CAX3T"},
                                      {"DCAX4", "CAX4T"}, {"DCAX6", "CAX6T"},  {"DCAX8", "CAX8T"},  {"DC3D4", "C3D4T"},  {"DC3D6", "C3D6T"},
                                      {"DC3D8", "C3D8T"}, {"DC3D10", "C3D10T"}, {"DC3D15", "C3D15T"}, {"DC3D20", "C3D20T"}};
      PetscInt            cp     = -1;
      for (size_t k = 0; k < sizeof(pair) / sizeof(pair[0]); k++)
        if (!strcmp(pair[k][0], type->name)) cp = TslElementTypeFind(pair[k][1]);
      /* the links (a line family) have no coupled counterpart: tests/link checks them against closed forms */
      if (type->geom->dim > 1)
        Check(&log, cp >= 0 && TslElementTypeHeatCounterpart(TslElementTypeGet(cp)) == t, 1, 0, "%s is the heat-transfer counterpart of %s", type->name,
              cp >= 0 ? TslElementTypeGet(cp)->name : "(none)");
      if (cp >= 0) PetscCall(CheckHeatCounterpart(&log, type, TslElementTypeGet(cp)));
      for (PetscInt f = 0; f <= type->geom->nface; f++) {
        CaseSetUp(&c, type, 0.08);
        PetscCall(CheckTangent(&log, &c, f, TSL_FACE_FILM));
      }
      continue;
    }
    CaseSetUp(&c, type, 0);
    PetscCall(CheckRigidMotion(&log, &c));
    CaseSetUp(&c, type, 0.08);
    PetscCall(CheckRigidMotion(&log, &c));
    for (PetscInt constrained = 0; constrained < 2; constrained++) {
      /* a continuum shell's constrained stress follows its stack direction, which varies over a distorted
       * element: its exact value is the undistorted element's */
      CaseSetUp(&c, type, constrained && type->kin == TSL_KIN_CONTINUUM_SHELL ? 0 : 0.08);
      PetscCall(CheckThermalPatch(&log, &c, (PetscBool)constrained));
    }
    CaseSetUp(&c, type, 0.08);
    PetscCall(CheckLinearTemperature(&log, &c));
    CaseSetUp(&c, type, 0);
    PetscCall(CheckVolumeAndHeat(&log, &c));
    if (!strcmp(type->name, "CPE6T") || !strcmp(type->name, "C3D10T")) {
      CaseSetUp(&c, type, 0);
      PetscCall(CheckExactLumping(&log, &c));
    }
    CaseSetUp(&c, type, 0);
    PetscCall(CheckFaceLoads(&log, &c));
    CaseSetUp(&c, type, 0);
    PetscCall(CheckBodyFlux(&log, &c));
    CaseSetUp(&c, type, 0);
    PetscCall(CheckBodyForce(&log, &c));
    for (PetscInt f = 0; f <= type->geom->nface; f++) {
      CaseSetUp(&c, type, 0.08);
      PetscCall(CheckTangent(&log, &c, f, TSL_FACE_FILM));
      if (f == 0) continue;
      CaseSetUp(&c, type, 0.08);
      PetscCall(CheckTangent(&log, &c, f, TSL_FACE_RADIATION));
    }
    CaseSetUp(&c, type, 0.08);
    TemperatureDependent(&c);
    printf("(temperature-dependent properties)\n");
    PetscCall(CheckTangent(&log, &c, 0, TSL_FACE_FILM));
    if (type->kin == TSL_KIN_AXISYMMETRIC_TWIST) {
      CaseSetUp(&c, type, 0);
      PetscCall(CheckTorsion(&log, &c));
    }
    if (type->nextra) {
      CaseSetUp(&c, type, 0);
      PetscCall(CheckReferenceNode(&log, &c));
    }
    CaseSetUp(&c, type, 0);
    PetscCall(CheckPositivePressure(&log, &c));
    if (type->geom->order == 2) {
      CaseSetUp(&c, type, 0);
      PetscCall(CheckQuadraticExpansion(&log, &c));
    }
    CaseSetUp(&c, type, 0);
    PetscCall(CheckInverted(&log, &c));
    /* collapsed as Abaqus/CAE writes a triangle or wedge: rigid motion, the thermal patch, linear temperature
     * and the tangent hold for it as they are */
    CaseSetUp(&c, type, 0.08);
    if (Collapse(&c)) {
      printf("(collapsed onto one edge of face S%d)\n", type->dim == 2 ? 3 : 5);
      PetscCall(CheckRigidMotion(&log, &c));
      for (PetscInt constrained = 0; constrained < 2; constrained++) {
        CaseSetUp(&c, type, constrained && type->kin == TSL_KIN_CONTINUUM_SHELL ? 0 : 0.08); /* as above */
        (void)Collapse(&c);
        PetscCall(CheckThermalPatch(&log, &c, (PetscBool)constrained));
      }
      CaseSetUp(&c, type, 0.08);
      (void)Collapse(&c);
      PetscCall(CheckLinearTemperature(&log, &c));
      CaseSetUp(&c, type, 0.08);
      (void)Collapse(&c);
      PetscCall(CheckTangent(&log, &c, 0, TSL_FACE_FILM));
    }
    if (type->kin == TSL_KIN_CONTINUUM_SHELL) {
      CaseSetUp(&c, type, 0.08);
      PetscCall(CheckStackDirection(&log, &c));
    }
  }
  PetscCall(PetscFinalize());
  return Summary(&log);
}
