/* Integration-point geometry, strain-displacement matrices and elasticity for each kinematics.
 *
 * Every kinematic assumption is expressed in the full 3D Voigt space (11, 22, 33, 12, 13, 23) so that
 * the kernels have one code path:
 *   plane strain   eps_33 = 0 (row of B is zero), full isotropic D, so sigma_33 = nu (s11 + s22) - E alpha dT
 *   plane stress   sigma_33 = 0 by static condensation of D (D_ps), thermal stress D_ps eps_th [1,1,0]
 *   axisymmetric   x = r, y = z, eps_33 = u_r / r (hoop), dV = 2 pi r dA
 *   3D             all six components
 *   continuum shell  all six components of the strain; plane stress in the plane normal to the stack
 *                  direction and the thickness modulus along it (ShellLocal, rotated to the global axes)
 */
#include "element_impl.h"
#include <stdio.h>

static PetscInt RigidPlane(const PetscReal x[3], PetscReal modes[6][3])
{
  modes[0][0] = 1, modes[1][1] = 1;
  modes[2][0] = -x[1], modes[2][1] = x[0];
  return 3;
}

/* twist: the axial translation and the rigid rotation about the axis (phi = 1) */
static PetscInt RigidTwist(const PetscReal x[3], PetscReal modes[6][3])
{
  (void)x;
  modes[0][1] = 1;
  modes[1][2] = 1;
  return 2;
}

/* a radial shift strains the hoop direction: only the axial translation is rigid */
static PetscInt RigidAxisymmetric(const PetscReal x[3], PetscReal modes[6][3])
{
  (void)x;
  modes[0][1] = 1;
  return 1;
}

static PetscInt RigidSolid(const PetscReal x[3], PetscReal modes[6][3])
{
  for (PetscInt i = 0; i < 3; i++) modes[i][i] = 1;
  modes[3][1] = -x[2], modes[3][2] = x[1];
  modes[4][0] = x[2], modes[4][2] = -x[0];
  modes[5][0] = -x[1], modes[5][1] = x[0];
  return 6;
}

/* columns: name, hoop, free_normal, revolve, thickness, twist, reference, shell, rigid modes */
static const struct TslKinematicsRow KinematicsTable[TSL_NKIN] = {
    [TSL_KIN_PLANE_STRAIN] = {"plane strain", PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_TRUE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, RigidPlane},
    [TSL_KIN_PLANE_STRESS] = {"plane stress", PETSC_FALSE, PETSC_TRUE, PETSC_FALSE, PETSC_TRUE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, RigidPlane},
    [TSL_KIN_GENERALIZED_PLANE_STRAIN] = {"generalized plane strain", PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_TRUE, PETSC_FALSE, PETSC_TRUE,
                                          PETSC_FALSE, RigidPlane},
    [TSL_KIN_AXISYMMETRIC]             = {"axisymmetric", PETSC_TRUE, PETSC_FALSE, PETSC_TRUE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE,
                                          RigidAxisymmetric},
    [TSL_KIN_AXISYMMETRIC_TWIST] = {"axisymmetric with twist", PETSC_TRUE, PETSC_FALSE, PETSC_TRUE, PETSC_FALSE, PETSC_TRUE, PETSC_FALSE, PETSC_FALSE,
                                    RigidTwist},
    [TSL_KIN_SOLID3D]            = {"3D", PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, RigidSolid},
    [TSL_KIN_CONTINUUM_SHELL]    = {"continuum shell", PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_TRUE,
                                    RigidSolid},
};

const struct TslKinematicsRow *TslKinematicsRowGet(TslKinematics kin)
{
  return &KinematicsTable[kin];
}

const char *TslElementTypeKinematicsName(const TslElementType *t)
{
  return KinematicsTable[t->kin].name;
}

/* 3D kinematics differ only in the constitutive assumption (a continuum shell glued to a solid is a common
 * model), so any two of them may share nodes. */
PetscBool TslElementTypeSameKinematics(const TslElementType *a, const TslElementType *b)
{
  /* a heat-transfer link (DC1D2, DC1D3: a line) joins any heat-transfer body of a planar or 3D model */
  const PetscBool link = a->ndof == 1 && b->ndof == 1 && (a->geom->dim == 1 || b->geom->dim == 1) ? PETSC_TRUE : PETSC_FALSE;
  return a->kin == b->kin || (a->dim == 3 && b->dim == 3) || link ? PETSC_TRUE : PETSC_FALSE;
}

