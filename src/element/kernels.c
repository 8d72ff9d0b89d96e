/* Coupled temperature-displacement element kernels (small strain, isotropic, temperature-dependent
 * properties), one generic code path for every catalogue row. The row's formulation (element_impl.h)
 * supplies the mechanical integration points, the hybrid pressure space, the hourglass control, the
 * lumping weights and the face rule; the kinematics row supplies the strain and the measure.
 *
 * Unknowns per node in the type's node_dof order (displacements, theta last); element vectors
 * node-major: a*ndof + i. No time discretisation here: capacity and mass are returned separately
 * (TslElementLumped) and combined by the solver.
 */
#include "element_impl.h"

static const PetscReal VoigtM[6] = {1, 1, 1, 0, 0, 0};

static PetscReal NodalTheta(const TslElementInput *in, const PetscReal *N, const PetscReal *u)
{
  const PetscInt ndof = in->type->ndof, th = ndof - 1;
  PetscReal      theta = 0;
  for (PetscInt a = 0; a < in->type->geom->nnode; a++) theta += N[a] * u[ndof * a + th];
  return theta;
}

static PetscReal PointInitialTheta(const TslElementInput *in, const TslElementPoint *p)
{
  PetscReal theta = 0;
  for (PetscInt a = 0; a < in->type->geom->nnode; a++) theta += p->N[a] * in->theta_init[a];
  return theta;
}

/* The geometry at the points of the family's full rule, shared by conduction and (for fully integrated
 * rows) the mechanical terms; PETSC_FALSE for an inverted element. */
static PetscBool FullPoints(const TslElementInput *in, TslElementPoint pts[])
{
  const TslGeometry *g = in->type->geom;
  for (PetscInt q = 0; q < g->full.n; q++)
    if (!TslElementPointEvaluate(in->type, in->sec, in->x, g->full.xi[q], g->full.w[q], &pts[q])) return PETSC_FALSE;
  return PETSC_TRUE;
}

/* Conduction with the family's full rule: R_theta(a) = int k grad N_a . grad theta dV;
 * K = int k grad N_a . grad N_b + dk/dtheta (grad N_a . grad theta) N_b dV. */
static void Conduction(const TslElementInput *in, const TslElementPoint pts[], PetscReal R[], PetscReal K[])
{
  const TslElementType *t   = in->type;
  const TslGeometry    *g   = t->geom;
  const PetscInt        dim = t->dim, ndof = t->ndof, th = ndof - 1, n = g->nnode, nd = TslElementTypeNodes(t) * ndof;

  for (PetscInt q = 0; q < g->full.n; q++) {
    const TslElementPoint *p       = &pts[q];
    PetscReal              grad[3] = {0, 0, 0}, theta;
    TslMaterialPoint       mp;

    theta = NodalTheta(in, p->N, in->u);
    for (PetscInt a = 0; a < n; a++)
      for (PetscInt d = 0; d < dim; d++) grad[d] += p->dNdx[a][d] * in->u[ndof * a + th];
    TslMaterialEval(in->sec->mat, theta, &mp);
    for (PetscInt a = 0; a < n; a++) {
      PetscReal ga = 0;
      for (PetscInt d = 0; d < dim; d++) ga += p->dNdx[a][d] * grad[d];
      R[ndof * a + th] += mp.k * ga * p->dV;
      if (!K) continue;
      for (PetscInt b = 0; b < n; b++) {
        PetscReal kab = 0;
        for (PetscInt d = 0; d < dim; d++) kab += p->dNdx[a][d] * p->dNdx[b][d];
        K[(ndof * a + th) * nd + ndof * b + th] += (mp.k * kab + mp.dk * ga * p->N[b]) * p->dV;
      }
    }
  }
}

/* State of the mechanical terms at one point. */
typedef struct {
  const TslElementPoint *p; /* the point's geometry: given by the caller or evaluated into own */
  TslElementPoint        own;
  TslMaterialPoint       mp;
  PetscReal              B[6][TSL_MAX_ELEM_NODES * 3];
  PetscReal              eps[6], eps_th, deps_th; /* total strain, thermal strain (per normal component) and d/dtheta */
  /* the nonzeros of each column c of B (at most 4 of the 6 rows: B is sparse, and every product with it
   * below runs over these only): rows bz_row[c][0..bz_n[c]), values bz_val */
  PetscInt  bz_n[TSL_MAX_ELEM_NODES * 3], bz_row[TSL_MAX_ELEM_NODES * 3][6];
  PetscReal bz_val[TSL_MAX_ELEM_NODES * 3][6];
} MechPoint;

/* The 3D solid's strain from the spatial gradients without building B (residual-only evaluations, the
 * explicit force loop): eps = (u_x,x, u_y,y, u_z,z, u_x,y + u_y,x, u_x,z + u_z,x, u_y,z + u_z,y), each
 * component summed in the order the B path sums it (node by node, displacement component by component),
 * so the two give the same bits. */
static PetscBool LeanStrain(const TslElementInput *in)
{
  const TslElementType *t = in->type;
  return t->kin == TSL_KIN_SOLID3D && t->ndof == 4 && TslElementTypeNodes(t) == t->geom->nnode ? PETSC_TRUE : PETSC_FALSE;
}

/* The nonzeros of B's columns (MechPoint.bz_*) and, with strain, eps = B u summed in that order. */
static void StrainNonzeros(const TslElementInput *in, MechPoint *mq, PetscBool strain)
{
  const PetscInt ndof = in->type->ndof, nu = ndof - 1, n = TslElementTypeNodes(in->type);

  if (strain)
    for (PetscInt r = 0; r < 6; r++) mq->eps[r] = 0;
  for (PetscInt a = 0; a < n; a++)
    for (PetscInt i = 0; i < nu; i++) {
      const PetscInt c = nu * a + i;
      mq->bz_n[c]      = 0;
      for (PetscInt r = 0; r < 6; r++) {
        if (mq->B[r][c] == 0) continue;
        mq->bz_row[c][mq->bz_n[c]]   = r;
        mq->bz_val[c][mq->bz_n[c]++] = mq->B[r][c];
        if (strain) mq->eps[r] += mq->B[r][c] * in->u[ndof * a + i];
      }
    }
}

/* pre: the point's geometry when already evaluated (NULL: evaluate it here); lean: no B (LeanStrain
 * types only; the caller then forms B^T sigma from dNdx itself, MechanicsForce) */
static PetscBool MechPointEvaluate(const TslElementInput *in, const PetscReal xi[], PetscReal w, const TslElementPoint *pre, PetscBool lean, MechPoint *mq)
{
  const TslElementType *t    = in->type;
  const PetscInt        n = TslElementTypeNodes(t);
  PetscReal             theta;

  if (pre)
    mq->p = pre;
  else {
    if (!TslElementPointEvaluate(t, in->sec, in->x, xi, w, &mq->own)) return PETSC_FALSE;
    mq->p = &mq->own;
  }
  if (lean) {
    PetscReal *e = mq->eps;
    for (PetscInt r = 0; r < 6; r++) e[r] = 0;
    for (PetscInt a = 0; a < n; a++) {
      const PetscReal *g = mq->p->dNdx[a], ux = in->u[4 * a], uy = in->u[4 * a + 1], uz = in->u[4 * a + 2];
      e[0] += g[0] * ux, e[3] += g[1] * ux, e[4] += g[2] * ux;
      e[1] += g[1] * uy, e[3] += g[0] * uy, e[5] += g[2] * uy;
      e[2] += g[2] * uz, e[4] += g[0] * uz, e[5] += g[1] * uz;
    }
    goto material;
  }
  TslElementStrainMatrix(t, in->sec, in->x, mq->p, mq->B);
  StrainNonzeros(in, mq, PETSC_TRUE);
material:
  theta = NodalTheta(in, mq->p->N, in->u);
  TslMaterialEval(in->sec->mat, theta, &mq->mp);
  mq->eps_th = TslMaterialThermalStrain(in->sec->mat, theta, PointInitialTheta(in, mq->p), &mq->deps_th);
  return PETSC_TRUE;
}

/* Finite strain (TslElementInput.nlgeom, *STEP, NLGEOM; docs/elements.md "Finite strain"), total Lagrangian on the
 * reference configuration with the material as St Venant-Kirchhoff (CalculiX's reading of a linear elastic material in
 * a geometrically nonlinear step): S = D (E - E_th m), S the second Piola-Kirchhoff stress, E = (F^T F - I) / 2 the
 * Green-Lagrange strain and E_th = eps_th + eps_th^2 / 2 the Green-Lagrange strain of the free thermal stretch
 * 1 + eps_th (so a free body heated by alpha dT is stress-free with J = (1 + alpha dT)^3). The point's B becomes dE/du
 * (the rows of sym(F^T dF/du_c)), its eps the E of F, and the element's forms keep their shape: R_u = int B^T S dV0,
 * K_uu = int B^T D B dV0 plus the geometric stiffness int dF_c^T dF_d : S dV0 (GeometricStiffness). Every element
 * formulation goes through these points (hybrid: the pressure on tr E; reduced: the hourglass control of u on the
 * reference configuration, zero for a rigid motion; continuum shells: the shell's D in its reference frame). */
typedef struct {
  PetscReal         F[3][3], J;
  TslGradientColumn col[TSL_MAX_ELEM_NODES * 3];
} FinitePoint;

static const PetscInt VoigtI[6] = {0, 1, 2, 0, 0, 1}, VoigtJ[6] = {0, 1, 2, 1, 2, 2};

static PetscReal Det3(const PetscReal F[3][3])
{
  return F[0][0] * (F[1][1] * F[2][2] - F[1][2] * F[2][1]) - F[0][1] * (F[1][0] * F[2][2] - F[1][2] * F[2][0]) +
         F[0][2] * (F[1][0] * F[2][1] - F[1][1] * F[2][0]);
}

/* The Green-Lagrange strain (Voigt, engineering shear) of the displacement gradient H: E = (H + H^T + H^T H) / 2, from H
 * rather than F^T F - I, so that small strains keep their digits. */
static void GreenStrain(const PetscReal H[3][3], PetscReal Eg[6])
{
  for (PetscInt r = 0; r < 6; r++) {
    const PetscInt K = VoigtI[r], L = VoigtJ[r];
    PetscReal      c = H[K][L] + H[L][K];
    for (PetscInt i = 0; i < 3; i++) c += H[i][K] * H[i][L];
    Eg[r] = r < 3 ? 0.5 * c : c;
  }
}

/* The Green-Lagrange strain of the free thermal stretch 1 + eps_th, E_th = eps_th + eps_th^2 / 2, in place with its
 * temperature derivative. */
static void ThermalGreenStrain(PetscReal *eps_th, PetscReal *deps_th)
{
  const PetscReal e = *eps_th;
  *eps_th           = e + 0.5 * e * e;
  *deps_th *= 1 + e;
}

/* The small-strain point mq (MechPointEvaluate, not lean) made the finite-strain one; PETSC_FALSE where det F <= 0
 * (an element turned inside out: the increment is cut back, as for an inverted element). */
static PetscBool MechPointFinite(const TslElementInput *in, MechPoint *mq, FinitePoint *fp)
{
  const TslElementType *t    = in->type;
  const PetscInt        ncol = TslElementTypeNodes(t) * (t->ndof - 1);
  PetscReal             H[3][3];

  TslElementDeformation(t, in->sec, in->x, mq->p, in->u, H, fp->col);
  for (PetscInt i = 0; i < 3; i++)
    for (PetscInt j = 0; j < 3; j++) fp->F[i][j] = (i == j) + H[i][j];
  fp->J = Det3(fp->F);
  if (!(fp->J > 0)) return PETSC_FALSE;
  for (PetscInt c = 0; c < ncol; c++) {
    const TslGradientColumn *col = &fp->col[c];
    for (PetscInt r = 0; r < 6; r++) mq->B[r][c] = 0;
    for (PetscInt q = 0; q < col->n; q++) { /* (F^T dF)_KL += F_iK v for the entry (i, L, v) */
      const PetscInt i = col->i[q], L = col->k[q];
      const PetscReal v = col->v[q];
      mq->B[L][c] += fp->F[i][L] * v;
      for (PetscInt r = 3; r < 6; r++) {
        if (VoigtJ[r] == L) mq->B[r][c] += fp->F[i][VoigtI[r]] * v;
        if (VoigtI[r] == L) mq->B[r][c] += fp->F[i][VoigtJ[r]] * v;
      }
    }
  }
  StrainNonzeros(in, mq, PETSC_FALSE);
  GreenStrain(H, mq->eps);
  ThermalGreenStrain(&mq->eps_th, &mq->deps_th);
  return PETSC_TRUE;
}

static void VoigtTensor(const PetscReal v[6], PetscReal S[3][3])
{
  for (PetscInt r = 0; r < 6; r++) S[VoigtI[r]][VoigtJ[r]] = S[VoigtJ[r]][VoigtI[r]] = v[r];
}

/* The geometric stiffness at a point, int dF_c^T dF_d : S dV0 (two columns' entries pair where they share the row i:
 * v w S_KL), and twist's P : d2F / du_c du_d (P = F S; F_31, F_32 are products of u_r and phi) into the upper
 * triangle of Kuu (ncol x ncol). */
static void GeometricStiffness(const TslElementInput *in, const MechPoint *mq, const FinitePoint *fp, const PetscReal sig[6], PetscReal Kuu[])
{
  const TslElementType *t = in->type;
  const PetscInt        nu = t->ndof - 1, ncol = TslElementTypeNodes(t) * nu, n = t->geom->nnode;
  const PetscReal       dV = mq->p->dV;
  PetscReal             S[3][3];

  VoigtTensor(sig, S);
  for (PetscInt c1 = 0; c1 < ncol; c1++) {
    const TslGradientColumn *a = &fp->col[c1];
    for (PetscInt c2 = c1; c2 < ncol; c2++) {
      const TslGradientColumn *b = &fp->col[c2];
      PetscReal                k = 0;
      for (PetscInt q1 = 0; q1 < a->n; q1++)
        for (PetscInt q2 = 0; q2 < b->n; q2++)
          if (a->i[q1] == b->i[q2]) k += a->v[q1] * b->v[q2] * S[a->k[q1]][b->k[q2]];
      Kuu[c1 * ncol + c2] += k * dV;
    }
  }
  if (TslKinematicsRowGet(t->kin)->twist) {
    PetscReal P[2] = {0, 0}; /* P_3j = F_3K S_Kj, j = r, z */
    for (PetscInt j = 0; j < 2; j++)
      for (PetscInt k = 0; k < 3; k++) P[j] += fp->F[2][k] * S[k][j];
    for (PetscInt a = 0; a < n; a++)
      for (PetscInt b = 0; b < n; b++) {
        const PetscInt c = nu * a, d = nu * b + 2; /* u_r of a, phi of b */
        Kuu[PetscMin(c, d) * ncol + PetscMax(c, d)] += mq->p->N[a] * (P[0] * mq->p->dNdx[b][0] + P[1] * mq->p->dNdx[b][1]) * dV;
      }
  }
}

/* Eigenvalues w and eigenvectors (columns of Q) of a symmetric 3 x 3 matrix, by cyclic Jacobi rotations. */
static void SymmetricEigen3(const PetscReal A0[3][3], PetscReal w[3], PetscReal Q[3][3])
{
  PetscReal A[3][3];

  for (PetscInt i = 0; i < 3; i++)
    for (PetscInt j = 0; j < 3; j++) A[i][j] = A0[i][j], Q[i][j] = i == j;
  for (PetscInt sweep = 0; sweep < 50; sweep++) {
    const PetscReal off = PetscAbsReal(A[0][1]) + PetscAbsReal(A[0][2]) + PetscAbsReal(A[1][2]);
    const PetscReal dia = PetscAbsReal(A[0][0]) + PetscAbsReal(A[1][1]) + PetscAbsReal(A[2][2]);
    if (off <= 1e-18 * dia || off == 0) break;
    for (PetscInt p = 0; p < 2; p++)
      for (PetscInt q = p + 1; q < 3; q++) {
        PetscReal th, tn, cs, sn;
        if (A[p][q] == 0) continue;
        th = (A[q][q] - A[p][p]) / (2 * A[p][q]);
        tn = (th >= 0 ? 1 : -1) / (PetscAbsReal(th) + PetscSqrtReal(th * th + 1));
        cs = 1 / PetscSqrtReal(tn * tn + 1), sn = tn * cs;
        for (PetscInt k = 0; k < 3; k++) { /* A = G^T A G, G the rotation in the (p, q) plane */
          const PetscReal akp = A[k][p], akq = A[k][q];
          A[k][p] = cs * akp - sn * akq, A[k][q] = sn * akp + cs * akq;
        }
        for (PetscInt k = 0; k < 3; k++) {
          const PetscReal apk = A[p][k], aqk = A[q][k];
          A[p][k] = cs * apk - sn * aqk, A[q][k] = sn * apk + cs * aqk;
        }
        for (PetscInt k = 0; k < 3; k++) {
          const PetscReal qkp = Q[k][p], qkq = Q[k][q];
          Q[k][p] = cs * qkp - sn * qkq, Q[k][q] = sn * qkp + cs * qkq;
        }
      }
  }
  for (PetscInt i = 0; i < 3; i++) w[i] = A[i][i];
}

/* A finite-strain point's share of the element output (nq points): the Cauchy stress sigma = F S F^T / J and the
 * logarithmic strain LE = ln V = 1/2 ln(F F^T) (engineering shear, as E), Abaqus's S and LE. Plane stress: F_33 from
 * the E_33 that makes S_33 = 0. */
