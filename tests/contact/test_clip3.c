/* 3D surface-to-surface contact points (contact/clip3.c):
 *  - clipping: overlap areas of known configurations (offset squares, a square turned by 45 degrees: the
 *    regular octagon, triangles on squares, a tri6 face) equal the sum of the points' weights to 1e-12;
 *    faces that do not face each other give no points; reference areas (the weights) differ from the
 *    current ones by the area ratio; a trapezoid overlap takes one 2 x 2 rule, exact for its area and moments
 *    up to degree 3 in each direction of its bilinear map; a sheared parallelogram overlap's int N_b N_a dA (a
 *    uniform pressure's integrand) exact with its 2 x 2 rule;
 *  - a secondary face covered by four main faces: the weights of each node summed over the four overlaps
 *    (sum of N_b w) equal its tributary area (TslContactFace3Integrate), for tri3, quad4 and tri6;
 *  - the expanded element's tangent against central differences (open, stick, slip with heating, LAGRANGE,
 *    smoothing by tilted nodal normals), quad4 and tri6 secondary faces on a warped quad4 and a tri3 main
 *    face, and the secondary face's rows summing to the kernel's. */
#include "check.h"
#include <thermoslide/contact_s2s.h>

#define TRI3  0
#define QUAD4 1
#define TRI6  2
#define NU    TSL_CONTACT3_NU
#define MAXD  TSL_CONTACT_S2S3_MAX_DOF
#define CAP   TSL_CONTACT_OVERLAP_MAX_POINTS

static TslContactOverlapPoint Pts[CAP];

/* A flat face in the plane z = h: the corners (x, y) given; mirrored (normal -z) when down. tri6 gets the
 * middles of its edges. */
static void Flat(PetscInt kind, const PetscReal c[][2], PetscReal h, PetscBool down, PetscReal x[])
{
  const PetscInt nc = kind == QUAD4 ? 4 : 3, e[3][2] = {{0, 1}, {1, 2}, {2, 0}};

  for (PetscInt a = 0; a < nc; a++) {
    PetscInt src = down ? (nc - a) % nc : a; /* reversed order: 0, n-1, ..., 1 */
    x[3 * a] = c[src][0], x[3 * a + 1] = c[src][1], x[3 * a + 2] = h;
  }
  if (kind == TRI6)
    for (PetscInt m = 0; m < 3; m++)
      for (PetscInt d = 0; d < 3; d++) x[3 * (3 + m) + d] = 0.5 * (x[3 * e[m][0] + d] + x[3 * e[m][1] + d]);
}

/* The bilinear shape functions of a flat parallelogram main face (corners xp[3 a + d], a = 0..3 counter-
 * clockwise) at the plane point x: its affine map x = P0 + xi (P1 - P0) + eta (P3 - P0) inverted. */
static void MainShape(const PetscReal xp[12], const PetscReal x[2], PetscReal Na[4])
{
  const PetscReal e1[2] = {xp[3] - xp[0], xp[4] - xp[1]}, e2[2] = {xp[9] - xp[0], xp[10] - xp[1]}, r[2] = {x[0] - xp[0], x[1] - xp[1]};
  const PetscReal det = e1[0] * e2[1] - e1[1] * e2[0], xi = (r[0] * e2[1] - r[1] * e2[0]) / det, eta = (e1[0] * r[1] - e1[1] * r[0]) / det;

  Na[0] = (1 - xi) * (1 - eta), Na[1] = xi * (1 - eta), Na[2] = xi * eta, Na[3] = (1 - xi) * eta;
}

/* Gauss-Legendre on [0, 1], 5 points (degree 9): the references of the exactness checks */
static const PetscReal G5[5] = {0.04691007703066800360, 0.23076534494715845448, 0.5, 0.76923465505284154552, 0.95308992296933199640};
static const PetscReal W5[5] = {0.11846344252809454376, 0.23931433524968323402, 0.28444444444444444444, 0.23931433524968323402,
                                0.11846344252809454376};

