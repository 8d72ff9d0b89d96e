/* Integration-point geometry, strain-displacement matrices and elasticity for each kinematics.
 *
 * Every kinematic assumption is expressed in the full 3D Voigt space (11, 22, 33, 12, 13, 23) so that
 * the kernels have one code path:
 *   plane strain   eps_33 = 0 (row of B is zero), full isotropic D, so sigma_33 = nu (s11 + s22) - E alpha dT
 *   plane stress   sigma_33 = 0 by static condensation of D (D_ps), thermal stress D_ps alpha [1,1,0]
 *   axisymmetric   x = r, y = z, eps_33 = u_r / r (hoop), dV = 2 pi r dA
 *   3D             all six components
 */
#include "element_impl.h"

/* columns: hoop, free_normal, revolve, thickness */
static const TslKinematicsInfo KinematicsTable[] = {
    [TSL_KIN_PLANE_STRAIN] = {PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_TRUE},
    [TSL_KIN_PLANE_STRESS] = {PETSC_FALSE, PETSC_TRUE, PETSC_FALSE, PETSC_TRUE},
    [TSL_KIN_AXISYMMETRIC] = {PETSC_TRUE, PETSC_FALSE, PETSC_TRUE, PETSC_FALSE},
    [TSL_KIN_SOLID3D]      = {PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE},
};

const TslKinematicsInfo *TslKinematicsInfoGet(TslKinematics kin)
{
  return &KinematicsTable[kin];
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

PetscBool TslElementPointEvaluate(const TslElementType *type, const TslElementMaterial *mat, const PetscReal x[], const PetscReal xi[], PetscReal w,
                                  TslElementPoint *p)
{
  const TslGeometry       *g    = type->geom;
  const TslKinematicsInfo *info = TslKinematicsInfoGet(type->kin);
  const PetscInt           dim = g->dim, n                     = g->nnode;
  PetscReal                dN[TSL_MAX_ELEM_NODES * 3], J[3][3] = {{0}}, Ji[3][3] = {{0}};

  g->shape(xi, p->N, dN);
  for (PetscInt d = 0; d < 3; d++) p->x[d] = 0;
  for (PetscInt a = 0; a < n; a++) {
    for (PetscInt d = 0; d < 3; d++) p->x[d] += p->N[a] * x[3 * a + d];
    for (PetscInt i = 0; i < dim; i++)
      for (PetscInt j = 0; j < dim; j++) J[i][j] += x[3 * a + i] * dN[dim * a + j];
  }
  p->detJ = InvertJacobian(dim, J, Ji);
  if (!(p->detJ > 0)) return PETSC_FALSE;
  for (PetscInt a = 0; a < n; a++) {
    for (PetscInt i = 0; i < 3; i++) p->dNdx[a][i] = 0;
    for (PetscInt i = 0; i < dim; i++)
      for (PetscInt j = 0; j < dim; j++) p->dNdx[a][i] += dN[dim * a + j] * Ji[j][i];
  }
  p->dV = w * p->detJ;
  if (info->thickness) p->dV *= mat->thickness > 0 ? mat->thickness : 1.0;
  if (info->revolve) {
    if (!(p->x[0] > 0)) return PETSC_FALSE;
    p->dV *= 2 * PETSC_PI * p->x[0];
  }
  return PETSC_TRUE;
}

void TslElementStrainMatrix(const TslElementType *type, const TslElementPoint *p, PetscReal B[6][TSL_MAX_ELEM_NODES * 3])
{
  const PetscInt           dim = type->dim, n = type->geom->nnode;
  const TslKinematicsInfo *info = TslKinematicsInfoGet(type->kin);
  /* Voigt row -> (i, j) of the symmetric gradient; for the 3D shear rows both orders contribute */
  static const PetscInt vi[6] = {0, 1, 2, 0, 0, 1}, vj[6] = {0, 1, 2, 1, 2, 2};

  for (PetscInt r = 0; r < 6; r++)
    for (PetscInt c = 0; c < n * dim; c++) B[r][c] = 0;
  for (PetscInt a = 0; a < n; a++) {
    for (PetscInt r = 0; r < 6; r++) {
      const PetscInt i = vi[r], j = vj[r];
      if (i >= dim || j >= dim) continue;
      B[r][dim * a + i] += p->dNdx[a][j];
      if (i != j) B[r][dim * a + j] += p->dNdx[a][i];
    }
    if (info->hoop) B[2][dim * a + 0] = p->N[a] / p->x[0];
  }
}

void TslElementElasticity(TslKinematics kin, const TslElementMaterial *mat, PetscReal D[6][6], PetscReal beta[6])
{
  const PetscReal E = mat->E, nu = mat->nu;
  const PetscReal lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const PetscReal m[6] = {1, 1, 1, 0, 0, 0};

  for (PetscInt i = 0; i < 6; i++)
    for (PetscInt j = 0; j < 6; j++) D[i][j] = (i < 3 && j < 3 ? lambda : 0) + (i == j ? (i < 3 ? 2 * mu : mu) : 0);
  if (TslKinematicsInfoGet(kin)->free_normal) {
    /* sigma_33 = 0: eliminate eps_33 = -(D_3j eps_j) / D_33, giving D_ps on the remaining rows */
    const PetscReal d33 = D[2][2];
    PetscReal       c[6];
    for (PetscInt j = 0; j < 6; j++) c[j] = D[2][j];
    for (PetscInt i = 0; i < 6; i++)
      for (PetscInt j = 0; j < 6; j++) D[i][j] -= c[i] * c[j] / d33;
    for (PetscInt j = 0; j < 6; j++) D[2][j] = D[j][2] = 0;
  }
  for (PetscInt i = 0; i < 6; i++) {
    beta[i] = 0;
    for (PetscInt j = 0; j < 6; j++) beta[i] += D[i][j] * m[j] * mat->alpha;
  }
}