static void FiniteOutput(const TslElementInput *in, const MechPoint *mq, const FinitePoint *fp, const PetscReal sig[6], PetscInt nq, TslElementResult *res)
{
  PetscReal F[3][3], S[3][3], b[3][3], w[3], Q[3][3], J;

  for (PetscInt i = 0; i < 3; i++)
    for (PetscInt j = 0; j < 3; j++) F[i][j] = fp->F[i][j];
  J = fp->J;
  if (TslKinematicsRowGet(in->type->kin)->free_normal) {
    const PetscReal ratio = mq->mp.nu / (1 - mq->mp.nu), e33 = mq->eps_th - ratio * (mq->eps[0] + mq->eps[1] - 2 * mq->eps_th);
    F[2][2] = PetscSqrtReal(PetscMax(1 + 2 * e33, 0));
    J *= F[2][2];
  }
  VoigtTensor(sig, S);
  for (PetscInt r = 0; r < 6; r++) {
    const PetscInt i = VoigtI[r], j = VoigtJ[r];
    PetscReal      s = 0, bb = 0;
    for (PetscInt k = 0; k < 3; k++) {
      bb += F[i][k] * F[j][k];
      for (PetscInt l = 0; l < 3; l++) s += F[i][k] * S[k][l] * F[j][l];
    }
    res->S[r] += s / J / nq;
    b[i][j] = b[j][i] = bb;
  }
  SymmetricEigen3(b, w, Q);
  for (PetscInt r = 0; r < 6; r++) {
    const PetscInt i = VoigtI[r], j = VoigtJ[r];
    PetscReal      le = 0;
    for (PetscInt k = 0; k < 3; k++) le += Q[i][k] * 0.5 * PetscLogReal(w[k]) * Q[j][k];
    res->E[r] += (r < 3 ? le : 2 * le) / nq;
  }
}

/* Deviatoric elasticity 2 mu (I - m m^T / 3) in Voigt form (engineering shear) and the bulk modulus. */
static void Deviatoric(PetscReal mu, PetscReal Dd[6][6])
{
  for (PetscInt i = 0; i < 6; i++)
    for (PetscInt j = 0; j < 6; j++) Dd[i][j] = i < 3 && j < 3 ? 2 * mu * ((i == j) - 1.0 / 3) : (i == j ? mu : 0);
}

/* Hybrid condensation data, summed over the points: G = int B^T m P^T dV, H = int P P^T / K dV,
 * g0 = int P 3 eps_th dV, and their derivatives in each nodal temperature. */
typedef struct {
  PetscInt  np;
  PetscReal G[TSL_MAX_ELEM_NODES * 3][TSL_MAX_PRESSURE];
  PetscReal H[TSL_MAX_PRESSURE][TSL_MAX_PRESSURE], g0[TSL_MAX_PRESSURE];
  PetscReal dH[TSL_MAX_ELEM_NODES][TSL_MAX_PRESSURE][TSL_MAX_PRESSURE], dg0[TSL_MAX_ELEM_NODES][TSL_MAX_PRESSURE];
  PetscReal p[TSL_MAX_PRESSURE]; /* condensed pressure coefficients (mean stress, tension positive) */
  PetscReal trE[TSL_MAX_PRESSURE]; /* finite strain: int P tr E dV (small strain: G^T u is that integral) */
} Hybrid;

/* Inverse of a small dense matrix (n <= TSL_MAX_ENHANCED, row stride lda) by Gauss-Jordan elimination with partial
 * pivoting: the hybrid pressure's H and the incompatible modes' K_aa, both symmetric positive definite. */
static void DenseInverse(PetscInt n, PetscInt lda, const PetscReal *A, PetscReal *Ai)
{
  PetscReal M[TSL_MAX_ENHANCED][2 * TSL_MAX_ENHANCED];
  for (PetscInt i = 0; i < n; i++)
    for (PetscInt j = 0; j < 2 * n; j++) M[i][j] = j < n ? A[i * lda + j] : (j - n == i);
  for (PetscInt c = 0; c < n; c++) {
    PetscInt piv = c;
    for (PetscInt i = c + 1; i < n; i++)
      if (PetscAbsReal(M[i][c]) > PetscAbsReal(M[piv][c])) piv = i;
    for (PetscInt j = 0; j < 2 * n; j++) {
      PetscReal tmp = M[c][j];
      M[c][j] = M[piv][j], M[piv][j] = tmp;
    }
    for (PetscInt i = 0; i < n; i++) {
      PetscReal f;
      if (i == c) continue;
      f = M[i][c] / M[c][c];
      for (PetscInt j = 0; j < 2 * n; j++) M[i][j] -= f * M[c][j];
    }
  }
  for (PetscInt i = 0; i < n; i++)
    for (PetscInt j = 0; j < n; j++) Ai[i * lda + j] = M[i][n + j] / M[i][i];
}

static void SmallInverse(PetscInt n, PetscReal A[TSL_MAX_PRESSURE][TSL_MAX_PRESSURE], PetscReal Ai[TSL_MAX_PRESSURE][TSL_MAX_PRESSURE])
{
  DenseInverse(n, TSL_MAX_PRESSURE, &A[0][0], &Ai[0][0]);
}

/* B_a^T s dV for a 3D solid's node a with spatial gradient g and a Voigt vector s (engineering shear), the
 * nonzeros of B_a in row order (the lean residual's and the B path's summation order: the same bits). */
static inline void SolidBtS(const PetscReal g[3], const PetscReal s[6], PetscReal dV, PetscReal out[3])
{
  out[0] = (g[0] * s[0] + g[1] * s[3] + g[2] * s[4]) * dV;
  out[1] = (g[1] * s[1] + g[0] * s[3] + g[2] * s[5]) * dV;
  out[2] = (g[2] * s[2] + g[0] * s[4] + g[1] * s[5]) * dV;
}

/* The tangent of a 3D solid (LeanStrain types, displacement formulation) by node pairs instead of B^T D B:
 * for isotropic D,
 *   K_ab,ij = int lambda dN_a/dx_i dN_b/dx_j + mu dN_a/dx_j dN_b/dx_i + mu delta_ij grad N_a . grad N_b dV,
 * so with S_ab = int dN_a/dx (x) dN_b/dx dV (nine products per pair and point) K_ab = lambda S_ab + mu S_ab^T
 * + mu tr(S_ab) I, formed once per element while lambda and mu are those of the first point (a material
 * without temperature dependence: every point); a point with other moduli adds its own terms at once. A
 * third of the B^T D B path's products, without its index arrays. The residual and the temperature column
 * K_u_theta are those of the general path: sigma, dsigma as there, R in the lean path's order (same bits). */
static PetscBool MechanicsSolid3DTangent(const TslElementInput *in, const TslElementPoint full[], PetscReal R[], PetscReal K[])
{
  const TslElementType *t    = in->type;
  const TslGeometry    *g    = t->geom;
  const TslQuadrature  *quad = t->form->quadrature(g, in->sec);
  const PetscInt        n = g->nnode, nd = 4 * n;
  PetscReal             S[TSL_MAX_ELEM_NODES][TSL_MAX_ELEM_NODES][9], lambda0 = 0, mu0 = 0;
  MechPoint             mq;

  for (PetscInt a = 0; a < n; a++)
    for (PetscInt b = a; b < n; b++)
      for (PetscInt k = 0; k < 9; k++) S[a][b][k] = 0;
  for (PetscInt q = 0; q < quad->n; q++) {
    PetscReal D[6][6], dD[6][6], emech[6], sig[6], dsig[6], lambda, mu, dV, v[TSL_MAX_ELEM_NODES][3];

    if (!MechPointEvaluate(in, quad->xi[q], quad->w[q], full && quad == &g->full ? &full[q] : NULL, PETSC_TRUE, &mq)) return PETSC_FALSE;
    dV = mq.p->dV;
    TslElementElasticity(t, in->sec, mq.p, &mq.mp, D, dD);
    TslElementLame(&mq.mp, &lambda, &mu);
    for (PetscInt r = 0; r < 6; r++) emech[r] = mq.eps[r] - VoigtM[r] * mq.eps_th;
    for (PetscInt r = 0; r < 6; r++) {
      sig[r] = dsig[r] = 0;
      for (PetscInt s = 0; s < 6; s++) {
        sig[r] += D[r][s] * emech[s];
        dsig[r] += dD[r][s] * emech[s] - D[r][s] * VoigtM[s] * mq.deps_th;
      }
    }
    for (PetscInt a = 0; a < n; a++) {
      PetscReal f[3];
      SolidBtS(mq.p->dNdx[a], sig, dV, f);
      for (PetscInt i = 0; i < 3; i++) R[4 * a + i] += f[i];
      SolidBtS(mq.p->dNdx[a], dsig, dV, v[a]); /* K_u_theta: B_a^T dsigma N_b dV */
    }
    for (PetscInt a = 0; a < n; a++)
      for (PetscInt i = 0; i < 3; i++) {
        PetscReal *row = &K[(4 * a + i) * nd + 3];
        for (PetscInt b = 0; b < n; b++) row[4 * b] += v[a][i] * mq.p->N[b];
      }
    if (q == 0) lambda0 = lambda, mu0 = mu;
    if (lambda == lambda0 && mu == mu0) {
      for (PetscInt a = 0; a < n; a++) {
        const PetscReal ga[3] = {mq.p->dNdx[a][0] * dV, mq.p->dNdx[a][1] * dV, mq.p->dNdx[a][2] * dV};
        for (PetscInt b = a; b < n; b++) {
          const PetscReal *gb = mq.p->dNdx[b], g0 = gb[0], g1 = gb[1], g2 = gb[2];
          PetscReal       *s  = S[a][b];
          s[0] += ga[0] * g0, s[1] += ga[0] * g1, s[2] += ga[0] * g2;
          s[3] += ga[1] * g0, s[4] += ga[1] * g1, s[5] += ga[1] * g2;
          s[6] += ga[2] * g0, s[7] += ga[2] * g1, s[8] += ga[2] * g2;
        }
      }
    } else /* moduli of their own at this point: its terms straight into K */
      for (PetscInt a = 0; a < n; a++)
        for (PetscInt b = 0; b < n; b++) {
          const PetscReal *ga = mq.p->dNdx[a], *gb = mq.p->dNdx[b];
          const PetscReal  dot = (ga[0] * gb[0] + ga[1] * gb[1] + ga[2] * gb[2]) * mu * dV;
          for (PetscInt i = 0; i < 3; i++)
            for (PetscInt j = 0; j < 3; j++) K[(4 * a + i) * nd + 4 * b + j] += (lambda * ga[i] * gb[j] + mu * ga[j] * gb[i]) * dV + (i == j ? dot : 0);
        }
  }
  for (PetscInt a = 0; a < n; a++)
    for (PetscInt b = a; b < n; b++) {
      const PetscReal *s  = S[a][b];
      const PetscReal  tr = mu0 * (s[0] + s[4] + s[8]);
      for (PetscInt i = 0; i < 3; i++)
        for (PetscInt j = 0; j < 3; j++) {
          const PetscReal kij = lambda0 * s[3 * i + j] + mu0 * s[3 * j + i] + (i == j ? tr : 0);
          K[(4 * a + i) * nd + 4 * b + j] += kij;
          if (b != a) K[(4 * b + j) * nd + 4 * a + i] += kij;
        }
    }
  return PETSC_TRUE;
}

/* Finite strain in a 3D solid (LeanStrain types, displacement formulation; FinitePoint's model) by node pairs: with
 * dF/du_ai = e_i (x) g_a (g_a = grad N_a), h_a = F g_a and b = F F^T, for isotropic D
 *   R_ai = (F S g_a)_i dV,  K_ab,ij = [lambda h_a,i h_b,j + mu (b_ij g_a.g_b + h_b,i h_a,j) + delta_ij g_a^T S g_b] dV,
 *   K_ai,theta_b = (F dS/dtheta g_a)_i N_b dV,
 * the B^T D B and geometric terms of the general path without B (a tenth of its products). K may be NULL. */
static PetscBool MechanicsSolid3DFinite(const TslElementInput *in, const TslElementPoint full[], PetscReal R[], PetscReal K[])
{
  const TslElementType *t    = in->type;
  const TslGeometry    *g    = t->geom;
  const TslQuadrature  *quad = t->form->quadrature(g, in->sec);
  const PetscInt        n = g->nnode, nd = 4 * n;
  MechPoint             mq;

  for (PetscInt q = 0; q < quad->n; q++) {
    PetscReal D[6][6], dD[6][6], Eg[6], emech[6], sig[6], dsig[6], F[3][3], H[3][3] = {{0}}, S[3][3], dS[3][3], P[3][3], dP[3][3], bb[3][3];
    PetscReal lambda, mu, dV, h[TSL_MAX_ELEM_NODES][3];

    if (!MechPointEvaluate(in, quad->xi[q], quad->w[q], full && quad == &g->full ? &full[q] : NULL, PETSC_TRUE, &mq)) return PETSC_FALSE;
    dV = mq.p->dV;
    for (PetscInt a = 0; a < n; a++)
      for (PetscInt i = 0; i < 3; i++)
        for (PetscInt j = 0; j < 3; j++) H[i][j] += in->u[4 * a + i] * mq.p->dNdx[a][j];
    for (PetscInt i = 0; i < 3; i++)
      for (PetscInt j = 0; j < 3; j++) F[i][j] = (i == j) + H[i][j];
    if (!(Det3(F) > 0)) return PETSC_FALSE;
    GreenStrain(H, Eg);
    ThermalGreenStrain(&mq.eps_th, &mq.deps_th);
    TslElementElasticity(t, in->sec, mq.p, &mq.mp, D, K ? dD : NULL);
    TslElementLame(&mq.mp, &lambda, &mu);
    for (PetscInt r = 0; r < 6; r++) emech[r] = Eg[r] - VoigtM[r] * mq.eps_th;
    for (PetscInt r = 0; r < 6; r++) {
      sig[r] = dsig[r] = 0;
      for (PetscInt s = 0; s < 6; s++) {
        sig[r] += D[r][s] * emech[s];
        if (K) dsig[r] += dD[r][s] * emech[s] - D[r][s] * VoigtM[s] * mq.deps_th;
      }
    }
    VoigtTensor(sig, S);
    VoigtTensor(dsig, dS);
    for (PetscInt i = 0; i < 3; i++)
      for (PetscInt j = 0; j < 3; j++) {
        P[i][j] = dP[i][j] = bb[i][j] = 0;
        for (PetscInt k = 0; k < 3; k++) P[i][j] += F[i][k] * S[k][j], dP[i][j] += F[i][k] * dS[k][j], bb[i][j] += F[i][k] * F[j][k];
      }
    for (PetscInt a = 0; a < n; a++) {
      const PetscReal *ga = mq.p->dNdx[a];
      for (PetscInt i = 0; i < 3; i++) {
        R[4 * a + i] += (P[i][0] * ga[0] + P[i][1] * ga[1] + P[i][2] * ga[2]) * dV;
        h[a][i] = F[i][0] * ga[0] + F[i][1] * ga[1] + F[i][2] * ga[2];
      }
    }
    if (!K) continue;
    for (PetscInt a = 0; a < n; a++) {
      const PetscReal *ga = mq.p->dNdx[a];
      for (PetscInt i = 0; i < 3; i++) {
        const PetscReal v   = (dP[i][0] * ga[0] + dP[i][1] * ga[1] + dP[i][2] * ga[2]) * dV;
        PetscReal      *row = &K[(4 * a + i) * nd + 3];
        for (PetscInt b = 0; b < n; b++) row[4 * b] += v * mq.p->N[b];
      }
      for (PetscInt b = a; b < n; b++) {
        const PetscReal *gb = mq.p->dNdx[b], gg = ga[0] * gb[0] + ga[1] * gb[1] + ga[2] * gb[2];
        PetscReal        sgs = 0;
        for (PetscInt k = 0; k < 3; k++) sgs += ga[k] * (S[k][0] * gb[0] + S[k][1] * gb[1] + S[k][2] * gb[2]);
        for (PetscInt i = 0; i < 3; i++)
          for (PetscInt j = 0; j < 3; j++) {
            const PetscReal kij = (lambda * h[a][i] * h[b][j] + mu * (bb[i][j] * gg + h[b][i] * h[a][j]) + (i == j ? sgs : 0)) * dV;
            K[(4 * a + i) * nd + 4 * b + j] += kij;
            if (b != a) K[(4 * b + j) * nd + 4 * a + i] += kij;
          }
      }
    }
  }
  return PETSC_TRUE;
}

/* Incompatible modes (TslFormulation.incompatible; docs/elements.md "Incompatible modes"): the displacement
 * u = N u_hat + sum_k P_k alpha_k (P_k = 1 - xi_k^2, a vector alpha_k per bubble, every displacement component) adds the
 * strain G alpha. G is the bubbles' symmetric gradient with the centre's Jacobian, grad P_k = J0^-T dP_k/dxi (det J0 /
 * det J) (Taylor, Beresford and Wilson), less its volume mean, so that int G dV = 0 holds exactly on every shape and
 * kinematics (the axisymmetric r too): a constant stress does no work on the bubbles, and the patch test passes. No
 * hoop or out-of-plane strain from the bubbles. With sigma = D (B u + G alpha - eps_th m) the element's bubble equations
 * int G^T sigma dV = 0 give
 *   alpha = -K_aa^-1 r0,  K_aa = int G^T D G dV,  r0 = int G^T D (B u - eps_th m) dV,
 * the residual R_u = int B^T sigma dV at that alpha, and the condensed tangent
 *   K_uu = int B^T D B dV - K_ua K_aa^-1 K_au,  K_u_theta_b = t_b - K_ua K_aa^-1 s_b,
 * with t_b, s_b = int (B, G)^T dsigma_b dV, dsigma_b = (dD (eps - eps_th m) - D m deps_th) N_b at fixed alpha. The
 * material is elastic, so alpha follows from (u, theta) in each evaluation: no state is kept. */
/* The incompatible modes' strain matrix at each mechanical point (G[q], 6 x na, less its volume mean) and the points
 * evaluated once (mqs); FALSE for an inverted element. */
