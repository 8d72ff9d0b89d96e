/* Finite strain (TslElementInput.nlgeom; docs/elements.md "Finite strain"), for every coupled type whose kernels take
 * it: objectivity (the nodal forces of a body turned by 90 and by 390 degrees are the unturned forces turned, to
 * round-off; a body turned rigidly while heated freely by alpha dT = 0.2 carries no force or stress, J = 1.2^3;
 * the Cauchy stress and the logarithmic strain of a pre-stressed body turn with it), the tangent against central
 * differences of the residual at a finite deformation (both blocks, temperature-dependent properties), the
 * follower pressure's load stiffness on every face, and the closed forms of the St Venant-Kirchhoff material:
 * uniaxial stretch to lambda = 2 and simple shear to gamma = 1. */
#include <string.h>
#include "check.h"

typedef struct {
  const TslElementType *type;
  TslMaterial           mat;
  TslElementSection     sec;
  PetscReal             x[TSL_MAX_ELEM_NODES * 3], u[TSL_MAX_ELEM_DOF], theta_init[TSL_MAX_ELEM_NODES];
  TslElementInput       in;
  PetscReal             E, nu;
} Case;

static const PetscReal ALPHA = 1e-3, THETA0 = 20, PI = 3.14159265358979323846;

static void Constant(TslPropertyTable *t, PetscReal v0, PetscReal v1)
{
  t->n           = 1;
  t->value[0][0] = v0, t->value[0][1] = v1;
}

/* the natural logarithm (PetscLogReal is log(), which the checks' TestLog *log would hide) */
static PetscReal Ln(PetscReal v)
{
  return PetscLogReal(v);
}

static PetscBool IsAxi(const TslElementType *t)
{
  return t->kin == TSL_KIN_AXISYMMETRIC || t->kin == TSL_KIN_AXISYMMETRIC_TWIST;
}

static PetscReal UnitCoordinate(const TslGeometry *g, PetscInt a, PetscInt d)
{
  PetscReal lo = 0;
  for (PetscInt b = 0; b < g->nnode; b++) lo = PetscMin(lo, g->node_xi[b][d]);
  return lo < 0 ? 0.5 * (g->node_xi[a][d] + 1) : g->node_xi[a][d];
}

/* The unit element (r in [1, 2] in axisymmetry), distorted by `distortion`; at rest at THETA0. */
static void CaseSetUp(Case *c, const TslElementType *type, PetscReal distortion, PetscBool tdep)
{
  const TslGeometry *g = type->geom;

  c->type = type;
  c->E = 200e3, c->nu = 0.3;
  PetscCallAbort(PETSC_COMM_SELF, PetscMemzero(&c->mat, sizeof(c->mat)));
  Constant(&c->mat.prop[TSL_PROP_ELASTIC], c->E, c->nu);
  Constant(&c->mat.prop[TSL_PROP_CONDUCTIVITY], 10, 0);
  Constant(&c->mat.prop[TSL_PROP_DENSITY], 2, 0);
  Constant(&c->mat.prop[TSL_PROP_SPECIFIC_HEAT], 3, 0);
  Constant(&c->mat.prop[TSL_PROP_EXPANSION], ALPHA, 0);
  if (tdep) { /* E, nu and alpha linear in temperature between 0 and 400 */
    TslPropertyTable *t = &c->mat.prop[TSL_PROP_ELASTIC];
    t->n = 2, t->theta[0] = 0, t->theta[1] = 400, t->value[1][0] = 0.6 * c->E, t->value[1][1] = 0.35;
    t    = &c->mat.prop[TSL_PROP_EXPANSION];
    t->n = 2, t->theta[0] = 0, t->theta[1] = 400, t->value[1][0] = 1.5 * ALPHA;
  }
  c->sec = (TslElementSection){&c->mat, 0.5, 0, 0, 0};
  for (PetscInt a = 0; a < g->nnode; a++) {
    for (PetscInt d = 0; d < 3; d++) c->x[3 * a + d] = d < type->dim ? UnitCoordinate(g, a, d) + distortion * PetscSinReal(3.1 * a + 1.3 * d + 0.7) : 0;
    if (IsAxi(type)) c->x[3 * a] += 1;
  }
  for (PetscInt a = g->nnode; a < TslElementTypeNodes(type); a++) c->x[3 * a] = 0.3, c->x[3 * a + 1] = -0.2, c->x[3 * a + 2] = 0;
  for (PetscInt a = 0; a < TslElementTypeNodes(type); a++) {
    c->theta_init[a] = THETA0;
    for (PetscInt i = 0; i < type->ndof; i++) c->u[type->ndof * a + i] = i == type->ndof - 1 ? THETA0 : 0;
  }
  c->in = (TslElementInput){.type = type, .sec = &c->sec, .x = c->x, .u = c->u, .theta_init = c->theta_init, .nlgeom = PETSC_TRUE};
}

