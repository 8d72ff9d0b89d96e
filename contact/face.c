/* Face families of contact surfaces: the catalogue's face geometries seen on the segment parameter
 * 0 <= xi <= 1, the closest point on a face, its bounding box and the tributary weights of its nodes. */
#include "contact_impl.h"
/* TslGeomLine2, TslGeomLine3: the catalogue's face families, declared in the element module's header */
#include "../src/element/element_impl.h"

/* five-point Gauss-Legendre on [0, 1]: (1 +- x_k)/2 with weights w_k/2 */
#define G5A 0.45308992296933199640 /* sqrt(5 + 2 sqrt(10/7))/6 */
#define G5B 0.26923465505284154552 /* sqrt(5 - 2 sqrt(10/7))/6 */
#define W5A 0.11846344252809454376 /* (322 - 13 sqrt(70))/1800 */
#define W5B 0.23931433524968323402 /* (322 + 13 sqrt(70))/1800 */

static const TslContactFace Faces[TSL_CONTACT_FACE_NKINDS] = {
    /* one point: N_a is linear and |t| constant on a straight face */
    {&TslGeomLine2, 1, {0.5}, {1}, {{1, 0}, {0, 1}}},
    /* five points: exact while N_a |t| is a polynomial (straight faces, any midside position), and within
     * 1e-6 of the integral on an arc rising a quarter of its span (the three points of the geometry's own
     * rule: 4e-4); the middle control point of the Bernstein form is 2 x_3 - (x_1 + x_2)/2 */
    {&TslGeomLine3, 5, {0.5 - G5A, 0.5 - G5B, 0.5, 0.5 + G5B, 0.5 + G5A}, {W5A, W5B, 64.0 / 225, W5B, W5A}, {{1, 0, 0}, {0, 1, 0}, {-0.5, -0.5, 2}}},
};

const TslContactFace *TslContactFaceGet(TslContactFaceKind kind)
{
  if ((PetscInt)kind < 0 || kind >= TSL_CONTACT_FACE_NKINDS) return NULL;
  return &Faces[kind];
}

PetscInt TslContactFaceFind(const char *name)
{
  for (PetscInt k = 0; k < TSL_CONTACT_FACE_NKINDS; k++) {
    PetscBool same;
    PetscCallAbort(PETSC_COMM_SELF, PetscStrcasecmp(name, Faces[k].geom->name, &same));
    if (same) return k;
  }
  return -1;
}

/* The geometry's N(zeta), dN/dzeta at zeta = 2 xi - 1, so dN/dxi = 2 dN/dzeta. Second derivatives, which
 * TslGeometry does not give, by the central difference of dN with the step 1 in zeta: exact (to round-off)
 * for polynomials of degree <= 3, i.e. every family of order <= 3 (tests/contact/test_line3.c checks the
 * orders and the derivatives). */
void TslContactFaceShape(const TslContactFace *face, PetscReal xi, PetscReal N[], PetscReal dN[], PetscReal d2N[])
{
  const TslGeometry *g    = face->geom;
  PetscReal          z[3] = {2 * xi - 1, 0, 0}, Nz[TSL_MAX_ELEM_NODES], dp[TSL_MAX_ELEM_NODES], dm[TSL_MAX_ELEM_NODES];

  g->shape(z, N, dN);
  z[0] = 2 * xi;
  g->shape(z, Nz, dp);
  z[0] = 2 * xi - 2;
  g->shape(z, Nz, dm);
  for (PetscInt a = 0; a < g->nnode; a++) {
    dN[a] *= 2;
    d2N[a] = 2 * (dp[a] - dm[a]); /* 4 (dp - dm)/2 */
  }
}

