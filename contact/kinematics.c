/* Node-to-segment kinematics: smoothed normals, projection of the secondary node, history transfer.
 * Formulas in docs/contact.md ("Projection" and "Smoothing"). */
#include "contact_impl.h"

/* Unit outward normal (body on the left of a -> b): n = (e_y, -e_x), e = (b - a)/|b - a|. */
static void SegmentNormal(const TslDual a[2], const TslDual b[2], TslDual n[2])
{
  TslDual dx = DSub(b[0], a[0]), dy = DSub(b[1], a[1]);
  TslDual L = DSqrt(DAdd(DMul(dx, dx), DMul(dy, dy)));

  n[0] = DDiv(dy, L);
  n[1] = DScale(-1, DDiv(dx, L));
}

/* Weight of the neighbour's normal at distance t (in units of s, t = 1 at the node, 0 at the end of the
 * rounded zone): w = h(t)/2, h(t) = 3t^2 - 2t^3 on [0,1], so w and dw/dxi are continuous (w' = 0 at both ends
 * of the zone) and both segments meet at the average normal. */
static TslDual BlendWeight(TslDual t)
{
  if (t.v >= 1) return DConst(0.5);
  if (t.v <= 0) return DConst(0);
  return DScale(0.5, DMul(DMul(t, t), DAddC(DScale(-2, t), 3)));
}

void TslContactNormalDual(const TslContactGeom *geo, TslDual xi, TslDual n[2], TslDual tau[2])
{
  const PetscReal s = geo->s;
  TslDual         nc[2];

  SegmentNormal(geo->x1, geo->x2, nc);
  n[0] = nc[0];
  n[1] = nc[1];
  if (s > 0 && ((geo->has_prev && xi.v < s) || (geo->has_next && xi.v > 1 - s))) {
    PetscBool near_start = (PetscBool)(geo->has_prev && xi.v < s);
    TslDual   nb[2], t, w, m[2], len;

    if (near_start) {
      SegmentNormal(geo->x0, geo->x1, nb);
      t = DAddC(DScale(-1 / s, xi), 1); /* 1 - xi/s */
    } else {
      SegmentNormal(geo->x2, geo->x3, nb);
      t = DAddC(DScale(1 / s, xi), 1 - 1 / s); /* 1 - (1 - xi)/s */
    }
    w = BlendWeight(t);
    for (PetscInt d = 0; d < 2; d++) m[d] = DAdd(nc[d], DMul(w, DSub(nb[d], nc[d])));
    len  = DSqrt(DDot(m, m));
    n[0] = DDiv(m[0], len);
    n[1] = DDiv(m[1], len);
  }
  tau[0] = DScale(-1, n[1]);
  tau[1] = n[0];
}

/* F(xi) = (x_s - x_m(xi)) . tau(xi); zero at the normal projection. */
static TslDual ProjectionFunction(const TslContactGeom *geo, TslDual xi)
{
  TslDual n[2], tau[2], r[2];

  TslContactNormalDual(geo, xi, n, tau);
  for (PetscInt d = 0; d < 2; d++) {
    TslDual xm = DAdd(geo->x1[d], DMul(xi, DSub(geo->x2[d], geo->x1[d])));
    r[d]       = DSub(geo->xs[d], xm);
  }
  return DDot(r, tau);
}