static PetscInt NDof(const Case *c)
{
  return TslElementTypeNodes(c->type) * c->type->ndof;
}

/* The displacement components that are coordinates (a twist's third is the angle phi). */
static PetscInt NCoord(const TslElementType *t)
{
  return t->dim;
}

static void Rotation(PetscInt dim, PetscReal angle, PetscReal Q[3][3])
{
  PetscReal n[3] = {0, 0, 1};
  if (dim == 3) {
    const PetscReal l = PetscSqrtReal(14.0);
    n[0] = 1 / l, n[1] = 2 / l, n[2] = 3 / l;
  }
  /* Rodrigues: Q = cos I + sin [n]x + (1 - cos) n n^T */
  for (PetscInt i = 0; i < 3; i++)
    for (PetscInt j = 0; j < 3; j++) Q[i][j] = (i == j) * PetscCosReal(angle) + (1 - PetscCosReal(angle)) * n[i] * n[j];
  Q[0][1] -= PetscSinReal(angle) * n[2], Q[1][0] += PetscSinReal(angle) * n[2];
  Q[0][2] += PetscSinReal(angle) * n[1], Q[2][0] -= PetscSinReal(angle) * n[1];
  Q[1][2] -= PetscSinReal(angle) * n[0], Q[2][1] += PetscSinReal(angle) * n[0];
}

/* u of the homogeneous map x = F X at every node (the coordinate components), the temperature theta everywhere;
 * generalized plane strain: the reference node's U3 = (F_33 - 1) t (F_33 = 1: none). */
static void SetHomogeneous(Case *c, const PetscReal F[3][3], PetscReal theta)
{
  const TslElementType *t = c->type;
  const PetscInt        ndof = t->ndof, nc = NCoord(t), n = t->geom->nnode;

  for (PetscInt a = 0; a < n; a++) {
    for (PetscInt i = 0; i < nc; i++) {
      PetscReal xi = 0;
      for (PetscInt j = 0; j < nc; j++) xi += F[i][j] * c->x[3 * a + j];
      c->u[ndof * a + i] = xi - c->x[3 * a + i];
    }
    c->u[ndof * a + ndof - 1] = theta;
  }
  if (t->nextra) c->u[ndof * n] = (F[2][2] - 1) * c->sec.thickness, c->u[ndof * n + ndof - 1] = theta;
}