const char *TslElementTypeSectionKeyword(const TslElementType *t)
{
  return KinematicsTable[t->kin].shell ? "SHELL SECTION" : "SOLID SECTION";
}

PetscBool TslElementTypeStackAllowed(const TslElementType *t, PetscInt stack)
{
  if (stack < 0 || stack > 2) return PETSC_FALSE;
  return stack == 2 || t->geom == &TslGeomHex8 ? PETSC_TRUE : PETSC_FALSE;
}

PetscBool TslElementTypeSameModel(const TslElementType *a, const TslElementType *b)
{
  if (a->ndof != b->ndof || KinematicsTable[a->kin].revolve != KinematicsTable[b->kin].revolve) return PETSC_FALSE;
  for (PetscInt i = 0; i < a->ndof; i++)
    if (a->node_dof[i] != b->node_dof[i]) return PETSC_FALSE;
  return PETSC_TRUE;
}

PetscBool TslKinematicsRevolves(TslKinematics kin)
{
  return (PetscInt)kin >= 0 && kin < TSL_NKIN ? KinematicsTable[kin].revolve : PETSC_FALSE;
}

PetscBool TslKinematicsTwists(TslKinematics kin)
{
  return (PetscInt)kin >= 0 && kin < TSL_NKIN ? KinematicsTable[kin].twist : PETSC_FALSE;
}

PetscBool TslElementTypeHasDof(const TslElementType *t, PetscInt dof)
{
  for (PetscInt i = 0; i < t->ndof; i++)
    if (t->node_dof[i] == dof || (t->nextra && dof > 0 && t->extra_dof[i] == dof)) return PETSC_TRUE; /* CPEG: the reference node's 3, 4, 5 */
  return PETSC_FALSE;
}

const char *TslElementTypeDofList(const TslElementType *t, char *buf, size_t len)
{
  size_t k = 0;
  buf[0]   = 0;
  for (PetscInt i = 0; i < t->ndof && k + 8 < len; i++)
    if (t->node_dof[i]) k += (size_t)snprintf(buf + k, len - k, "%s%d", k ? ", " : "", (int)t->node_dof[i]);
  for (PetscInt i = 0, first = 1; t->nextra && i < t->ndof && k + (first ? 30 : 8) < len; i++)
    if (t->extra_dof[i]) k += (size_t)snprintf(buf + k, len - k, "%s%d", first ? "; the reference node's " : ", ", (int)t->extra_dof[i]), first = 0;
  return buf;
}

PetscInt TslElementTypeRigidModes(const TslElementType *t, const PetscReal x[3], PetscReal modes[6][3])
{
  for (PetscInt m = 0; m < 6; m++)
    for (PetscInt c = 0; c < 3; c++) modes[m][c] = 0;
  if (TslElementTypeHeatOnly(t)) return 0; /* no displacement, no rigid motion */
  return KinematicsTable[t->kin].rigid_modes(x, modes);
}

/* Inverse of the dim x dim Jacobian J[i][j] = dx_i/dxi_j; returns det J. */
static PetscReal InvertJacobian(PetscInt dim, const PetscReal J[3][3], PetscReal Ji[3][3])
{
  PetscReal det;
  if (dim == 2) {
    det      = J[0][0] * J[1][1] - J[0][1] * J[1][0];
    Ji[0][0] = J[1][1] / det;
    Ji[0][1] = -J[0][1] / det;
    Ji[1][0] = -J[1][0] / det;
    Ji[1][1] = J[0][0] / det;
    return det;
  }
  det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
        J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
  Ji[0][0] = (J[1][1] * J[2][2] - J[1][2] * J[2][1]) / det;
  Ji[0][1] = (J[0][2] * J[2][1] - J[0][1] * J[2][2]) / det;
  Ji[0][2] = (J[0][1] * J[1][2] - J[0][2] * J[1][1]) / det;
  Ji[1][0] = (J[1][2] * J[2][0] - J[1][0] * J[2][2]) / det;
  Ji[1][1] = (J[0][0] * J[2][2] - J[0][2] * J[2][0]) / det;
  Ji[1][2] = (J[0][2] * J[1][0] - J[0][0] * J[1][2]) / det;
  Ji[2][0] = (J[1][0] * J[2][1] - J[1][1] * J[2][0]) / det;
  Ji[2][1] = (J[0][1] * J[2][0] - J[0][0] * J[2][1]) / det;
  Ji[2][2] = (J[0][0] * J[1][1] - J[0][1] * J[1][0]) / det;
  return det;
}