static PetscBool IncompatibleModes(const TslElementInput *in, const TslElementPoint full[], MechPoint mqs[], PetscReal G[][6][TSL_MAX_ENHANCED], PetscInt *na_out)
{
  const TslElementType *t    = in->type;
  const TslGeometry    *g    = t->geom;
  const TslQuadrature  *quad = t->form->quadrature(g, in->sec);
  const PetscInt        dim = t->dim, gd = g->dim;
  PetscReal             xi0[3], det0, dP[3][3], vol = 0, Gbar[6][TSL_MAX_ENHANCED] = {{0}};
  PetscInt              nm, na;
  TslElementPoint       pc;
  static const PetscInt vi[6] = {0, 1, 2, 0, 0, 1}, vj[6] = {0, 1, 2, 1, 2, 2};

  /* the centre's inverse Jacobian J0^-1 (pc.Ji[e][d] = dxi_e / dx_d) and det J0 */
  if (quad->n > TSL_INCOMPATIBLE_QP) return PETSC_FALSE;
  TslElementCentre(g, xi0);
  nm = t->form->incompatible(g, xi0, dP);
  na = nm * dim;
  if (!TslElementPointEvaluate(t, in->sec, in->x, xi0, g->ref_volume, &pc)) return PETSC_FALSE;
  det0 = pc.detJ;
  /* G at each point, and its mean */
  for (PetscInt q = 0; q < quad->n; q++) {
    MechPoint *mq = &mqs[q];
    PetscReal  grad[3][3];
    if (!MechPointEvaluate(in, quad->xi[q], quad->w[q], full ? &full[q] : NULL, PETSC_FALSE, mq)) return PETSC_FALSE;
    (void)t->form->incompatible(g, quad->xi[q], dP);
    for (PetscInt k = 0; k < nm; k++)
      for (PetscInt i = 0; i < dim; i++) {
        grad[k][i] = 0;
        for (PetscInt j = 0; j < gd; j++) grad[k][i] += pc.Ji[j][i] * dP[k][j] * det0 / mq->p->detJ;
      }
    for (PetscInt r = 0; r < 6; r++)
      for (PetscInt c = 0; c < na; c++) G[q][r][c] = 0;
    for (PetscInt k = 0; k < nm; k++)
      for (PetscInt r = 0; r < 6; r++) {
        const PetscInt i = vi[r], j = vj[r];
        if (i >= dim || j >= dim) continue;
        G[q][r][dim * k + i] += grad[k][j];
        if (i != j) G[q][r][dim * k + j] += grad[k][i];
      }
    for (PetscInt r = 0; r < 6; r++)
      for (PetscInt c = 0; c < na; c++) Gbar[r][c] += G[q][r][c] * mq->p->dV;
    vol += mq->p->dV;
  }
  for (PetscInt q = 0; q < quad->n; q++)
    for (PetscInt r = 0; r < 6; r++)
      for (PetscInt c = 0; c < na; c++) G[q][r][c] -= Gbar[r][c] / vol;
  *na_out = na;
  return PETSC_TRUE;
}

/* The incompatible modes' condensation, d alpha = -K_aa^-1 (K_au du + s dtheta): K_uu -= K_ua K_aa^-1 K_au and
 * K_u_theta -= K_ua K_aa^-1 s; KiKau = K_aa^-1 K_au and Kis = K_aa^-1 s returned for the heat rows */
static void IncompatibleCondense(const TslElementInput *in, PetscInt na, const PetscReal Kai[], PetscReal Kau[][TSL_MAX_ELEM_NODES * 3],
                                 PetscReal Kua[][TSL_MAX_ENHANCED], PetscReal sb[][TSL_MAX_ELEM_NODES], PetscReal K[], PetscReal KiKau[][TSL_MAX_ELEM_NODES * 3],
                                 PetscReal Kis[][TSL_MAX_ELEM_NODES])
{
  const TslElementType *t    = in->type;
  const PetscInt        ndof = t->ndof, th = ndof - 1, nu = ndof - 1, n = t->geom->nnode, nd = n * ndof, ncol = n * nu;

  for (PetscInt c = 0; c < na; c++) {
    for (PetscInt b = 0; b < ncol; b++) {
      KiKau[c][b] = 0;
      for (PetscInt e = 0; e < na; e++) KiKau[c][b] += Kai[c * na + e] * Kau[e][b];
    }
    for (PetscInt b = 0; b < n; b++) {
      Kis[c][b] = 0;
      for (PetscInt e = 0; e < na; e++) Kis[c][b] += Kai[c * na + e] * sb[e][b];
    }
  }
  for (PetscInt c1 = 0; c1 < ncol; c1++) {
    const PetscInt r1 = ndof * (c1 / nu) + c1 % nu;
    for (PetscInt c2 = 0; c2 < ncol; c2++) {
      PetscReal kv = 0;
      for (PetscInt c = 0; c < na; c++) kv += Kua[c1][c] * KiKau[c][c2];
      K[r1 * nd + ndof * (c2 / nu) + c2 % nu] -= kv;
    }
    for (PetscInt b = 0; b < n; b++) {
      PetscReal kv = 0;
      for (PetscInt c = 0; c < na; c++) kv += Kua[c1][c] * Kis[c][b];
      K[r1 * nd + ndof * b + th] -= kv;
    }
  }
}

static PetscBool MechanicsIncompatible(const TslElementInput *in, const TslElementPoint full[], PetscReal R[], PetscReal K[], TslElementResult *res,
                                       PetscReal *energy)
{
  const TslElementType *t    = in->type;
  const TslGeometry    *g    = t->geom;
  const TslQuadrature  *quad = t->form->quadrature(g, in->sec);
  const PetscInt        ndof = t->ndof, th = ndof - 1, nu = ndof - 1, n = g->nnode, nd = n * ndof, ncol = n * nu;
  PetscReal             G[TSL_MAX_QP][6][TSL_MAX_ENHANCED], Kaa[TSL_MAX_ENHANCED * TSL_MAX_ENHANCED] = {0},
                        Kai[TSL_MAX_ENHANCED * TSL_MAX_ENHANCED], r0[TSL_MAX_ENHANCED] = {0}, alpha[TSL_MAX_ENHANCED] = {0};
  PetscReal             Kau[TSL_MAX_ENHANCED][TSL_MAX_ELEM_NODES * 3], sb[TSL_MAX_ENHANCED][TSL_MAX_ELEM_NODES];
  PetscReal            *se = res ? &res->strain_energy : energy;
  PetscInt              na;
  MechPoint             mqs[TSL_INCOMPATIBLE_QP]; /* each point evaluated once, for the three passes */

  if (!IncompatibleModes(in, full, mqs, G, &na)) return PETSC_FALSE;
  /* K_aa and r0 (first pass), alpha */
  for (PetscInt q = 0; q < quad->n; q++) {
    PetscReal D[6][6], DG[6][TSL_MAX_ENHANCED], s0[6];
    const MechPoint *mq = &mqs[q];
    TslElementElasticity(t, in->sec, mq->p, &mq->mp, D, NULL);
    for (PetscInt r = 0; r < 6; r++) {
      s0[r] = 0;
      for (PetscInt c = 0; c < na; c++) DG[r][c] = 0;
      for (PetscInt s2 = 0; s2 < 6; s2++) {
        s0[r] += D[r][s2] * (mq->eps[s2] - VoigtM[s2] * mq->eps_th);
        for (PetscInt c = 0; c < na; c++) DG[r][c] += D[r][s2] * G[q][s2][c];
      }
    }
    for (PetscInt c1 = 0; c1 < na; c1++) {
      for (PetscInt r = 0; r < 6; r++) r0[c1] += G[q][r][c1] * s0[r] * mq->p->dV;
      for (PetscInt c2 = 0; c2 < na; c2++)
        for (PetscInt r = 0; r < 6; r++) Kaa[c1 * na + c2] += G[q][r][c1] * DG[r][c2] * mq->p->dV;
    }
  }
  DenseInverse(na, na, Kaa, Kai);
  for (PetscInt c1 = 0; c1 < na; c1++)
    for (PetscInt c2 = 0; c2 < na; c2++) alpha[c1] -= Kai[c1 * na + c2] * r0[c2];
  /* second pass: stress with the bubbles, R_u, results, K_uu, K_au and the temperature columns */
  if (K) {
    for (PetscInt c = 0; c < na; c++)
      for (PetscInt b = 0; b < ncol; b++) Kau[c][b] = 0;
    for (PetscInt c = 0; c < na; c++)
      for (PetscInt b = 0; b < n; b++) sb[c][b] = 0;
  }
  for (PetscInt q = 0; q < quad->n; q++) {
    PetscReal D[6][6], dD[6][6], eps[6], emech[6], sig[6], dsig[6];
    const MechPoint *mq = &mqs[q];
    TslElementElasticity(t, in->sec, mq->p, &mq->mp, D, K ? dD : NULL);
    for (PetscInt r = 0; r < 6; r++) {
      eps[r] = mq->eps[r];
      for (PetscInt c = 0; c < na; c++) eps[r] += G[q][r][c] * alpha[c];
      emech[r] = eps[r] - VoigtM[r] * mq->eps_th;
    }
    for (PetscInt r = 0; r < 6; r++) {
      sig[r] = dsig[r] = 0;
      for (PetscInt s2 = 0; s2 < 6; s2++) {
        sig[r] += D[r][s2] * emech[s2];
        if (K) dsig[r] += dD[r][s2] * emech[s2] - D[r][s2] * VoigtM[s2] * mq->deps_th;
      }
    }
    for (PetscInt a = 0; a < n; a++)
      for (PetscInt i = 0; i < nu; i++) {
        PetscReal f = 0;
        for (PetscInt r = 0; r < 6; r++) f += mq->B[r][nu * a + i] * sig[r];
        R[ndof * a + i] += f * mq->p->dV;
      }
    if (res)
      for (PetscInt r = 0; r < 6; r++) res->E[r] += eps[r] / quad->n, res->S[r] += sig[r] / quad->n;
    if (se)
      for (PetscInt r = 0; r < 6; r++) *se += 0.5 * sig[r] * emech[r] * mq->p->dV;
    if (!K) continue;
    for (PetscInt c1 = 0; c1 < ncol; c1++) {
      const PetscInt r1 = ndof * (c1 / nu) + c1 % nu;
      PetscReal      DB[6], Bds = 0;
      for (PetscInt r = 0; r < 6; r++) {
        DB[r] = 0;
        for (PetscInt s2 = 0; s2 < 6; s2++) DB[r] += D[r][s2] * mq->B[s2][c1];
        Bds += mq->B[r][c1] * dsig[r];
      }
      for (PetscInt c2 = 0; c2 < ncol; c2++) {
        PetscReal kv = 0;
        for (PetscInt r = 0; r < 6; r++) kv += mq->B[r][c2] * DB[r];
        K[r1 * nd + ndof * (c2 / nu) + c2 % nu] += kv * mq->p->dV;
      }
      for (PetscInt c = 0; c < na; c++) {
        PetscReal kv = 0;
        for (PetscInt r = 0; r < 6; r++) kv += G[q][r][c] * DB[r];
        Kau[c][c1] += kv * mq->p->dV;
      }
      for (PetscInt b = 0; b < n; b++) K[r1 * nd + ndof * b + th] += Bds * mq->p->N[b] * mq->p->dV;
    }
    for (PetscInt c = 0; c < na; c++) {
      PetscReal Gds = 0;
      for (PetscInt r = 0; r < 6; r++) Gds += G[q][r][c] * dsig[r];
      for (PetscInt b = 0; b < n; b++) sb[c][b] += Gds * mq->p->N[b] * mq->p->dV;
    }
  }
  if (K) { /* condensation: K_uu -= K_ua K_aa^-1 K_au, K_u_theta -= K_ua K_aa^-1 s (K_ua = K_au^T: D is symmetric) */
    PetscReal KiKau[TSL_MAX_ENHANCED][TSL_MAX_ELEM_NODES * 3], Kis[TSL_MAX_ENHANCED][TSL_MAX_ELEM_NODES], Kua[TSL_MAX_ELEM_NODES * 3][TSL_MAX_ENHANCED];
    for (PetscInt c = 0; c < na; c++)
      for (PetscInt b = 0; b < ncol; b++) Kua[b][c] = Kau[c][b];
    IncompatibleCondense(in, na, Kai, Kau, Kua, sb, K, KiKau, Kis);
  }
  return PETSC_TRUE;
}

/* One mechanical point's share of a hybrid element's condensation data (Hybrid): P its pressure functions, kb and
 * dkb the bulk modulus and its temperature derivative; P_avg the pressure functions' mean over the nq points. */
static void HybridPoint(const TslElementInput *in, const MechPoint *mq, PetscReal kb, PetscReal dkb, PetscInt nq, Hybrid *hy, PetscReal P_avg[])
{
  const TslElementType *t = in->type;
  const PetscInt        n = t->geom->nnode, ncol = TslElementTypeNodes(t) * (t->ndof - 1);
  PetscReal             Bm[TSL_MAX_ELEM_NODES * 3], P[TSL_MAX_PRESSURE];

  hy->np = t->form->pressure(t->geom, mq->p, P);
  for (PetscInt c = 0; c < ncol; c++) {
    Bm[c] = 0;
    for (PetscInt r = 0; r < 3; r++) Bm[c] += mq->B[r][c];
  }
  for (PetscInt k = 0; k < hy->np; k++) {
    for (PetscInt c = 0; c < ncol; c++) hy->G[c][k] += Bm[c] * P[k] * mq->p->dV;
    hy->g0[k] += P[k] * 3 * mq->eps_th * mq->p->dV;
    hy->trE[k] += P[k] * (mq->eps[0] + mq->eps[1] + mq->eps[2]) * mq->p->dV;
    for (PetscInt l = 0; l < hy->np; l++) hy->H[k][l] += P[k] * P[l] / kb * mq->p->dV;
    for (PetscInt b = 0; b < n; b++) {
      hy->dg0[b][k] += P[k] * 3 * mq->deps_th * mq->p->N[b] * mq->p->dV;
      for (PetscInt l = 0; l < hy->np; l++) hy->dH[b][k][l] -= P[k] * P[l] * dkb / (kb * kb) * mq->p->N[b] * mq->p->dV;
    }
    P_avg[k] += P[k] / nq;
  }
}

/* A hybrid element's condensation after its points: the pressure coefficients H p = G^T u - g0, R_u += G p, the
 * stress output (the deviators' mean sdev_avg plus the mean pressure), the volumetric energy 1/2 p^T H p into *se
 * and K_uu += G H^-1 G^T with the temperature columns -G H^-1 (dg0 + dH p). */
static void HybridCondense(const TslElementInput *in, Hybrid *hy, const PetscReal P_avg[], const PetscReal sdev_avg[], PetscReal R[], PetscReal K[],
                           TslElementResult *res, PetscReal *se)
{
  const TslElementType *t    = in->type;
  const PetscInt        ndof = t->ndof, th = ndof - 1, nu = ndof - 1, n = t->geom->nnode, nv = TslElementTypeNodes(t), nd = nv * ndof, ncol = nv * nu;
  PetscReal      Hi[TSL_MAX_PRESSURE][TSL_MAX_PRESSURE], rhs[TSL_MAX_PRESSURE];
  const PetscInt np = hy->np;
  SmallInverse(np, hy->H, Hi);
  for (PetscInt k = 0; k < np; k++) {
    rhs[k] = -hy->g0[k];
    if (in->nlgeom) rhs[k] += hy->trE[k];
    else
      for (PetscInt a = 0; a < nv; a++)
        for (PetscInt i = 0; i < nu; i++) rhs[k] += hy->G[nu * a + i][k] * in->u[ndof * a + i];
  }
  for (PetscInt k = 0; k < np; k++) {
    hy->p[k] = 0;
    for (PetscInt l = 0; l < np; l++) hy->p[k] += Hi[k][l] * rhs[l];
  }
  for (PetscInt a = 0; a < nv; a++)
    for (PetscInt i = 0; i < nu; i++)
      for (PetscInt k = 0; k < np; k++) R[ndof * a + i] += hy->G[nu * a + i][k] * hy->p[k];
  if (res) {
    PetscReal pm = 0;
    for (PetscInt k = 0; k < np; k++) pm += hy->p[k] * P_avg[k];
    for (PetscInt r = 0; r < 6; r++) res->S[r] = sdev_avg[r] + VoigtM[r] * pm; /* point averages, as for the other formulations */
  }
  if (se) {
    PetscReal vol_energy = 0; /* volumetric energy: 1/2 p_hat^T H p_hat */
    for (PetscInt k = 0; k < np; k++)
      for (PetscInt l = 0; l < np; l++) vol_energy += 0.5 * hy->p[k] * hy->H[k][l] * hy->p[l];
    *se += vol_energy;
  }
  if (K) {
    PetscReal GHi[TSL_MAX_ELEM_NODES * 3][TSL_MAX_PRESSURE];
    for (PetscInt c = 0; c < ncol; c++)
      for (PetscInt k = 0; k < np; k++) {
        GHi[c][k] = 0;
        for (PetscInt l = 0; l < np; l++) GHi[c][k] += hy->G[c][l] * Hi[l][k];
      }
    for (PetscInt a = 0; a < nv; a++)
      for (PetscInt i = 0; i < nu; i++) {
        const PetscInt row = ndof * a + i, c = nu * a + i;
        for (PetscInt b = 0; b < nv; b++) {
          for (PetscInt j = 0; j < nu; j++) {
            PetscReal kij = 0;
            for (PetscInt k = 0; k < np; k++) kij += GHi[c][k] * hy->G[nu * b + j][k];
            K[row * nd + ndof * b + j] += kij;
          }
          if (b < n) {
            PetscReal kth = 0;
            for (PetscInt k = 0; k < np; k++) {
              PetscReal dHp = 0;
              for (PetscInt l = 0; l < np; l++) dHp += hy->dH[b][k][l] * hy->p[l];
              kth += GHi[c][k] * (-hy->dg0[b][k] - dHp);
            }
            K[row * nd + ndof * b + th] += kth;
          }
        }
      }
  }
}