PetscErrorCode TslContactProjectDual(const TslContactGeom *geo, TslDual *xi, PetscReal *xi_raw)
{
  PetscReal e[2] = {geo->x2[0].v - geo->x1[0].v, geo->x2[1].v - geo->x1[1].v}, L2 = e[0] * e[0] + e[1] * e[1];
  PetscReal x, tol, r[2];
  TslDual   F;
  PetscBool converged = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCheck(L2 > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "Contact segment of zero length");
  /* start from the projection on the straight segment: exact when no smoothing is active */
  r[0] = geo->xs[0].v - geo->x1[0].v;
  r[1] = geo->xs[1].v - geo->x1[1].v;
  x    = (r[0] * e[0] + r[1] * e[1]) / L2;
  /* xi is dimensionless, but its round-off is that of F / F_xi ~ eps (|x_s - x_1| + L) / L: a tolerance
   * a thousand times that floor, so that Newton stops as soon as it is exact to working precision,
   * whatever the length unit and the distance of the node */
  tol = 1e3 * PETSC_MACHINE_EPSILON * (1 + PetscSqrtReal((r[0] * r[0] + r[1] * r[1]) / L2));
  for (PetscInt it = 0; it < 50; it++) {
    PetscReal dx;

    F = ProjectionFunction(geo, DVar(x, TSL_DUAL_XI));
    PetscCheck(PetscIsNormalReal(F.d[TSL_DUAL_XI]), PETSC_COMM_SELF, PETSC_ERR_CONV_FAILED,
               "Contact projection: singular Newton derivative (node too far from a concave smoothed corner?)");
    dx = -F.v / F.d[TSL_DUAL_XI];
    dx = PetscMax(-0.25, PetscMin(0.25, dx)); /* the smoothed normal turns quickly: limit the step */
    x += dx;
    if (x < -1 || x > 2) {
      x         = x < -1 ? -1 : 2; /* far outside: the caller re-pairs, precision does not matter */
      converged = PETSC_TRUE;
      break;
    }
    if (PetscAbsReal(dx) < tol) {
      converged = PETSC_TRUE;
      break;
    }
  }
  PetscCheck(converged, PETSC_COMM_SELF, PETSC_ERR_CONV_FAILED, "Contact projection did not converge (xi = %g)", (double)x);
  *xi_raw = x;
  /* Slightly beyond a segment end the element keeps the extended segment (xi outside [0, 1], with its
   * derivatives) until the caller re-pairs the node after convergence. Clamping there instead froze xi:
   * a node sitting on a main node (blocks meshed node on node) then switched, from one Newton iterate to
   * the next, between a stuck element with the full stick stiffness (xi = +1e-7) and one without any
   * tangential stiffness (xi = -1e-7), and Newton cycled between two residuals (issue 8, item 8). Beyond
   * the search range the projection is a constant: the caller re-pairs, precision does not matter. */
  if (x <= -1 || x >= 2) {
    *xi = DConst(x);
  } else {
    /* implicit function theorem at F(xi, u) = 0: dxi/du = -F_u / F_xi */
    F   = ProjectionFunction(geo, DVar(x, TSL_DUAL_XI));
    *xi = DConst(x);
    for (PetscInt i = 0; i < TSL_DUAL_XI; i++) xi->d[i] = -F.d[i] / F.d[TSL_DUAL_XI];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Current position relative to the reference position O of the segment's first node: (X - O) + U. A
 * constant shift leaves every derivative unchanged, and the differences of nearby points (gap, slip,
 * projection) no longer lose digits to the size of the coordinates: a model far from the origin (or in
 * a small length unit) gives the same contact state as the same model at the origin. */
static void SetPoint(const PetscReal X[], const PetscReal U[], const PetscReal O[], PetscInt node, PetscBool seed, TslDual x[2])
{
  for (PetscInt d = 0; d < 2; d++) x[d] = DVar((X[d] - O[d]) + U[d], seed ? 3 * node + d : -1);
}

PetscErrorCode TslContactGeomSetUp(const TslContactInput *in, PetscBool seed, TslContactGeom *geo, PetscInt *nnode)
{
  PetscInt k = 3;

  PetscFunctionBeginUser;
  PetscCheck(in->smoothing >= 0 && in->smoothing < 0.5, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Contact smoothing fraction %g outside [0, 0.5)",
             (double)in->smoothing);
  PetscCheck(!in->x_prev == !in->u_prev && !in->x_next == !in->u_next, PETSC_COMM_SELF, PETSC_ERR_ARG_NULL,
             "Neighbour node needs both reference coordinates and unknowns");
  SetPoint(in->x[0], in->u[0], in->x[1], 0, seed, geo->xs);
  SetPoint(in->x[1], in->u[1], in->x[1], 1, seed, geo->x1);
  SetPoint(in->x[2], in->u[2], in->x[1], 2, seed, geo->x2);
  geo->has_prev = (PetscBool)(in->x_prev != NULL);
  geo->has_next = (PetscBool)(in->x_next != NULL);
  if (geo->has_prev) SetPoint(in->x_prev, in->u_prev, in->x[1], k++, seed, geo->x0);
  if (geo->has_next) SetPoint(in->x_next, in->u_next, in->x[1], k++, seed, geo->x3);
  geo->s = in->smoothing;
  if (nnode) *nnode = k;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactProject(const TslContactInput *in, PetscReal *xi, PetscReal *g, PetscReal n[])
{
  TslContactGeom geo;
  TslDual        x, nn[2], tau[2], r[2];
  PetscReal      raw;

  PetscFunctionBeginUser;
  PetscCall(TslContactGeomSetUp(in, PETSC_FALSE, &geo, NULL));
  PetscCall(TslContactProjectDual(&geo, &x, &raw));
  TslContactNormalDual(&geo, x, nn, tau);
  for (PetscInt d = 0; d < 2; d++) r[d] = DSub(geo.xs[d], DAdd(geo.x1[d], DMul(x, DSub(geo.x2[d], geo.x1[d]))));
  if (xi) *xi = raw;
  if (g) *g = DDot(r, nn).v;
  if (n) {
    n[0] = nn[0].v;
    n[1] = nn[1].v;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscInt TslContactProjectionSide(PetscReal xi, PetscReal tol)
{
  if (xi < -tol) return -1;
  if (xi > 1 + tol) return 1;
  return 0;
}

PetscErrorCode TslContactHistoryTransfer(PetscInt side, PetscReal L_from, PetscReal L_to, TslContactHistory *h)
{
  PetscReal r = L_from / L_to;

  PetscFunctionBeginUser;
  PetscCheck(side == 1 || side == -1, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "side must be +1 or -1");
  PetscCheck(L_from > 0 && L_to > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "segment lengths must be positive");
  if (side == 1) {
    h->xi_old    = (h->xi_old - 1) * r;
    h->xi_anchor = (h->xi_anchor - 1) * r;
  } else {
    h->xi_old    = 1 + h->xi_old * r;
    h->xi_anchor = 1 + h->xi_anchor * r;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactSmoothedNormal(const PetscReal x0[], const PetscReal x1[], const PetscReal x2[], const PetscReal x3[], PetscReal s,
                                        PetscReal xi, PetscReal n[])
{
  TslContactGeom geo;
  TslDual        nn[2], tau[2];

  PetscFunctionBeginUser;
  PetscCheck(s >= 0 && s < 0.5, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "smoothing %g outside [0, 0.5)", (double)s);
  for (PetscInt d = 0; d < 2; d++) {
    geo.x1[d] = DConst(x1[d]);
    geo.x2[d] = DConst(x2[d]);
    geo.x0[d] = DConst(x0 ? x0[d] : 0);
    geo.x3[d] = DConst(x3 ? x3[d] : 0);
    geo.xs[d] = DConst(0);
  }
  geo.has_prev = (PetscBool)(x0 != NULL);
  geo.has_next = (PetscBool)(x3 != NULL);
  geo.s        = s;
  TslContactNormalDual(&geo, DConst(xi), nn, tau);
  n[0] = nn[0].v;
  n[1] = nn[1].v;
  PetscFunctionReturn(PETSC_SUCCESS);
}
