/* Quadratic (line3) contact faces: the face table against the element catalogue's face geometries, the
 * projection of a node onto a curved segment (a parabola arc) against its analytic closest point, the
 * smoothed normal where two curved segments meet at a kink, the bounding box of a curved face, the
 * tributary weights of a secondary line3 face (plane and axisymmetric) against their analytic integrals,
 * and the nodal forces of a uniform pressure (1:4:1 on a line3 face). */
#include "check.h"

/* Shape functions on the segment parameter: partition of unity, Kronecker property at the nodes (0, 1,
 * 1/2), first and second derivatives (the latter a difference of the geometry's dN) against central
 * differences, orders within the exactness of that difference; and every catalogue face family contact
 * supports is the very geometry of its table row. */
static PetscErrorCode CheckShapes(TestLog *log)
{
  const PetscReal node_xi[TSL_CONTACT_MAX_FACE_NODES] = {0, 1, 0.5}, h = 1e-5;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < TSL_CONTACT_FACE_NKINDS; k++) {
    const TslContactFace *f = TslContactFaceGet((TslContactFaceKind)k);
    const TslGeometry    *g = f->geom;
    PetscReal             N[TSL_CONTACT_MAX_FACE_NODES], dN[TSL_CONTACT_MAX_FACE_NODES], d2N[TSL_CONTACT_MAX_FACE_NODES];
    PetscReal Np[TSL_CONTACT_MAX_FACE_NODES], dNp[TSL_CONTACT_MAX_FACE_NODES], Nm[TSL_CONTACT_MAX_FACE_NODES], dNm[TSL_CONTACT_MAX_FACE_NODES];
    PetscReal sum = 0, kron = 0, e1 = 0, e2 = 0;

    Check(log, (PetscReal)TslContactFaceFind(g->name), (PetscReal)k, 0, "%s: found by its catalogue name", g->name);
    Check(log, (PetscReal)(g->dim == 1 && g->nnode <= TSL_CONTACT_MAX_FACE_NODES && g->order <= 3 && g->ncorner == 2), 1, 0,
          "%s: a line of order <= 3 with its two ends first", g->name);
    for (PetscInt b = 0; b < g->nnode; b++) {
      TslContactFaceShape(f, node_xi[b], N, dN, d2N);
      for (PetscInt a = 0; a < g->nnode; a++) kron = PetscMax(kron, PetscAbsReal(N[a] - (a == b)));
    }
    TslContactFaceShape(f, 0.37 + h, Np, dNp, d2N);
    TslContactFaceShape(f, 0.37 - h, Nm, dNm, d2N);
    TslContactFaceShape(f, 0.37, N, dN, d2N);
    for (PetscInt a = 0; a < g->nnode; a++) {
      sum += N[a];
      e1 = PetscMax(e1, PetscAbsReal((Np[a] - Nm[a]) / (2 * h) - dN[a]));
      e2 = PetscMax(e2, PetscAbsReal((dNp[a] - dNm[a]) / (2 * h) - d2N[a]));
    }
    Check(log, kron, 0, 1e-15, "%s: N_a(xi_b) = delta_ab (ends at 0, 1, midside at 1/2)", g->name);
    Check(log, sum, 1, 1e-15, "%s: sum N_a = 1", g->name);
    Check(log, e1, 0, 1e-9, "%s: dN/dxi against central differences", g->name);
    Check(log, e2, 0, 1e-9, "%s: d2N/dxi2 against central differences", g->name);
  }
  for (PetscInt t = 0; t < TslElementTypeCount(); t++) {
    const TslGeometry *g = TslElementTypeGet(t)->geom;
    for (PetscInt fc = 0; fc < g->nface; fc++) {
      const TslGeometry *fg = g->face_geom[fc];
      PetscInt           k  = fg ? TslContactFaceFind(fg->name) : -1;
      if (k >= 0 && TslContactFaceGet((TslContactFaceKind)k)->geom != fg)
        Check(log, 1, 0, 0, "%s face S%d of %s: a different geometry than contact's row", fg->name, (int)fc + 1, TslElementTypeGet(t)->name);
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Main segment on the parabola y = c (1 - x^2), m1 = (1, 0) -> m2 = (-1, 0), midside (0, c): with the
 * midside node in the middle x(xi) = 1 - 2 xi is linear and the quadratic interpolates the parabola exactly.
 * Body below (left of m1 -> m2), outward normal up. */
#define PARABOLA_C 0.25

static void ParabolaPoint(PetscReal x, PetscReal P[2], PetscReal n[2])
{
  const PetscReal c    = PARABOLA_C;
  PetscReal       t[2] = {-2, 4 * c * x}, L = PetscSqrtReal(t[0] * t[0] + t[1] * t[1]); /* dP/dxi, dx/dxi = -2 */

  P[0] = x;
  P[1] = c * (1 - x * x);
  n[0] = t[1] / L;
  n[1] = -t[0] / L;
}

static TslContactInput ParabolaInput(const PetscReal p[2])
{
  const PetscReal x1[2] = {1, 0}, x2[2] = {-1, 0};
  TslContactInput in = InputSetUp(p, x1, x2);

  in.face    = TSL_CONTACT_FACE_LINE3;
  in.x[3][0] = 0;
  in.x[3][1] = PARABOLA_C;
  return in;
}

/* A point p = P(x*) + d n(x*) off the arc: its closest point is P(x*) (d below the radius of curvature,
 * >= 2 here), so xi = (1 - x*)/2 and g = d exactly. Also after a rigid motion (displacements), and by the
 * search's closest-point function. */
static PetscErrorCode CheckProjection(TestLog *log)
{
  const PetscReal xs[3] = {0.7, 0.2, -0.45}, ds[3] = {0.05, -0.02, 0.3};
  PetscReal       worst[4] = {0, 0, 0, 0};

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < 3; i++)
    for (PetscInt j = 0; j < 3; j++) {
      PetscReal       P[2], n[2], p[2], xi, g, nn[2], xi_f, face_x[6] = {1, 0, -1, 0, 0, PARABOLA_C};
      TslContactInput in;

      ParabolaPoint(xs[i], P, n);
      p[0] = P[0] + ds[j] * n[0];
      p[1] = P[1] + ds[j] * n[1];
      in   = ParabolaInput(p);
      PetscCall(TslContactProject(&in, &xi, &g, nn));
      worst[0] = PetscMax(worst[0], PetscAbsReal(xi - 0.5 * (1 - xs[i])));
      worst[1] = PetscMax(worst[1], PetscAbsReal(g - ds[j]));
      worst[2] = PetscMax(worst[2], PetscAbsReal(nn[0] - n[0]) + PetscAbsReal(nn[1] - n[1]));
      PetscCall(TslContactFaceProject(TSL_CONTACT_FACE_LINE3, face_x, p, &xi_f));
      worst[3] = PetscMax(worst[3], PetscAbsReal(xi_f - 0.5 * (1 - xs[i])));
    }
  Check(log, worst[0], 0, 1e-14, "parabola arc: xi = (1 - x*)/2 (9 points, gaps 0.05, -0.02, 0.3)");
  Check(log, worst[1], 0, 1e-14, "parabola arc: gap = distance along the normal");
  Check(log, worst[2], 0, 1e-14, "parabola arc: normal of the arc at the closest point");
  Check(log, worst[3], 0, 1e-14, "parabola arc: search closest point (TslContactFaceProject)");

  /* rigid motion: rotate by 0.3 rad about (0.5, -1) and translate (0.2, 0.1); xi and g unchanged */
  {
    const PetscReal a = 0.3, cs = PetscCosReal(a), sn = PetscSinReal(a), O[2] = {0.5, -1}, T[2] = {0.2, 0.1};
    PetscReal       P[2], n[2], p[2], xi, g;
    TslContactInput in;

    ParabolaPoint(0.2, P, n);
    p[0] = P[0] - 0.01 * n[0];
    p[1] = P[1] - 0.01 * n[1];
    in   = ParabolaInput(p);
    for (PetscInt k = 0; k < 4; k++) {
      PetscReal r[2] = {in.x[k][0] - O[0], in.x[k][1] - O[1]};
      in.u[k][0]     = O[0] + cs * r[0] - sn * r[1] + T[0] - in.x[k][0];
      in.u[k][1]     = O[1] + sn * r[0] + cs * r[1] + T[1] - in.x[k][1];
    }
    PetscCall(TslContactProject(&in, &xi, &g, NULL));
    Check(log, xi, 0.4, 1e-13, "parabola arc, rigidly moved: xi");
    Check(log, g, -0.01, 1e-13, "parabola arc, rigidly moved: gap (penetration)");
  }
  /* a midside node off the middle: the parametrisation is no longer uniform, the closest point still
   * satisfies (x_s - x_m) x t = 0 with the gap equal to the distance */
  {
    const PetscReal p[2] = {0.3, 0.4};
    TslContactInput in   = ParabolaInput(p);
    PetscReal       xi, g, xm[2], n[2], r[2];

    in.x[3][0] = 0.35;
    in.x[3][1] = 0.2;
    PetscCall(TslContactProject(&in, &xi, &g, n));
    PetscCall(TslContactSurfacePoint(&in, xi, xm, NULL));
    r[0] = p[0] - xm[0];
    r[1] = p[1] - xm[1];
    Check(log, r[0] * n[1] - r[1] * n[0], 0, 1e-14, "off-centre midside: x_s - x_m parallel to n");
    Check(log, g, PetscSqrtReal(r[0] * r[0] + r[1] * r[1]), 1e-14, "off-centre midside: gap = distance");
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Two curved segments meeting at a kink (a convex corner at B = (0, 0)): A = (2, 0) -> (0, 0), midside
 * (1, 0.1); C = (0, 0) -> (-1.5, -0.8), midside 0.05 out of its chord. With smoothing s the normal is the
 * face's own normal away from the ends, the two faces give the same normal at the shared node, and its
 * derivative along the arc is continuous there (the neighbour is extended by the ratio of the metrics). */
static PetscErrorCode CheckSmoothedKink(TestLog *log)
{
  const PetscReal A[3][2] = {{2, 0}, {0, 0}, {1, 0.1}}, s = 0.2, h = 1e-6;
  PetscReal       C[3][2] = {{0, 0}, {-1.5, -0.8}, {0, 0}}, xa_next[4], xc_prev[4], zero[6] = {0, 0, 0, 0, 0, 0}, p[2] = {0, 0};
  TslContactInput a, c;
  PetscReal       na1[2], nc0[2], na[2], nc[2], ta[2], tc[2], n_mid[2], n_flat[2], La, Lc;

  PetscFunctionBeginUser;
  {
    PetscReal e[2] = {C[1][0] - C[0][0], C[1][1] - C[0][1]}, L = PetscSqrtReal(e[0] * e[0] + e[1] * e[1]);
    C[2][0] = 0.5 * (C[0][0] + C[1][0]) + 0.05 * e[1] / L;
    C[2][1] = 0.5 * (C[0][1] + C[1][1]) - 0.05 * e[0] / L;
  }
  a      = InputSetUp(p, A[0], A[1]);
  c      = InputSetUp(p, C[0], C[1]);
  a.face = c.face = TSL_CONTACT_FACE_LINE3;
  for (PetscInt d = 0; d < 2; d++) {
    a.x[3][d]      = A[2][d];
    c.x[3][d]      = C[2][d];
    xa_next[d]     = C[1][d]; /* next of A: C without its start (shared) */
    xa_next[2 + d] = C[2][d];
    xc_prev[d]     = A[0][d]; /* previous of C: A without its end (shared) */
    xc_prev[2 + d] = A[2][d];
  }
  a.x_next = xa_next, a.u_next = zero, a.smoothing = s;
  c.x_prev = xc_prev, c.u_prev = zero, c.smoothing = s;
  PetscCall(TslContactSurfacePoint(&a, 1, NULL, na1));
  PetscCall(TslContactSurfacePoint(&c, 0, NULL, nc0));
  Check(log, PetscAbsReal(na1[0] - nc0[0]) + PetscAbsReal(na1[1] - nc0[1]), 0, 1e-15, "curved kink: same normal from both faces at the node");
  /* derivative along the arc: dn/ds = (dn/dxi) / |t| at the node, one-sided from each face */
  PetscCall(TslContactFaceEvaluate(TSL_CONTACT_FACE_LINE3, &A[0][0], 1, NULL, ta));
  PetscCall(TslContactFaceEvaluate(TSL_CONTACT_FACE_LINE3, &C[0][0], 0, NULL, tc));
  La = PetscSqrtReal(ta[0] * ta[0] + ta[1] * ta[1]);
  Lc = PetscSqrtReal(tc[0] * tc[0] + tc[1] * tc[1]);
  PetscCall(TslContactSurfacePoint(&a, 1 - h, NULL, na));
  PetscCall(TslContactSurfacePoint(&c, h, NULL, nc));
  Check(log, (na1[0] - na[0]) / (h * La) - (nc[0] - nc0[0]) / (h * Lc), 0, 1e-5, "curved kink: dn_x/ds continuous across the node (|t| %.3g vs %.3g)",
        (double)La, (double)Lc);
  Check(log, (na1[1] - na[1]) / (h * La) - (nc[1] - nc0[1]) / (h * Lc), 0, 1e-5, "curved kink: dn_y/ds continuous across the node");
  /* inside the face (beyond the rounded zone) the face's own normal: the smoothing leaves it alone */
  PetscCall(TslContactSurfacePoint(&a, 0.5, NULL, n_mid));
  a.x_next = NULL, a.u_next = NULL;
  PetscCall(TslContactSurfacePoint(&a, 0.5, NULL, n_flat));
  Check(log, PetscAbsReal(n_mid[0] - n_flat[0]) + PetscAbsReal(n_mid[1] - n_flat[1]), 0, 0, "curved face: no blending outside the rounded zones");
  Check(log, n_flat[1], 1, 1e-15, "curved face: normal at the crest (xi = 1/2) is (0, 1)");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The box of a curved face holds every point of it; a straight face's box is that of its end points. */
static PetscErrorCode CheckBox(TestLog *log)
{
  const PetscReal x[6] = {1, 0, -1, 0, 0.4, 0.5}, y[4] = {2, 1, -1, 3};
  PetscReal       box[4], out                          = 0;

  PetscFunctionBeginUser;
  PetscCall(TslContactFaceBox(TSL_CONTACT_FACE_LINE3, x, box));
  for (PetscInt i = 0; i <= 100; i++) {
    PetscReal p[2];
    PetscCall(TslContactFaceEvaluate(TSL_CONTACT_FACE_LINE3, x, 0.01 * i, p, NULL));
    out = PetscMax(out, PetscMax(PetscMax(box[0] - p[0], p[0] - box[2]), PetscMax(box[1] - p[1], p[1] - box[3])));
  }
  Check(log, (PetscReal)(out <= 0), 1, 0, "line3 box contains the curve (largest excess %g)", (double)out);
  Check(log, box[3], 2 * 0.5 - 0, 1e-15, "line3 box: top at the Bernstein control point 2 y_3 - (y_1 + y_2)/2");
  PetscCall(TslContactFaceBox(TSL_CONTACT_FACE_LINE2, y, box));
  Check(log, PetscAbsReal(box[0] + 1) + PetscAbsReal(box[1] - 1) + PetscAbsReal(box[2] - 2) + PetscAbsReal(box[3] - 3), 0, 0,
        "line2 box = box of the end points");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Parabola arc length from -1 to 1: int sqrt(1 + 4 c^2 x^2) dx. */
static PetscReal ParabolaLength(PetscReal c)
{
  PetscReal k = 2 * c, F = 0.5 * PetscSqrtReal(1 + k * k) + PetscLogReal(k + PetscSqrtReal(1 + k * k)) / (2 * k);
  return 2 * F;
}

/* Tributary weights w_a = int N_a ds of a secondary line3 face. */
static PetscErrorCode CheckWeights(TestLog *log)
{
  PetscReal w[3], L;

  PetscFunctionBeginUser;
  /* straight, midside in the middle, length 5: L/6, L/6, 2L/3 (node order end, end, middle) */
  {
    const PetscReal x[6] = {1, 1, 4, 5, 2.5, 3};
    PetscCall(TslContactFaceIntegrate(TSL_CONTACT_FACE_LINE3, x, w, &L));
    Check(log, w[0], 5.0 / 6, 1e-14, "line3 straight: w_1 = L/6");
    Check(log, w[1], 5.0 / 6, 1e-14, "line3 straight: w_2 = L/6");
    Check(log, w[2], 10.0 / 3, 1e-14, "line3 straight: w_3 (midside) = 2L/3");
    Check(log, L, 5, 1e-14, "line3 straight: length");
  }
  /* straight, midside at the fraction alpha = 0.3 of the way: ds/dxi = L (a xi + b), a = 4 - 8 alpha,
   * b = 4 alpha - 1, so w = L (b/6, (a + b)/6, a/3 + 2b/3) */
  {
    const PetscReal alpha = 0.3, a = 4 - 8 * alpha, b = 4 * alpha - 1, x[6] = {0, 0, 3, 4, 3 * alpha, 4 * alpha};
    PetscCall(TslContactFaceIntegrate(TSL_CONTACT_FACE_LINE3, x, w, &L));
    Check(log, w[0], 5 * b / 6, 1e-14, "line3 off-centre midside: w_1 = L b/6");
    Check(log, w[1], 5 * (a + b) / 6, 1e-14, "line3 off-centre midside: w_2 = L (a + b)/6");
    Check(log, w[2], 5 * (a / 3 + 2 * b / 3), 1e-14, "line3 off-centre midside: w_3 = L (a/3 + 2b/3)");
  }
  /* curved (the parabola arc): the total is the arc length; the five-point rule is not exact for
   * sqrt(1 + 4 c^2 x^2), so the weights are compared with a converged composite Simpson rule */
  {
    const PetscReal x[6]   = {1, 0, -1, 0, 0, PARABOLA_C};
    PetscReal       ref[3] = {0, 0, 0};
    const PetscInt  M      = 2000;
    PetscCall(TslContactFaceIntegrate(TSL_CONTACT_FACE_LINE3, x, w, &L));
    for (PetscInt i = 0; i <= M; i++) {
      PetscReal xi = (PetscReal)i / M, N[3], dN[3], d2N[3], t[2], c = (i == 0 || i == M) ? 1 : (i % 2 ? 4 : 2);
      TslContactFaceShape(TslContactFaceGet(TSL_CONTACT_FACE_LINE3), xi, N, dN, d2N);
      PetscCall(TslContactFaceEvaluate(TSL_CONTACT_FACE_LINE3, x, xi, NULL, t));
      for (PetscInt a = 0; a < 3; a++) ref[a] += c * N[a] * PetscSqrtReal(t[0] * t[0] + t[1] * t[1]) / (3.0 * M);
    }
    CheckRel(log, L, ParabolaLength(PARABOLA_C), 1e-6, 0, "line3 parabola arc: length (five-point rule vs analytic)");
    for (PetscInt a = 0; a < 3; a++) CheckRel(log, w[a], ref[a], 1e-6, 0, "line3 parabola arc: w_%d (five-point rule vs converged)", (int)a + 1);
  }
  /* axisymmetric: the kernel's area is w_a 2 pi r_a. On a straight line3 face r is linear in xi, and
   * Simpson's rule (nodes 0, 1/2, 1, weights 1/6, 2/3, 1/6) integrates N_a r exactly, so the areas are the
   * consistent integrals int N_a 2 pi r ds. Face from (r, z) = (1, 2) to (3, 0.5): L = 2.5, r = 1 + 2 xi:
   * int N_a r dxi = 1/6, 3/6, 4/3 (times L 2 pi). */
  {
    const PetscReal x[6] = {1, 2, 3, 0.5, 2, 1.25}, expect[3] = {1.0 / 6, 3.0 / 6, 4.0 / 3};
    TslContactLaw   law;
    PetscReal       total = 0;

    PetscCall(TslContactFaceIntegrate(TSL_CONTACT_FACE_LINE3, x, w, &L));
    PetscCall(TslContactLawSetDefaults(&law));
    law.eps_n = 1;
    for (PetscInt a = 0; a < 3; a++) {
      const PetscReal  m1[2] = {10, 0}, m2[2] = {-10, 0}; /* any main segment: only the area is looked at */
      TslContactInput  in = InputSetUp(&x[2 * a], m1, m2);
      TslContactOutput out;

      in.kin    = TSL_KIN_AXISYMMETRIC;
      in.length = w[a];
      PetscCall(TslContactElement(&law, &in, NULL, NULL, &out));
      CheckRel(log, out.area, 2 * PETSC_PI * 2.5 * expect[a], 1e-14, 0, "line3 axisymmetric: area of node %d = int N_a 2 pi r ds", (int)a + 1);
      total += out.area;
      in.kin = TSL_KIN_AXISYMMETRIC_TWIST; /* the twist rows (CGAX) revolve too */
      PetscCall(TslContactElement(&law, &in, NULL, NULL, &out));
      CheckRel(log, out.area, 2 * PETSC_PI * 2.5 * expect[a], 1e-14, 0, "line3 axisymmetric with twist: area of node %d", (int)a + 1);
    }
    /* the lateral area of the cone frustum: pi (r1 + r2) L */
    CheckRel(log, total, PETSC_PI * 4 * 2.5, 1e-14, 0, "line3 axisymmetric: total = pi (r1 + r2) L");
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A flat line3 main face (2, 0) -> (0, 0), midside (1, 0), and the secondary nodes of a line3 face on it
 * ((0, g), (2, g), midside (1, g), face length 2) all pressed to the same penetration: pressure p on every
 * node, forces A_a p with A_a = w_a t in the ratio 1:4:1 on the secondary nodes (consistent nodal forces
 * p t L (1/6, 2/3, 1/6)), and the same on the main nodes, as the secondary nodes sit on them. */
static PetscErrorCode CheckUniformPressure(TestLog *log)
{
  const PetscReal sec[6] = {0, -0.01, 2, -0.01, 1, -0.01}, m1[2] = {2, 0}, m2[2] = {0, 0}, t = 1.5, p = 100;
  PetscReal       w[3], Rs[3], Rm[3] = {0, 0, 0}, R[12];
  TslContactLaw   law;

  PetscFunctionBeginUser;
  PetscCall(TslContactFaceIntegrate(TSL_CONTACT_FACE_LINE3, sec, w, NULL));
  PetscCall(TslContactLawSetDefaults(&law));
  law.eps_n = p / 0.01;
  for (PetscInt a = 0; a < 3; a++) {
    TslContactInput  in = InputSetUp(&sec[2 * a], m1, m2);
    TslContactOutput out;

    in.face      = TSL_CONTACT_FACE_LINE3;
    in.x[3][0]   = 1;
    in.x[3][1]   = 0;
    in.thickness = t;
    in.length    = w[a];
    PetscCall(TslContactElement(&law, &in, R, NULL, &out));
    Check(log, out.pressure, p, 1e-10, "uniform pressure: CPRESS at secondary node %d", (int)a + 1);
    Rs[a] = -R[1]; /* force on the secondary node (residual = -force) */
    for (PetscInt b = 0; b < 3; b++) Rm[b] += R[3 * (b + 1) + 1];
  }
  Check(log, Rs[2] / Rs[0], 4, 1e-12, "uniform pressure: secondary forces midside/end = 4");
  Check(log, Rs[1] / Rs[0], 1, 1e-12, "uniform pressure: secondary forces end/end = 1");
  Check(log, Rs[0], p * t * 2 / 6, 1e-10, "uniform pressure: end force = p t L / 6");
  Check(log, Rs[0] + Rs[1] + Rs[2], p * t * 2, 1e-10, "uniform pressure: total = p t L");
  Check(log, Rm[2] / Rm[0], 4, 1e-12, "uniform pressure: main forces midside/end = 4");
  Check(log, Rm[1] / Rm[0], 1, 1e-12, "uniform pressure: main forces end/end = 1");
  Check(log, Rm[0] + Rm[1] + Rm[2], p * t * 2, 1e-10, "uniform pressure: main reaction = p t L");
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  TestLog log = {0, 0};

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(CheckShapes(&log));
  PetscCall(CheckProjection(&log));
  PetscCall(CheckSmoothedKink(&log));
  PetscCall(CheckBox(&log));
  PetscCall(CheckWeights(&log));
  PetscCall(CheckUniformPressure(&log));
  PetscCall(PetscFinalize());
  return Summary(&log);
}
