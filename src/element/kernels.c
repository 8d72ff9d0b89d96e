/* Coupled temperature-displacement element kernels (small strain, linear, isotropic).
 *
 * Unknowns are interleaved per node, (u_1..u_dim, theta), element vectors node-major: a*ndof + i.
 * All volume integrals use the family's full quadrature; reduced/hybrid formulations are not here.
 */
#include "element_impl.h"

/* Nodal capacity weights V_a = int N_a dV (row-sum lumping). Lumping rather than the consistent
 * capacity matrix keeps backward Euler monotone after a sudden change of flux (no undershoot below
 * the initial temperature next to the loaded face), and makes the stored heat a nodal sum that the
 * global heat balance can close exactly. Returns PETSC_FALSE for an invalid (inverted) element. */
static PetscBool NodalVolume(const TslElementInput *in, PetscReal vol[])
{
  const TslGeometry *g = in->type->geom;
  TslElementPoint    p;

  for (PetscInt a = 0; a < g->nnode; a++) vol[a] = 0;
  for (PetscInt q = 0; q < g->full.n; q++) {
    if (!TslElementPointEvaluate(in->type, in->mat, in->x, g->full.xi[q], g->full.w[q], &p)) return PETSC_FALSE;
    for (PetscInt a = 0; a < g->nnode; a++) vol[a] += p.N[a] * p.dV;
  }
  return PETSC_TRUE;
}

/* Strain (Voigt, engineering shear) and theta - theta_init at a point. */
static void PointStrain(const TslElementInput *in, const TslElementPoint *p, PetscReal B[6][TSL_MAX_ELEM_NODES * 3], PetscReal eps[6],
                        PetscReal *dtheta)
{
  const PetscInt dim = in->type->dim, ndof = in->type->ndof, n = in->type->geom->nnode;

  TslElementStrainMatrix(in->type, p, B);
  *dtheta = 0;
  for (PetscInt r = 0; r < 6; r++) eps[r] = 0;
  for (PetscInt a = 0; a < n; a++) {
    *dtheta += p->N[a] * (in->u[ndof * a + dim] - in->theta_init[a]);
    for (PetscInt i = 0; i < dim; i++)
      for (PetscInt r = 0; r < 6; r++) eps[r] += B[r][dim * a + i] * in->u[ndof * a + i];
  }
}

/* Weak form, per integration point with dV = w detJ (t | 2 pi r | 1):
 *   R_u(a)     = int B_a^T sigma dV,          sigma = D (eps(u) - m alpha (theta - theta_init))
 *   R_theta(a) = int k grad N_a . grad theta dV + C_a (theta_a - theta_old_a) / dt,  C_a = rho c V_a
 * Tangent: K_uu = int B^T D B dV, K_u_theta = -int B^T beta N dV (beta = D m alpha), K_theta_u = 0,
 *          K_theta_theta = int k grad N grad N^T dV + diag(C_a / dt). The capacity is dropped when steady. */