static PetscErrorCode Internal(Case *c, PetscReal R[], PetscReal K[])
{
  PetscBool inv;

  PetscFunctionBeginUser;
  PetscCall(TslElementInternal(&c->in, R, K, &inv));
  PetscCheck(!inv, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: unexpected inverted element", c->type->name);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscReal MaxDisplacementRow(const Case *c, const PetscReal R[])
{
  PetscReal m = 0;
  for (PetscInt i = 0; i < NDof(c); i++)
    if (i % c->type->ndof != c->type->ndof - 1) m = PetscMax(m, PetscAbsReal(R[i]));
  return m;
}

/* A smooth finite deformation (gradients ~0.15) and temperatures around THETA0 + 100. */
static void SetDeformed(Case *c)
{
  const PetscInt ndof = c->type->ndof;
  for (PetscInt i = 0; i < NDof(c); i++) {
    const PetscInt a = i / ndof, k = i % ndof;
    if (k == ndof - 1)
      c->u[i] = THETA0 + 100 + 30 * PetscSinReal(1.1 * i + 0.3);
    else if (a >= c->type->geom->nnode)
      c->u[i] = 0.02 * PetscCosReal(1.7 * i); /* the reference node's U3, UR1, UR2 */
    else if (c->type->kin == TSL_KIN_AXISYMMETRIC_TWIST && k == 2)
      c->u[i] = 0.1 * PetscCosReal(2.3 * i + 0.1); /* phi */
    else { /* a smooth field: a gradient of ~0.15 and a bend */
      static const PetscReal G[3][3] = {{0.12, -0.15, 0.08}, {0.1, -0.09, 0.14}, {-0.07, 0.11, 0.13}};
      const PetscReal       *X       = &c->x[3 * a];
      c->u[i] = 0.05 * PetscSinReal(1.3 * X[0] + 0.7 * X[1] + 0.4 * X[2] + k);
      for (PetscInt j = 0; j < c->type->dim; j++) c->u[i] += G[k][j] * X[j];
    }
  }
}

/* (a) forces of a turned body: R'(node) = Q R(node), the temperature rows and a reference node's unchanged. The
 * axisymmetric types turn about their axis only: a twist's phi + angle (no change at all); the plain ones move along
 * the axis instead. */
static PetscErrorCode CheckTurnedForces(TestLog *log, Case *c, PetscReal angle)
{
  const TslElementType *t = c->type;
  const PetscInt        ndof = t->ndof, nc = NCoord(t), n = t->geom->nnode;
  PetscReal             R0[TSL_MAX_ELEM_DOF], R1[TSL_MAX_ELEM_DOF], Q[3][3], err = 0, scale;

  PetscFunctionBeginUser;
  SetDeformed(c);
  PetscCall(Internal(c, R0, NULL));
  Rotation(t->dim, angle, Q);
  for (PetscInt a = 0; a < n; a++) {
    PetscReal xc[3];
    if (t->kin == TSL_KIN_AXISYMMETRIC) {
      c->u[ndof * a + 1] += 0.3;
      continue;
    }
    if (t->kin == TSL_KIN_AXISYMMETRIC_TWIST) {
      c->u[ndof * a + 2] += angle;
      continue;
    }
    for (PetscInt i = 0; i < nc; i++) xc[i] = c->x[3 * a + i] + c->u[ndof * a + i];
    for (PetscInt i = 0; i < nc; i++) {
      PetscReal y = 0;
      for (PetscInt j = 0; j < nc; j++) y += Q[i][j] * xc[j];
      c->u[ndof * a + i] = y - c->x[3 * a + i];
    }
  }
  PetscCall(Internal(c, R1, NULL));
  scale = PetscMax(MaxDisplacementRow(c, R0), 1e-300);
  for (PetscInt a = 0; a < TslElementTypeNodes(t); a++)
    for (PetscInt i = 0; i < ndof; i++) {
      PetscReal expect = R0[ndof * a + i];
      if (a < n && i < nc && !IsAxi(t)) {
        expect = 0;
        for (PetscInt j = 0; j < nc; j++) expect += Q[i][j] * R0[ndof * a + j];
      }
      err = PetscMax(err, PetscAbsReal(R1[ndof * a + i] - expect) / (i == ndof - 1 ? PetscMax(PetscAbsReal(R0[ndof * a + i]), 1) : scale));
    }
  Check(log, err, 0, 1e-10, "%s forces of the body turned by %g degrees: max |R' - Q R| (relative)", t->name, (double)(angle * 180 / PI));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* (b) turned rigidly while heated freely by alpha dT = 0.2: x = 1.2 Q X (plane strain: not heated, its F_33 = 1
 * holds the thickness), no force, no stress, LE = ln 1.2 in every normal direction the heating stretches. */
static PetscErrorCode CheckTurnedHeated(TestLog *log, Case *c, PetscReal angle)
{
  const TslElementType *t     = c->type;
  const PetscBool       plain = t->kin == TSL_KIN_PLANE_STRAIN ? PETSC_TRUE : PETSC_FALSE;
  const PetscReal       s = plain ? 1 : 1.2, dT = plain ? 0 : 0.2 / ALPHA;
  PetscReal             Q[3][3], F[3][3], R[TSL_MAX_ELEM_DOF], Rc[TSL_MAX_ELEM_DOF], smax = 0, emax = 0;
  TslElementResult      res;

  PetscFunctionBeginUser;
  Rotation(t->dim, IsAxi(t) ? 0 : angle, Q);
  for (PetscInt i = 0; i < 3; i++)
    for (PetscInt j = 0; j < 3; j++) F[i][j] = s * Q[i][j];
  if (t->dim == 2) F[2][2] = s; /* the plane's normal stretches too (GPS: its reference node) */
  SetHomogeneous(c, F, THETA0 + dT);
  if (t->kin == TSL_KIN_AXISYMMETRIC_TWIST)
    for (PetscInt a = 0; a < t->geom->nnode; a++) c->u[t->ndof * a + 2] = angle;
  PetscCall(Internal(c, R, NULL));
  PetscCall(TslElementOutput(&c->in, &res));
  /* the scale: the forces of the same element held while heated by dT */
  {
    PetscReal u[TSL_MAX_ELEM_DOF];
    PetscCall(PetscArraycpy(u, c->u, NDof(c)));
    for (PetscInt i = 0; i < NDof(c); i++)
      if (i % t->ndof != t->ndof - 1) c->u[i] = 0;
      else c->u[i] = THETA0 + 0.2 / ALPHA;
    PetscCall(Internal(c, Rc, NULL));
    PetscCall(PetscArraycpy(c->u, u, NDof(c)));
  }
  for (PetscInt r = 0; r < 6; r++) {
    smax = PetscMax(smax, PetscAbsReal(res.S[r]));
    emax = PetscMax(emax, PetscAbsReal(res.E[r] - (r < 3 && (r < 2 || !plain) ? Ln(s) : 0)));
  }
  Check(log, MaxDisplacementRow(c, R) / MaxDisplacementRow(c, Rc), 0, 1e-10, "%s turned by %g degrees and heated freely (alpha dT = %g): max|R_u| / held", t->name,
        (double)(angle * 180 / PI), (double)(s - 1));
  Check(log, smax / (c->E * 0.2), 0, 1e-8, "%s turned and heated freely: max|S| / (E alpha dT)", t->name);
  Check(log, emax, 0, 1e-12, "%s turned and heated freely: max|LE - ln %g|", t->name, (double)s);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* (c) a pre-stressed body turned: S' = Q S Q^T and LE' = Q LE Q^T (Voigt, engineering shear). */
static PetscErrorCode CheckTurnedStress(TestLog *log, Case *c, PetscReal angle)
{
  const TslElementType *t = c->type;
  static const PetscInt vi[6] = {0, 1, 2, 0, 0, 1}, vj[6] = {0, 1, 2, 1, 2, 2};
  PetscReal             F0[3][3] = {{1.12, 0.06, 0.02}, {-0.04, 0.93, 0.05}, {0.03, -0.02, 1.05}}, F[3][3], Q[3][3];
  PetscReal             S0[3][3], E0[3][3], es = 0, ee = 0, smax = 0;
  TslElementResult      r0, r1;

  PetscFunctionBeginUser;
  if (t->dim == 2) F0[0][2] = F0[1][2] = F0[2][0] = F0[2][1] = 0, F0[2][2] = t->kin == TSL_KIN_GENERALIZED_PLANE_STRAIN ? 1.05 : 1;
  SetHomogeneous(c, F0, THETA0 + 50);
  PetscCall(TslElementOutput(&c->in, &r0));
  for (PetscInt r = 0; r < 6; r++) {
    S0[vi[r]][vj[r]] = S0[vj[r]][vi[r]] = r0.S[r];
    E0[vi[r]][vj[r]] = E0[vj[r]][vi[r]] = r < 3 ? r0.E[r] : 0.5 * r0.E[r];
    smax = PetscMax(smax, PetscAbsReal(r0.S[r]));
  }
  Rotation(t->dim, angle, Q);
  for (PetscInt i = 0; i < 3; i++)
    for (PetscInt j = 0; j < 3; j++) {
      F[i][j] = 0;
      for (PetscInt k = 0; k < 3; k++) F[i][j] += Q[i][k] * F0[k][j];
    }
  SetHomogeneous(c, F, THETA0 + 50);
  PetscCall(TslElementOutput(&c->in, &r1));
  for (PetscInt r = 0; r < 6; r++) {
    PetscReal s = 0, e = 0;
    for (PetscInt k = 0; k < 3; k++)
      for (PetscInt l = 0; l < 3; l++) s += Q[vi[r]][k] * S0[k][l] * Q[vj[r]][l], e += Q[vi[r]][k] * E0[k][l] * Q[vj[r]][l];
    es = PetscMax(es, PetscAbsReal(r1.S[r] - s));
    ee = PetscMax(ee, PetscAbsReal(r1.E[r] - (r < 3 ? e : 2 * e)));
  }
  Check(log, es / smax, 0, 1e-6, "%s pre-stressed, turned by %g degrees: max|S' - Q S Q^T| / max|S|", t->name, (double)(angle * 180 / PI));
  Check(log, ee, 0, 1e-9, "%s pre-stressed, turned: max|LE' - Q LE Q^T|", t->name);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* (d) K against central differences of R at a finite deformation, block by block, relative to each block's largest
 * entry; face > 0: a follower pressure on that face alone. */
static PetscErrorCode Part(Case *c, PetscInt face, PetscReal R[], PetscReal K[])
{
  const PetscInt nd = NDof(c);

  PetscFunctionBeginUser;
  if (!face) PetscFunctionReturn(Internal(c, R, K));
  for (PetscInt i = 0; i < nd; i++) R[i] = 0;
  if (K)
    for (PetscInt i = 0; i < nd * nd; i++) K[i] = 0;
  PetscCall(TslElementFaceLoad(&c->in, TSL_FACE_PRESSURE, face, &(TslFaceLoadValue){3.0e3, 0, 0}, R, K, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckTangent(TestLog *log, Case *c, PetscInt face)
{
  static const char *block_name[2][2] = {{"uu", "u-theta"}, {"theta-u", "theta-theta"}};
  const PetscInt     nd = NDof(c), ndof = c->type->ndof;
  PetscReal          K[TSL_MAX_ELEM_DOF * TSL_MAX_ELEM_DOF], R[TSL_MAX_ELEM_DOF], Rp[TSL_MAX_ELEM_DOF], Rm[TSL_MAX_ELEM_DOF];
  PetscReal          kmax[2][2] = {{0}}, err[2][2] = {{0}};

  PetscFunctionBeginUser;
  SetDeformed(c);
  PetscCall(Part(c, face, R, K));
  for (PetscInt j = 0; j < nd; j++) {
    const PetscReal save = c->u[j], h = 1e-6 * PetscMax(1, PetscAbsReal(save));
    c->u[j] = save + h;
    PetscCall(Part(c, face, Rp, NULL));
    c->u[j] = save - h;
    PetscCall(Part(c, face, Rm, NULL));
    c->u[j] = save;
    for (PetscInt i = 0; i < nd; i++) {
      const PetscInt bi = i % ndof == ndof - 1, bj = j % ndof == ndof - 1;
      err[bi][bj]  = PetscMax(err[bi][bj], PetscAbsReal((Rp[i] - Rm[i]) / (2 * h) - K[i * nd + j]));
      kmax[bi][bj] = PetscMax(kmax[bi][bj], PetscAbsReal(K[i * nd + j]));
    }
  }
  for (PetscInt bi = 0; bi < 2; bi++)
    for (PetscInt bj = 0; bj < 2; bj++) {
      if (face && (bi || bj)) continue; /* a pressure has no temperature row or column */
      Check(log, err[bi][bj] / (kmax[bi][bj] > 0 ? kmax[bi][bj] : 1), 0, 1e-6, "%s finite strain%s tangent %s block vs central differences (relative)",
            c->type->name, face ? (const char *[]){"", " pressure on S1", " pressure on S2", " pressure on S3", " pressure on S4", " pressure on S5", " pressure on S6"}[face] : "",
            block_name[bi][bj]);
    }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* (e) closed forms of St Venant-Kirchhoff, S = lambda tr(E) I + 2 mu E on the undistorted element:
 * uniaxial stretch lambda = 2 with the lateral stretch lt = sqrt(1 - nu (lambda^2 - 1)) (S_22 = 0 makes E_22 = -nu E_11):
 * sigma_11 = lambda S_11 / lt^2 with S_11 = E (lambda^2 - 1) / 2, LE = (ln 2, ln lt, ln lt); simple shear gamma = 1:
 * E = [[0, 1/2], [1/2, 1/2]], sigma = F S F^T, LE from the eigenvalues (3 +- sqrt 5) / 2 of F F^T. */
static PetscErrorCode CheckClosedForms(TestLog *log, Case *c)
{
  const TslElementType *t = c->type;
  const PetscReal       E = c->E, nu = c->nu, lam = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  TslElementResult      res;

  PetscFunctionBeginUser;
  if (t->kin == TSL_KIN_SOLID3D || t->kin == TSL_KIN_PLANE_STRESS) {
    const PetscReal l = 2, lt = PetscSqrtReal(1 - nu * (l * l - 1)), S11 = E * (l * l - 1) / 2;
    PetscReal       F[3][3] = {{l, 0, 0}, {0, lt, 0}, {0, 0, t->dim == 3 ? lt : 1}};
    SetHomogeneous(c, F, THETA0);
    PetscCall(TslElementOutput(&c->in, &res));
    CheckRel(log, res.S[0], l * S11 / (lt * lt), 1e-10, 1, "%s uniaxial stretch to 2: Cauchy S11", t->name);
    for (PetscInt r = 1; r < 6; r++) Check(log, res.S[r] / S11, 0, 1e-10, "%s uniaxial stretch to 2: S%" PetscInt_FMT " / S11", t->name, r + 1);
    CheckRel(log, res.E[0], Ln(2), 1e-10, 1, "%s uniaxial stretch to 2: LE11", t->name);
    CheckRel(log, res.E[1], Ln(lt), 1e-10, 1, "%s uniaxial stretch to 2: LE22", t->name);
    CheckRel(log, res.E[2], Ln(lt), 1e-10, 1, "%s uniaxial stretch to 2: LE33", t->name);
  }
  if (t->kin == TSL_KIN_SOLID3D || t->kin == TSL_KIN_PLANE_STRAIN) {
    const PetscReal F[3][3] = {{1, 1, 0}, {0, 1, 0}, {0, 0, 1}}, Ev[3][3] = {{0, 0.5, 0}, {0.5, 0.5, 0}, {0, 0, 0}};
    const PetscReal w1 = (3 + PetscSqrtReal(5.0)) / 2, w2 = (3 - PetscSqrtReal(5.0)) / 2;
    PetscReal       S[3][3], sig[3][3], v1[2] = {1, w1 - 2}, v2[2] = {1, w2 - 2}, n1 = PetscSqrtReal(1 + (w1 - 2) * (w1 - 2)), n2 = PetscSqrtReal(1 + (w2 - 2) * (w2 - 2));
    PetscReal       LE[2][2];
    for (PetscInt i = 0; i < 3; i++)
      for (PetscInt j = 0; j < 3; j++) S[i][j] = lam * 0.5 * (i == j) + 2 * mu * Ev[i][j];
    for (PetscInt i = 0; i < 3; i++)
      for (PetscInt j = 0; j < 3; j++) {
        sig[i][j] = 0;
        for (PetscInt k = 0; k < 3; k++)
          for (PetscInt l = 0; l < 3; l++) sig[i][j] += F[i][k] * S[k][l] * F[j][l];
      }
    for (PetscInt i = 0; i < 2; i++)
      for (PetscInt j = 0; j < 2; j++) LE[i][j] = 0.5 * Ln(w1) * v1[i] * v1[j] / (n1 * n1) + 0.5 * Ln(w2) * v2[i] * v2[j] / (n2 * n2);
    SetHomogeneous(c, F, THETA0);
    PetscCall(TslElementOutput(&c->in, &res));
    CheckRel(log, res.S[0], sig[0][0], 1e-10, E, "%s simple shear to 1: Cauchy S11", t->name);
    CheckRel(log, res.S[1], sig[1][1], 1e-10, E, "%s simple shear to 1: Cauchy S22", t->name);
    CheckRel(log, res.S[2], sig[2][2], 1e-10, E, "%s simple shear to 1: Cauchy S33", t->name);
    CheckRel(log, res.S[3], sig[0][1], 1e-10, E, "%s simple shear to 1: Cauchy S12", t->name);
    CheckRel(log, res.E[0], LE[0][0], 1e-10, 1, "%s simple shear to 1: LE11", t->name);
    CheckRel(log, res.E[1], LE[1][1], 1e-10, 1, "%s simple shear to 1: LE22", t->name);
    CheckRel(log, res.E[3], 2 * LE[0][1], 1e-10, 1, "%s simple shear to 1: LE12 (engineering)", t->name);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  TestLog log = {0, 0};
  Case    c;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  for (PetscInt k = 0; k < TslElementTypeCount(); k++) {
    const TslElementType *type = TslElementTypeGet(k);
    if (TslElementTypeHeatOnly(type) || !TslElementTypeFiniteStrain(type)) continue;
    printf("---- %s: %s\n", type->name, type->description);
    for (PetscInt a = 0; a < 2; a++) {
      const PetscReal angle = a ? 390 * PI / 180 : PI / 2;
      CaseSetUp(&c, type, 0.08, PETSC_FALSE);
      PetscCall(CheckTurnedForces(&log, &c, angle));
      CaseSetUp(&c, type, 0.08, PETSC_FALSE);
      PetscCall(CheckTurnedHeated(&log, &c, angle));
      if (!IsAxi(type)) {
        CaseSetUp(&c, type, 0.08, PETSC_FALSE);
        PetscCall(CheckTurnedStress(&log, &c, angle));
      }
    }
    CaseSetUp(&c, type, 0.08, PETSC_TRUE);
    PetscCall(CheckTangent(&log, &c, 0));
    for (PetscInt f = 1; f <= type->geom->nface; f++) {
      CaseSetUp(&c, type, 0.08, PETSC_FALSE);
      PetscCall(CheckTangent(&log, &c, f));
    }
    CaseSetUp(&c, type, 0, PETSC_FALSE);
    PetscCall(CheckClosedForms(&log, &c));
  }
  PetscCall(PetscFinalize());
  return Summary(&log);
}