PetscBool TslElementPointEvaluate(const TslElementType *type, const TslElementSection *sec, const PetscReal x[], const PetscReal xi[], PetscReal w,
                                  TslElementPoint *p)
{
  const TslGeometry             *g    = type->geom;
  const struct TslKinematicsRow *info = TslKinematicsRowGet(type->kin);
  const PetscInt                 dim = g->dim, n                     = g->nnode;
  PetscReal                      dN[TSL_MAX_ELEM_NODES * 3], J[3][3] = {{0}}, Ji[3][3] = {{0}};

  g->shape(xi, p->N, dN);
  for (PetscInt d = 0; d < 3; d++) p->x[d] = 0, p->xi[d] = d < dim ? xi[d] : 0;
  if (dim == 1) {
    /* a link (DC1D2, DC1D3): a line in space; its gradient is along the tangent t = dx/dxi, dN/ds t / |t| with
     * ds = |t| dxi, and its measure the section's cross-section area A (the *SOLID SECTION value) times ds */
    PetscReal t[3] = {0, 0, 0}, L2;
    for (PetscInt a = 0; a < n; a++)
      for (PetscInt d = 0; d < 3; d++) p->x[d] += p->N[a] * x[3 * a + d], t[d] += dN[a] * x[3 * a + d];
    L2      = t[0] * t[0] + t[1] * t[1] + t[2] * t[2];
    p->detJ = PetscSqrtReal(L2);
    if (!(p->detJ > 0)) return PETSC_FALSE;
    for (PetscInt i = 0; i < 3; i++)
      for (PetscInt j = 0; j < 3; j++) p->Ji[i][j] = i == 0 ? t[j] / L2 : 0;
    for (PetscInt a = 0; a < n; a++)
      for (PetscInt i = 0; i < 3; i++) p->dNdx[a][i] = dN[a] * t[i] / L2;
    p->dV = w * p->detJ * (sec && sec->thickness > 0 ? sec->thickness : 1.0);
    return PETSC_TRUE;
  }
  for (PetscInt a = 0; a < n; a++) {
    for (PetscInt d = 0; d < 3; d++) p->x[d] += p->N[a] * x[3 * a + d];
    for (PetscInt i = 0; i < dim; i++)
      for (PetscInt j = 0; j < dim; j++) J[i][j] += x[3 * a + i] * dN[dim * a + j];
  }
  p->detJ = InvertJacobian(dim, J, Ji);
  if (!(p->detJ > 0)) return PETSC_FALSE;
  for (PetscInt i = 0; i < 3; i++)
    for (PetscInt j = 0; j < 3; j++) p->Ji[i][j] = Ji[i][j];
  for (PetscInt a = 0; a < n; a++) {
    for (PetscInt i = 0; i < 3; i++) p->dNdx[a][i] = 0;
    for (PetscInt i = 0; i < dim; i++)
      for (PetscInt j = 0; j < dim; j++) p->dNdx[a][i] += dN[dim * a + j] * Ji[j][i];
  }
  p->dV = w * p->detJ;
  if (info->thickness) p->dV *= sec->thickness > 0 ? sec->thickness : 1.0;
  if (info->revolve) {
    if (!(p->x[0] > 0)) return PETSC_FALSE;
    p->dV *= 2 * PETSC_PI * p->x[0];
  }
  return PETSC_TRUE;
}

