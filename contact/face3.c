/* Face families of 3D contact surfaces (tri3, quad4, tri6): the catalogue's 2D geometries seen as faces
 * of 3D elements, on their own reference coordinates (quads [-1,1]^2, triangles the unit triangle). The
 * closest point on a face, its normal, bounding box and tributary weights, and the 2D Newton solver
 * that the projections of face3.c and kernel3.c share. Formulas: docs/contact.md, "3D node-to-surface". */
#include "contact_impl.h"
#include "../src/element/element_impl.h"

/* Distance from the edges in units of the face, for the normal smoothing: the nearer of the two edges
 * xi_i = +-1, (1 - |xi_i|)/2, per direction of a quad; the three barycentric coordinates of a triangle
 * (the distance from the edge opposite each corner over that corner's height). */
static PetscInt QuadEdgeDistance(const TslDual xi[2], TslDual d[3])
{
  for (PetscInt i = 0; i < 2; i++) d[i] = DScale(0.5, xi[i].v >= 0 ? DAddC(DScale(-1, xi[i]), 1) : DAddC(xi[i], 1));
  return 2;
}

static PetscInt TriEdgeDistance(const TslDual xi[2], TslDual d[3])
{
  d[0] = DAddC(DScale(-1, DAdd(xi[0], xi[1])), 1);
  d[1] = xi[0];
  d[2] = xi[1];
  return 3;
}

static const TslContactFace3 Faces[] = {
    {&TslGeomTri3, {1.0 / 3, 1.0 / 3}, 1, 0, 1, 1, PETSC_TRUE, TriEdgeDistance, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}},
    {&TslGeomQuad4, {0, 0}, 2, -1, 1, PETSC_MAX_REAL, PETSC_FALSE, QuadEdgeDistance, {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}},
    /* the edge control points of a quadratic triangle are 2 x_m - (x_a + x_b)/2, m the midside node of edge (a, b) */
    {&TslGeomTri6,
     {1.0 / 3, 1.0 / 3},
     1,
     0,
     1,
     1,
     PETSC_FALSE,
     TriEdgeDistance,
     {{1, 0, 0, 0, 0, 0}, {0, 1, 0, 0, 0, 0}, {0, 0, 1, 0, 0, 0}, {-0.5, -0.5, 0, 2, 0, 0}, {0, -0.5, -0.5, 0, 2, 0}, {-0.5, 0, -0.5, 0, 0, 2}}},
};
#define NFACE3 ((PetscInt)(sizeof(Faces) / sizeof(Faces[0])))

const TslContactFace3 *TslContactFace3Get(PetscInt kind)
{
  return kind >= 0 && kind < NFACE3 ? &Faces[kind] : NULL;
}

PetscInt TslContactFace3Find(const char *name)
{
  for (PetscInt k = 0; k < NFACE3; k++) {
    PetscBool same;
    PetscCallAbort(PETSC_COMM_SELF, PetscStrcasecmp(name, Faces[k].geom->name, &same));
    if (same) return k;
  }
  return -1;
}

PetscInt TslContactFace3Nodes(PetscInt kind)
{
  return kind >= 0 && kind < NFACE3 ? Faces[kind].geom->nnode : 0;
}