/* Mises plasticity with isotropic, linear kinematic or nonlinear kinematic hardening (*PLASTIC; docs/keywords.md,
 * docs/elements.md "Plasticity"). The point's return below works in the whole 3D strain; plane stress solves its eps_33
 * around it (PlasticReturnPlaneStress), the continuum shells work in their frame (PlasticReturnShell), the hybrid types
 * keep its deviatoric part (MechanicsPlastic), the incompatible modes solve their bubbles around it
 * (MechanicsIncompatiblePlastic). At each point, from the committed plastic
 * strain eps_p, equivalent plastic strain p and back stresses a_k (in->pstate), the return (backward Euler) of the
 * trial e = eps - eps_th m - eps_p, d = dev e (tensor components): with theta_k = 1 / (1 + gamma_k dl) each back
 * stress a_k = theta_k (a_k,n + sqrt(2/3) C_k dl n), and the relative stress xi = sigma_dev - sum a_k lies along
 *   xit(dl) = 2 mu d - sum theta_k a_k,n,   n = xit / |xit|,
 * so yield at q_tr = sqrt(3/2) |xit(0)| > sigma_y(p, theta) and then the scalar equation
 *   g(dl) = sqrt(3/2) |xit(dl)| - (3 mu + sum theta_k C_k) dl - sigma_y(p + dl, theta) = 0
 * (Newton, safeguarded by bisection on [0, q_tr / (3 mu)]: g(0) > 0 and g(q_tr / (3 mu)) < 0 since |a_k| stays below
 * sqrt(2/3) C_k / gamma_k), with -g' = D = 3 mu + sum C_k theta_k^2 + H - sqrt(3/2) n : v, v = sum gamma_k theta_k^2
 * a_k,n; sigma = K tr(e) m + 2 mu d - sqrt(6) mu dl n, d eps_p = sqrt(3/2) dl n (engineering shear x 2). Isotropic
 * hardening: no back stress; HARDENING=KINEMATIC: one with gamma = 0 (theta = 1, xit fixed: the radial return). The
 * consistent tangent, with beta = 1 - sqrt(6) mu dl / |xit| and v_perp = v - n (n : v),
 *   C = K m m^T + 2 mu beta P_dev + 2 mu (1 - beta - 3 mu / D) n n^T - 2 mu (1 - beta) sqrt(3/2) / D v_perp n^T
 * (not symmetric when gamma > 0), its temperature column from d dl / d theta = (sqrt(3/2) n : 2 dmu d - 3 dmu dl -
 * d sigma_y / d theta) / D, and the plastic heat: a source eta w inelastic_rate with w the plastic work of the
 * increment per volume, int sigma_y dp (exact for the tables and the exponential law) plus the back stresses' share,
 * the trapezoid sqrt(3/2) dl n : (a_n + a) / 2 (exact for linear kinematic hardening), linearised in u and theta
 * through dl and n (docs/elements.md). *RATE DEPENDENT scales sigma_y by R(dl / dt) (PlasticYield: H and the work
 * take its derivative). Nothing is stored here: the state the current u reaches goes to in->pstate_new when asked
 * (the commit of an accepted increment). Outputs (res; TslElementOutput) come after the commit, at the committed
 * state's displacement: they take its stress as it is, with no return (one would be a further increment of time at
 * that strain, which a rate-dependent point spends relaxing). */
/* The yield stress at p0 + dl, with *RATE DEPENDENT's factor R at the rate dl / dt (dt = 0: none), H and dsy its
 * derivatives in dl and theta, dR = dR / d dl */
static PetscReal PlasticYield(const TslElementInput *in, PetscReal p0, PetscReal dl, PetscReal theta, PetscReal *H, PetscReal *dsy, PetscReal *R, PetscReal *dR)
{
  const TslMaterial *mat = in->sec->mat;
  const PetscReal    s   = TslMaterialYield(mat, p0 + dl, theta, H, dsy);

  *R = 1, *dR = 0;
  if (!mat->plastic.rate_law || !(in->dt > 0)) return s;
  *R = TslMaterialRateFactor(mat, dl / in->dt, dR);
  *dR /= in->dt;
  *H   = *H * *R + s * *dR;
  *dsy *= *R;
  return s * *R;
}

/* What the return gives at one point: the stress, the flow, the work and, with tangent, their derivatives in the
 * strain (C; dw_de, engineering components) and in theta at fixed strain (dsig, dw_dth). */
typedef struct {
  PetscReal sig[6], deps[6], dl, w, se;
  PetscReal C[6][6], dsig[6], dw_de[6], dw_dth;
  PetscReal back[6 * TSL_MAX_BACKSTRESS]; /* the back stresses reached */
} PlasticPoint;

/* The return at one point from the committed state st for the total strain eps (Voigt, engineering shear; eps_th
 * per normal component and its theta-derivative deps_th), at theta with the moduli mu, Kb and their derivatives;
 * frozen: no return (an output at the committed state), tangent: C, dsig, dw_de, dw_dth too. */
static void PlasticReturn(const TslElementInput *in, const PetscReal *st, const PetscReal eps[6], PetscReal eps_th, PetscReal deps_th, PetscReal theta,
                          PetscReal mu, PetscReal Kb, PetscReal dmu, PetscReal dKb, PetscBool frozen, PetscBool tangent, PlasticPoint *o)
{
  const TslMaterial     *mat = in->sec->mat;
  const TslPlasticTable *pl  = &mat->plastic;
  const PetscReal        s23 = PetscSqrtReal(2.0 / 3.0), s32 = PetscSqrtReal(1.5), s6 = PetscSqrtReal(6.0);
  const PetscInt         nb = pl->nback;
  const PetscReal       *ab0 = st + 7; /* the committed back stresses, 6 each */
  PetscReal e[6], d[6], nh[6] = {0}, xi[6], v[6] = {0}, A[6] = {0}, tr, nx, qtr, sy, H, dsy, dl = 0, thk[TSL_MAX_BACKSTRESS], Dd = 0;
  PetscReal Ck[TSL_MAX_BACKSTRESS], gk[TSL_MAX_BACKSTRESS], dCk[TSL_MAX_BACKSTRESS], dgk[TSL_MAX_BACKSTRESS], rk[TSL_MAX_BACKSTRESS], drk[TSL_MAX_BACKSTRESS];
  PetscReal ab[6 * TSL_MAX_BACKSTRESS]; /* the committed back stresses carried to theta: r_k a_k,n (Abaqus's (1/C) dC/dtheta term, exactly) */
  PetscReal dw_th_fixed = 0, Rf = 1, dRf = 0, ws = 0, w = 0; /* d w / d theta at fixed p0, p1; the rate factor, its d / d dl; int sigma_static dp */
  PetscBool plastic = PETSC_FALSE;

  for (PetscInt r = 0; r < 6; r++) e[r] = eps[r] - VoigtM[r] * eps_th - st[r];
  tr = e[0] + e[1] + e[2];
  for (PetscInt r = 0; r < 6; r++) d[r] = r < 3 ? e[r] - tr / 3 : 0.5 * e[r];
  for (PetscInt k = 0; k < nb; k++) thk[k] = 1;
  /* the back stresses' C_k, gamma_k at theta; with temperature-dependent data a back stress committed at theta_n is
   * scaled by r_k = C_k(theta) / C_k(theta_n) (da = (dC / C) a at no flow) */
  TslMaterialBackStress(mat, theta, Ck, gk, dCk, dgk);
  for (PetscInt k = 0; k < nb; k++) rk[k] = 1, drk[k] = 0;
  if (pl->nkt > 1 && st[7 + 6 * nb] != 0) {
    PetscReal Cn[TSL_MAX_BACKSTRESS], gn[TSL_MAX_BACKSTRESS], dCn[TSL_MAX_BACKSTRESS], dgn[TSL_MAX_BACKSTRESS];
    TslMaterialBackStress(mat, st[8 + 6 * nb], Cn, gn, dCn, dgn);
    for (PetscInt k = 0; k < nb; k++)
      if (Cn[k] > 0) rk[k] = Ck[k] / Cn[k], drk[k] = dCk[k] / Cn[k];
  }
  for (PetscInt k = 0; k < nb; k++)
    for (PetscInt r = 0; r < 6; r++) ab[6 * k + r] = rk[k] * ab0[6 * k + r];
  /* xit(dl) and |xit|: the relative trial stress with the back stresses' recovery at dl */
#define XIT(DL)                                                                                                  \
  do {                                                                                                           \
    for (PetscInt r = 0; r < 6; r++) xi[r] = 2 * mu * d[r];                                                      \
    for (PetscInt k = 0; k < nb; k++) {                                                                          \
      thk[k] = 1 / (1 + gk[k] * (DL));                                                                    \
      for (PetscInt r = 0; r < 6; r++) xi[r] -= thk[k] * ab[6 * k + r];                                          \
    }                                                                                                            \
    nx = PetscSqrtReal(xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2] + 2 * (xi[3] * xi[3] + xi[4] * xi[4] + xi[5] * xi[5])); \
  } while (0)
  XIT(0);
  qtr = s32 * nx;
  sy  = PlasticYield(in, st[6], 0, theta, &H, &dsy, &Rf, &dRf);
  if (!frozen && qtr > sy * (1 + 1e-12)) { /* plastic: g(dl) = 0 on [0, q_tr / (3 mu)] */
    PetscReal lo = 0, hi = qtr / (3 * mu);
    plastic = PETSC_TRUE;
    for (PetscInt it = 0; it < 100; it++) {
      PetscReal gv, next, xv = 0, sumtc = 0;
      Dd = 3 * mu + H;
      for (PetscInt k = 0; k < nb; k++) {
        const PetscReal an = (xi[0] * ab[6 * k] + xi[1] * ab[6 * k + 1] + xi[2] * ab[6 * k + 2] +
                              2 * (xi[3] * ab[6 * k + 3] + xi[4] * ab[6 * k + 4] + xi[5] * ab[6 * k + 5])) / nx;
        sumtc += thk[k] * Ck[k];
        Dd += Ck[k] * thk[k] * thk[k];
        xv += gk[k] * thk[k] * thk[k] * an;
      }
      Dd -= s32 * xv;
      gv = s32 * nx - (3 * mu + sumtc) * dl - sy;
      if (PetscAbsReal(gv) <= 1e-14 * qtr) break; /* g's terms are of the size of q_tr: its round-off, not sigma_y's */
      if (gv > 0) lo = dl;
      else hi = dl;
      next = Dd > 0 ? dl + gv / Dd : 0.5 * (lo + hi);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      dl = next;
      sy = PlasticYield(in, st[6], dl, theta, &H, &dsy, &Rf, &dRf);
      XIT(dl);
    }
    /* at the converged dl: n, D, v and the work */
    Dd = 3 * mu + H;
    for (PetscInt r = 0; r < 6; r++) nh[r] = xi[r] / nx;
    ws = TslMaterialYieldIntegral(mat, st[6], st[6] + dl, theta, &dw_th_fixed);
    w = Rf * ws, dw_th_fixed *= Rf; /* at the increment's rate */
    for (PetscInt k = 0; k < nb; k++) {
      const PetscReal *ak = ab + 6 * k, gt2 = gk[k] * thk[k] * thk[k];
      const PetscReal  an = ak[0] * nh[0] + ak[1] * nh[1] + ak[2] * nh[2] + 2 * (ak[3] * nh[3] + ak[4] * nh[4] + ak[5] * nh[5]);
      Dd += Ck[k] * thk[k] * thk[k] - s32 * gt2 * an;
      for (PetscInt r = 0; r < 6; r++) v[r] += gt2 * ak[r], A[r] += (1 + thk[k]) * ak[r];
      /* the back stress's share, the trapezoid of (a_n + a) / 2 : d eps_p (exact on the radial path of gamma = 0) */
      w += 0.5 * s32 * dl * (1 + thk[k]) * an + 0.5 * dl * dl * thk[k] * Ck[k];
    }
  } else if (nx > 0)
    for (PetscInt r = 0; r < 6; r++) nh[r] = xi[r] / nx;
#undef XIT
  for (PetscInt r = 0; r < 6; r++) {
    o->sig[r]  = (r < 3 ? Kb * tr : 0) + 2 * mu * d[r] - (plastic ? s6 * mu * dl * nh[r] : 0);
    o->deps[r] = plastic ? dl * s32 * nh[r] * (r < 3 ? 1 : 2) : 0;
  }
  for (PetscInt k = 0; k < nb; k++)
    for (PetscInt r = 0; r < 6; r++) o->back[6 * k + r] = thk[k] * (ab[6 * k + r] + s23 * Ck[k] * dl * nh[r]);
  o->dl = dl, o->w = w, o->se = 0;
  for (PetscInt r = 0; r < 6; r++) o->se += 0.5 * o->sig[r] * (e[r] - o->deps[r]);
  if (!tangent) return;
  {
    PetscReal       vp[6] = {0}, Ap[6] = {0};
    const PetscReal beta = plastic ? 1 - s6 * mu * dl / nx : 1, hn = plastic ? 2 * mu * (1 - beta - 3 * mu / Dd) : 0;
    const PetscReal hv = plastic ? -2 * mu * (1 - beta) * s32 / Dd : 0;
    PetscReal       nv_ = 0, nA = 0;
    for (PetscInt r = 0; r < 6; r++) o->dw_de[r] = 0;
    o->dw_dth = 0;
    if (plastic) {
      for (PetscInt r = 0; r < 6; r++) {
        const PetscReal wr = r < 3 ? 1 : 2;
        nv_ += wr * nh[r] * v[r], nA += wr * nh[r] * A[r];
      }
      for (PetscInt r = 0; r < 6; r++) vp[r] = v[r] - nh[r] * nv_, Ap[r] = A[r] - nh[r] * nA;
    }
    for (PetscInt r = 0; r < 6; r++)
      for (PetscInt c = 0; c < 6; c++) {
        const PetscReal pdev = r < 3 && c < 3 ? (r == c) - 1.0 / 3 : (r == c ? 0.5 : 0);
        o->C[r][c] = (r < 3 && c < 3 ? Kb : 0) + 2 * mu * beta * pdev + hn * nh[r] * nh[c] + hv * vp[r] * nh[c];
      }
    if (plastic) {
      /* with the back stresses fixed, xit turns with theta through mu: d xit / d theta = 2 dmu d; then
       * d dl / d theta = (sqrt(3/2) n : 2 dmu d - 3 dmu dl - dsy) / D, dn = (I - n n) (2 dmu d + v ddl) / |xit|,
       * d sigma_dev = 2 dmu d - sqrt(6) (dmu dl + mu ddl) n - sqrt(6) mu dl dn. The work: w_dl = sigma_y(p1) + the
       * back stresses' sqrt(3/2) / 2 sum (1 + theta_k) n : a_k,n - sqrt(3/2) dl / 2 sum gamma_k theta_k^2 n : a_k,n +
       * dl sum theta_k C_k - dl^2 / 2 sum gamma_k theta_k^2 C_k, and its direction term sqrt(3/2) dl / 2 A_perp : dn
       * (A = sum (1 + theta_k) a_k,n) */
      /* X = d xit / d theta at fixed dl: 2 dmu d - sum (d theta_k a_k + theta_k dr_k a_k,n), d theta_k = -dl theta_k^2 dgamma_k;
       * dg / dtheta = sqrt(3/2) n : X - 3 dmu dl - sum (d theta_k C_k + theta_k dC_k) dl - dsy */
      PetscReal X[6], nX = 0, dgt = -3 * dmu * dl - dsy, wfix = 0;
      for (PetscInt r = 0; r < 6; r++) X[r] = 2 * dmu * d[r];
      for (PetscInt kk = 0; kk < nb; kk++) {
        const PetscReal dth = -dl * thk[kk] * thk[kk] * dgk[kk];
        const PetscReal an  = ab[6 * kk] * nh[0] + ab[6 * kk + 1] * nh[1] + ab[6 * kk + 2] * nh[2] + 2 * (ab[6 * kk + 3] * nh[3] + ab[6 * kk + 4] * nh[4] + ab[6 * kk + 5] * nh[5]);
        const PetscReal an0 = ab0[6 * kk] * nh[0] + ab0[6 * kk + 1] * nh[1] + ab0[6 * kk + 2] * nh[2] +
                              2 * (ab0[6 * kk + 3] * nh[3] + ab0[6 * kk + 4] * nh[4] + ab0[6 * kk + 5] * nh[5]); /* n : a_k,n */
        for (PetscInt r = 0; r < 6; r++) X[r] -= dth * ab[6 * kk + r] + thk[kk] * drk[kk] * ab0[6 * kk + r];
        dgt -= (dth * Ck[kk] + thk[kk] * dCk[kk]) * dl;
        /* the work's partial derivative at fixed dl and n */
        wfix += 0.5 * s32 * dl * (dth * an + (1 + thk[kk]) * drk[kk] * an0) + 0.5 * dl * dl * (dth * Ck[kk] + thk[kk] * dCk[kk]);
      }
      for (PetscInt r = 0; r < 6; r++) nX += (r < 3 ? 1 : 2) * nh[r] * X[r];
      dgt += s32 * nX;
      const PetscReal ddl = dgt / Dd;
      PetscReal       wdl = sy + dRf * ws, Apv = 0, Apd = 0;
      for (PetscInt k = 0; k < nb; k++) {
        const PetscReal *ak = ab + 6 * k, gt2 = gk[k] * thk[k] * thk[k];
        const PetscReal  an = ak[0] * nh[0] + ak[1] * nh[1] + ak[2] * nh[2] + 2 * (ak[3] * nh[3] + ak[4] * nh[4] + ak[5] * nh[5]);
        wdl += 0.5 * s32 * (1 + thk[k]) * an - 0.5 * s32 * dl * gt2 * an + dl * thk[k] * Ck[k] - 0.5 * dl * dl * gt2 * Ck[k];
      }
      for (PetscInt r = 0; r < 6; r++) {
        const PetscReal wr = r < 3 ? 1 : 2;
        Apv += wr * Ap[r] * v[r], Apd += wr * Ap[r] * X[r];
      }
      wdl += 0.5 * s32 * dl * Apv / nx;
      for (PetscInt r = 0; r < 6; r++) {
        const PetscReal dn = (X[r] - nh[r] * nX + vp[r] * ddl) / nx;
        o->dsig[r] = (r < 3 ? dKb * tr - 3 * Kb * deps_th : 0) + 2 * dmu * d[r] - s6 * (dmu * dl + mu * ddl) * nh[r] - s6 * mu * dl * dn;
      }
      for (PetscInt c = 0; c < 6; c++) o->dw_de[c] = wdl * s6 * mu / Dd * nh[c] + 0.5 * s32 * dl * 2 * mu * Ap[c] / nx;
      o->dw_dth = dw_th_fixed + wfix + wdl * ddl + 0.5 * s32 * dl * Apd / nx;
    } else
      for (PetscInt r = 0; r < 6; r++) o->dsig[r] = (r < 3 ? dKb * tr - 3 * Kb * deps_th : 0) + 2 * dmu * d[r];
  }
}