static PetscErrorCode FaceGet(TslContactFaceKind kind, const TslContactFace **f)
{
  PetscFunctionBeginUser;
  *f = TslContactFaceGet(kind);
  PetscCheck(*f, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Unknown contact face family %d", (int)kind);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Position, tangent and its derivative, all relative to the first node (x = x_1 + sum_{a>1} N_a (x_a - x_1),
 * as sum N_a = 1): the tangent of a straight face is exactly x_2 - x_1. */
static void Evaluate(const TslContactFace *f, const PetscReal x[], PetscReal xi, PetscReal p[2], PetscReal t[2], PetscReal dt[2])
{
  PetscReal N[TSL_CONTACT_MAX_FACE_NODES], dN[TSL_CONTACT_MAX_FACE_NODES], d2N[TSL_CONTACT_MAX_FACE_NODES];

  TslContactFaceShape(f, xi, N, dN, d2N);
  for (PetscInt d = 0; d < 2; d++) {
    p[d] = x[d];
    t[d] = dt[d] = 0;
    for (PetscInt a = 1; a < f->geom->nnode; a++) {
      PetscReal e = x[2 * a + d] - x[d];
      p[d] += N[a] * e;
      t[d] += dN[a] * e;
      dt[d] += d2N[a] * e;
    }
  }
}

PetscErrorCode TslContactFaceEvaluate(TslContactFaceKind kind, const PetscReal x[], PetscReal xi, PetscReal p[], PetscReal t[])
{
  const TslContactFace *f;
  PetscReal             pp[2], tt[2], dt[2];

  PetscFunctionBeginUser;
  PetscCall(FaceGet(kind, &f));
  Evaluate(f, x, xi, pp, tt, dt);
  for (PetscInt d = 0; d < 2; d++) {
    if (p) p[d] = pp[d];
    if (t) t[d] = tt[d];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactFaceProject(TslContactFaceKind kind, const PetscReal x[], const PetscReal p[], PetscReal *xi)
{
  const TslContactFace *f;
  PetscReal             e[2], r[2], L2, s, tol;

  PetscFunctionBeginUser;
  PetscCall(FaceGet(kind, &f));
  e[0] = x[2] - x[0], e[1] = x[3] - x[1];
  r[0] = p[0] - x[0], r[1] = p[1] - x[1];
  L2 = e[0] * e[0] + e[1] * e[1];
  PetscCheck(L2 > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "Contact face with coincident end nodes");
  s = (r[0] * e[0] + r[1] * e[1]) / L2;
  if (f->geom->order > 1) {
    /* minimise D(xi) = |p - x(xi)|^2 / 2: D' = -F, F = (p - x) . t, D'' = t . t - (p - x) . t'; where D is
     * not convex (far on the concave side) a fixed step down the slope; steps limited to a quarter of the
     * face; tolerance at the round-off floor of xi (as TslContactProjectDual) */
    tol = 1e3 * PETSC_MACHINE_EPSILON * (1 + PetscSqrtReal((r[0] * r[0] + r[1] * r[1]) / L2));
    for (PetscInt it = 0; it < 50; it++) {
      PetscReal q[2], t[2], dt[2], F, D2, dx;

      Evaluate(f, x, s, q, t, dt);
      r[0] = p[0] - q[0], r[1] = p[1] - q[1];
      F  = r[0] * t[0] + r[1] * t[1];
      D2 = t[0] * t[0] + t[1] * t[1] - (r[0] * dt[0] + r[1] * dt[1]);
      dx = D2 > 0 ? F / D2 : (F > 0 ? 0.25 : -0.25);
      dx = PetscMax(-0.25, PetscMin(0.25, dx));
      s += dx;
      if (s < -1 || s > 2) {
        s = s < -1 ? -1 : 2;
        break;
      }
      if (PetscAbsReal(dx) < tol) break;
    }
  }
  *xi = s;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactFaceBox(TslContactFaceKind kind, const PetscReal x[], PetscReal box[4])
{
  const TslContactFace *f;

  PetscFunctionBeginUser;
  PetscCall(FaceGet(kind, &f));
  box[0] = box[1] = PETSC_MAX_REAL;
  box[2] = box[3] = -PETSC_MAX_REAL;
  for (PetscInt i = 0; i < f->geom->nnode; i++)
    for (PetscInt d = 0; d < 2; d++) {
      PetscReal c = 0;
      for (PetscInt a = 0; a < f->geom->nnode; a++) c += f->hull[i][a] * x[2 * a + d];
      box[d]     = PetscMin(box[d], c);
      box[d + 2] = PetscMax(box[d + 2], c);
    }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactFaceIntegrate(TslContactFaceKind kind, const PetscReal x[], PetscReal w[], PetscReal *length)
{
  const TslContactFace *f;
  PetscReal             total = 0;

  PetscFunctionBeginUser;
  PetscCall(FaceGet(kind, &f));
  for (PetscInt a = 0; a < f->geom->nnode; a++) w[a] = 0;
  for (PetscInt q = 0; q < f->nq; q++) {
    PetscReal N[TSL_CONTACT_MAX_FACE_NODES], dN[TSL_CONTACT_MAX_FACE_NODES], d2N[TSL_CONTACT_MAX_FACE_NODES], p[2], t[2], dt[2], ds;

    TslContactFaceShape(f, f->q_xi[q], N, dN, d2N);
    Evaluate(f, x, f->q_xi[q], p, t, dt);
    ds = PetscSqrtReal(t[0] * t[0] + t[1] * t[1]);
    PetscCheck(ds > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "Contact face with a degenerate parametrisation (|dx/dxi| = 0)");
    for (PetscInt a = 0; a < f->geom->nnode; a++) w[a] += N[a] * ds * f->q_w[q];
    total += ds * f->q_w[q];
  }
  if (length) *length = total;
  PetscFunctionReturn(PETSC_SUCCESS);
}