static PetscErrorCode FaceGet(PetscInt kind, const TslContactFace3 **f)
{
  PetscFunctionBeginUser;
  *f = TslContactFace3Get(kind);
  PetscCheck(*f, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Unknown 3D contact face family %d", (int)kind);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Second derivatives, which TslGeometry does not give, by the central difference of dN with a unit step
 * in each reference coordinate: exact (to round-off) while dN is a polynomial of degree <= 2 in it. For the
 * three families dN is of degree <= 1 in each coordinate (tri3 constant, quad4 bilinear, tri6 linear), so the
 * second derivatives are constants: they are taken once per family at the reference origin, where the
 * differences evaluate the shape functions at integer points (exactly), and checked at a second point; a
 * family whose second derivatives vary (none today) is differenced at every point. The projection's Newton
 * iterations evaluated the shape functions five times per call for them. */
static void Difference(const TslGeometry *g, const PetscReal xi[2], PetscReal d2N[][2][2])
{
  PetscReal z[3], Nz[TSL_MAX_ELEM_NODES], dp[TSL_MAX_ELEM_NODES * 3], dm[TSL_MAX_ELEM_NODES * 3];

  for (PetscInt j = 0; j < 2; j++) {
    z[0] = xi[0], z[1] = xi[1], z[2] = 0;
    z[j] = xi[j] + 1;
    g->shape(z, Nz, dp);
    z[j] = xi[j] - 1;
    g->shape(z, Nz, dm);
    for (PetscInt a = 0; a < g->nnode; a++)
      for (PetscInt i = 0; i < 2; i++) d2N[a][i][j] = 0.5 * (dp[2 * a + i] - dm[2 * a + i]);
  }
}

void TslContactFace3Shape(const TslContactFace3 *face, const PetscReal xi[2], PetscReal N[], PetscReal dN[][2], PetscReal d2N[][2][2])
{
  static PetscReal   D2[NFACE3][TSL_CONTACT3_MAX_FACE_NODES][2][2];
  static PetscInt    known[NFACE3]; /* 0 not yet, 1 constant (D2), 2 varies */
  const TslGeometry *g    = face->geom;
  const PetscInt     k    = (PetscInt)(face - Faces);
  PetscReal          z[3] = {xi[0], xi[1], 0}, d[TSL_MAX_ELEM_NODES * 3];

  g->shape(z, N, d);
  for (PetscInt a = 0; a < g->nnode; a++)
    for (PetscInt i = 0; i < 2; i++) dN[a][i] = d[2 * a + i];
  if (!known[k]) {
    const PetscReal origin[2] = {0, 0}, other[2] = {0.3, 0.2};
    PetscReal       e[TSL_CONTACT3_MAX_FACE_NODES][2][2];
    Difference(g, origin, D2[k]);
    Difference(g, other, e);
    known[k] = 1;
    for (PetscInt a = 0; a < g->nnode; a++)
      for (PetscInt i = 0; i < 2; i++)
        for (PetscInt j = 0; j < 2; j++)
          if (PetscAbsReal(e[a][i][j] - D2[k][a][i][j]) > 1e-12) known[k] = 2;
  }
  if (known[k] == 2)
    Difference(g, xi, d2N);
  else
    for (PetscInt a = 0; a < g->nnode; a++)
      for (PetscInt i = 0; i < 2; i++)
        for (PetscInt j = 0; j < 2; j++) d2N[a][i][j] = D2[k][a][i][j];
}

void TslContactFace3ShapeValues(PetscInt kind, const PetscReal xi[2], PetscReal N[])
{
  const TslContactFace3 *f    = TslContactFace3Get(kind);
  PetscReal              z[3] = {xi[0], xi[1], 0}, d[TSL_MAX_ELEM_NODES * 3];
  if (f) f->geom->shape(z, N, d);
}

/* x = x_1 + sum_{a>1} N_a (x_a - x_1) (sum N_a = 1), a_alpha = sum_{a>1} dN_a/dxi_alpha (x_a - x_1): differences
 * of nearby nodes, and the tangents of a flat tri3 are exactly its edge vectors (as the 2D faces). */
void TslContactFace3PointDual(const TslContactFace3 *face, const TslDual x[][3], const TslDual xi[2], TslDual p[3], TslDual a[2][3], TslDual N[])
{
  PetscReal Nv[TSL_CONTACT3_MAX_FACE_NODES], dN[TSL_CONTACT3_MAX_FACE_NODES][2], d2N[TSL_CONTACT3_MAX_FACE_NODES][2][2], xv[2] = {xi[0].v, xi[1].v};

  TslContactFace3Shape(face, xv, Nv, dN, d2N);
  for (PetscInt d = 0; d < 3; d++) {
    p[d]    = x[0][d];
    a[0][d] = a[1][d] = DConst(0);
  }
  for (PetscInt b = 0; b < face->geom->nnode; b++) {
    TslDual Nb = DChain2(xi[0], xi[1], Nv[b], dN[b][0], dN[b][1]), dNb[2];

    if (N) N[b] = Nb;
    if (b == 0) continue;
    for (PetscInt i = 0; i < 2; i++) dNb[i] = DChain2(xi[0], xi[1], dN[b][i], d2N[b][i][0], d2N[b][i][1]);
    for (PetscInt d = 0; d < 3; d++) {
      TslDual e = DSub(x[b][d], x[0][d]);

      DAccMul(&p[d], &Nb, &e);
      for (PetscInt i = 0; i < 2; i++) DAccMul(&a[i][d], &dNb[i], &e);
    }
  }
}

/* Zero derivatives but in the slot when it is one the variant carries. */
static inline void SetSlot(TslDual *r, PetscInt slot, PetscReal v)
{
  if (slot >= 0 && slot < TSL_DUAL_N) r->d[slot] = v;
}

void TslContactFace3PointSeeded(const TslContactFace3 *face, const PetscReal x[][3], PetscInt slot0, const PetscReal xi[2], PetscBool seed,
                                TslDual p[3], TslDual a[2][3], TslDual N[])
{
  const PetscInt nn = face->geom->nnode;
  PetscReal      Nv[TSL_CONTACT3_MAX_FACE_NODES], dN[TSL_CONTACT3_MAX_FACE_NODES][2], d2N[TSL_CONTACT3_MAX_FACE_NODES][2][2];

  TslContactFace3Shape(face, xi, Nv, dN, d2N);
  for (PetscInt b = 0; N && b < nn; b++) {
    N[b] = DConst(Nv[b]);
    if (seed) N[b].d[TSL_DUAL_XI] = dN[b][0], N[b].d[TSL_DUAL_ETA] = dN[b][1];
  }
  for (PetscInt d = 0; d < 3; d++) {
    TslDual  *q[3]  = {&p[d], &a[0][d], &a[1][d]};
    PetscReal s0[3] = {1, 0, 0};

    p[d] = DConst(x[0][d]), a[0][d] = DConst(0), a[1][d] = DConst(0);
    for (PetscInt b = 1; b < nn; b++) {
      const PetscReal e = x[b][d] - x[0][d], f[3] = {Nv[b], dN[b][0], dN[b][1]};
      for (PetscInt k = 0; k < 3; k++) { /* p, a_1, a_2: the values f_b e_b, the parameters' slots from the next derivatives */
        q[k]->v += f[k] * e;
        s0[k] -= f[k];
        SetSlot(q[k], slot0 < 0 ? -1 : slot0 + TSL_CONTACT3_NU * b + d, f[k]);
      }
      if (seed) {
        p[d].d[TSL_DUAL_XI] += dN[b][0] * e, p[d].d[TSL_DUAL_ETA] += dN[b][1] * e;
        for (PetscInt i = 0; i < 2; i++) a[i][d].d[TSL_DUAL_XI] += d2N[b][i][0] * e, a[i][d].d[TSL_DUAL_ETA] += d2N[b][i][1] * e;
      }
    }
    for (PetscInt k = 0; k < 3; k++) SetSlot(q[k], slot0 < 0 ? -1 : slot0 + d, s0[k]);
  }
}

void TslContactFace3PointAtSeeded(const TslContactFace3 *face, const PetscReal x[][3], PetscInt slot0, const PetscReal xi[2], TslDual p[3])
{
  PetscReal z[3] = {xi[0], xi[1], 0}, Nv[TSL_MAX_ELEM_NODES], dz[TSL_MAX_ELEM_NODES * 3];

  face->geom->shape(z, Nv, dz);
  for (PetscInt k = 0; k < 3; k++) {
    PetscReal s0 = 1;
    p[k]         = DConst(x[0][k]);
    for (PetscInt b = 1; b < face->geom->nnode; b++) {
      p[k].v += Nv[b] * (x[b][k] - x[0][k]);
      s0 -= Nv[b];
      SetSlot(&p[k], slot0 < 0 ? -1 : slot0 + TSL_CONTACT3_NU * b + k, Nv[b]);
    }
    SetSlot(&p[k], slot0 < 0 ? -1 : slot0 + k, s0);
  }
}

PetscBool TslContactSolve2(const PetscReal A[2][2], const PetscReal b[2], PetscReal x[2])
{
  PetscReal det = A[0][0] * A[1][1] - A[0][1] * A[1][0], scale = PetscAbsReal(A[0][0] * A[1][1]) + PetscAbsReal(A[0][1] * A[1][0]);

  if (!(PetscAbsReal(det) > 1e-14 * scale)) return PETSC_FALSE;
  x[0] = (A[1][1] * b[0] - A[0][1] * b[1]) / det;
  x[1] = (A[0][0] * b[1] - A[1][0] * b[0]) / det;
  return PETSC_TRUE;
}

/* Clamps xi to the band of one face size around the face; PETSC_TRUE when it was outside. */
static PetscBool ClampToBand(const TslContactFace3 *f, PetscReal xi[2])
{
  const PetscReal lo = f->lo - f->size, hi = f->hi + f->size, sum = f->sum + f->size;
  PetscBool       out = PETSC_FALSE;

  for (PetscInt i = 0; i < 2; i++)
    if (xi[i] < lo || xi[i] > hi) {
      xi[i] = PetscMax(lo, PetscMin(hi, xi[i]));
      out   = PETSC_TRUE;
    }
  if (xi[0] + xi[1] > sum) {
    PetscReal over = 0.5 * (xi[0] + xi[1] - sum);

    for (PetscInt i = 0; i < 2; i++) xi[i] = PetscMax(lo, xi[i] - over);
    out = PETSC_TRUE;
  }
  return out;
}

PetscErrorCode TslContactFace3Solve(const TslContactFace3 *face, TslContactFace3Function fn, void *ctx, PetscReal step, PetscReal tol,
                                    PetscReal xi[2], PetscBool *frozen)
{
  PetscBool converged = PETSC_FALSE;

  PetscFunctionBeginUser;
  *frozen = PETSC_FALSE;
  for (PetscInt it = 0; it < 100 && !converged; it++) {
    TslDual   F[2];
    PetscReal J[2][2], b[2], dx[2], len;

    PetscCall(fn(ctx, xi, F));
    for (PetscInt i = 0; i < 2; i++) {
      J[i][0] = F[i].d[TSL_DUAL_XI];
      J[i][1] = F[i].d[TSL_DUAL_ETA];
      b[i]    = -F[i].v;
    }
    /* F is minus the gradient of |x_s - x|^2 / 2 (or close to it): its Jacobian is minus a metric near the
     * face; where it is not (-J not positive definite, or singular) step down the gradient instead */
    if (!(-J[0][0] > 0 && J[0][0] * J[1][1] - J[0][1] * J[1][0] > 0 && TslContactSolve2(J, b, dx))) {
      PetscReal nF = PetscSqrtReal(F[0].v * F[0].v + F[1].v * F[1].v);

      PetscCheck(nF > 0, PETSC_COMM_SELF, PETSC_ERR_CONV_FAILED, "3D contact projection: singular Newton derivative at a stationary point");
      dx[0] = step * F[0].v / nF;
      dx[1] = step * F[1].v / nF;
    }
    len = PetscMax(PetscAbsReal(dx[0]), PetscAbsReal(dx[1]));
    if (len > step) {
      dx[0] *= step / len;
      dx[1] *= step / len;
    }
    xi[0] += dx[0];
    xi[1] += dx[1];
    if (ClampToBand(face, xi)) {
      /* far outside: the caller re-pairs, precision does not matter */
      *frozen   = PETSC_TRUE;
      converged = PETSC_TRUE;
    } else if (len < tol)
      converged = PETSC_TRUE;
  }
  PetscCheck(converged, PETSC_COMM_SELF, PETSC_ERR_CONV_FAILED, "3D contact projection did not converge (xi = %g, %g)", (double)xi[0], (double)xi[1]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscReal TslContactFace3Size(const TslContactFace3 *face, const PetscReal x[])
{
  PetscReal h2 = 0;

  for (PetscInt a = 1; a < face->geom->ncorner; a++) {
    PetscReal l2 = 0;
    for (PetscInt d = 0; d < 3; d++) l2 += (x[3 * a + d] - x[d]) * (x[3 * a + d] - x[d]);
    h2 = PetscMax(h2, l2);
  }
  return PetscSqrtReal(h2);
}

/* Node positions as constant duals relative to the first node. */
static void FaceNodes(const TslContactFace3 *f, const PetscReal x[], TslDual xd[][3])
{
  for (PetscInt a = 0; a < f->geom->nnode; a++)
    for (PetscInt d = 0; d < 3; d++) xd[a][d] = DConst(x[3 * a + d] - x[d]);
}

PetscErrorCode TslContactFace3Evaluate(PetscInt kind, const PetscReal x[], const PetscReal xi[], PetscReal p[], PetscReal n[])
{
  const TslContactFace3 *f;
  TslDual                xd[TSL_CONTACT3_MAX_FACE_NODES][3], pd[3], a[2][3], c[3], len, xv[2];

  PetscFunctionBeginUser;
#if !defined(TSL_DUAL_VALUES)
  PetscCall(TslContactFace3Evaluate_Values(kind, x, xi, p, n)); /* values alone (contact/values/) */
  PetscFunctionReturn(PETSC_SUCCESS);
#endif
  PetscCall(FaceGet(kind, &f));
  FaceNodes(f, x, xd);
  xv[0] = DConst(xi[0]);
  xv[1] = DConst(xi[1]);
  TslContactFace3PointDual(f, xd, xv, pd, a, NULL);
  DCross(a[0], a[1], c);
  len = DSqrt(DDot3(c, c));
  PetscCheck(len.v > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "3D contact face with a degenerate parametrisation (a1 x a2 = 0)");
  for (PetscInt d = 0; d < 3; d++) {
    if (p) p[d] = x[d] + pd[d].v;
    if (n) n[d] = c[d].v / len.v;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* F_alpha = (p - x(xi)) . a_alpha: minus the gradient of |p - x|^2 / 2, whose Jacobian is minus the Hessian
 * a_alpha . a_beta - (p - x) . a_alpha,beta (the second term through the duals of a). */
typedef struct {
  const TslContactFace3 *f;
  TslDual                x[TSL_CONTACT3_MAX_FACE_NODES][3];
  PetscReal              p[3];
} ClosestPoint;

static PetscErrorCode ClosestPointFunction(void *ctx, const PetscReal xi[2], TslDual F[2])
{
  ClosestPoint *cp    = (ClosestPoint *)ctx;
  TslDual       xv[2] = {DVar(xi[0], TSL_DUAL_XI), DVar(xi[1], TSL_DUAL_ETA)}, q[3], a[2][3], r[3];

  PetscFunctionBeginUser;
  TslContactFace3PointDual(cp->f, (const TslDual(*)[3])cp->x, xv, q, a, NULL);
  for (PetscInt d = 0; d < 3; d++) r[d] = DSub(DConst(cp->p[d]), q[d]);
  for (PetscInt i = 0; i < 2; i++) F[i] = DDot3(r, a[i]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactFace3Project(PetscInt kind, const PetscReal x[], const PetscReal p[], PetscReal xi[])
{
  ClosestPoint cp;
  PetscReal    h, dist2 = 0, tol;
  PetscBool    frozen;

  PetscFunctionBeginUser;
#if !defined(TSL_DUAL_VALUES)
  PetscCall(TslContactFace3Project_Values(kind, x, p, xi)); /* values alone (contact/values/) */
  PetscFunctionReturn(PETSC_SUCCESS);
#endif
  PetscCall(FaceGet(kind, &cp.f));
  FaceNodes(cp.f, x, cp.x);
  for (PetscInt d = 0; d < 3; d++) {
    cp.p[d] = p[d] - x[d];
    dist2 += cp.p[d] * cp.p[d];
  }
  h = TslContactFace3Size(cp.f, x);
  PetscCheck(h > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "3D contact face with coincident nodes");
  /* the round-off floor of xi, eps (|p - x_1| + h) / h in units of the face, times a thousand (as 2D) */
  tol   = 1e3 * PETSC_MACHINE_EPSILON * (1 + PetscSqrtReal(dist2) / h) * cp.f->size;
  xi[0] = cp.f->centre[0];
  xi[1] = cp.f->centre[1];
  /* an affine face (tri3) is one linear solve: no step limit, exact in one step */
  PetscCall(TslContactFace3Solve(cp.f, ClosestPointFunction, &cp, cp.f->affine ? PETSC_MAX_REAL : 0.25 * cp.f->size, tol, xi, &frozen));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscBool TslContactFace3Inside(PetscInt kind, const PetscReal xi[], PetscReal tol)
{
  const TslContactFace3 *f = TslContactFace3Get(kind);

  if (!f) return PETSC_FALSE;
  for (PetscInt i = 0; i < 2; i++)
    if (xi[i] < f->lo - tol || xi[i] > f->hi + tol) return PETSC_FALSE;
  return (PetscBool)(xi[0] + xi[1] <= f->sum + tol);
}

PetscErrorCode TslContactFace3Box(PetscInt kind, const PetscReal x[], PetscReal box[6])
{
  const TslContactFace3 *f;

  PetscFunctionBeginUser;
  PetscCall(FaceGet(kind, &f));
  for (PetscInt d = 0; d < 3; d++) {
    box[d]     = PETSC_MAX_REAL;
    box[d + 3] = -PETSC_MAX_REAL;
  }
  for (PetscInt i = 0; i < f->geom->nnode; i++)
    for (PetscInt d = 0; d < 3; d++) {
      PetscReal c = 0;
      for (PetscInt a = 0; a < f->geom->nnode; a++) c += f->hull[i][a] * x[3 * a + d];
      box[d]     = PetscMin(box[d], c);
      box[d + 3] = PetscMax(box[d + 3], c);
    }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscReal TslContactFace3HullBound(PetscInt kind)
{
  const TslContactFace3 *f = TslContactFace3Get(kind);
  PetscReal              b = 1;

  for (PetscInt i = 0; f && i < f->geom->nnode; i++) {
    PetscReal s = 0;
    for (PetscInt a = 0; a < f->geom->nnode; a++) s += PetscAbsReal(f->hull[i][a]);
    b = PetscMax(b, s);
  }
  return b;
}

/* |a1 x a2| at reference point xi (the area element), with the shape functions there. */
static PetscErrorCode AreaElement(const TslContactFace3 *f, const PetscReal x[], const PetscReal xi[], PetscReal N[], PetscReal *dA)
{
  PetscReal dN[TSL_CONTACT3_MAX_FACE_NODES][2], d2N[TSL_CONTACT3_MAX_FACE_NODES][2][2], a[2][3] = {{0}}, c[3];

  PetscFunctionBeginUser;
  TslContactFace3Shape(f, xi, N, dN, d2N);
  for (PetscInt b = 1; b < f->geom->nnode; b++)
    for (PetscInt i = 0; i < 2; i++)
      for (PetscInt d = 0; d < 3; d++) a[i][d] += dN[b][i] * (x[3 * b + d] - x[d]);
  c[0] = a[0][1] * a[1][2] - a[0][2] * a[1][1];
  c[1] = a[0][2] * a[1][0] - a[0][0] * a[1][2];
  c[2] = a[0][0] * a[1][1] - a[0][1] * a[1][0];
  *dA  = PetscSqrtReal(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  PetscCheck(*dA > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "3D contact face with a degenerate parametrisation (|a1 x a2| = 0)");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* w_a = int N_a dA with the family's as_face rule (exact for N_a N_b on a flat face: N_a |a1 x a2| is of that
 * degree). tri6: the weights of the linear subdivision (A_sub/3 to each node of each sub-triangle), since its
 * consistent corner weights are zero; the area is the tri6's own integral. */
PetscErrorCode TslContactFace3Integrate(PetscInt kind, const PetscReal x[], PetscReal w[], PetscReal *area)
{
  const TslContactFace3 *f;
  const TslQuadrature   *Q;
  PetscReal              total = 0;

  PetscFunctionBeginUser;
  PetscCall(FaceGet(kind, &f));
  Q = &f->geom->as_face;
  for (PetscInt a = 0; a < f->geom->nnode; a++) w[a] = 0;
  for (PetscInt q = 0; q < Q->n; q++) {
    PetscReal N[TSL_CONTACT3_MAX_FACE_NODES], dA;

    PetscCall(AreaElement(f, x, Q->xi[q], N, &dA));
    total += dA * Q->w[q];
    if (!f->geom->nsub)
      for (PetscInt a = 0; a < f->geom->nnode; a++) w[a] += N[a] * dA * Q->w[q];
  }
  for (PetscInt s = 0; s < f->geom->nsub; s++) {
    const PetscInt *v = f->geom->sub_node[s];
    PetscReal       e1[3], e2[3], c[3], As;

    for (PetscInt d = 0; d < 3; d++) {
      e1[d] = x[3 * v[1] + d] - x[3 * v[0] + d];
      e2[d] = x[3 * v[2] + d] - x[3 * v[0] + d];
    }
    c[0] = e1[1] * e2[2] - e1[2] * e2[1];
    c[1] = e1[2] * e2[0] - e1[0] * e2[2];
    c[2] = e1[0] * e2[1] - e1[1] * e2[0];
    As   = 0.5 * PetscSqrtReal(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    for (PetscInt i = 0; i < 3; i++) w[v[i]] += As / 3;
  }
  if (area) *area = total;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactStateStart3(PetscReal xi[], TslContactState *h)
{
  PetscFunctionBeginUser;
  h->xi_old = h->xi_anchor = xi[0];
  h->eta_old = h->eta_anchor = xi[1];
  h->lambda                  = 0;
  h->w_old = h->w_anchor = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactStateTransfer3(PetscInt kind_from, const PetscReal x_from[], PetscInt kind_to, const PetscReal x_to[], TslContactState *h)
{
  PetscReal *param[2][2] = {{&h->xi_old, &h->eta_old}, {&h->xi_anchor, &h->eta_anchor}};

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < 2; k++) {
    PetscReal xi[2] = {*param[k][0], *param[k][1]}, p[3];

    PetscCall(TslContactFace3Evaluate(kind_from, x_from, xi, p, NULL));
    PetscCall(TslContactFace3Project(kind_to, x_to, p, xi));
    *param[k][0] = xi[0];
    *param[k][1] = xi[1];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