/* Plane stress (the plane-stress types): the return with eps_33 its own unknown, Newton on sigma_33(eps_33) = 0 with
 * the consistent C_33 (from the elastic plane-stress eps_33; quadratic, a few steps), then everything condensed
 * onto the in-plane strain: C_ps = C - C[:, 3] C[3, :] / C_33 (row and column 3 zero, as B's row 3 is), dsig and
 * the work's derivatives likewise through d eps_33 = -(C[3, :] d eps + dsig_3 d theta) / C_33. eps[2] is set to
 * the eps_33 found. FALSE: no convergence (the caller reports the point as failed). */
static PetscBool PlasticReturnPlaneStress(const TslElementInput *in, const PetscReal *st, PetscReal eps[6], PetscReal eps_th, PetscReal deps_th,
                                          PetscReal theta, PetscReal mu, PetscReal Kb, PetscReal dmu, PetscReal dKb, PetscBool frozen, PetscBool tangent,
                                          PlasticPoint *o)
{
  const PetscReal lam = Kb - 2 * mu / 3, ratio = lam / (lam + 2 * mu);
  PetscReal       scale;

  /* the elastic plane-stress eps_33 from the committed plastic strain: sigma_33 = 0 for an elastic point */
  eps[2] = st[2] + eps_th - ratio * (eps[0] - st[0] + eps[1] - st[1] - 2 * eps_th);
  PlasticReturn(in, st, eps, eps_th, deps_th, theta, mu, Kb, dmu, dKb, frozen, PETSC_TRUE, o);
  scale = PetscAbsReal(o->sig[0]) + PetscAbsReal(o->sig[1]) + PetscAbsReal(o->sig[3]) + mu * 1e-12;
  /* to round-off (a looser sigma_33 = 0 leaves noise in the residual that finite differences and the incompatible
   * modes' own Newton see) */
  for (PetscInt it = 0; PetscAbsReal(o->sig[2]) > 1e-15 * scale; it++) {
    if (it >= 8 && PetscAbsReal(o->sig[2]) <= 1e-12 * scale) break; /* round-off: no further progress */
    if (it == 50 || !(o->C[2][2] > 0)) return PETSC_FALSE;
    eps[2] -= o->sig[2] / o->C[2][2];
    PlasticReturn(in, st, eps, eps_th, deps_th, theta, mu, Kb, dmu, dKb, frozen, PETSC_TRUE, o);
  }
  o->sig[2] = 0;
  if (!tangent) return PETSC_TRUE;
  {
    const PetscReal c33 = o->C[2][2], ds3 = o->dsig[2], dw3 = o->dw_de[2];
    PetscReal       c3[6];
    for (PetscInt c = 0; c < 6; c++) c3[c] = o->C[2][c];
    for (PetscInt r = 0; r < 6; r++) {
      const PetscReal cr3 = o->C[r][2];
      for (PetscInt c = 0; c < 6; c++) o->C[r][c] -= cr3 * c3[c] / c33;
      o->dsig[r] -= cr3 * ds3 / c33;
    }
    for (PetscInt c = 0; c < 6; c++) o->dw_de[c] -= dw3 * c3[c] / c33;
    o->dw_dth -= dw3 * ds3 / c33;
    for (PetscInt c = 0; c < 6; c++) o->C[2][c] = o->C[c][2] = 0;
    o->dsig[2] = 0, o->dw_de[2] = 0;
  }
  return PETSC_TRUE;
}

/* The state a point's return reaches from st: plastic strain, PEEQ, back stresses and, with temperature-dependent
 * back stresses, the temperature their C_k's were taken at */
static void PlasticStateNew(const TslMaterial *mat, const PetscReal *st, const PlasticPoint *o, PetscReal theta, PetscReal *sn)
{
  const PetscInt nb = mat->plastic.nback;
  for (PetscInt r = 0; r < 6; r++) sn[r] = st[r] + o->deps[r];
  sn[6] = st[6] + o->dl;
  for (PetscInt k = 0; k < 6 * nb; k++) sn[7 + k] = o->back[k];
  if (mat->plastic.nkt > 1) sn[7 + 6 * nb] = 1, sn[8 + 6 * nb] = theta;
}

/* Continuum shells (SC6RT, SC8RT): the material's plane stress in the shell's frame, as the elastic shell has it
 * (kinematics.c, ShellLocal): the in-plane strain (11, 22, 12) takes the plane-stress return (its own eps_33), the
 * thickness stress is the thickness modulus's E_t (eps_33 - eps_th) and the transverse shears k G gamma (k = 5/6), both
 * elastic and outside the yield condition, as in a conventional shell's plasticity; then rotated to the global axes.
 * The thickness stress is the elastic shell's E_t (eps_33 - eps_th): as there, the element's thickness does not follow
 * the in-plane strain (no Poisson or plastic thinning; the material's own eps_33 is the return's). The state's
 * plastic strain is kept in the frame; Tinv (local -> global strain) turns it back for the output. */
static PetscBool PlasticReturnShell(const TslElementInput *in, const MechPoint *mq, const PetscReal *st, const PetscReal eps[6], PetscReal theta,
                                    PetscReal mu, PetscReal Kb, PetscReal dmu, PetscReal dKb, PetscBool frozen, PetscBool tangent, PlasticPoint *o,
                                    PetscReal Tinv[6][6])
{
  PetscReal       Q[3][3], Qt[3][3], T[6][6], el[6], em[6], sl[6], Cl[6][6] = {{0}}, dsl[6], dwl[6];
  const PetscReal Et = TslElementShellThicknessModulus(in->sec, &mq->mp), dEt = in->sec->thickness_modulus > 0 ? 0 : 2 * dmu, ks = 5.0 / 6.0;
  PetscReal       se;

  TslElementShellFrame(in->sec, mq->p, Q);
  for (PetscInt i = 0; i < 3; i++)
    for (PetscInt j = 0; j < 3; j++) Qt[i][j] = Q[j][i];
  TslElementStrainTransform(Q, T);
  TslElementStrainTransform(Qt, Tinv);
  for (PetscInt r = 0; r < 6; r++) {
    el[r] = 0;
    for (PetscInt c = 0; c < 6; c++) el[r] += T[r][c] * eps[c];
  }
  for (PetscInt r = 0; r < 6; r++) em[r] = r == 4 || r == 5 ? 0 : el[r];
  if (!PlasticReturnPlaneStress(in, st, em, mq->eps_th, mq->deps_th, theta, mu, Kb, dmu, dKb, frozen, tangent, o)) return PETSC_FALSE;
  /* the frame's stress: the return's in-plane part, the elastic thickness and transverse shear */
  for (PetscInt r = 0; r < 6; r++) sl[r] = o->sig[r];
  sl[2] = Et * (el[2] - mq->eps_th), sl[4] = ks * mu * el[4], sl[5] = ks * mu * el[5];
  /* the return's energy counts its in-plane part: the thickness and shear terms with their own strains */
  se = o->se + 0.5 * sl[2] * (el[2] - mq->eps_th) + 0.5 * (sl[4] * el[4] + sl[5] * el[5]);
  for (PetscInt r = 0; r < 6; r++) {
    o->sig[r] = 0;
    for (PetscInt c = 0; c < 6; c++) o->sig[r] += T[c][r] * sl[c];
  }
  o->se = se;
  if (!tangent) return PETSC_TRUE;
  for (PetscInt r = 0; r < 6; r++)
    for (PetscInt c = 0; c < 6; c++)
      if ((r == 0 || r == 1 || r == 3) && (c == 0 || c == 1 || c == 3)) Cl[r][c] = o->C[r][c];
  Cl[2][2] = Et, Cl[4][4] = Cl[5][5] = ks * mu;
  for (PetscInt r = 0; r < 6; r++) dsl[r] = r == 2 || r >= 4 ? 0 : o->dsig[r], dwl[r] = r == 2 || r >= 4 ? 0 : o->dw_de[r];
  dsl[2] = dEt * (el[2] - mq->eps_th) - Et * mq->deps_th, dsl[4] = ks * dmu * el[4], dsl[5] = ks * dmu * el[5];
  for (PetscInt r = 0; r < 6; r++) {
    o->dsig[r] = o->dw_de[r] = 0;
    for (PetscInt c = 0; c < 6; c++) o->dsig[r] += T[c][r] * dsl[c], o->dw_de[r] += T[c][r] * dwl[c];
    for (PetscInt c = 0; c < 6; c++) {
      PetscReal v = 0;
      for (PetscInt a = 0; a < 6; a++)
        for (PetscInt b = 0; b < 6; b++) v += T[a][r] * Cl[a][b] * T[b][c];
      o->C[r][c] = v;
    }
  }
  return PETSC_TRUE;
}

/* The shear and bulk moduli of a point and their temperature derivatives */
static void PlasticModuli(const MechPoint *mq, PetscReal *mu, PetscReal *Kb, PetscReal *dmu, PetscReal *dKb)
{
  const PetscReal E = mq->mp.E, vv = mq->mp.nu, a = (1 + vv) * (1 - 2 * vv);
  PetscReal       lam, dlam;
  TslElementLame(&mq->mp, &lam, mu);
  dlam = mq->mp.dE * vv / a + mq->mp.dnu * E * (1 + 2 * vv * vv) / (a * a);
  *dmu = mq->mp.dE / (2 * (1 + vv)) - mq->mp.dnu * E / (2 * (1 + vv) * (1 + vv));
  *Kb = lam + 2 * *mu / 3, *dKb = dlam + 2 * *dmu / 3;
}

/* Plasticity with incompatible modes (C3D8I, CPE4I, CPS4I, CAX4I): the bubbles' alpha solves the element's own
 * equations int G^T sigma(B u + G alpha) dV = 0 at the committed plastic state, by Newton with K_aa = int G^T C G dV
 * (the return's consistent C; from alpha = 0 each evaluation, so no alpha is kept: it follows from u, theta and the
 * committed state); then R_u = int B^T sigma dV and, condensed, K_uu = int B^T C B - K_ua K_aa^-1 K_au (C need not be
 * symmetric), K_u_theta = t - K_ua K_aa^-1 s (t, s the B and G moments of dsig N_b), and the heat rows' derivatives
 * through alpha likewise. FALSE: an inverted element, or alpha not converged (a cutback). */
static PetscBool MechanicsIncompatiblePlastic(const TslElementInput *in, const TslElementPoint full[], PetscReal R[], PetscReal K[], TslElementResult *res,
                                              PetscReal energy[4], PetscReal heat_out[])
{
  const TslElementType *t    = in->type;
  const TslGeometry    *g    = t->geom;
  const TslQuadrature  *quad = t->form->quadrature(g, in->sec);
  const TslMaterial    *mat  = in->sec->mat;
  const PetscInt        ndof = t->ndof, th = ndof - 1, nu = ndof - 1, n = g->nnode, nd = n * ndof, ncol = n * nu, nq = quad->n;
  const PetscInt        ns = TslMaterialPlasticState(mat);
  const PetscReal       heat = mat->heat_fraction * in->inelastic_rate;
  const PetscBool       ps = TslKinematicsRowGet(t->kin)->free_normal, frozen = res ? PETSC_TRUE : PETSC_FALSE;
  PetscReal             G[TSL_MAX_QP][6][TSL_MAX_ENHANCED], alpha[TSL_MAX_ENHANCED] = {0}, Kaa[TSL_MAX_ENHANCED * TSL_MAX_ENHANCED], Kai[TSL_MAX_ENHANCED * TSL_MAX_ENHANCED];
  PetscReal             mu[TSL_INCOMPATIBLE_QP], Kb[TSL_INCOMPATIBLE_QP], dmu[TSL_INCOMPATIBLE_QP], dKb[TSL_INCOMPATIBLE_QP], theta[TSL_INCOMPATIBLE_QP];
  PetscReal             eps[TSL_INCOMPATIBLE_QP][6];
  PetscInt              na;
  MechPoint             mqs[TSL_INCOMPATIBLE_QP];
  PlasticPoint          o[TSL_INCOMPATIBLE_QP];

  if (energy) energy[0] = energy[2] = energy[3] = 0;
  if (!IncompatibleModes(in, full, mqs, G, &na)) return PETSC_FALSE;
  for (PetscInt q = 0; q < nq; q++) {
    theta[q] = NodalTheta(in, mqs[q].p->N, in->u);
    PlasticModuli(&mqs[q], &mu[q], &Kb[q], &dmu[q], &dKb[q]);
  }
  /* Newton on the bubbles' equations */
  for (PetscInt it = 0;; it++) {
    PetscReal Ra[TSL_MAX_ENHANCED] = {0}, scale = 0, rmax = 0;
    for (PetscInt c = 0; c < na * na; c++) Kaa[c] = 0;
    for (PetscInt q = 0; q < nq; q++) {
      const MechPoint *mq = &mqs[q];
      const PetscReal *st = in->pstate + ns * q;
      for (PetscInt r = 0; r < 6; r++) {
        eps[q][r] = mq->eps[r];
        for (PetscInt c = 0; c < na; c++) eps[q][r] += G[q][r][c] * alpha[c];
      }
      if (ps) {
        if (!PlasticReturnPlaneStress(in, st, eps[q], mq->eps_th, mq->deps_th, theta[q], mu[q], Kb[q], dmu[q], dKb[q], frozen, PETSC_TRUE, &o[q])) return PETSC_FALSE;
      } else PlasticReturn(in, st, eps[q], mq->eps_th, mq->deps_th, theta[q], mu[q], Kb[q], dmu[q], dKb[q], frozen, PETSC_TRUE, &o[q]);
      for (PetscInt c1 = 0; c1 < na; c1++) {
        PetscReal CG[6];
        for (PetscInt r = 0; r < 6; r++) {
          Ra[c1] += G[q][r][c1] * o[q].sig[r] * mq->p->dV;
          scale += PetscAbsReal(G[q][r][c1] * o[q].sig[r]) * mq->p->dV;
        }
        for (PetscInt r = 0; r < 6; r++) {
          CG[r] = 0;
          for (PetscInt s2 = 0; s2 < 6; s2++) CG[r] += o[q].C[r][s2] * G[q][s2][c1];
        }
        for (PetscInt c2 = 0; c2 < na; c2++)
          for (PetscInt r = 0; r < 6; r++) Kaa[c2 * na + c1] += G[q][r][c2] * CG[r] * mq->p->dV; /* row c2: d R_a,c2 / d alpha_c1 */
      }
    }
    for (PetscInt c = 0; c < na; c++) rmax = PetscMax(rmax, PetscAbsReal(Ra[c]));
    DenseInverse(na, na, Kaa, Kai);
    if (rmax <= 1e-15 * scale || (it >= 8 && rmax <= 1e-12 * scale) || it == 50) { /* to round-off, as the plane-stress eps_33 */
      if (rmax > 1e-8 * scale) return PETSC_FALSE; /* the bubbles did not settle: a cutback */
      break;
    }
    for (PetscInt c1 = 0; c1 < na; c1++)
      for (PetscInt c2 = 0; c2 < na; c2++) alpha[c1] -= Kai[c1 * na + c2] * Ra[c2];
  }
  /* at the bubbles' solution: forces, heat, state, outputs */
  for (PetscInt q = 0; q < nq; q++) {
    const MechPoint *mq = &mqs[q];
    const PetscReal *st = in->pstate + ns * q;
    for (PetscInt a = 0; a < n; a++)
      for (PetscInt i = 0; i < nu; i++) {
        PetscReal f = 0;
        for (PetscInt r = 0; r < 6; r++) f += mq->B[r][nu * a + i] * o[q].sig[r];
        R[ndof * a + i] += f * mq->p->dV;
      }
    for (PetscInt a = 0; a < n; a++) {
      const PetscReal qa = mq->p->N[a] * heat * o[q].w * mq->p->dV;
      if (heat_out) heat_out[a] += qa;
      else R[ndof * a + th] -= qa;
    }
    if (in->pstate_new) PlasticStateNew(mat, st, &o[q], theta[q], in->pstate_new + ns * q);
    if (res) {
      for (PetscInt r = 0; r < 6; r++) res->E[r] += eps[q][r] / nq, res->S[r] += o[q].sig[r] / nq, res->PE[r] += (st[r] + o[q].deps[r]) / nq;
      res->PEEQ += (st[6] + o[q].dl) / nq;
      res->strain_energy += o[q].se * mq->p->dV;
    }
    if (energy) energy[0] += o[q].se * mq->p->dV, energy[2] += o[q].w * mq->p->dV, energy[3] += heat * o[q].w * mq->p->dV;
  }
  if (!K) return PETSC_TRUE;
  {
    PetscReal Kua[TSL_MAX_ELEM_NODES * 3][TSL_MAX_ENHANCED] = {{0}}, Kau[TSL_MAX_ENHANCED][TSL_MAX_ELEM_NODES * 3] = {{0}}, sb[TSL_MAX_ENHANCED][TSL_MAX_ELEM_NODES] = {{0}};
    PetscReal hG[TSL_MAX_ELEM_NODES][TSL_MAX_ENHANCED] = {{0}}; /* the heat rows' alpha derivatives, -N_a heat int dw/de G dV */
    PetscReal KiKau[TSL_MAX_ENHANCED][TSL_MAX_ELEM_NODES * 3], Kis[TSL_MAX_ENHANCED][TSL_MAX_ELEM_NODES];
    for (PetscInt q = 0; q < nq; q++) {
      const MechPoint *mq = &mqs[q];
      const PetscReal  dV = mq->p->dV;
      for (PetscInt c1 = 0; c1 < ncol; c1++) {
        const PetscInt r1 = ndof * (c1 / nu) + c1 % nu;
        PetscReal      BC[6], CB[6], Bds = 0;
        for (PetscInt r = 0; r < 6; r++) {
          BC[r] = CB[r] = 0;
          for (PetscInt s2 = 0; s2 < 6; s2++) BC[r] += mq->B[s2][c1] * o[q].C[s2][r], CB[r] += o[q].C[r][s2] * mq->B[s2][c1];
          Bds += mq->B[r][c1] * o[q].dsig[r];
        }
        for (PetscInt c2 = 0; c2 < ncol; c2++) {
          PetscReal kv = 0;
          for (PetscInt r = 0; r < 6; r++) kv += BC[r] * mq->B[r][c2];
          K[r1 * nd + ndof * (c2 / nu) + c2 % nu] += kv * dV;
        }
        for (PetscInt c = 0; c < na; c++) {
          PetscReal ua = 0, au = 0;
          for (PetscInt r = 0; r < 6; r++) ua += BC[r] * G[q][r][c], au += G[q][r][c] * CB[r];
          Kua[c1][c] += ua * dV, Kau[c][c1] += au * dV;
        }
        for (PetscInt b = 0; b < n; b++) K[r1 * nd + ndof * b + th] += Bds * mq->p->N[b] * dV;
      }
      for (PetscInt c = 0; c < na; c++) {
        PetscReal Gds = 0, wG = 0;
        for (PetscInt r = 0; r < 6; r++) Gds += G[q][r][c] * o[q].dsig[r], wG += o[q].dw_de[r] * G[q][r][c];
        for (PetscInt b = 0; b < n; b++) sb[c][b] += Gds * mq->p->N[b] * dV;
        if (heat > 0 && o[q].dl > 0)
          for (PetscInt a = 0; a < n; a++) hG[a][c] -= mq->p->N[a] * heat * wG * dV;
      }
      if (heat > 0 && o[q].dl > 0)
        for (PetscInt a = 0; a < n; a++) {
          const PetscReal f = -mq->p->N[a] * heat * dV;
          for (PetscInt c2 = 0; c2 < ncol; c2++) {
            PetscReal kv = 0;
            for (PetscInt r = 0; r < 6; r++) kv += o[q].dw_de[r] * mq->B[r][c2];
            K[(ndof * a + th) * nd + ndof * (c2 / nu) + c2 % nu] += f * kv;
          }
          for (PetscInt b = 0; b < n; b++) K[(ndof * a + th) * nd + ndof * b + th] += f * o[q].dw_dth * mq->p->N[b];
        }
    }
    /* condensation through d alpha = -K_aa^-1 (K_au du + s dtheta) */
    IncompatibleCondense(in, na, Kai, Kau, Kua, sb, K, KiKau, Kis);
    for (PetscInt a = 0; a < n; a++) {
      for (PetscInt c2 = 0; c2 < ncol; c2++) {
        PetscReal kv = 0;
        for (PetscInt c = 0; c < na; c++) kv += hG[a][c] * KiKau[c][c2];
        K[(ndof * a + th) * nd + ndof * (c2 / nu) + c2 % nu] -= kv;
      }
      for (PetscInt b = 0; b < n; b++) {
        PetscReal kv = 0;
        for (PetscInt c = 0; c < na; c++) kv += hG[a][c] * Kis[c][b];
        K[(ndof * a + th) * nd + ndof * b + th] -= kv;
      }
    }
  }
  return PETSC_TRUE;
}