void TslElementStrainMatrix(const TslElementType *type, const TslElementSection *sec, const PetscReal x[], const TslElementPoint *p,
                            PetscReal B[6][TSL_MAX_ELEM_NODES * 3])
{
  const PetscInt                 dim = type->dim, nu = type->ndof - 1, n = type->geom->nnode, nv = TslElementTypeNodes(type);
  const struct TslKinematicsRow *info = TslKinematicsRowGet(type->kin);
  /* Voigt row -> (i, j) of the symmetric gradient; for the 3D shear rows both orders contribute */
  static const PetscInt vi[6] = {0, 1, 2, 0, 0, 1}, vj[6] = {0, 1, 2, 1, 2, 2};

  for (PetscInt r = 0; r < 6; r++)
    for (PetscInt c = 0; c < nv * nu; c++) B[r][c] = 0;
  for (PetscInt a = 0; a < n; a++) {
    for (PetscInt r = 0; r < 6; r++) {
      const PetscInt i = vi[r], j = vj[r];
      if (i >= dim || j >= dim) continue;
      B[r][nu * a + i] += p->dNdx[a][j];
      if (i != j) B[r][nu * a + j] += p->dNdx[a][i];
    }
    if (info->hoop) B[2][nu * a + 0] = p->N[a] / p->x[0];
    if (info->twist) {
      /* the twist phi (dof 5, radians) is the third unknown: u_theta = r phi, so
       * gamma_r-theta = r dphi/dr (Voigt 13) and gamma_z-theta = r dphi/dz (Voigt 23) */
      B[4][nu * a + 2] = p->x[0] * p->dNdx[a][0];
      B[5][nu * a + 2] = p->x[0] * p->dNdx[a][1];
    }
  }
  if (info->reference) {
    /* generalized plane strain: the bounding planes move apart by U3 and turn by UR1, UR2 (the reference
     * node's dofs 3, 4, 5, at (X0, Y0)); over the thickness t,
     * eps_33 = (U3 + UR1 (y - Y0) - UR2 (x - X0)) / t */
    const PetscReal  t  = sec->thickness > 0 ? sec->thickness : 1.0;
    const PetscReal *x0 = &x[3 * n];
    B[2][nu * n + 0]    = 1 / t;
    B[2][nu * n + 1]    = (p->x[1] - x0[1]) / t;
    B[2][nu * n + 2]    = -(p->x[0] - x0[0]) / t;
  }
}

static void ColumnAdd(TslGradientColumn *c, PetscInt i, PetscInt k, PetscReal v)
{
  c->i[c->n] = i, c->k[c->n] = k, c->v[c->n++] = v;
}

void TslElementDeformation(const TslElementType *type, const TslElementSection *sec, const PetscReal x[], const TslElementPoint *p, const PetscReal u[],
                           PetscReal H[3][3], TslGradientColumn col[])
{
  const PetscInt                 dim = type->dim, ndof = type->ndof, nu = ndof - 1, n = type->geom->nnode, nv = TslElementTypeNodes(type);
  const struct TslKinematicsRow *info = TslKinematicsRowGet(type->kin);
  const PetscInt                 ng   = info->twist ? 2 : nu; /* displacement components with a gradient in the plane or space */
  PetscReal                      ur = 0, dphi[2] = {0, 0};

  for (PetscInt i = 0; i < 3; i++)
    for (PetscInt j = 0; j < 3; j++) H[i][j] = 0;
  for (PetscInt a = 0; a < n; a++) {
    for (PetscInt i = 0; i < ng && i < dim; i++)
      for (PetscInt j = 0; j < dim; j++) H[i][j] += u[ndof * a + i] * p->dNdx[a][j];
    if (info->hoop) ur += p->N[a] * u[ndof * a];
    if (info->twist)
      for (PetscInt j = 0; j < 2; j++) dphi[j] += u[ndof * a + 2] * p->dNdx[a][j];
  }
  if (info->hoop) H[2][2] = ur / p->x[0];
  if (info->twist) H[2][0] = (p->x[0] + ur) * dphi[0], H[2][1] = (p->x[0] + ur) * dphi[1];
  for (PetscInt c = 0; c < nv * nu; c++) col[c].n = 0;
  for (PetscInt a = 0; a < n; a++) {
    for (PetscInt i = 0; i < ng && i < dim; i++)
      for (PetscInt j = 0; j < dim; j++) ColumnAdd(&col[nu * a + i], i, j, p->dNdx[a][j]);
    if (info->hoop) ColumnAdd(&col[nu * a], 2, 2, p->N[a] / p->x[0]);
    if (info->twist) {
      for (PetscInt j = 0; j < 2; j++) {
        ColumnAdd(&col[nu * a], 2, j, p->N[a] * dphi[j]);
        ColumnAdd(&col[nu * a + 2], 2, j, (p->x[0] + ur) * p->dNdx[a][j]);
      }
    }
  }
  if (info->reference) { /* eps_33 of the reference node's dofs (TslElementStrainMatrix) */
    const PetscReal  t = sec->thickness > 0 ? sec->thickness : 1.0, *x0 = &x[3 * n];
    const PetscReal  g[3] = {1 / t, (p->x[1] - x0[1]) / t, -(p->x[0] - x0[0]) / t};
    for (PetscInt k = 0; k < 3; k++) {
      H[2][2] += g[k] * u[ndof * n + k];
      ColumnAdd(&col[nu * n + k], 2, 2, g[k]);
    }
  }
}

/* Isotropic D in (lambda, mu): lambda m m^T + mu diag(2, 2, 2, 1, 1, 1). Linear in (lambda, mu), so the
 * same function gives dD from (dlambda, dmu) before the plane-stress condensation. */
