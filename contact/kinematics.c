/* Node-to-segment kinematics: the segment's curve and its smoothed normals, projection of the secondary
 * node, history transfer. Formulas in docs/contact.md ("Projection" and "Smoothing"). */
#include "contact_impl.h"

/* x_m = x_1 + sum_{a>1} N_a (x_a - x_1) (sum N_a = 1) and t = sum_{a>1} dN_a (x_a - x_1): differences of
 * nearby nodes, no cancellation between large coordinates, and the tangent of a straight segment is
 * exactly x_2 - x_1. N_a and dN_a carry their xi-derivatives (dN_a, d2N_a), so that t, the normal and the
 * projection are differentiated through the curvature. */
void TslContactFacePointDual(const TslContactFace *face, const TslDual x[][2], TslDual xi, TslDual p[2], TslDual t[2])
{
  PetscReal N[TSL_CONTACT_MAX_FACE_NODES], dN[TSL_CONTACT_MAX_FACE_NODES], d2N[TSL_CONTACT_MAX_FACE_NODES];

  TslContactFaceShape(face, xi.v, N, dN, d2N);
  for (PetscInt d = 0; d < 2; d++) {
    p[d] = x[0][d];
    t[d] = DConst(0);
  }
  for (PetscInt a = 1; a < face->geom->nnode; a++) {
    TslDual Na = DChain(xi, N[a], dN[a]), dNa = DChain(xi, dN[a], d2N[a]);

    for (PetscInt d = 0; d < 2; d++) {
      TslDual e = DSub(x[a][d], x[0][d]);
      DAccMul(&p[d], &Na, &e);
      DAccMul(&t[d], &dNa, &e);
    }
  }
}

static TslDual Norm(const TslDual t[2])
{
  return DSqrt(DDot(t, t));
}

/* Unit outward normal of a tangent (body on the left): n = (t_y, -t_x)/|t|. */
static void NormalOfTangent(const TslDual t[2], TslDual n[2])
{
  TslDual L = Norm(t);

  n[0] = DDiv(t[1], L);
  n[1] = DScale(-1, DDiv(t[0], L));
}

/* Weight of the neighbour's normal at distance t (in units of s, t = 1 at the node, 0 at the end of the
 * rounded zone): w = h(t)/2, h(t) = 3t^2 - 2t^3 on [0,1], so w and dw/dxi are continuous (w' = 0 at both ends
 * of the zone) and both segments meet at the average normal. */
static TslDual BlendWeight(TslDual t)
{
  return DScale(0.5, DSmoothStep(t));
}

/* Normal of the neighbouring segment nb[] at the point as far from the shared node as xi is on this one:
 * its parameter is extended beyond the node (xb = 1 + rho xi before m1, rho (xi - 1) after m2, rho the
 * ratio of the two metrics |t| at the node), so that at the node both segments' blended normals agree in
 * value and in their derivative along the arc, also when the segments are curved. A straight neighbour
 * has the same normal everywhere. */
static void NeighbourNormal(const TslContactGeom *geo, const TslDual nb[][2], PetscBool before, TslDual xi, TslDual n[2])
{
  const TslContactFace *face = geo->face;
  TslDual               p[2], tc[2], tb[2], xb = DConst(before ? 1 : 0);

  if (face->geom->order > 1) {
    TslDual rho;

    TslContactFacePointDual(face, geo->seg, DConst(before ? 0 : 1), p, tc);
    TslContactFacePointDual(face, nb, xb, p, tb);
    rho = DDiv(Norm(tc), Norm(tb));
    xb  = before ? DAddC(DMul(rho, xi), 1) : DMul(rho, DAddC(xi, -1));
  }
  TslContactFacePointDual(face, nb, xb, p, tb);
  NormalOfTangent(tb, n);
}