static PetscBool MechanicsPlastic(const TslElementInput *in, const TslElementPoint full[], PetscReal R[], PetscReal K[], TslElementResult *res,
                                  PetscReal energy[4], PetscReal heat_out[])
{
  const TslElementType *t    = in->type;
  const TslGeometry    *g    = t->geom;
  const TslQuadrature  *quad = t->form->quadrature(g, in->sec);
  const TslMaterial    *mat  = in->sec->mat;
  const PetscInt        ndof = t->ndof, th = ndof - 1, nu = ndof - 1, n = g->nnode, nv = TslElementTypeNodes(t), nd = nv * ndof, ncol = nv * nu;
  const PetscReal       heat = mat->heat_fraction * in->inelastic_rate;
  const PetscInt        nb = mat->plastic.nback, ns = TslMaterialPlasticState(mat);
  const PetscBool       ps = TslKinematicsRowGet(t->kin)->free_normal, hybrid = t->form->pressure ? PETSC_TRUE : PETSC_FALSE;
  const PetscBool       shell = TslKinematicsRowGet(t->kin)->shell;
  PetscReal             Tinv[6][6];
  PetscReal             sdev_avg[6] = {0, 0, 0, 0, 0, 0}, P_avg[TSL_MAX_PRESSURE] = {0};
  MechPoint             mq;
  PlasticPoint          o;
  Hybrid                hy;
  PetscBool             symmetric = PETSC_TRUE; /* C is, unless a back stress recovers (gamma > 0: the v_perp n^T term) */
  PetscReal             CB[TSL_MAX_ELEM_NODES * 3][6]; /* B^T C dV, by column of B */

  for (PetscInt r = 0; r < mat->plastic.nkt; r++)
    for (PetscInt kb = 0; kb < nb; kb++)
      if (mat->plastic.kt_gamma[r][kb] > 0) symmetric = PETSC_FALSE;
  if (t->form->incompatible) return MechanicsIncompatiblePlastic(in, full, R, K, res, energy, heat_out);
  if (energy) energy[0] = energy[2] = energy[3] = 0;
  if (hybrid) PetscCallAbort(PETSC_COMM_SELF, PetscMemzero(&hy, sizeof(hy)));
  for (PetscInt q = 0; q < quad->n; q++) {
    const PetscReal *st = in->pstate + ns * q;
    PetscReal        mu, Kb, dmu, dKb, theta, eps[6];

    if (!MechPointEvaluate(in, quad->xi[q], quad->w[q], full && quad == &g->full ? &full[q] : NULL, PETSC_FALSE, &mq)) return PETSC_FALSE;
    theta = NodalTheta(in, mq.p->N, in->u);
    PlasticModuli(&mq, &mu, &Kb, &dmu, &dKb);
    for (PetscInt r = 0; r < 6; r++) eps[r] = mq.eps[r];
    if (shell) {
      if (!PlasticReturnShell(in, &mq, st, eps, theta, mu, Kb, dmu, dKb, res ? PETSC_TRUE : PETSC_FALSE, K ? PETSC_TRUE : PETSC_FALSE, &o, Tinv)) return PETSC_FALSE;
    } else if (ps) {
      if (!PlasticReturnPlaneStress(in, st, eps, mq.eps_th, mq.deps_th, theta, mu, Kb, dmu, dKb, res ? PETSC_TRUE : PETSC_FALSE, K ? PETSC_TRUE : PETSC_FALSE, &o))
        return PETSC_FALSE;
    } else /* outputs (res) come at the committed state: no return there */
      PlasticReturn(in, st, eps, mq.eps_th, mq.deps_th, theta, mu, Kb, dmu, dKb, res ? PETSC_TRUE : PETSC_FALSE, K ? PETSC_TRUE : PETSC_FALSE, &o);
    if (hybrid) { /* the pressure is the element's own (HybridCondense): the return's deviatoric part alone here (the flow is isochoric) */
      const PetscReal trE = eps[0] + eps[1] + eps[2] - 3 * mq.eps_th - (st[0] + st[1] + st[2]);
      HybridPoint(in, &mq, Kb, dKb, quad->n, &hy, P_avg);
      for (PetscInt r = 0; r < 3; r++) {
        o.sig[r] -= Kb * trE, o.dsig[r] -= dKb * trE - 3 * Kb * mq.deps_th;
        for (PetscInt c = 0; c < 3; c++) o.C[r][c] -= Kb;
      }
      o.se -= 0.5 * Kb * trE * trE;
    }
    for (PetscInt a = 0; a < nv; a++)
      for (PetscInt i = 0; i < nu; i++) {
        PetscReal f = 0;
        for (PetscInt r = 0; r < 6; r++) f += mq.B[r][nu * a + i] * o.sig[r];
        R[ndof * a + i] += f * mq.p->dV;
      }
    for (PetscInt a = 0; a < n; a++) { /* the plastic heat, a source */
      const PetscReal qa = mq.p->N[a] * heat * o.w * mq.p->dV;
      if (heat_out) heat_out[a] += qa;
      else R[ndof * a + th] -= qa;
    }
    if (in->pstate_new) PlasticStateNew(mat, st, &o, theta, in->pstate_new + ns * q);
    if (res) {
      for (PetscInt r = 0; r < 6; r++) {
        PetscReal pe = st[r] + o.deps[r];
        if (shell) { /* the frame's plastic strain to the global axes */
          pe = 0;
          for (PetscInt c = 0; c < 6; c++) pe += Tinv[r][c] * (st[c] + o.deps[c]);
        }
        res->E[r] += eps[r] / quad->n, res->PE[r] += pe / quad->n;
      }
      for (PetscInt r = 0; r < 6; r++) *(hybrid ? &sdev_avg[r] : &res->S[r]) += o.sig[r] / quad->n;
      res->PEEQ += (st[6] + o.dl) / quad->n;
      res->strain_energy += o.se * mq.p->dV;
    }
    if (energy) energy[0] += o.se * mq.p->dV, energy[2] += o.w * mq.p->dV, energy[3] += heat * o.w * mq.p->dV;
    if (!K) continue;
    /* K_uu += B^T C B dV over B's nonzeros (bz: at most 4 of a column's 6 rows), the upper triangle where C is
     * symmetric (no recovering back stress), and the temperature column B^T dsig N_b dV */
    for (PetscInt c1 = 0; c1 < ncol; c1++) {
      PetscReal Bds = 0;
      for (PetscInt r = 0; r < 6; r++) CB[c1][r] = 0;
      for (PetscInt j = 0; j < mq.bz_n[c1]; j++) {
        const PetscReal  v  = mq.bz_val[c1][j] * mq.p->dV;
        const PetscReal *cr = o.C[mq.bz_row[c1][j]];
        for (PetscInt r = 0; r < 6; r++) CB[c1][r] += v * cr[r];
        Bds += v * o.dsig[mq.bz_row[c1][j]];
      }
      for (PetscInt b = 0; b < n; b++) K[(ndof * (c1 / nu) + c1 % nu) * nd + ndof * b + th] += Bds * mq.p->N[b];
    }
    for (PetscInt c1 = 0; c1 < ncol; c1++) {
      const PetscInt r1 = ndof * (c1 / nu) + c1 % nu;
      for (PetscInt c2 = symmetric ? c1 : 0; c2 < ncol; c2++) {
        PetscReal kv = 0;
        for (PetscInt j = 0; j < mq.bz_n[c2]; j++) kv += CB[c1][mq.bz_row[c2][j]] * mq.bz_val[c2][j];
        K[r1 * nd + ndof * (c2 / nu) + c2 % nu] += kv;
        if (symmetric && c2 != c1) K[(ndof * (c2 / nu) + c2 % nu) * nd + r1] += kv;
      }
    }
    if (heat > 0 && o.dl > 0)
      for (PetscInt a = 0; a < n; a++) {
        const PetscReal f = -mq.p->N[a] * heat * mq.p->dV;
        for (PetscInt c2 = 0; c2 < ncol; c2++) {
          PetscReal kv = 0;
          for (PetscInt j = 0; j < mq.bz_n[c2]; j++) kv += o.dw_de[mq.bz_row[c2][j]] * mq.bz_val[c2][j];
          K[(ndof * a + th) * nd + ndof * (c2 / nu) + c2 % nu] += f * kv;
        }
        for (PetscInt b = 0; b < n; b++) K[(ndof * a + th) * nd + ndof * b + th] += f * o.dw_dth * mq.p->N[b];
      }
  }
  if (hybrid) HybridCondense(in, &hy, P_avg, sdev_avg, R, K, res, res ? &res->strain_energy : energy ? &energy[0] : NULL);
  return PETSC_TRUE;
}

PetscInt TslElementTypeMechanicalPoints(const TslElementType *t, const TslElementSection *sec)
{
  return t->form->quadrature(t->geom, sec)->n;
}

/* The displacement block from the upper triangle Kuu (ncol x ncol), both triangles, into K. */
static void FoldUpper(const TslElementInput *in, PetscInt ncol, const PetscReal Kuu[], PetscReal K[])
{
  const TslElementType *t    = in->type;
  const PetscInt        ndof = t->ndof, nu = ndof - 1, nd = TslElementTypeNodes(t) * ndof;

  for (PetscInt c1 = 0; c1 < ncol; c1++)
    for (PetscInt c2 = c1; c2 < ncol; c2++) {
      const PetscInt r1 = ndof * (c1 / nu) + c1 % nu, r2 = ndof * (c2 / nu) + c2 % nu;
      K[r1 * nd + r2] += Kuu[c1 * ncol + c2];
      if (c2 != c1) K[r2 * nd + r1] += Kuu[c1 * ncol + c2];
    }
}

/* A finite-strain hybrid element after its condensation: each point's pressure p = P^T p_hat in the geometric
 * stiffness (the deviator's share was added with the points) and in the output, the Cauchy stress of the point's
 * whole S = S_dev + p m. Kuu: work space. */
static PetscBool FiniteHybridPressure(const TslElementInput *in, const Hybrid *hy, PetscReal K[], TslElementResult *res, PetscReal Kuu[])
{
  const TslElementType *t    = in->type;
  const TslQuadrature  *quad = t->form->quadrature(t->geom, in->sec);
  const PetscInt        ncol = TslElementTypeNodes(t) * (t->ndof - 1);
  MechPoint             mq;
  FinitePoint           fp;

  if (K) PetscCallAbort(PETSC_COMM_SELF, PetscArrayzero(Kuu, ncol * ncol));
  if (res)
    for (PetscInt r = 0; r < 6; r++) res->S[r] = res->E[r] = 0;
  for (PetscInt q = 0; q < quad->n; q++) {
    PetscReal P[TSL_MAX_PRESSURE], pq = 0, sig[6], D[6][6];
    if (!MechPointEvaluate(in, quad->xi[q], quad->w[q], NULL, PETSC_FALSE, &mq) || !MechPointFinite(in, &mq, &fp)) return PETSC_FALSE;
    (void)t->form->pressure(t->geom, mq.p, P);
    for (PetscInt k = 0; k < hy->np; k++) pq += P[k] * hy->p[k];
    for (PetscInt r = 0; r < 6; r++) sig[r] = VoigtM[r] * pq;
    if (K) GeometricStiffness(in, &mq, &fp, sig, Kuu);
    if (!res) continue;
    Deviatoric(mq.mp.E / (2 * (1 + mq.mp.nu)), D);
    for (PetscInt r = 0; r < 6; r++)
      for (PetscInt s = 0; s < 6; s++) sig[r] += D[r][s] * mq.eps[s];
    FiniteOutput(in, &mq, &fp, sig, quad->n, res);
  }
  if (K) FoldUpper(in, ncol, Kuu, K);
  return PETSC_TRUE;
}

/* Mechanical terms over the formulation's points. Displacement formulation:
 *   sigma = D (eps - eps_th m),  R_u = int B^T sigma dV,
 *   K_uu = int B^T D B dV,  K_u_theta_b = int B^T (dD (eps - eps_th m) - D m deps_th) N_b dV.
 * Hybrid (independent pressure p = P^T p_hat, condensed): sigma = 2 mu dev(eps) + p m with
 *   int P (tr eps - 3 eps_th - p / K) dV = 0, i.e. H p_hat = G^T u - g0, so
 *   R_u = int B^T 2 mu dev(eps) dV + G p_hat,  K_uu = K_dev + G H^-1 G^T,
 *   d p_hat / d theta_b = H^-1 (-dg0_b - dH_b p_hat). The thermal strain is volumetric, so it enters
 *   only through the pressure equation. Nearly incompressible material does not lock: the volumetric
 *   constraint is imposed on the pressure space only (one term per linear element, 1 + dim per
 *   quadratic one). If res is given, stresses, strains and the strain energy are averaged into it. */