static void Isotropic(PetscReal lambda, PetscReal mu, PetscReal D[6][6])
{
  PetscCallAbort(PETSC_COMM_SELF, PetscArrayzero(&D[0][0], 36));
  for (PetscInt i = 0; i < 3; i++) {
    D[i][0] = D[i][1] = D[i][2] = lambda;
    D[i][i] += 2 * mu;
    D[i + 3][i + 3] = mu;
  }
}

void TslElementLame(const TslMaterialPoint *mp, PetscReal *lambda, PetscReal *mu)
{
  *lambda = mp->E * mp->nu / ((1 + mp->nu) * (1 - 2 * mp->nu));
  *mu     = mp->E / (2 * (1 + mp->nu));
}

/* A continuum shell's elasticity in the frame (e1, e2, n) of its stack direction n (Abaqus's SC8R, SC6R):
 * plane stress in the shell plane, sigma_nn = E_t eps_nn uncoupled from it (E_t the section's thickness
 * modulus, by default 2 G, Abaqus's default), transverse shear k G with k = 5/6 (the shear correction of a
 * homogeneous section). The thermal strain acts in every direction through D (eps - eps_th m). */
static void ShellLocal(const TslElementSection *sec, const TslMaterialPoint *mp, PetscReal D[6][6], PetscReal dD[6][6])
{
  const PetscReal E = mp->E, nu = mp->nu, c = 1 / (1 - nu * nu), G = E / (2 * (1 + nu));
  const PetscReal dG    = mp->dE / (2 * (1 + nu)) - mp->dnu * E / (2 * (1 + nu) * (1 + nu));
  const PetscBool given = sec && sec->thickness_modulus > 0 ? PETSC_TRUE : PETSC_FALSE;
  const PetscReal k     = 5.0 / 6.0;

  PetscCallAbort(PETSC_COMM_SELF, PetscArrayzero(&D[0][0], 36));
  D[0][0] = D[1][1] = E * c;
  D[0][1] = D[1][0] = nu * E * c;
  D[2][2]           = TslElementShellThicknessModulus(sec, mp);
  D[3][3]           = G;
  D[4][4] = D[5][5] = k * G;
  if (!dD) return;
  PetscCallAbort(PETSC_COMM_SELF, PetscArrayzero(&dD[0][0], 36));
  dD[0][0] = dD[1][1] = mp->dE * c + E * 2 * nu * c * c * mp->dnu;
  dD[0][1] = dD[1][0] = (mp->dnu * E + nu * mp->dE) * c + nu * E * 2 * nu * c * c * mp->dnu;
  dD[2][2]            = given ? 0 : 2 * dG;
  dD[3][3]            = dG;
  dD[4][4] = dD[5][5] = k * dG;
}

PetscReal TslElementShellThicknessModulus(const TslElementSection *sec, const TslMaterialPoint *mp)
{
  return sec && sec->thickness_modulus > 0 ? sec->thickness_modulus : mp->E / (1 + mp->nu);
}

/* The shell frame at a point: n the unit gradient of the stack coordinate (the section's stack direction, the
 * third reference coordinate by default; normal to the element's layers), e1 the global axis least aligned
 * with n projected onto the shell plane, e2 = n x e1; rows of Q. For an isotropic material the choice of e1
 * does not matter. */