PetscErrorCode TslElementResidual(const TslElementInput *in, PetscReal R[], PetscReal K[], PetscBool *inverted)
{
  const TslElementType *t   = in->type;
  const TslGeometry    *g   = t->geom;
  const PetscInt        dim = t->dim, ndof = t->ndof, n = g->nnode, nd = n * ndof;
  const PetscReal       k = in->mat->conductivity;
  PetscReal             D[6][6], beta[6], B[6][TSL_MAX_ELEM_NODES * 3], vol[TSL_MAX_ELEM_NODES];
  TslElementPoint       p;

  PetscFunctionBeginUser;
  PetscCheck(in->steady || in->dt > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Transient element residual needs dt > 0, got %g", (double)in->dt);
  *inverted = PETSC_FALSE;
  TslElementElasticity(t->kin, in->mat, D, beta);
  for (PetscInt i = 0; i < nd; i++) R[i] = 0;
  for (PetscInt a = 0; a < n; a++) vol[a] = 0;
  if (K)
    for (PetscInt i = 0; i < nd * nd; i++) K[i] = 0;
  for (PetscInt q = 0; q < g->full.n; q++) {
    PetscReal eps[6], sig[6], dtheta, grad[3] = {0, 0, 0}, DB[6][TSL_MAX_ELEM_NODES * 3];

    if (!TslElementPointEvaluate(t, in->mat, in->x, g->full.xi[q], g->full.w[q], &p)) {
      *inverted = PETSC_TRUE;
      PetscFunctionReturn(PETSC_SUCCESS);
    }
    PointStrain(in, &p, B, eps, &dtheta);
    for (PetscInt r = 0; r < 6; r++) {
      sig[r] = -beta[r] * dtheta;
      for (PetscInt s = 0; s < 6; s++) sig[r] += D[r][s] * eps[s];
    }
    for (PetscInt a = 0; a < n; a++) {
      vol[a] += p.N[a] * p.dV; /* the same V_a as NodalVolume() */
      for (PetscInt d = 0; d < dim; d++) grad[d] += p.dNdx[a][d] * in->u[ndof * a + dim];
    }
    for (PetscInt a = 0; a < n; a++) {
      for (PetscInt i = 0; i < dim; i++)
        for (PetscInt r = 0; r < 6; r++) R[ndof * a + i] += B[r][dim * a + i] * sig[r] * p.dV;
      for (PetscInt d = 0; d < dim; d++) R[ndof * a + dim] += k * p.dNdx[a][d] * grad[d] * p.dV;
    }
    if (!K) continue;
    for (PetscInt r = 0; r < 6; r++)
      for (PetscInt c = 0; c < n * dim; c++) {
        DB[r][c] = 0;
        for (PetscInt s = 0; s < 6; s++) DB[r][c] += D[r][s] * B[s][c];
      }
    for (PetscInt a = 0; a < n; a++) {
      for (PetscInt i = 0; i < dim; i++) {
        const PetscInt row   = ndof * a + i;
        PetscReal      Bbeta = 0;
        for (PetscInt r = 0; r < 6; r++) Bbeta += B[r][dim * a + i] * beta[r];
        for (PetscInt b = 0; b < n; b++) {
          for (PetscInt j = 0; j < dim; j++) {
            PetscReal kij = 0;
            for (PetscInt r = 0; r < 6; r++) kij += B[r][dim * a + i] * DB[r][dim * b + j];
            K[row * nd + ndof * b + j] += kij * p.dV;
          }
          K[row * nd + ndof * b + dim] -= Bbeta * p.N[b] * p.dV;
        }
      }
      for (PetscInt b = 0; b < n; b++) {
        PetscReal kab = 0;
        for (PetscInt d = 0; d < dim; d++) kab += p.dNdx[a][d] * p.dNdx[b][d];
        K[(ndof * a + dim) * nd + ndof * b + dim] += k * kab * p.dV;
      }
    }
  }
  if (in->steady) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt a = 0; a < n; a++) {
    const PetscReal c   = in->mat->density * in->mat->specific_heat * vol[a] / in->dt;
    const PetscInt  row = ndof * a + dim;
    R[row] += c * (in->u[row] - in->u_old[row]);
    if (K) K[row * nd + row] += c;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One face integration point: shape values of the face nodes, position, and the outward normal
 * scaled by the area element, n dA (2D: (dy, -dx) dxi times t or 2 pi r; 3D: x_xi x x_eta dxi deta). */
typedef struct {
  PetscReal N[TSL_MAX_FACE_NODES];
  PetscReal x[3];
  PetscReal ndA[3];
  PetscReal dA;
} FacePoint;

static void FacePointEvaluate(const TslElementInput *in, PetscInt face, PetscInt q, FacePoint *fp)
{
  const TslGeometry       *g = in->type->geom, *fg = g->face_geom[face];
  const TslKinematicsInfo *info = TslKinematicsInfoGet(in->type->kin);
  const PetscInt           fn = g->face_nnode[face], fdim      = fg->dim;
  PetscReal                dN[TSL_MAX_FACE_NODES * 3], T[2][3] = {{0}};

  fg->shape(fg->full.xi[q], fp->N, dN);
  for (PetscInt d = 0; d < 3; d++) fp->x[d] = 0;
  for (PetscInt f = 0; f < fn; f++) {
    const PetscReal *xa = &in->x[3 * g->face_node[face][f]];
    for (PetscInt d = 0; d < 3; d++) {
      fp->x[d] += fp->N[f] * xa[d];
      for (PetscInt j = 0; j < fdim; j++) T[j][d] += dN[fdim * f + j] * xa[d];
    }
  }
  if (fdim == 1) {
    fp->ndA[0] = T[0][1];
    fp->ndA[1] = -T[0][0];
    fp->ndA[2] = 0;
  } else {
    fp->ndA[0] = T[0][1] * T[1][2] - T[0][2] * T[1][1];
    fp->ndA[1] = T[0][2] * T[1][0] - T[0][0] * T[1][2];
    fp->ndA[2] = T[0][0] * T[1][1] - T[0][1] * T[1][0];
  }
  {
    PetscReal scale = fg->full.w[q];
    if (info->thickness) scale *= in->mat->thickness > 0 ? in->mat->thickness : 1.0;
    if (info->revolve) scale *= 2 * PETSC_PI * fp->x[0];
    for (PetscInt d = 0; d < 3; d++) fp->ndA[d] *= scale;
    fp->dA = PetscSqrtReal(fp->ndA[0] * fp->ndA[0] + fp->ndA[1] * fp->ndA[1] + fp->ndA[2] * fp->ndA[2]);
  }
}

/* Body heat source, R_theta(a) -= int N_a q dV; returns int q dV. */
static PetscReal BodyFlux(const TslElementInput *in, PetscReal q, PetscReal R[])
{
  const TslGeometry *g    = in->type->geom;
  const PetscInt     ndof = in->type->ndof, dim = in->type->dim;
  PetscReal          heat = 0;
  TslElementPoint    p;

  for (PetscInt i = 0; i < g->full.n; i++) {
    (void)TslElementPointEvaluate(in->type, in->mat, in->x, g->full.xi[i], g->full.w[i], &p);
    for (PetscInt a = 0; a < g->nnode; a++) R[ndof * a + dim] -= p.N[a] * q * p.dV;
    heat += q * p.dV;
  }
  return heat;
}

/* Face loads on the reference configuration (small strain), with n the outward unit normal:
 *   pressure p (pushes inward, traction -p n):  R_u(a)     += int N_a p n dA
 *   flux q into the body:                       R_theta(a) -= int N_a q dA,            heat = int q dA
 *   film h, sink:                               R_theta(a) += int N_a h (theta - sink) dA,
 *                                               K_ab       += int h N_a N_b dA,        heat = -int h (theta - sink) dA
 *   body flux q per volume:                     R_theta(a) -= int N_a q dV,            heat = int q dV */
PetscErrorCode TslElementFaceLoad(const TslElementInput *in, TslFaceLoadKind kind, PetscInt face, PetscReal value, PetscReal value2, PetscReal R[],
                                  PetscReal K[], PetscReal *heat)
{
  const TslGeometry *g    = in->type->geom;
  const PetscInt     ndof = in->type->ndof, dim = in->type->dim, nd = g->nnode * ndof;
  PetscReal          total = 0;

  PetscFunctionBeginUser;
  if (kind == TSL_BODY_FLUX) {
    total = BodyFlux(in, value, R);
    if (heat) *heat = total;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCheck(face >= 1 && face <= g->nface, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "Face S%" PetscInt_FMT " out of range 1..%" PetscInt_FMT " for %s", face, g->nface, in->type->name);
  face--;
  for (PetscInt q = 0; q < g->face_geom[face]->full.n; q++) {
    const PetscInt *node = g->face_node[face];
    const PetscInt  fn   = g->face_nnode[face];
    FacePoint       fp;
    PetscReal       theta = 0;

    FacePointEvaluate(in, face, q, &fp);
    switch (kind) {
    case TSL_FACE_PRESSURE:
      for (PetscInt f = 0; f < fn; f++)
        for (PetscInt i = 0; i < dim; i++) R[ndof * node[f] + i] += fp.N[f] * value * fp.ndA[i];
      break;
    case TSL_FACE_FLUX:
      for (PetscInt f = 0; f < fn; f++) R[ndof * node[f] + dim] -= fp.N[f] * value * fp.dA;
      total += value * fp.dA;
      break;
    case TSL_FACE_FILM:
      for (PetscInt f = 0; f < fn; f++) theta += fp.N[f] * in->u[ndof * node[f] + dim];
      for (PetscInt f = 0; f < fn; f++) {
        const PetscInt row = ndof * node[f] + dim;
        R[row] += fp.N[f] * value * (theta - value2) * fp.dA;
        if (K)
          for (PetscInt e = 0; e < fn; e++) K[row * nd + ndof * node[e] + dim] += value * fp.N[f] * fp.N[e] * fp.dA;
      }
      total -= value * (theta - value2) * fp.dA;
      break;
    default:
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Unknown face load kind %d", (int)kind);
    }
  }
  if (heat) *heat = total;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* dQ = sum_a C_a (theta_a - theta_old_a), the same lumped capacity as in the residual, so that
 * heat in - heat out - stored closes to solver tolerance. */
PetscErrorCode TslElementHeatChange(const TslElementInput *in, PetscReal *dQ)
{
  const PetscInt ndof = in->type->ndof, dim = in->type->dim;
  PetscReal      vol[TSL_MAX_ELEM_NODES];

  PetscFunctionBeginUser;
  PetscCheck(NodalVolume(in, vol), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "Inverted %s element", in->type->name);
  *dQ = 0;
  for (PetscInt a = 0; a < in->type->geom->nnode; a++)
    *dQ += in->mat->density * in->mat->specific_heat * vol[a] * (in->u[ndof * a + dim] - in->u_old[ndof * a + dim]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Arithmetic means over the full-quadrature points of sigma = D (eps - m alpha dT), eps, and -k grad theta.
 * Plane stress reports the out-of-plane strain that makes sigma_33 = 0 with the full isotropic D:
 *   eps_33 = alpha dT - lambda (eps_11 + eps_22 - 2 alpha dT) / (lambda + 2 mu). */
PetscErrorCode TslElementOutput(const TslElementInput *in, PetscReal S[6], PetscReal E[6], PetscReal HFL[3])
{
  const TslElementType *t   = in->type;
  const TslGeometry    *g   = t->geom;
  const PetscInt        dim = t->dim, ndof = t->ndof, nq = g->full.n;
  const PetscReal       nu = in->mat->nu, alpha = in->mat->alpha;
  PetscReal             D[6][6], beta[6], B[6][TSL_MAX_ELEM_NODES * 3];
  TslElementPoint       p;

  PetscFunctionBeginUser;
  TslElementElasticity(t->kin, in->mat, D, beta);
  for (PetscInt r = 0; r < 6; r++) S[r] = E[r] = 0;
  for (PetscInt d = 0; d < 3; d++) HFL[d] = 0;
  for (PetscInt q = 0; q < nq; q++) {
    PetscReal eps[6], dtheta;

    PetscCheck(TslElementPointEvaluate(t, in->mat, in->x, g->full.xi[q], g->full.w[q], &p), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
               "Inverted %s element", t->name);
    PointStrain(in, &p, B, eps, &dtheta);
    for (PetscInt r = 0; r < 6; r++) {
      PetscReal s = -beta[r] * dtheta;
      for (PetscInt c = 0; c < 6; c++) s += D[r][c] * eps[c];
      S[r] += s / nq;
    }
    if (TslKinematicsInfoGet(t->kin)->free_normal) {
      const PetscReal ratio = nu / (1 - nu); /* lambda / (lambda + 2 mu) */
      eps[2]                = alpha * dtheta - ratio * (eps[0] + eps[1] - 2 * alpha * dtheta);
    }
    for (PetscInt r = 0; r < 6; r++) E[r] += eps[r] / nq;
    for (PetscInt a = 0; a < g->nnode; a++)
      for (PetscInt d = 0; d < dim; d++) HFL[d] -= in->mat->conductivity * p.dNdx[a][d] * in->u[ndof * a + dim] / nq;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslElementNodalVolume(const TslElementInput *in, PetscReal vol[])
{
  PetscFunctionBeginUser;
  PetscCheck(NodalVolume(in, vol), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "Inverted %s element", in->type->name);
  PetscFunctionReturn(PETSC_SUCCESS);
}