static PetscBool Mechanics(const TslElementInput *in, const TslElementPoint full[], PetscReal R[], PetscReal K[], Hybrid *hy, TslElementResult *res,
                           PetscReal *energy)
{
  const TslElementType *t    = in->type;
  const TslGeometry    *g    = t->geom;
  const TslQuadrature  *quad = t->form->quadrature(g, in->sec);
  const PetscInt        ndof = t->ndof, th = ndof - 1, nu = ndof - 1, n = g->nnode, nv = TslElementTypeNodes(t), nd = nv * ndof, ncol = nv * nu;
  const PetscBool       hybrid      = t->form->pressure ? PETSC_TRUE : PETSC_FALSE;
  PetscReal             sdev_avg[6] = {0, 0, 0, 0, 0, 0}, P_avg[TSL_MAX_PRESSURE] = {0};
  const PetscBool       finite      = in->nlgeom;                               /* finite strain (FinitePoint) */
  const PetscBool       lean        = !K && !res && !hybrid && !finite && LeanStrain(in); /* forces only: no B, no tangent terms */
  PetscReal            *se          = res ? &res->strain_energy : energy;      /* int 1/2 sigma : eps_mech dV, when wanted */
  MechPoint             mq;
  FinitePoint           fp;
  PetscReal             Kuu[TSL_MAX_ELEM_NODES * 3 * TSL_MAX_ELEM_NODES * 3]; /* upper triangle, ncol x ncol */

  if (nu == 0) return PETSC_TRUE; /* a heat-transfer type: no displacement, no mechanical term */
  if (in->pstate) return MechanicsPlastic(in, full, R, K, res, NULL, NULL);
  if (t->form->incompatible) return MechanicsIncompatible(in, full, R, K, res, energy);
  if (K && !se && !hybrid && !finite && LeanStrain(in)) return MechanicsSolid3DTangent(in, full, R, K);
  if (finite && !se && !res && !hybrid && LeanStrain(in)) return MechanicsSolid3DFinite(in, full, R, K);
  if (hybrid) PetscCallAbort(PETSC_COMM_SELF, PetscMemzero(hy, sizeof(*hy)));
  if (K) memset(Kuu, 0, sizeof(PetscReal) * (size_t)(ncol * ncol)); /* (not PetscArrayzero: GCC then cannot see Kuu set for FoldUpper) */
  for (PetscInt q = 0; q < quad->n; q++) {
    PetscReal D[6][6], dD[6][6], emech[6], sig[6], dsig[6];
    PetscReal DB[6][TSL_MAX_ELEM_NODES * 3];

    if (!MechPointEvaluate(in, quad->xi[q], quad->w[q], full && quad == &g->full ? &full[q] : NULL, lean, &mq)) return PETSC_FALSE;
    if (finite && !MechPointFinite(in, &mq, &fp)) return PETSC_FALSE;
    if (hybrid) {
      const PetscReal nuv = mq.mp.nu, E = mq.mp.E, mu = E / (2 * (1 + nuv)), kb = E / (3 * (1 - 2 * nuv));
      const PetscReal dmu = mq.mp.dE / (2 * (1 + nuv)) - mq.mp.dnu * E / (2 * (1 + nuv) * (1 + nuv));
      const PetscReal dkb = mq.mp.dE / (3 * (1 - 2 * nuv)) + mq.mp.dnu * 2 * E / (3 * (1 - 2 * nuv) * (1 - 2 * nuv));
      HybridPoint(in, &mq, kb, dkb, quad->n, hy, P_avg);
      Deviatoric(mu, D);
      Deviatoric(dmu, dD);
      for (PetscInt r = 0; r < 6; r++) emech[r] = mq.eps[r]; /* the deviatoric part ignores the volumetric eps_th */
    } else {
      TslElementElasticity(t, in->sec, mq.p, &mq.mp, D, K ? dD : NULL);
      for (PetscInt r = 0; r < 6; r++) emech[r] = mq.eps[r] - VoigtM[r] * mq.eps_th;
    }
    if (lean) {
      /* R_a += B_a^T sigma dV with the nonzeros of B_a in the B path's order (rows ascending) */
      for (PetscInt r = 0; r < 6; r++) {
        sig[r] = 0;
        for (PetscInt s = 0; s < 6; s++) sig[r] += D[r][s] * emech[s];
      }
      for (PetscInt a = 0; a < nv; a++) {
        PetscReal f[3];
        SolidBtS(mq.p->dNdx[a], sig, mq.p->dV, f);
        for (PetscInt i = 0; i < 3; i++) R[4 * a + i] += f[i];
      }
      if (se)
        for (PetscInt r = 0; r < 6; r++) *se += 0.5 * sig[r] * emech[r] * mq.p->dV;
      continue;
    }
    for (PetscInt r = 0; r < 6; r++) {
      sig[r] = dsig[r] = 0;
      for (PetscInt s = 0; s < 6; s++) {
        sig[r] += D[r][s] * emech[s];
        dsig[r] += dD[r][s] * emech[s] - (hybrid ? 0 : D[r][s] * VoigtM[s] * mq.deps_th);
      }
    }
    for (PetscInt a = 0; a < nv; a++)
      for (PetscInt i = 0; i < nu; i++) {
        const PetscInt c = nu * a + i;
        PetscReal      f = 0;
        for (PetscInt k = 0; k < mq.bz_n[c]; k++) f += mq.bz_val[c][k] * sig[mq.bz_row[c][k]];
        R[ndof * a + i] += f * mq.p->dV;
      }
    if (res && finite) {
      if (!hybrid) FiniteOutput(in, &mq, &fp, sig, quad->n, res); /* hybrid: with each point's pressure, below */
    } else if (res) {
      for (PetscInt r = 0; r < 6; r++) {
        res->E[r] += mq.eps[r] / quad->n;
        if (hybrid)
          sdev_avg[r] += sig[r] / quad->n;
        else
          res->S[r] += sig[r] / quad->n;
      }
    }
    if (se) {
      if (!hybrid)
        for (PetscInt r = 0; r < 6; r++) *se += 0.5 * sig[r] * emech[r] * mq.p->dV;
      else
        for (PetscInt r = 0; r < 6; r++) *se += 0.5 * sig[r] * mq.eps[r] * mq.p->dV;
    }
    if (!K) continue;
    if (finite) GeometricStiffness(in, &mq, &fp, sig, Kuu);
    /* DB = D B dV (rows of D skip its zeros; contiguous in the columns), then the upper triangle of
     * B^T D B dV row by row over the nonzeros of B's column (symmetric: D is), into Kuu */
    for (PetscInt r = 0; r < 6; r++) {
      for (PetscInt c = 0; c < ncol; c++) DB[r][c] = 0;
      for (PetscInt s = 0; s < 6; s++) {
        const PetscReal drs = D[r][s] * mq.p->dV;
        if (drs == 0) continue;
        for (PetscInt c = 0; c < ncol; c++) DB[r][c] += drs * mq.B[s][c];
      }
    }
    for (PetscInt c1 = 0; c1 < ncol; c1++) {
      PetscReal *kr = &Kuu[c1 * ncol], Bds = 0;
      for (PetscInt k = 0; k < mq.bz_n[c1]; k++) {
        const PetscReal  v  = mq.bz_val[c1][k];
        const PetscReal *db = DB[mq.bz_row[c1][k]];
        for (PetscInt c2 = c1; c2 < ncol; c2++) kr[c2] += v * db[c2];
        Bds += v * dsig[mq.bz_row[c1][k]];
      }
      for (PetscInt b = 0; b < n; b++) K[(ndof * (c1 / nu) + c1 % nu) * nd + ndof * b + th] += Bds * mq.p->N[b] * mq.p->dV;
    }
  }
  if (K) FoldUpper(in, ncol, Kuu, K);
  if (hybrid) {
    HybridCondense(in, hy, P_avg, sdev_avg, R, K, res, se);
    if (finite && (K || res)) return FiniteHybridPressure(in, hy, K, res, K ? Kuu : NULL);
  }
  return PETSC_TRUE;
}

/* The stabilisation of a reduced-integration element is evaluated with the material at the element
 * centre (the single mechanical point; a continuum shell's points lie above and below it). */