void TslElementShellFrame(const TslElementSection *sec, const TslElementPoint *p, PetscReal Q[3][3])
{
  const PetscInt s    = TslElementShellStack(sec);
  PetscReal      n[3] = {p->Ji[s][0], p->Ji[s][1], p->Ji[s][2]}, len = PetscSqrtReal(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), e1[3], dot;
  PetscInt  k = 0;

  for (PetscInt d = 0; d < 3; d++) n[d] /= len;
  for (PetscInt d = 1; d < 3; d++)
    if (PetscAbsReal(n[d]) < PetscAbsReal(n[k])) k = d;
  dot = n[k];
  for (PetscInt d = 0; d < 3; d++) e1[d] = (d == k) - dot * n[d];
  len = PetscSqrtReal(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  for (PetscInt d = 0; d < 3; d++) Q[0][d] = e1[d] / len, Q[2][d] = n[d];
  Q[1][0] = n[1] * Q[0][2] - n[2] * Q[0][1];
  Q[1][1] = n[2] * Q[0][0] - n[0] * Q[0][2];
  Q[1][2] = n[0] * Q[0][1] - n[1] * Q[0][0];
}

/* D = T^T D_l T with T the Voigt (engineering shear) map of global strains to the frame's, eps_l = T eps:
 * eps'_ij = Q_ik Q_jl eps_kl, a global shear component counted for both its orders, a local one doubled. */
void TslElementStrainTransform(const PetscReal Q[3][3], PetscReal T[6][6])
{
  static const PetscInt vi[6] = {0, 1, 2, 0, 0, 1}, vj[6] = {0, 1, 2, 1, 2, 2};
  for (PetscInt r = 0; r < 6; r++)
    for (PetscInt s = 0; s < 6; s++) {
      const PetscInt i = vi[r], j = vj[r], k = vi[s], l = vj[s];
      T[r][s] = (k == l ? Q[i][k] * Q[j][k] : 0.5 * (Q[i][k] * Q[j][l] + Q[i][l] * Q[j][k])) * (r < 3 ? 1 : 2);
    }
}

static void Rotate(const PetscReal Q[3][3], PetscReal D[6][6])
{
  PetscReal T[6][6], TD[6][6];

  TslElementStrainTransform(Q, T);
  for (PetscInt r = 0; r < 6; r++)
    for (PetscInt s = 0; s < 6; s++) {
      TD[r][s] = 0;
      for (PetscInt m = 0; m < 6; m++) TD[r][s] += T[m][r] * D[m][s];
    }
  for (PetscInt r = 0; r < 6; r++)
    for (PetscInt s = 0; s < 6; s++) {
      D[r][s] = 0;
      for (PetscInt m = 0; m < 6; m++) D[r][s] += TD[r][m] * T[m][s];
    }
}

PetscReal TslElementWaveModulus(const TslElementType *type, const TslMaterialPoint *mp)
{
  const struct TslKinematicsRow *info = TslKinematicsRowGet(type->kin);
  PetscReal                      lambda, mu;

  if (info->free_normal || info->shell) return mp->E / (1 - mp->nu * mp->nu);
  TslElementLame(mp, &lambda, &mu);
  return lambda + 2 * mu;
}

void TslElementElasticity(const TslElementType *type, const TslElementSection *sec, const TslElementPoint *p, const TslMaterialPoint *mp,
                          PetscReal D[6][6], PetscReal dD[6][6])
{
  const PetscReal E = mp->E, nu = mp->nu, a = (1 + nu) * (1 - 2 * nu);
  PetscReal       lambda, mu;
  /* d lambda / d nu = E (1 + 2 nu^2) / a^2, d mu / d nu = -E / (2 (1 + nu)^2) */
  const PetscReal dlambda = mp->dE * nu / a + mp->dnu * E * (1 + 2 * nu * nu) / (a * a);
  const PetscReal dmu     = mp->dE / (2 * (1 + nu)) - mp->dnu * E / (2 * (1 + nu) * (1 + nu));
  PetscReal       D0[6][6], dD0[6][6];

  if (TslKinematicsRowGet(type->kin)->shell) {
    PetscReal Q[3][3];
    ShellLocal(sec, mp, D, dD);
    TslElementShellFrame(sec, p, Q);
    Rotate(Q, D);
    if (dD) Rotate(Q, dD);
    return;
  }
  TslElementLame(mp, &lambda, &mu);
  if (!TslKinematicsRowGet(type->kin)->free_normal) { /* straight into D (and dD only when asked: the explicit forces do not) */
    Isotropic(lambda, mu, D);
    if (dD) Isotropic(dlambda, dmu, dD);
    return;
  }
  /* sigma_33 = 0: eliminate eps_33 = -(D_3j eps_j) / D_33, D_ps = D - c c^T / d33 with c = D[:, 2];
   * its derivative dD - (dc c^T + c dc^T) / d33 + c c^T dd33 / d33^2 */
  Isotropic(lambda, mu, D0);
  if (dD) Isotropic(dlambda, dmu, dD0);
  for (PetscInt i = 0; i < 6; i++)
    for (PetscInt j = 0; j < 6; j++) {
      const PetscReal ci = D0[i][2], cj = D0[j][2], d33 = D0[2][2];
      D[i][j] = D0[i][j] - ci * cj / d33;
      if (dD) dD[i][j] = dD0[i][j] - (dD0[i][2] * cj + ci * dD0[j][2]) / d33 + ci * cj * dD0[2][2] / (d33 * d33);
    }
  for (PetscInt j = 0; j < 6; j++) {
    D[2][j] = D[j][2] = 0;
    if (dD) dD[2][j] = dD[j][2] = 0;
  }
}
