/* Surface-to-surface contact points: segmentation of a secondary face at the main surface's kinks, Gauss
 * rules on the pieces, and the node-to-segment kernel at a point expanded to the secondary face's nodes.
 * Interface and method: include/thermoslide/contact_s2s.h, docs/contact.md. */
#include <thermoslide/contact_s2s.h>

/* Gauss-Legendre on [0, 1] */
static const PetscReal G2x[2] = {0.21132486540518711775, 0.78867513459481288225}; /* (1 -+ sqrt(1/3))/2 */
static const PetscReal G2w[2] = {0.5, 0.5};
static const PetscReal G3x[3] = {0.11270166537925831148, 0.5, 0.88729833462074168852}; /* (1 -+ sqrt(3/5))/2 */
static const PetscReal G3w[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};

PetscInt TslContactSegmentGaussPoints(TslContactFaceKind kind)
{
  return kind == TSL_CONTACT_FACE_LINE2 ? 2 : 3;
}

PetscErrorCode TslContactSegmentBreaks(TslContactFaceKind kind, const PetscReal y[], PetscInt np, const PetscReal pts[], PetscReal tol, PetscInt cap,
                                       PetscReal zeta[], PetscInt *n)
{
  PetscInt m = 0;

  PetscFunctionBeginUser;
  PetscCheck(cap >= 2, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Break array too small");
  zeta[m++] = 0;
  zeta[m++] = 1;
  for (PetscInt i = 0; i < np; i++) {
    PetscReal z;
    PetscCall(TslContactFaceProject(kind, y, &pts[2 * i], &z));
    if (z > tol && z < 1 - tol) {
      PetscCheck(m < cap, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "More than %" PetscInt_FMT " break points on a secondary face", cap);
      zeta[m++] = z;
    }
  }
  PetscCall(PetscSortReal(m, zeta));
  *n = 1;
  for (PetscInt i = 1; i < m; i++) {
    if (zeta[i] - zeta[*n - 1] <= tol) {
      if (i == m - 1) zeta[*n - 1] = 1; /* the end wins over a point just before it */
      continue;
    }
    zeta[(*n)++] = zeta[i];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactSegmentRule(TslContactFaceKind kind, const PetscReal X[], PetscReal z0, PetscReal z1, PetscInt *nq, PetscReal zeta[],
                                     PetscReal w[])
{
  const PetscReal *gx = kind == TSL_CONTACT_FACE_LINE2 ? G2x : G3x, *gw = kind == TSL_CONTACT_FACE_LINE2 ? G2w : G3w;

  PetscFunctionBeginUser;
  *nq = TslContactSegmentGaussPoints(kind);
  for (PetscInt q = 0; q < *nq; q++) {
    PetscReal t[2];
    zeta[q] = z0 + gx[q] * (z1 - z0);
    PetscCall(TslContactFaceEvaluate(kind, X, zeta[q], NULL, t));
    w[q] = gw[q] * (z1 - z0) * PetscSqrtReal(t[0] * t[0] + t[1] * t[1]);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactPointSetUp(TslContactFaceKind kind, const PetscReal X[], const PetscReal U[], PetscReal zeta, TslContactInput *in)
{
  const TslContactFace *face = TslContactFaceGet(kind);
  const PetscInt        nu   = TslContactNodeUnknowns(in->kin);
  PetscReal             N[TSL_CONTACT_MAX_FACE_NODES], dN[TSL_CONTACT_MAX_FACE_NODES], d2N[TSL_CONTACT_MAX_FACE_NODES];

  PetscFunctionBeginUser;
  PetscCheck(face, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Unknown contact face family %d", (int)kind);
  TslContactFaceShape(face, zeta, N, dN, d2N);
  for (PetscInt d = 0; d < 2; d++) in->x[0][d] = 0;
  for (PetscInt c = 0; c < TSL_CONTACT_MAX_NODE_DOF; c++) in->u[0][c] = 0;
  for (PetscInt b = 0; b < face->geom->nnode; b++) {
    for (PetscInt d = 0; d < 2; d++) in->x[0][d] += N[b] * X[2 * b + d];
    for (PetscInt c = 0; c < nu; c++) in->u[0][c] += N[b] * U[nu * b + c];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactPointExpand(PetscInt nu, PetscInt nk, PetscInt nsn, const PetscReal N[], const PetscReal Rk[], const PetscReal Kk[], PetscReal R[],
                                     PetscReal K[])
{
  /* expanded dofs: the secondary face's nu*nsn (node b's unknown c is the virtual node's c with factor N_b), then
   * the kernel's own nu*(nk - 1) others; row and column blocks by the same rule, each product formed as
   * (N_b N_b') K_cc' so that the values are those of a factor table fac[ii] fac[jj] K */
  const PetscInt ns = nu * nsn, nkd = nu * nk, nm = nkd - nu, ne = ns + nm;

  PetscFunctionBeginUser;
  PetscCheck(ne <= TSL_CONTACT_S2S3_MAX_DOF, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Expanded contact element too large");
  if (R) {
    for (PetscInt b = 0; b < nsn; b++)
      for (PetscInt c = 0; c < nu; c++) R[nu * b + c] += N[b] * Rk[c];
    for (PetscInt i = 0; i < nm; i++) R[ns + i] += Rk[nu + i];
  }
  if (K) {
    for (PetscInt b = 0; b < nsn; b++)
      for (PetscInt c = 0; c < nu; c++) {
        PetscReal       *row = &K[(nu * b + c) * ne];
        const PetscReal *kr  = &Kk[c * nkd];
        for (PetscInt bb = 0; bb < nsn; bb++) {
          const PetscReal w = N[b] * N[bb];
          for (PetscInt cc = 0; cc < nu; cc++) row[nu * bb + cc] += w * kr[cc];
        }
        for (PetscInt j = 0; j < nm; j++) row[ns + j] += N[b] * kr[nu + j];
      }
    for (PetscInt i = 0; i < nm; i++) {
      PetscReal       *row = &K[(ns + i) * ne];
      const PetscReal *kr  = &Kk[(nu + i) * nkd];
      for (PetscInt bb = 0; bb < nsn; bb++)
        for (PetscInt cc = 0; cc < nu; cc++) row[nu * bb + cc] += N[bb] * kr[cc];
      for (PetscInt j = 0; j < nm; j++) row[ns + j] += kr[nu + j];
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactPointElement(const TslContactLaw *law, const TslContactInput *in, TslContactFaceKind kind, PetscReal zeta, PetscReal R[],
                                      PetscReal K[], TslContactOutput *out)
{
  const TslContactFace *face = TslContactFaceGet(kind);
  PetscReal             Rk[TSL_CONTACT_MAX_DOF], Kk[TSL_CONTACT_MAX_DOF * TSL_CONTACT_MAX_DOF], N[TSL_CONTACT_MAX_FACE_NODES];
  PetscReal             dN[TSL_CONTACT_MAX_FACE_NODES], d2N[TSL_CONTACT_MAX_FACE_NODES];
  TslContactOutput      o;
  PetscInt              nsn;

  PetscFunctionBeginUser;
  PetscCheck(face, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Unknown contact face family %d", (int)kind);
  PetscCall(TslContactElement(law, in, Rk, K ? Kk : NULL, &o));
  nsn = face->geom->nnode;
  TslContactFaceShape(face, zeta, N, dN, d2N);
  PetscCall(TslContactPointExpand(o.nu, o.nnode, nsn, N, Rk, K ? Kk : NULL, R, K));
  if (out) {
    *out       = o;
    out->nnode = nsn + o.nnode - 1;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