static PetscErrorCode Hourglass(const TslElementInput *in, PetscReal R[], PetscReal K[], PetscReal *energy)
{
  const TslGeometry *g = in->type->geom;
  PetscReal          xi0[3];
  MechPoint          mq;

  PetscFunctionBeginUser;
  *energy = 0;
  if (!in->type->form->hourglass) PetscFunctionReturn(PETSC_SUCCESS);
  TslElementCentre(g, xi0);
  PetscCheck(MechPointEvaluate(in, xi0, g->ref_volume, NULL, LeanStrain(in), &mq), PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "hourglass control of an inverted element");
  PetscCall(in->type->form->hourglass(in, &mq.mp, R, K, energy));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscBool TslElementValid(const TslElementInput *in)
{
  const TslGeometry   *g    = in->type->geom;
  const TslQuadrature *quad = in->type->form->quadrature(g, in->sec);
  TslElementPoint      full[TSL_MAX_QP], p;

  if (!FullPoints(in, full)) return PETSC_FALSE;
  if (quad != &g->full)
    for (PetscInt q = 0; q < quad->n; q++)
      if (!TslElementPointEvaluate(in->type, in->sec, in->x, quad->xi[q], quad->w[q], &p)) return PETSC_FALSE;
  return PETSC_TRUE;
}

static PetscErrorCode InternalEnergy(const TslElementInput *in, PetscReal R[], PetscReal K[], PetscBool *inverted, PetscReal energy[4], PetscReal heat_out[]);

PetscErrorCode TslElementInternal(const TslElementInput *in, PetscReal R[], PetscReal K[], PetscBool *inverted)
{
  PetscFunctionBeginUser;
  PetscCall(TslElementInternalEnergy(in, R, K, inverted, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslElementInternalEnergy(const TslElementInput *in, PetscReal R[], PetscReal K[], PetscBool *inverted, PetscReal energy[4])
{
  PetscFunctionBeginUser;
  PetscCall(InternalEnergy(in, R, K, inverted, energy, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslElementInternalPlasticHeat(const TslElementInput *in, PetscReal R[], PetscBool *inverted, PetscReal energy[4], PetscReal heat[])
{
  PetscFunctionBeginUser;
  PetscCall(PetscArrayzero(heat, TslElementTypeNodes(in->type)));
  PetscCall(InternalEnergy(in, R, NULL, inverted, energy, in->pstate ? heat : NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* TslElementInternalEnergy; heat_out not NULL: a plastic element's heat sources there (MechanicsPlastic), not in R */
static PetscErrorCode InternalEnergy(const TslElementInput *in, PetscReal R[], PetscReal K[], PetscBool *inverted, PetscReal energy[4], PetscReal heat_out[])
{
  const PetscInt  nd = TslElementTypeNodes(in->type) * in->type->ndof;
  Hybrid          hy;
  PetscReal       ehg;
  TslElementPoint full[TSL_MAX_QP];

  PetscFunctionBeginUser;
  *inverted = PETSC_FALSE;
  if (energy) energy[0] = energy[1] = energy[2] = energy[3] = 0;
  PetscCall(PetscArrayzero(R, nd));
  if (K) PetscCall(PetscArrayzero(K, nd * nd));
  if (!FullPoints(in, full)) {
    *inverted = PETSC_TRUE;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  Conduction(in, full, R, K);
  if (!(in->pstate ? MechanicsPlastic(in, full, R, K, NULL, energy, heat_out) : Mechanics(in, full, R, K, &hy, NULL, energy))) {
    *inverted = PETSC_TRUE;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(Hourglass(in, R, K, &ehg));
  if (energy) energy[1] = ehg;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslElementNodalVolume(const TslElementInput *in, PetscReal vol[])
{
  PetscFunctionBeginUser;
  PetscCheck(in->type->form->nodal_volume(in, vol), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "Inverted %s element", in->type->name);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Lumped capacity and mass at the nodal temperatures: Q_a = rho V_a e(theta_a), C_a = dQ_a/dtheta_a,
 * M_a = rho V_a. The density is taken at the node's temperature too. */
PetscErrorCode TslElementLumped(const TslElementInput *in, PetscReal Q[], PetscReal C[], PetscReal M[])
{
  const PetscInt ndof = in->type->ndof, th = ndof - 1;
  PetscReal      vol[TSL_MAX_ELEM_NODES];

  PetscFunctionBeginUser;
  PetscCall(TslElementNodalVolume(in, vol));
  for (PetscInt a = 0; a < in->type->geom->nnode; a++) {
    const PetscReal  theta = in->u[ndof * a + th];
    TslMaterialPoint mp;
    PetscReal        c, e = TslMaterialHeatContent(in->sec->mat, theta, &c);
    TslMaterialEval(in->sec->mat, theta, &mp);
    if (Q) Q[a] = mp.rho * vol[a] * e;
    if (C) C[a] = mp.rho * vol[a] * c;
    if (M) M[a] = mp.rho * vol[a];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Heat content for the implicit procedures (TslElementHeatContent, element.h). Consistent (a formulation with
 * consistent_capacity on a second-order family): Q_a = int N_a rho e(theta_h) dV, C_ab = int N_a rho c(theta_h)
 * N_b dV, with theta_h = sum_b N_b theta_b, at the points of a rule exact for N_a N_b on straight-sided elements:
 * the family's lumping rule where it has one (tri6: 6 points, tet10: 14), else its full rule (quad8, hex20,
 * wedge15). The full rules of tri6 and tet10 (3 and 4 points, degree 2) are not: with fewer points than nodes
 * they gave a capacity matrix of rank 3 (of 6) and 4 (of 10). sum_a Q_a = int rho e(theta_h) dV, so the heat stored is
 * still the residual's own and the heat balance closes. rho is taken at theta_h and its derivative left out,
 * as the lumped kernel leaves it out. Lumped otherwise: TslElementLumped's Q and C on the diagonal. */
PetscErrorCode TslElementHeatContent(const TslElementInput *in, PetscReal Q[], PetscReal C[])
{
  const TslGeometry   *g    = in->type->geom;
  const TslQuadrature *rule = g->lump.n ? &g->lump : &g->full;
  const PetscInt     ndof = in->type->ndof, th = ndof - 1, n = g->nnode;
  TslElementPoint    p;

  PetscFunctionBeginUser;
  if (C)
    for (PetscInt a = 0; a < n * n; a++) C[a] = 0;
  if (!TslElementCapacityConsistent(in->type)) {
    PetscReal c[TSL_MAX_ELEM_NODES];
    PetscCall(TslElementLumped(in, Q, C ? c : NULL, NULL));
    if (C)
      for (PetscInt a = 0; a < n; a++) C[a * n + a] = c[a];
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  for (PetscInt a = 0; a < n; a++) Q[a] = 0;
  for (PetscInt q = 0; q < rule->n; q++) {
    TslMaterialPoint mp;
    PetscReal        theta = 0, c, e;
    PetscCheck(TslElementPointEvaluate(in->type, in->sec, in->x, rule->xi[q], rule->w[q], &p), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
               "Inverted %s element", in->type->name);
    for (PetscInt b = 0; b < n; b++) theta += p.N[b] * in->u[ndof * b + th];
    e = TslMaterialHeatContent(in->sec->mat, theta, &c);
    TslMaterialEval(in->sec->mat, theta, &mp);
    for (PetscInt a = 0; a < n; a++) {
      Q[a] += p.N[a] * mp.rho * e * p.dV;
      if (C)
        for (PetscInt b = 0; b < n; b++) C[a * n + b] += p.N[a] * mp.rho * c * p.N[b] * p.dV;
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscBool TslElementCapacityConsistent(const TslElementType *t)
{
  return (PetscBool)(t->form->consistent_capacity && t->geom->order >= 2);
}

/* One face integration point: shape values of the face nodes, position, and the outward normal
 * scaled by the area element, n dA (2D: (dy, -dx) dxi times t or 2 pi r; 3D: x_xi x x_eta dxi deta). */
typedef struct {
  PetscReal N[TSL_MAX_FACE_NODES];
  PetscReal x[3];
  PetscReal ndA[3];
  PetscReal dA;
} FacePoint;

static void FacePointEvaluate(const TslElementInput *in, PetscInt face, const TslFaceRule *rule, PetscInt q, FacePoint *fp)
{
  const TslGeometry             *g = in->type->geom, *fg = g->face_geom[face];
  const struct TslKinematicsRow *info = TslKinematicsRowGet(in->type->kin);
  const PetscInt                 fn = g->face_nnode[face], fdim = fg->dim;
  PetscReal                      T[2][3] = {{0}}, scale = rule->w[q];

  for (PetscInt d = 0; d < 3; d++) fp->x[d] = 0;
  for (PetscInt f = 0; f < fn; f++) {
    const PetscReal *xa = &in->x[3 * g->face_node[face][f]];
    fp->N[f]            = rule->N[q][f];
    for (PetscInt d = 0; d < 3; d++) {
      fp->x[d] += fp->N[f] * xa[d];
      for (PetscInt j = 0; j < fdim; j++) T[j][d] += rule->dN[q][f][j] * xa[d];
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
  if (info->thickness) scale *= in->sec->thickness > 0 ? in->sec->thickness : 1.0;
  if (info->revolve) scale *= 2 * PETSC_PI * fp->x[0];
  for (PetscInt d = 0; d < 3; d++) fp->ndA[d] *= scale;
  fp->dA = PetscSqrtReal(fp->ndA[0] * fp->ndA[0] + fp->ndA[1] * fp->ndA[1] + fp->ndA[2] * fp->ndA[2]);
}

/* A follower pressure's load stiffness at face point q of the deformed face (in->x current): K_(a i)(b d) +=
 * N_a p d(n dA)_i / du_(b d). 2D: n dA = s (T_y, -T_x), T = sum_b dN_b x_b, s = w t or w 2 pi r (r current);
 * 3D: n dA = w T_1 x T_2. */
static void FollowerStiffness(const TslElementInput *in, PetscInt face, const TslFaceRule *rule, PetscInt q, const FacePoint *fp, PetscReal p,
                              PetscReal K[])
{
  const TslGeometry             *g    = in->type->geom;
  const struct TslKinematicsRow *info = TslKinematicsRowGet(in->type->kin);
  const PetscInt                 ndof = in->type->ndof, dim = in->type->dim, nd = TslElementTypeNodes(in->type) * ndof, fn = g->face_nnode[face];
  const PetscInt                *node = g->face_node[face];
  PetscReal                      T[2][3] = {{0}};

  for (PetscInt f = 0; f < fn; f++)
    for (PetscInt j = 0; j < dim - 1; j++)
      for (PetscInt d = 0; d < 3; d++) T[j][d] += rule->dN[q][f][j] * in->x[3 * node[f] + d];
  for (PetscInt b = 0; b < fn; b++)
    for (PetscInt d = 0; d < dim; d++) {
      PetscReal dn[3] = {0, 0, 0}; /* d(n dA) / du_(b d) */
      if (dim == 2) {
        const PetscReal s  = rule->w[q] * (info->thickness && in->sec->thickness > 0 ? in->sec->thickness : 1) * (info->revolve ? 2 * PETSC_PI * fp->x[0] : 1);
        const PetscReal dN = rule->dN[q][b][0];
        if (d == 1) dn[0] = s * dN;
        if (d == 0) dn[1] = -s * dN;
        if (info->revolve && d == 0)
          for (PetscInt i = 0; i < 2; i++) dn[i] += fp->ndA[i] * fp->N[b] / fp->x[0];
      } else {
        const PetscReal a1 = rule->dN[q][b][0], a2 = rule->dN[q][b][1], w = rule->w[q];
        PetscReal       e[3] = {0, 0, 0};
        e[d]  = 1;
        dn[0] = w * (a1 * (e[1] * T[1][2] - e[2] * T[1][1]) + a2 * (T[0][1] * e[2] - T[0][2] * e[1]));
        dn[1] = w * (a1 * (e[2] * T[1][0] - e[0] * T[1][2]) + a2 * (T[0][2] * e[0] - T[0][0] * e[2]));
        dn[2] = w * (a1 * (e[0] * T[1][1] - e[1] * T[1][0]) + a2 * (T[0][0] * e[1] - T[0][1] * e[0]));
      }
      for (PetscInt a = 0; a < fn; a++)
        for (PetscInt i = 0; i < dim; i++) K[(ndof * node[a] + i) * nd + ndof * node[b] + d] += fp->N[a] * p * dn[i];
    }
}

/* Body heat source, consistent: R_theta(a) -= int N_a q dV with the family's full rule (the conduction's
 * points), in every formulation; returns int q dV = sum_a of the loads, since sum_a N_a = 1. Not the
 * capacity's lumping weights: HRZ (quad8) and the linear sub-elements (tri6, tet10) are not the
 * integrals of the quadratic N_a, and with them the second-order types fell to L2 rate 2 and H1 rate 1
 * under a source (tests/element/body_convergence.c). A uniform q gives zero (tri6) or negative (quad8,
 * tet10) corner loads; no condition asks positive weights of a heat load (the capacity's must be, and
 * stay lumped). Nothing is added to R for an inverted element (TslElementInternal reports it). */
static PetscReal BodyFlux(const TslElementInput *in, PetscReal q, PetscReal R[])
{
  const TslGeometry *g    = in->type->geom;
  const PetscInt     ndof = in->type->ndof, th = ndof - 1;
  PetscReal          heat = 0, load[TSL_MAX_ELEM_NODES] = {0};
  TslElementPoint    p;

  for (PetscInt k = 0; k < g->full.n; k++) {
    if (!TslElementPointEvaluate(in->type, in->sec, in->x, g->full.xi[k], g->full.w[k], &p)) return 0;
    for (PetscInt a = 0; a < g->nnode; a++) load[a] += p.N[a] * q * p.dV;
    heat += q * p.dV;
  }
  for (PetscInt a = 0; a < g->nnode; a++) R[ndof * a + th] -= load[a];
  return heat;
}

/* Body forces (element.h): the acceleration b at each point of the full rule, times rho at the point's initial
 * temperature and N_a dV. The full rule integrates N_a dV exactly on an undistorted element of any family, so a
 * uniform gravity gives the element's weight to rounding in every formulation, reduced ones included (their
 * mechanical points would do as well for the sum, not for its split among the nodes of a quadratic family). */
PetscErrorCode TslElementBodyForce(const TslElementInput *in, TslFaceLoadKind kind, PetscReal value, const PetscReal axis[6], PetscReal R[],
                                   PetscReal force[3])
{
  const TslGeometry *g    = in->type->geom;
  const PetscInt     ndof = in->type->ndof, dim = in->type->dim;
  PetscReal          total[3] = {0, 0, 0};
  TslElementPoint    p;

  PetscFunctionBeginUser;
  PetscCheck(TslFaceLoadKindIsBodyForce(kind), PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Not a body force: kind %d", (int)kind);
  for (PetscInt k = 0; k < g->full.n; k++) {
    TslMaterialPoint mp;
    PetscReal        b[3];

    if (!TslElementPointEvaluate(in->type, in->sec, in->x, g->full.xi[k], g->full.w[k], &p)) break;
    if (kind == TSL_BODY_GRAV)
      for (PetscInt i = 0; i < 3; i++) b[i] = value * axis[i];
    else {
      PetscReal r[3], along = 0;
      for (PetscInt i = 0; i < 3; i++) r[i] = p.x[i] - axis[i], along += r[i] * axis[3 + i];
      for (PetscInt i = 0; i < 3; i++) b[i] = value * (r[i] - along * axis[3 + i]);
    }
    TslMaterialEval(in->sec->mat, PointInitialTheta(in, &p), &mp);
    for (PetscInt i = 0; i < dim; i++) {
      const PetscReal f = mp.rho * b[i] * p.dV;
      for (PetscInt a = 0; a < g->nnode; a++) R[ndof * a + i] -= p.N[a] * f;
      total[i] += f;
    }
  }
  if (force)
    for (PetscInt i = 0; i < 3; i++) force[i] = total[i];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Face loads on the reference configuration (small strain), with n the outward unit normal:
 *   pressure p (pushes inward, traction -p n):  R_u(a)     += int N_a p n dA
 *   flux q into the body:                       R_theta(a) -= int N_a q dA,            heat = int q dA
 *   film h, sink:                               R_theta(a) += int N_a h (theta - sink) dA,
 *                                               K_ab       += int h N_a N_b dA,        heat = -int h (theta - sink) dA
 *   radiation c = sigma eps, ambient theta_a:   R_theta(a) += int N_a q_r dA,  q_r = c [(theta - theta_Z)^4 - (theta_a - theta_Z)^4],
 *                                               K_ab       += int 4 c (theta - theta_Z)^3 N_a N_b dA,   heat = -int q_r dA
 *   body flux q per volume:                     R_theta(a) -= int N_a q dV,            heat = int q dV
 * theta is the face's interpolated temperature at the point, so the radiation's K is the exact derivative of its
 * R (the Stefan-Boltzmann law in absolute temperature, theta_Z = *PHYSICAL CONSTANTS, ABSOLUTE ZERO; the
 * CalculiX manual's *RADIATE, Abaqus's "Thermal loads"). The points are the formulation's face rules: for
 * flux, film and radiation the face family's own shape functions with a rule exact for h N_a N_b (the
 * radiation's quartic is integrated by the same points, not exactly: it converges with the mesh as the
 * temperature does); for pressure the same, or the linear sub-faces of a modified element, whose nodal
 * weights are all positive. The body flux takes the family's full rule, as conduction does. */
PetscErrorCode TslElementFaceLoad(const TslElementInput *in, TslFaceLoadKind kind, PetscInt face, const TslFaceLoadValue *v, PetscReal R[],
                                  PetscReal K[], PetscReal *heat)
{
  const TslGeometry *g    = in->type->geom;
  const PetscInt     ndof = in->type->ndof, dim = in->type->dim, th = ndof - 1, nd = TslElementTypeNodes(in->type) * ndof;
  const PetscReal    value = v->value;
  const PetscBool    follow = kind == TSL_FACE_PRESSURE && in->nlgeom && ndof > 1 ? PETSC_TRUE : PETSC_FALSE;
  PetscReal          total = 0, xc[TSL_MAX_ELEM_NODES * 3];
  TslFaceRule        rule;
  TslElementInput    cur;

  PetscFunctionBeginUser;
  if (kind == TSL_BODY_FLUX) {
    total = BodyFlux(in, value, R);
    if (heat) *heat = total;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCheck(face >= 1 && face <= g->nface, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "Face S%" PetscInt_FMT " out of range 1..%" PetscInt_FMT " for %s", face, g->nface, in->type->name);
  face--;
  if (kind == TSL_FACE_PRESSURE)
    in->type->form->pressure_face_rule(g, face, &rule);
  else
    in->type->form->thermal_face_rule(g, face, &rule);
  if (follow) { /* finite strain: the pressure acts on the deformed face (x + u; a twist's phi is no coordinate) */
    cur = *in;
    for (PetscInt a = 0; a < g->nnode; a++)
      for (PetscInt d = 0; d < 3; d++) xc[3 * a + d] = in->x[3 * a + d] + (d < dim ? in->u[ndof * a + d] : 0);
    cur.x = xc;
  }
  for (PetscInt q = 0; q < rule.n; q++) {
    const PetscInt *node = g->face_node[face];
    const PetscInt  fn   = g->face_nnode[face];
    FacePoint       fp;
    PetscReal       theta = 0, drive = 0, dq = 0;

    FacePointEvaluate(follow ? &cur : in, face, &rule, q, &fp);
    switch (kind) {
    case TSL_FACE_PRESSURE:
      for (PetscInt f = 0; f < fn; f++)
        for (PetscInt i = 0; i < dim; i++) R[ndof * node[f] + i] += fp.N[f] * value * fp.ndA[i];
      if (follow && K) FollowerStiffness(&cur, face, &rule, q, &fp, value, K);
      break;
    case TSL_FACE_FLUX:
      for (PetscInt f = 0; f < fn; f++) R[ndof * node[f] + th] -= fp.N[f] * value * fp.dA;
      total += value * fp.dA;
      break;
    case TSL_FACE_FILM:
    case TSL_FACE_RADIATION:
      for (PetscInt f = 0; f < fn; f++) theta += fp.N[f] * in->u[ndof * node[f] + th];
      /* q_out = value drive, d q_out / d theta = dq */
      if (kind == TSL_FACE_FILM) {
        drive = theta - v->sink;
        dq    = value;
      } else {
        const PetscReal ta = theta - v->zero, tsa = v->sink - v->zero;
        drive = ta * ta * ta * ta - tsa * tsa * tsa * tsa;
        dq    = 4 * value * ta * ta * ta;
      }
      for (PetscInt f = 0; f < fn; f++) {
        const PetscInt row = ndof * node[f] + th;
        R[row] += fp.N[f] * value * drive * fp.dA;
        if (K)
          for (PetscInt e = 0; e < fn; e++) K[row * nd + ndof * node[e] + th] += dq * fp.N[f] * fp.N[e] * fp.dA;
      }
      total -= value * drive * fp.dA;
      break;
    default:
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Unknown face load kind %d", (int)kind);
    }
  }
  if (heat) *heat = total;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Averages over the mechanical points of sigma and eps, over the full rule of -k grad theta; the strain
 * energy int 1/2 sigma : eps_mech dV and the hourglass energy. Plane stress reports the out-of-plane
 * strain that makes sigma_33 = 0 with the full isotropic D:
 *   eps_33 = eps_th - lambda (eps_11 + eps_22 - 2 eps_th) / (lambda + 2 mu). */
PetscErrorCode TslElementOutput(const TslElementInput *in, TslElementResult *res)
{
  const TslElementType *t   = in->type;
  const TslGeometry    *g   = t->geom;
  const PetscInt        dim = t->dim, ndof = t->ndof, th = ndof - 1;
  PetscReal             R[TSL_MAX_ELEM_DOF];
  Hybrid                hy;
  TslElementPoint       p;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(res, sizeof(*res)));
  for (PetscInt i = 0; i < TslElementTypeNodes(t) * ndof; i++) R[i] = 0;
  PetscCheck(Mechanics(in, NULL, R, NULL, &hy, res, NULL), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "Inverted %s element", t->name);
  /* a plastic point's eps_33 is its return's (MechanicsPlastic); finite strain's the logarithm of its F_33 (FiniteOutput) */
  if (TslKinematicsRowGet(t->kin)->free_normal && !in->pstate && !(in->nlgeom && !t->form->incompatible)) {
    const TslQuadrature *quad = t->form->quadrature(g, in->sec);
    res->E[2]                 = 0;
    for (PetscInt q = 0; q < quad->n; q++) {
      MechPoint mq;
      PetscReal ratio;
      (void)MechPointEvaluate(in, quad->xi[q], quad->w[q], NULL, PETSC_FALSE, &mq);
      ratio = mq.mp.nu / (1 - mq.mp.nu); /* lambda / (lambda + 2 mu) */
      res->E[2] += (mq.eps_th - ratio * (mq.eps[0] + mq.eps[1] - 2 * mq.eps_th)) / quad->n;
    }
  }
  for (PetscInt q = 0; q < g->full.n; q++) {
    TslMaterialPoint mp;
    PetscCheck(TslElementPointEvaluate(t, in->sec, in->x, g->full.xi[q], g->full.w[q], &p), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
               "Inverted %s element", t->name);
    TslMaterialEval(in->sec->mat, NodalTheta(in, p.N, in->u), &mp);
    for (PetscInt a = 0; a < g->nnode; a++)
      for (PetscInt d = 0; d < dim; d++) res->HFL[d] -= mp.k * p.dNdx[a][d] * in->u[ndof * a + th] / g->full.n;
  }
  PetscCall(Hourglass(in, R, NULL, &res->hourglass_energy));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Bulk viscosity (explicit steps, *BULK VISCOSITY; Abaqus Analysis User's Guide, "Bulk viscosity"): at the
 * element centre the pressure (positive in tension, as the strain rate)
 *   p = b1 rho c_d L_e eps_vol_dot + rho (b2 L_e)^2 |eps_vol_dot| min(0, eps_vol_dot),
 * the quadratic term only in compression, with eps_vol_dot the volumetric strain rate of the nodal velocities
 * v[] (laid out as in->u; temperature slots ignored). With L_e = c_d dt_e (dt_e the element's own stable
 * increment, so no characteristic length is guessed) both terms are multiples of M = lambda + 2 mu = rho c_d^2:
 *   p = M (eta1 eps_vol_dot - eta2 eps_vol_dot^2 [eps_vol_dot < 0]),  eta1 = b1 dt_e,  eta2 = (b2 dt_e)^2.
 * Its nodal forces p int B_vol dV (one point: the centre) are added to R, and *power = p eps_vol_dot V
 * = M (eta1 eps^2 + eta2 |eps|^3 [compression]) V >= 0 is what it dissipates. */
PetscErrorCode TslElementBulkViscosity(const TslElementInput *in, const PetscReal v[], PetscReal eta1, PetscReal eta2, PetscReal R[],
                                       PetscReal *power, PetscReal qr[2])
{
  const TslElementType *t = in->type;
  const TslGeometry    *g = t->geom;
  const PetscInt        ndof = t->ndof, nu = ndof - 1, n = TslElementTypeNodes(t);
  PetscReal             xi[3], B[6][TSL_MAX_ELEM_NODES * 3], M, rate = 0, p;
  TslElementPoint       pt;
  TslMaterialPoint      mp;

  PetscFunctionBeginUser;
  *power = 0;
  TslElementCentre(g, xi);
  PetscCheck(TslElementPointEvaluate(t, in->sec, in->x, xi, g->ref_volume, &pt), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "Inverted %s element", t->name);
  TslMaterialEval(in->sec->mat, NodalTheta(in, pt.N, in->u), &mp);
  M = TslElementWaveModulus(t, &mp);
  if (in->nlgeom) { /* finite strain: the rate J'/J of the current volume, dJ/du_c = J tr(F^-1 dF_c), and p J on it */
    PetscReal         H[3][3], F[3][3], Fi[3][3], J, g[TSL_MAX_ELEM_NODES * 3];
    TslGradientColumn col[TSL_MAX_ELEM_NODES * 3];
    TslElementDeformation(t, in->sec, in->x, &pt, in->u, H, col);
    for (PetscInt i = 0; i < 3; i++)
      for (PetscInt j = 0; j < 3; j++) F[i][j] = (i == j) + H[i][j];
    J = Det3(F);
    PetscCheck(J > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "%s element turned inside out (det F <= 0)", t->name);
    for (PetscInt i = 0; i < 3; i++)
      for (PetscInt j = 0; j < 3; j++) /* the cofactors over J */
        Fi[j][i] = (F[(i + 1) % 3][(j + 1) % 3] * F[(i + 2) % 3][(j + 2) % 3] - F[(i + 1) % 3][(j + 2) % 3] * F[(i + 2) % 3][(j + 1) % 3]) / J;
    for (PetscInt a = 0; a < n; a++)
      for (PetscInt i = 0; i < nu; i++) {
        const PetscInt c = nu * a + i;
        g[c]             = 0;
        for (PetscInt k = 0; k < col[c].n; k++) g[c] += J * col[c].v[k] * Fi[col[c].k[k]][col[c].i[k]];
        rate += g[c] * v[ndof * a + i] / J;
      }
    p = eta1 * M * rate;
    if (rate < 0) p -= eta2 * M * rate * rate;
    for (PetscInt a = 0; a < n; a++)
      for (PetscInt i = 0; i < nu; i++) R[ndof * a + i] += p * g[nu * a + i] * pt.dV;
    *power = p * rate * J * pt.dV;
    if (qr) qr[0] = p * J * pt.dV, qr[1] = rate;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  TslElementStrainMatrix(t, in->sec, in->x, &pt, B);
  for (PetscInt a = 0; a < n; a++)
    for (PetscInt i = 0; i < nu; i++)
      for (PetscInt r = 0; r < 3; r++) rate += B[r][nu * a + i] * v[ndof * a + i];
  p = eta1 * M * rate;
  if (rate < 0) p -= eta2 * M * rate * rate;
  for (PetscInt a = 0; a < n; a++)
    for (PetscInt i = 0; i < nu; i++)
      for (PetscInt r = 0; r < 3; r++) R[ndof * a + i] += p * B[r][nu * a + i] * pt.dV;
  *power = p * rate * pt.dV;
  if (qr) qr[0] = p * pt.dV, qr[1] = rate;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The displacement gradient H at the element's centre (TslElementDeformation: the kinematics' own, hoop and twist
 * included); PETSC_FALSE for an inverted element. */
static PetscBool CentreGradient(const TslElementInput *in, PetscReal H[3][3])
{
  const TslElementType *t = in->type;
  PetscReal             xi[3];
  TslElementPoint       pt;
  TslGradientColumn     col[TSL_MAX_ELEM_NODES * 3];

  TslElementCentre(t->geom, xi);
  if (!TslElementPointEvaluate(t, in->sec, in->x, xi, t->geom->ref_volume, &pt)) return PETSC_FALSE;
  TslElementDeformation(t, in->sec, in->x, &pt, in->u, H, col);
  return PETSC_TRUE;
}

PetscBool TslElementCentreStretch(const TslElementInput *in, PetscReal C[6])
{
  PetscReal H[3][3], F[3][3];

  if (!CentreGradient(in, H)) return PETSC_FALSE;
  for (PetscInt i = 0; i < 3; i++)
    for (PetscInt j = 0; j < 3; j++) F[i][j] = (i == j) + H[i][j];
  for (PetscInt r = 0; r < 6; r++) {
    const PetscInt K = VoigtI[r], L = VoigtJ[r];
    C[r]             = 0;
    for (PetscInt i = 0; i < 3; i++) C[r] += F[i][K] * F[i][L];
  }
  return Det3(F) > 0 ? PETSC_TRUE : PETSC_FALSE;
}

PetscBool TslElementCentreRotation(const TslElementInput *in, PetscReal *theta)
{
  PetscReal H[3][3], s = 0;

  *theta = 0;
  if (in->type->ndof < 2) return PETSC_TRUE; /* a heat-transfer type: nothing turns */
  if (!CentreGradient(in, H)) return PETSC_FALSE;
  /* F = I + H: |axial(F - F^T)| / 2 = sin theta and (tr F - 1) / 2 = cos theta for a rotation by theta */
  for (PetscInt i = 0; i < 3; i++)
    for (PetscInt j = i + 1; j < 3; j++) s += 0.25 * (H[i][j] - H[j][i]) * (H[i][j] - H[j][i]);
  *theta = PetscAtan2Real(PetscSqrtReal(s), 1 + 0.5 * (H[0][0] + H[1][1] + H[2][2]));
  return PETSC_TRUE;
}