void TslContactSurfaceDual(const TslContactGeom *geo, TslDual xi, TslDual x[2], TslDual n[2], TslDual tau[2])
{
  const PetscReal s = geo->s;
  TslDual         p[2], t[2], nc[2];

  TslContactFacePointDual(geo->face, geo->seg, xi, p, t);
  NormalOfTangent(t, nc);
  if (x) {
    x[0] = p[0];
    x[1] = p[1];
  }
  n[0] = nc[0];
  n[1] = nc[1];
  if (s > 0 && ((geo->has_prev && xi.v < s) || (geo->has_next && xi.v > 1 - s))) {
    PetscBool near_start = (PetscBool)(geo->has_prev && xi.v < s);
    TslDual   nb[2], w, m[2], len, tt;

    NeighbourNormal(geo, near_start ? geo->prev : geo->next, near_start, xi, nb);
    if (near_start)
      tt = DAddC(DScale(-1 / s, xi), 1); /* 1 - xi/s */
    else
      tt = DAddC(DScale(1 / s, xi), 1 - 1 / s); /* 1 - (1 - xi)/s */
    w = BlendWeight(tt);
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
  TslDual xm[2], n[2], tau[2], r[2];

  TslContactSurfaceDual(geo, xi, xm, n, tau);
  for (PetscInt d = 0; d < 2; d++) r[d] = DSub(geo->xs[d], xm[d]);
  return DDot(r, tau);
}

PetscErrorCode TslContactProjectDual(const TslContactGeom *geo, TslDual *xi, PetscReal *xi_raw)
{
  PetscReal e[2] = {geo->seg[1][0].v - geo->seg[0][0].v, geo->seg[1][1].v - geo->seg[0][1].v}, L2 = e[0] * e[0] + e[1] * e[1];
  PetscReal x, tol, r[2];
  TslDual   F;
  PetscBool converged = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCheck(L2 > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "Contact segment of zero length");
  /* start from the projection on the chord m1 -> m2: exact for a straight segment without smoothing */
  r[0] = geo->xs[0].v - geo->seg[0][0].v;
  r[1] = geo->xs[1].v - geo->seg[0][1].v;
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
    for (PetscInt i = TSL_DUAL_DOF; i < TSL_DUAL_N; i++) xi->d[i] = -F.d[i] / F.d[TSL_DUAL_XI];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Current position relative to the reference position O of the segment's first node: (X - O) + U. A
 * constant shift leaves every derivative unchanged, and the differences of nearby points (gap, slip,
 * projection) no longer lose digits to the size of the coordinates: a model far from the origin (or in
 * a small length unit) gives the same contact state as the same model at the origin. */
static void SetPoint(const PetscReal X[], const PetscReal U[], const PetscReal O[], PetscInt node, PetscInt nu, PetscBool seed, TslDual x[2])
{
  for (PetscInt d = 0; d < 2; d++) x[d] = DVar((X[d] - O[d]) + U[d], seed ? TSL_DUAL_DOF + nu * node + d : -1);
}

PetscErrorCode TslContactGeomSetUp(const TslContactInput *in, PetscBool seed, TslContactGeom *geo, PetscInt *nnode)
{
  const PetscReal *O = in->x[1];
  PetscInt         k = 0, nper;

  PetscFunctionBeginUser;
  PetscCheck(in->smoothing >= 0 && in->smoothing < 0.5, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Contact smoothing fraction %g outside [0, 0.5)",
             (double)in->smoothing);
  PetscCheck(!in->x_prev == !in->u_prev && !in->x_next == !in->u_next, PETSC_COMM_SELF, PETSC_ERR_ARG_NULL,
             "Neighbour node needs both reference coordinates and unknowns");
  geo->face = TslContactFaceGet(in->face);
  PetscCheck(geo->face, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Unknown contact face family %d", (int)in->face);
  nper    = geo->face->geom->nnode;
  geo->nu = TslContactNodeUnknowns(in->kin);
  SetPoint(in->x[0], in->u[0], O, k++, geo->nu, seed, geo->xs);
  for (PetscInt a = 0; a < nper; a++) SetPoint(in->x[1 + a], in->u[1 + a], O, k++, geo->nu, seed, geo->seg[a]);
  geo->has_prev = (PetscBool)(in->x_prev != NULL);
  geo->has_next = (PetscBool)(in->x_next != NULL);
  /* a neighbour shares one end with this segment: the previous one its end (node 1) with m1, the next one
   * its start (node 0) with m2; its other nodes come in face order */
  if (geo->has_prev)
    for (PetscInt a = 0, j = 0; a < nper; a++) {
      if (a == 1) {
        geo->prev[a][0] = geo->seg[0][0];
        geo->prev[a][1] = geo->seg[0][1];
      } else {
        SetPoint(&in->x_prev[2 * j], &in->u_prev[geo->nu * j], O, k++, geo->nu, seed, geo->prev[a]);
        j++;
      }
    }
  if (geo->has_next)
    for (PetscInt a = 0, j = 0; a < nper; a++) {
      if (a == 0) {
        geo->next[a][0] = geo->seg[1][0];
        geo->next[a][1] = geo->seg[1][1];
      } else {
        SetPoint(&in->x_next[2 * j], &in->u_next[geo->nu * j], O, k++, geo->nu, seed, geo->next[a]);
        j++;
      }
    }
  geo->s = in->smoothing;
  if (nnode) *nnode = k;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactProject(const TslContactInput *in, PetscReal *xi, PetscReal *g, PetscReal n[])
{
  TslContactGeom geo;
  TslDual        x, xm[2], nn[2], tau[2], r[2];
  PetscReal      raw;

  PetscFunctionBeginUser;
#if !defined(TSL_DUAL_VALUES)
  PetscCall(TslContactProject_Values(in, xi, g, n)); /* values alone (contact/values/) */
  PetscFunctionReturn(PETSC_SUCCESS);
#endif
  PetscCall(TslContactGeomSetUp(in, PETSC_FALSE, &geo, NULL));
  PetscCall(TslContactProjectDual(&geo, &x, &raw));
  TslContactSurfaceDual(&geo, x, xm, nn, tau);
  for (PetscInt d = 0; d < 2; d++) r[d] = DSub(geo.xs[d], xm[d]);
  if (xi) *xi = raw;
  if (g) *g = DDot(r, nn).v;
  if (n) {
    n[0] = nn[0].v;
    n[1] = nn[1].v;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactSurfacePoint(const TslContactInput *in, PetscReal xi, PetscReal x[], PetscReal n[])
{
  TslContactGeom geo;
  TslDual        xm[2], nn[2], tau[2];

  PetscFunctionBeginUser;
#if !defined(TSL_DUAL_VALUES)
  PetscCall(TslContactSurfacePoint_Values(in, xi, x, n)); /* values alone (contact/values/) */
  PetscFunctionReturn(PETSC_SUCCESS);
#endif
  PetscCall(TslContactGeomSetUp(in, PETSC_FALSE, &geo, NULL));
  TslContactSurfaceDual(&geo, DConst(xi), xm, nn, tau);
  for (PetscInt d = 0; d < 2; d++) {
    if (x) x[d] = xm[d].v + in->x[1][d]; /* the geometry is relative to the reference position of m1 */
    if (n) n[d] = nn[d].v;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscInt TslContactProjectionSide(PetscReal xi, PetscReal tol)
{
  if (xi < -tol) return -1;
  if (xi > 1 + tol) return 1;
  return 0;
}

PetscErrorCode TslContactStateTransfer(PetscInt side, PetscReal L_from, PetscReal L_to, TslContactState *h)
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
  geo.face = TslContactFaceGet(TSL_CONTACT_FACE_LINE2);
  for (PetscInt d = 0; d < 2; d++) {
    geo.seg[0][d] = geo.prev[1][d] = DConst(x1[d]);
    geo.seg[1][d] = geo.next[0][d] = DConst(x2[d]);
    geo.prev[0][d]                 = DConst(x0 ? x0[d] : 0);
    geo.next[1][d]                 = DConst(x3 ? x3[d] : 0);
    geo.xs[d]                      = DConst(0);
  }
  geo.has_prev = (PetscBool)(x0 != NULL);
  geo.has_next = (PetscBool)(x3 != NULL);
  geo.s        = s;
  geo.nu       = 3;
  TslContactSurfaceDual(&geo, DConst(xi), NULL, nn, tau);
  n[0] = nn[0].v;
  n[1] = nn[1].v;
  PetscFunctionReturn(PETSC_SUCCESS);
}