/* M[b][a] += sum over the n points of Pts of w N_b N_a: N_b the quad4 secondary face's (corners xs), N_a the
 * parallelogram main face's (corners xm) at the point's place in the plane */
static void PointProducts(PetscInt n, const PetscReal xs[12], const PetscReal xm[12], PetscReal M[4][4])
{
  for (PetscInt q = 0; q < n; q++) {
    PetscReal x[2] = {0, 0}, Na[4];
    for (PetscInt b = 0; b < 4; b++)
      for (PetscInt d = 0; d < 2; d++) x[d] += Pts[q].N[b] * xs[3 * b + d];
    MainShape(xm, x, Na);
    for (PetscInt b = 0; b < 4; b++)
      for (PetscInt a = 0; a < 4; a++) M[b][a] += Pts[q].w * Pts[q].N[b] * Na[a];
  }
}

static PetscErrorCode Overlap(PetscInt skind, const PetscReal X[], const PetscReal y[], PetscInt mkind, const PetscReal ym[], PetscReal *sum, PetscInt *n)
{
  PetscFunctionBeginUser;
  PetscCall(TslContactOverlap3(skind, X, y, mkind, ym, CAP, Pts, n, NULL));
  *sum = 0;
  for (PetscInt q = 0; q < *n; q++) *sum += Pts[q].w;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckAreas(TestLog *log)
{
  /* secondary faces: bottom faces of an upper body (normal -z) at z = 0; main faces: top faces (normal +z)
   * at z = -0.01 */
  const PetscReal sq[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, off[4][2] = {{0.3, 0.4}, {1.3, 0.4}, {1.3, 1.4}, {0.3, 1.4}};
  const PetscReal tri[3][2] = {{0, 0}, {1, 0}, {0, 1}}, big[4][2] = {{-5, -5}, {5, -5}, {5, 5}, {-5, 5}};
  PetscReal       rot[4][2], xs[18], xm[18], X2[18], sum, r = PetscSqrtReal(0.5);
  PetscInt        n;

  PetscFunctionBeginUser;
  for (PetscInt a = 0; a < 4; a++) {
    PetscReal t = PETSC_PI / 4 + a * PETSC_PI / 2;
    rot[a][0] = 0.5 + r * PetscCosReal(t + PETSC_PI / 4), rot[a][1] = 0.5 + r * PetscSinReal(t + PETSC_PI / 4);
  }
  Flat(QUAD4, sq, 0, PETSC_TRUE, xs);
  Flat(QUAD4, off, -0.01, PETSC_FALSE, xm);
  PetscCall(Overlap(QUAD4, xs, xs, QUAD4, xm, &sum, &n));
  Check(log, sum, 0.42, 1e-12, "quad4 on quad4 offset by (0.3, 0.4): sum of weights = overlap 0.7 x 0.6");
  Flat(QUAD4, rot, -0.01, PETSC_FALSE, xm);
  PetscCall(Overlap(QUAD4, xs, xs, QUAD4, xm, &sum, &n));
  Check(log, sum, 2 * (PetscSqrtReal(2) - 1), 1e-12, "unit squares, one turned by 45 degrees: the octagon 2 (sqrt 2 - 1)");
  /* the octagon is fanned into 8 triangles, each with the 6-point rule: int N_b N_a dA (total degree 4 on each
   * triangle) exact for all 16 pairs against a conical 5 x 5 Gauss product rule on the same 8 triangles */
  {
    const PetscReal a = 1 - r, oct[8][2] = {{a, 0}, {r, 0}, {1, a}, {1, r}, {r, 1}, {a, 1}, {0, r}, {0, a}};
    PetscReal       M[4][4] = {{0}}, R[4][4] = {{0}}, err = 0, scale = 0;

    PointProducts(n, xs, xm, M);
    for (PetscInt t = 0; t < 8; t++) {
      const PetscReal *p1 = oct[t], *p2 = oct[(t + 1) % 8], p0[2] = {0.5, 0.5};
      const PetscReal  area = 0.5 * PetscAbsReal((p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1]));
      for (PetscInt i = 0; i < 5; i++)
        for (PetscInt j = 0; j < 5; j++) { /* x = p0 + u (p1 - p0) + u v (p2 - p1), dA = 2 area u du dv */
          const PetscReal u = G5[i], v = G5[j], wq = W5[i] * W5[j] * 2 * area * u;
          PetscReal       x[2], Nb[4], Na[4];
          for (PetscInt d = 0; d < 2; d++) x[d] = p0[d] + u * (p1[d] - p0[d]) + u * v * (p2[d] - p1[d]);
          for (PetscInt b = 0; b < 4; b++) Nb[b] = (xs[3 * b] > 0.5 ? x[0] : 1 - x[0]) * (xs[3 * b + 1] > 0.5 ? x[1] : 1 - x[1]);
          MainShape(xm, x, Na);
          for (PetscInt b = 0; b < 4; b++)
            for (PetscInt c = 0; c < 4; c++) R[b][c] += wq * Nb[b] * Na[c];
        }
    }
    for (PetscInt b = 0; b < 4; b++)
      for (PetscInt c = 0; c < 4; c++) err = PetscMax(err, PetscAbsReal(M[b][c] - R[b][c])), scale = PetscMax(scale, PetscAbsReal(R[b][c]));
    Check(log, (PetscReal)n, 8 * TSL_CONTACT_TRI_GAUSS, 0, "the octagon: 8 fan triangles x the 6-point rule");
    Check(log, err / scale, 0, 1e-13, "the octagon: int N_b N_a dA, all 16, against a conical 5 x 5 Gauss rule on its fan");
  }
  Flat(TRI3, tri, -0.01, PETSC_FALSE, xm);
  PetscCall(Overlap(QUAD4, xs, xs, TRI3, xm, &sum, &n));
  Check(log, sum, 0.5, 1e-12, "tri3 main on the unit quad4: 1/2");
  Flat(TRI3, tri, 0, PETSC_TRUE, xs);
  Flat(QUAD4, off, -0.01, PETSC_FALSE, xm);
  PetscCall(Overlap(TRI3, xs, xs, QUAD4, xm, &sum, &n));
  Check(log, sum, 0.045, 1e-12, "tri3 secondary on the offset quad4: the corner triangle 0.3 x 0.3 / 2");
  Flat(TRI6, tri, 0, PETSC_TRUE, xs);
  PetscCall(Overlap(TRI6, xs, xs, QUAD4, xm, &sum, &n));
  Check(log, sum, 0.045, 1e-12, "tri6 secondary (four sub-triangles) on the offset quad4");
  Flat(QUAD4, big, -0.01, PETSC_FALSE, xm);
  PetscCall(Overlap(TRI6, xs, xs, QUAD4, xm, &sum, &n));
  Check(log, sum, 0.5, 1e-12, "tri6 secondary covered: its area");
  /* reference twice the size of the current face: weights are reference areas */
  for (PetscInt i = 0; i < 18; i++) X2[i] = 2 * xs[i];
  PetscCall(Overlap(TRI6, X2, xs, QUAD4, xm, &sum, &n));
  Check(log, sum, 2.0, 1e-12, "tri6 covered, reference face twice the current: reference area 2");
  /* a trapezoid overlap (a main quad whose slanted edge crosses the unit square's bottom and top): one 2 x 2
   * rule through its bilinear map, 4 points (the main face is linear), exact for the area and the moments whose
   * integrand times the map's Jacobian is of degree <= 3 in each direction (int x dA, int x^2 dA, int x y dA; the
   * fan of four 7-point triangles gave 28 points); int x^2 y dA (degree 4) is not */
  {
    const PetscReal trap[4][2] = {{-0.5, -0.5}, {0.9, -0.5}, {0.6, 1.5}, {-0.5, 1.5}}, a = 0.825, b = 0.15;
    PetscReal       mx = 0, mxx = 0, mxy = 0, mxxy = 0, xq[12], xt[12], exy;
    Flat(QUAD4, sq, 0, PETSC_TRUE, xq);
    Flat(QUAD4, trap, -0.01, PETSC_FALSE, xt);
    PetscCall(Overlap(QUAD4, xq, xq, QUAD4, xt, &sum, &n));
    for (PetscInt q = 0; q < n; q++) {
      PetscReal x = 0, y = 0;
      for (PetscInt c = 0; c < 4; c++) x += Pts[q].N[c] * xq[3 * c], y += Pts[q].N[c] * xq[3 * c + 1];
      mx += Pts[q].w * x, mxx += Pts[q].w * x * x, mxy += Pts[q].w * x * y, mxxy += Pts[q].w * x * x * y;
    }
    /* the overlap: 0 <= y <= 1, 0 <= x <= a - b y */
    exy = (PetscPowRealInt(a, 5) - 5 * a * PetscPowRealInt(a - b, 4) + 4 * PetscPowRealInt(a - b, 5)) / (60 * b * b);
    Check(log, (PetscReal)n, 4, 0, "trapezoid overlap: one 2 x 2 rule (4 points)");
    Check(log, sum, 0.75, 1e-12, "trapezoid overlap: sum of weights = its area 0.75");
    Check(log, mx, (PetscPowRealInt(a, 3) - PetscPowRealInt(a - b, 3)) / (6 * b), 1e-12, "trapezoid overlap: int x dA");
    Check(log, mxx, (PetscPowRealInt(a, 4) - PetscPowRealInt(a - b, 4)) / (12 * b), 1e-12, "trapezoid overlap: int x^2 dA");
    Check(log, mxy, 0.5 * (a * a / 2 - 2 * a * b / 3 + b * b / 4), 1e-12, "trapezoid overlap: int x y dA");
    Check(log, PetscAbsReal(mxxy - exy) / exy > 1e-6 ? 1.0 : 0.0, 1, 0, "trapezoid overlap: int x^2 y dA (degree 4) is not exact");
  }
  /* a parallelogram overlap with one pair of edges from each face (the square's sides x = 0, 1 and a sheared
   * main face's sides of slope 0.2): int N_b N_a dA, the integrand of a uniform pressure, is of degree <= 3 in
   * each direction of the overlap, so the 2 x 2 rule gives all 16 products exactly (reference: 5 x 5 Gauss
   * on the overlap's affine map x = s, y = 0.3 + 0.2 s + 0.3 t) */
  {
    const PetscReal par[4][2] = {{-0.5, 0.2}, {1.5, 0.6}, {1.5, 0.9}, {-0.5, 0.5}};
    PetscReal       xq[12], xp[12], M[4][4] = {{0}}, R[4][4] = {{0}}, err = 0, scale = 0;

    Flat(QUAD4, sq, 0, PETSC_TRUE, xq);
    Flat(QUAD4, par, -0.01, PETSC_FALSE, xp);
    PetscCall(Overlap(QUAD4, xq, xq, QUAD4, xp, &sum, &n));
    Check(log, (PetscReal)n, 4, 0, "sheared parallelogram overlap: one 2 x 2 rule (4 points)");
    PointProducts(n, xq, xp, M);
    for (PetscInt i = 0; i < 5; i++)
      for (PetscInt j = 0; j < 5; j++) {
        const PetscReal x[2] = {G5[i], 0.3 + 0.2 * G5[i] + 0.3 * G5[j]}, wq = W5[i] * W5[j] * 0.3;
        PetscReal       Nb[4], Na[4];
        for (PetscInt b = 0; b < 4; b++) /* the square's bilinear functions, its corners as Flat() put them */
          Nb[b] = (xq[3 * b] > 0.5 ? x[0] : 1 - x[0]) * (xq[3 * b + 1] > 0.5 ? x[1] : 1 - x[1]);
        MainShape(xp, x, Na);
        for (PetscInt b = 0; b < 4; b++)
          for (PetscInt a = 0; a < 4; a++) R[b][a] += wq * Nb[b] * Na[a];
      }
    for (PetscInt b = 0; b < 4; b++)
      for (PetscInt a = 0; a < 4; a++) err = PetscMax(err, PetscAbsReal(M[b][a] - R[b][a])), scale = PetscMax(scale, PetscAbsReal(R[b][a]));
    Check(log, err / scale, 0, 1e-13, "sheared parallelogram overlap: int N_b N_a dA, all 16, 2 x 2 rule against 5 x 5");
  }
  /* same orientation (not facing): nothing */
  Flat(QUAD4, big, -0.01, PETSC_TRUE, xm);
  PetscCall(Overlap(TRI6, xs, xs, QUAD4, xm, &sum, &n));
  Check(log, (PetscReal)n, 0, 0, "faces not facing each other: no points");
  /* beside each other: nothing */
  {
    const PetscReal far[4][2] = {{1, 0}, {2, 0}, {2, 1}, {1, 1}};
    Flat(QUAD4, sq, 0, PETSC_TRUE, xs);
    Flat(QUAD4, far, -0.01, PETSC_FALSE, xm);
    PetscCall(Overlap(QUAD4, xs, xs, QUAD4, xm, &sum, &n));
    Check(log, (PetscReal)n, 0, 0, "faces sharing only an edge in projection: no points");
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A tilted secondary face (normal not along z) covered by four main quads cut at (0.37, 0.61) of a slightly
 * tilted main plane: per node, the sum of N_b w over the overlaps equals int N_b dA. */
static PetscErrorCode CheckTributary(TestLog *log, PetscInt kind)
{
  const PetscReal sq[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, tri[3][2] = {{0, 0}, {1, 0}, {0, 1}}, cx[3] = {-2, 0.37, 3}, cy[3] = {-2, 0.61, 3};
  PetscReal       xs[18], w[6], acc[6] = {0, 0, 0, 0, 0, 0}, area, tot = 0, err = 0;
  const char     *name[3] = {"tri3", "quad4", "tri6"};

  PetscFunctionBeginUser;
  Flat(kind, kind == QUAD4 ? sq : tri, 0, PETSC_TRUE, xs);
  for (PetscInt a = 0; a < 6; a++) xs[3 * a + 2] = 0.1 * xs[3 * a] + 0.05 * xs[3 * a + 1]; /* the plane z = 0.1 x + 0.05 y */
  PetscCall(TslContactFace3Integrate(kind, xs, w, &area));
  for (PetscInt i = 0; i < 2; i++)
    for (PetscInt j = 0; j < 2; j++) {
      const PetscReal c[4][2] = {{cx[i], cy[j]}, {cx[i + 1], cy[j]}, {cx[i + 1], cy[j + 1]}, {cx[i], cy[j + 1]}};
      PetscReal       xm[12], sum;
      PetscInt        n;
      Flat(QUAD4, c, 0, PETSC_FALSE, xm);
      for (PetscInt a = 0; a < 4; a++) xm[3 * a + 2] = 0.09 * xm[3 * a] + 0.06 * xm[3 * a + 1] - 0.02;
      PetscCall(Overlap(kind, xs, xs, QUAD4, xm, &sum, &n));
      tot += sum;
      for (PetscInt q = 0; q < n; q++)
        for (PetscInt b = 0; b < TslContactFace3Nodes(kind); b++) acc[b] += Pts[q].N[b] * Pts[q].w;
    }
  for (PetscInt b = 0; b < TslContactFace3Nodes(kind); b++) err = PetscMax(err, PetscAbsReal(acc[b] - w[b]));
  Check(log, tot, area, 1e-12 * area, "%s tilted, covered by four main faces: sum of weights = face area", name[kind]);
  Check(log, err, 0, 1e-12 * area, "%s: per node, sum of N_b w over the overlaps = int N_b dA (max difference)", name[kind]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

typedef struct {
  TslContactInput3 in;
  PetscInt         skind, nsn;
  PetscReal        N[6], X[18], U[4 * 6];
} Case;

static PetscReal *Unknown(Case *c, PetscInt i)
{
  PetscInt node = i / NU, comp = i % NU;
  if (node < c->nsn) return &c->U[NU * node + comp];
  return &c->in.u[1 + node - c->nsn][comp];
}

static PetscErrorCode Eval(const TslContactLaw *law, Case *c, PetscReal R[], PetscReal K[], TslContactOutput *out)
{
  PetscFunctionBeginUser;
  TslContactPointSetUp3(c->nsn, c->N, c->X, c->U, &c->in);
  if (R) PetscCall(PetscArrayzero(R, MAXD)); /* the point's block is added to R, K */
  if (K) PetscCall(PetscArrayzero(K, MAXD * MAXD));
  PetscCall(TslContactPointElement3(law, &c->in, c->nsn, c->N, R, K, out));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Main face (body below): a warped quad4 or a tri3 around the origin; secondary face above it (normal down),
 * at height gap + the main face's height, small displacements and temperatures; the point is the fourth
 * of the overlap's points (with smoothing the one nearest the secondary face's first corner). History: the start of the increment ds away (reference
 * units), the anchor `anchor` beyond it. */
static PetscErrorCode CaseSetUp(Case *c, PetscInt mkind, PetscInt skind, PetscReal gap, PetscReal smoothing, PetscReal ds, PetscReal anchor)
{
  const PetscReal quad[4][3] = {{-0.6, -0.6, 0}, {0.6, -0.54, 0.05}, {0.66, 0.6, -0.05}, {-0.54, 0.66, 0.04}}, tri[3][3] = {{-0.6, -0.6, 0}, {0.8, -0.5, 0.05}, {-0.4, 0.9, -0.05}};
  const PetscReal ss[4][2] = {{-0.3, -0.35}, {0.35, -0.3}, {0.3, 0.3}, {-0.35, 0.32}}, st[3][2] = {{-0.3, -0.35}, {0.4, -0.3}, {-0.2, 0.4}};
  PetscReal       ym[18], y[18];
  PetscInt        nm = TslContactFace3Nodes(mkind), n;
  TslContactOutput o;

  PetscFunctionBeginUser;
  memset(c, 0, sizeof(*c));
  c->skind        = skind;
  c->nsn          = TslContactFace3Nodes(skind);
  c->in.face      = mkind;
  c->in.dt        = 0.2;
  c->in.smoothing = smoothing;
  for (PetscInt a = 0; a < nm; a++) {
    for (PetscInt d = 0; d < 3; d++) {
      c->in.x[1 + a][d] = mkind == QUAD4 ? quad[a][d] : tri[a][d];
      c->in.u[1 + a][d] = 0.002 * PetscSinReal(1.0 + 3 * a + d);
      ym[3 * a + d]     = c->in.x[1 + a][d] + c->in.u[1 + a][d];
    }
    c->in.u[1 + a][3] = 100 + 10 * a;
    /* nodal normals: +z tilted differently at each node */
    {
      PetscReal t[3] = {0.1 * PetscCosReal(2.0 * a), 0.1 * PetscSinReal(2.0 * a), 1}, l = PetscSqrtReal(t[0] * t[0] + t[1] * t[1] + 1);
      for (PetscInt d = 0; d < 3; d++) c->in.nodal_normal[a][d] = t[d] / l;
    }
  }
  Flat(skind, skind == QUAD4 ? ss : st, 0, PETSC_TRUE, c->X);
  for (PetscInt b = 0; b < c->nsn; b++) {
    c->X[3 * b + 2] = gap + 0.02 * c->X[3 * b] - 0.01 * c->X[3 * b + 1];
    if (skind == TRI6 && b >= 3) c->X[3 * b + 2] += 0.01; /* curved */
    for (PetscInt k = 0; k < NU; k++) c->U[NU * b + k] = k < 3 ? 0.003 * PetscCosReal(2.0 + 5 * b + k) : 40 + 3 * b;
    for (PetscInt d = 0; d < 3; d++) y[3 * b + d] = c->X[3 * b + d] + c->U[NU * b + d];
  }
  PetscCall(TslContactOverlap3(skind, c->X, y, mkind, ym, CAP, Pts, &n, NULL));
  PetscCheck(n > 3, PETSC_COMM_SELF, PETSC_ERR_PLIB, "test faces do not overlap");
  {
    /* smoothed: the point nearest the secondary face's first corner, towards the main face's edges (tri6 on
     * tri3: in the rounded zone, barycentric 0.18 < s); otherwise one off the centre. Chosen by position, not
     * by the rule's order (which depends on the overlap's shape). */
    PetscInt  q    = PetscMin(3, n - 1);
    PetscReal best = PETSC_MAX_REAL;
    for (PetscInt k = 0; smoothing > 0 && k < n; k++) {
      PetscReal x[3] = {0, 0, 0}, d2 = 0;
      for (PetscInt b = 0; b < c->nsn; b++)
        for (PetscInt d = 0; d < 3; d++) x[d] += Pts[k].N[b] * c->X[3 * b + d];
      for (PetscInt d = 0; d < 2; d++) d2 += (x[d] - c->X[d]) * (x[d] - c->X[d]);
      if (d2 < best) best = d2, q = k;
    }
    for (PetscInt b = 0; b < c->nsn; b++) c->N[b] = Pts[q].N[b];
    c->in.area = Pts[q].w;
  }
  TslContactPointSetUp3(c->nsn, c->N, c->X, c->U, &c->in);
  {
    TslContactLaw law;
    PetscCall(TslContactLawSetDefaults(&law));
    law.eps_n = 2e4;
    PetscCall(TslContactElement3(&law, &c->in, NULL, NULL, &o));
  }
  c->in.hist.xi_old     = o.xi + ds;
  c->in.hist.eta_old    = o.eta - 0.5 * ds;
  c->in.hist.xi_anchor  = c->in.hist.xi_old + anchor;
  c->in.hist.eta_anchor = c->in.hist.eta_old + 0.7 * anchor;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckTangent(TestLog *log, const char *name, const TslContactLaw *law, Case *c, TslContactStatus status)
{
  static PetscReal K[MAXD * MAXD], Kfd[MAXD * MAXD];
  PetscReal        Rp[MAXD], Rm[MAXD], R0[MAXD], Rk[NU * 7], sum[NU] = {0, 0, 0, 0};
  TslContactOutput out, op, om, o;
  PetscInt         nd, kind[MAXD];
  const char      *kname[2] = {"u", "theta"};

  PetscFunctionBeginUser;
  PetscCall(Eval(law, c, R0, K, &out));
  nd = NU * out.nnode;
  Check(log, (PetscReal)out.status, status, 0, "%s: status (gap %g, p %g)", name, (double)out.gap, (double)out.pressure);
  PetscCall(TslContactElement3(law, &c->in, Rk, NULL, &o));
  for (PetscInt b = 0; b < c->nsn; b++)
    for (PetscInt k = 0; k < NU; k++) sum[k] += R0[NU * b + k];
  for (PetscInt k = 0; k < NU; k++) Check(log, sum[k], Rk[k], 1e-12 * (1 + PetscAbsReal(Rk[k])), "%s: sum of the face's rows %d = kernel's", name, (int)k);
  for (PetscInt j = 0; j < nd; j++) {
    PetscReal *v = Unknown(c, j), v0 = *v, h = (j % NU == 3) ? 1e-5 * PetscMax(1, PetscAbsReal(v0)) : 1e-7;

    *v = v0 + h;
    PetscCall(Eval(law, c, Rp, NULL, &op));
    *v = v0 - h;
    PetscCall(Eval(law, c, Rm, NULL, &om));
    *v = v0;
    PetscCheck(op.status == out.status && om.status == out.status, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: perturbation %d changes the status", name, (int)j);
    for (PetscInt i = 0; i < nd; i++) Kfd[i * nd + j] = (Rp[i] - Rm[i]) / (2 * h);
  }
  PetscCall(Eval(law, c, R0, K, &out));
  for (PetscInt i = 0; i < nd; i++) kind[i] = i % NU == 3;
  CheckTangentBlocks(log, name, nd, K, Kfd, kind, 2, kname);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckTangents(TestLog *log, PetscInt mkind, PetscInt skind, PetscReal s)
{
  TslContactLaw   law;
  Case            c;
  const PetscReal kp[2] = {100, 400}, kv[2] = {20, 5};
  const char     *fn[3] = {"tri3", "quad4", "tri6"};
  char            name[160];
  const PetscReal ds = 0.005;

  PetscFunctionBeginUser;
  TestLawSetUp(&law, PETSC_TRUE); /* open: clearance conductance and radiation */
  PetscCall(CaseSetUp(&c, mkind, skind, 0.04, s, ds, 0));
  snprintf(name, sizeof(name), "%s on %s%s: open, clearance conductance + radiation", fn[skind], fn[mkind], s > 0 ? " smoothed" : "");
  PetscCall(CheckTangent(log, name, &law, &c, TSL_CONTACT_OPEN));
  law.conductance = TSL_CONTACT_CONDUCTANCE_PRESSURE;
  law.k_n = 2, law.k_arg = kp, law.k_value = kv;
  law.F_n = 0;
  PetscCall(CaseSetUp(&c, mkind, skind, -0.01, s, ds, -0.5 * ds));
  snprintf(name, sizeof(name), "%s on %s%s: stick, pressure conductance", fn[skind], fn[mkind], s > 0 ? " smoothed" : "");
  PetscCall(CheckTangent(log, name, &law, &c, TSL_CONTACT_STICK));
  law.F_n = 2;
  PetscCall(CaseSetUp(&c, mkind, skind, -0.01, s, ds, 10 * ds));
  snprintf(name, sizeof(name), "%s on %s%s: slip + radiation + heating", fn[skind], fn[mkind], s > 0 ? " smoothed" : "");
  PetscCall(CheckTangent(log, name, &law, &c, TSL_CONTACT_SLIP));
  law.friction = TSL_CONTACT_FRICTION_LAGRANGE;
  law.slip_tol = 1e-6;
  PetscCall(CaseSetUp(&c, mkind, skind, -0.01, s, ds, 0));
  snprintf(name, sizeof(name), "%s on %s%s: Lagrange slip + heating", fn[skind], fn[mkind], s > 0 ? " smoothed" : "");
  PetscCall(CheckTangent(log, name, &law, &c, TSL_CONTACT_SLIP));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  TestLog log = {0, 0};

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(CheckAreas(&log));
  for (PetscInt k = 0; k < 3; k++) PetscCall(CheckTributary(&log, k));
  PetscCall(CheckTangents(&log, QUAD4, QUAD4, 0));
  PetscCall(CheckTangents(&log, QUAD4, QUAD4, 0.2));
  PetscCall(CheckTangents(&log, TRI3, TRI6, 0.2));
  PetscCall(CheckTangents(&log, QUAD4, TRI3, 0));
  PetscCall(PetscFinalize());
  return Summary(&log);
}
