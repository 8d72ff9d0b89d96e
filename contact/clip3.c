/* 3D surface-to-surface contact points: the overlap of a secondary face with a main face by polygon
 * clipping, a triangle rule on the overlap, and the 3D node-to-surface kernel at a point expanded to the
 * secondary face's nodes. Interface: include/thermoslide/contact_s2s.h; method: docs/contact.md,
 * "3D surface-to-surface". */
#include <thermoslide/contact_s2s.h>
#include "contact_impl.h"

/* The 6-point rule of degree 4 on the triangle (Strang & Fix; Dunavant): two orbits (a, a, 1 - 2a), positive
 * weights (relative to the triangle's area). */
#define T6A1 0.44594849091596488632
#define T6B1 0.10810301816807022736 /* 1 - 2 T6A1 */
#define T6W1 0.22338158967801146594
#define T6A2 0.09157621350977074346
#define T6B2 0.81684757298045851308 /* 1 - 2 T6A2 */
#define T6W2 0.10995174365532186739
static const PetscReal TriL[TSL_CONTACT_TRI_GAUSS][3] = {{T6A1, T6A1, T6B1}, {T6A1, T6B1, T6A1}, {T6B1, T6A1, T6A1},
                                                         {T6A2, T6A2, T6B2}, {T6A2, T6B2, T6A2}, {T6B2, T6A2, T6A2}};
static const PetscReal TriW[TSL_CONTACT_TRI_GAUSS]    = {T6W1, T6W1, T6W1, T6W2, T6W2, T6W2};
/* Gauss-Legendre on [-1, 1]: 2 points (degree 3) and 3 points (degree 5) */
static const PetscReal G2[2] = {-0.57735026918962576451, 0.57735026918962576451}, W2[2] = {1, 1};
static const PetscReal G3[3] = {-0.77459666924148337704, 0, 0.77459666924148337704}, W3[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};

PetscReal TslContactPolygonArea(PetscInt n, const PetscReal P[])
{
  PetscReal a = 0;
  /* relative to the first vertex: no digits lost to the position of the polygon */
  for (PetscInt i = 1; i + 1 < n; i++) a += (P[2 * i] - P[0]) * (P[2 * i + 3] - P[1]) - (P[2 * i + 2] - P[0]) * (P[2 * i + 1] - P[1]);
  return 0.5 * a;
}

PetscErrorCode TslContactClipPolygon(PetscInt n, const PetscReal P[], PetscInt m, const PetscReal C[], PetscInt cap, PetscReal Q[], PetscInt *nq)
{
  PetscReal A[2 * TSL_CONTACT_CLIP_MAX_VERTICES], B[2 * TSL_CONTACT_CLIP_MAX_VERTICES];
  PetscInt  na = n;

  PetscFunctionBeginUser;
  PetscCheck(n <= TSL_CONTACT_CLIP_MAX_VERTICES, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Polygon with more than %d vertices", TSL_CONTACT_CLIP_MAX_VERTICES);
  for (PetscInt i = 0; i < 2 * n; i++) A[i] = P[i];
  for (PetscInt k = 0; k < m && na > 0; k++) {
    const PetscReal *c0 = &C[2 * k], *c1 = &C[2 * ((k + 1) % m)];
    const PetscReal  ex = c1[0] - c0[0], ey = c1[1] - c0[1];
    PetscInt         nb = 0;

    /* keep the part on the left of the edge c0 -> c1 (inside a counter-clockwise convex polygon) */
    for (PetscInt i = 0; i < na; i++) {
      const PetscReal *p = &A[2 * i], *q = &A[2 * ((i + 1) % na)];
      const PetscReal  sp = ex * (p[1] - c0[1]) - ey * (p[0] - c0[0]), sq = ex * (q[1] - c0[1]) - ey * (q[0] - c0[0]);

      if (sp >= 0) {
        PetscCheck(nb < TSL_CONTACT_CLIP_MAX_VERTICES, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Clipped polygon too large");
        B[2 * nb] = p[0], B[2 * nb + 1] = p[1], nb++;
      }
      if ((sp >= 0) != (sq >= 0)) {
        const PetscReal t = sp / (sp - sq);
        PetscCheck(nb < TSL_CONTACT_CLIP_MAX_VERTICES, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Clipped polygon too large");
        B[2 * nb] = p[0] + t * (q[0] - p[0]), B[2 * nb + 1] = p[1] + t * (q[1] - p[1]), nb++;
      }
    }
    na = nb;
    for (PetscInt i = 0; i < 2 * na; i++) A[i] = B[i];
  }
  PetscCheck(na <= cap, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Clipped polygon has %" PetscInt_FMT " vertices, room for %" PetscInt_FMT, na, cap);
  for (PetscInt i = 0; i < 2 * na; i++) Q[i] = A[i];
  *nq = na;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static void Cross(const PetscReal a[3], const PetscReal b[3], PetscReal c[3])
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

static PetscReal Dot(const PetscReal a[3], const PetscReal b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Area vector of a linear face's corners y[3*a + d] (3 or 4): exact for a flat triangle and for the bilinear
 * quad (half the cross product of the diagonals); right-hand rule on the face order. */
static void AreaVector(PetscInt nc, const PetscReal y[], PetscReal A[3])
{
  PetscReal e[3], g[3];
  for (PetscInt d = 0; d < 3; d++) {
    e[d] = nc == 4 ? y[6 + d] - y[d] : y[3 + d] - y[d];
    g[d] = nc == 4 ? y[9 + d] - y[3 + d] : y[6 + d] - y[d];
  }
  Cross(e, g, A);
  for (PetscInt d = 0; d < 3; d++) A[d] *= 0.5;
}

/* Parameters xi[2] of the plane point q on the linear piece whose corners are P[2*a + d] in the plane
 * (geometry g: tri3 affine, quad4 bilinear by Newton from the centre); N[], dN[] there and the plane
 * Jacobian det(dq/dxi). */
static PetscErrorCode PieceParameters(const TslGeometry *g, const PetscReal P[], const PetscReal q[2], PetscReal xi[2], PetscReal N[], PetscReal dN[],
                                      PetscReal *Jp)
{
  PetscReal z[3] = {0, 0, 0};

  PetscFunctionBeginUser;
  z[0] = z[1] = g->nnode == 4 ? 0 : 1.0 / 3; /* the centre */
  for (PetscInt it = 0;; it++) {
    PetscReal r[2] = {-q[0], -q[1]}, J[2][2] = {{0, 0}, {0, 0}}, dz[2];

    g->shape(z, N, dN);
    for (PetscInt a = 0; a < g->nnode; a++)
      for (PetscInt d = 0; d < 2; d++) {
        r[d] += N[a] * P[2 * a + d];
        for (PetscInt i = 0; i < 2; i++) J[d][i] += dN[2 * a + i] * P[2 * a + d];
      }
    *Jp = J[0][0] * J[1][1] - J[0][1] * J[1][0];
    r[0] = -r[0], r[1] = -r[1];
    PetscCheck(TslContactSolve2(J, r, dz), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "Degenerate secondary face in surface-to-surface contact");
    z[0] += dz[0], z[1] += dz[1];
    if (PetscMax(PetscAbsReal(dz[0]), PetscAbsReal(dz[1])) < 1e-14 || g->nnode == 3) {
      /* one more evaluation at the final parameters (affine: the step was exact) */
      g->shape(z, N, dN);
      J[0][0] = J[0][1] = J[1][0] = J[1][1] = 0;
      for (PetscInt a = 0; a < g->nnode; a++)
        for (PetscInt d = 0; d < 2; d++)
          for (PetscInt i = 0; i < 2; i++) J[d][i] += dN[2 * a + i] * P[2 * a + d];
      *Jp = J[0][0] * J[1][1] - J[0][1] * J[1][0];
      break;
    }
    PetscCheck(it < 50, PETSC_COMM_SELF, PETSC_ERR_CONV_FAILED, "Surface-to-surface: inverse map of a secondary quad did not converge");
  }
  xi[0] = z[0], xi[1] = z[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The clipped polygon's corners: its vertices less those that add no area (repeated, or collinear with
 * their neighbours: below 1e-14 of the overlap's area aq); returns how many. */
static PetscInt Corners(PetscInt nq, const PetscReal Q[], PetscReal aq, PetscReal V[])
{
  PetscInt nv = 0;

  for (PetscInt i = 0; i < nq; i++) {
    const PetscReal *a = nv ? &V[2 * (nv - 1)] : &Q[2 * (nq - 1)], *b = &Q[2 * i], *c = &Q[2 * ((i + 1) % nq)];
    if (0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])) <= 1e-14 * aq) continue;
    V[2 * nv] = b[0], V[2 * nv + 1] = b[1], nv++;
  }
  if (nv >= 3) { /* the first corner against the last one kept */
    const PetscReal *a = &V[2 * (nv - 1)], *b = &V[0], *c = &V[2];
    if (0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])) <= 1e-14 * aq) {
      for (PetscInt i = 0; i + 1 < nv; i++) V[2 * i] = V[2 * i + 2], V[2 * i + 1] = V[2 * i + 3];
      nv--;
    }
  }
  return nv;
}

/* Whether the quadrilateral V0..V3 is a parallelogram (V0 + V2 = V1 + V3 to 1e-12 of its size). */
static PetscBool Parallelogram(const PetscReal V[8])
{
  PetscReal size = 0, gap = 0;
  for (PetscInt d = 0; d < 2; d++) {
    size = PetscMax(size, PetscMax(PetscAbsReal(V[4 + d] - V[d]), PetscAbsReal(V[6 + d] - V[2 + d])));
    gap  = PetscMax(gap, PetscAbsReal(V[d] + V[4 + d] - V[2 + d] - V[6 + d]));
  }
  return (PetscBool)(gap <= 1e-12 * size);
}

/* A point of the overlap at plane coordinates q with plane weight w: its parameters on the piece (P its
 * corners in the plane, Xp in the reference configuration, idx its nodes on the face), the face's shape
 * functions there and its weight as a reference area (w dA_ref / dA_plane). */
static PetscErrorCode AddPoint(const TslGeometry *sg, const TslGeometry *pg, PetscInt nc, const PetscInt idx[], const PetscReal P[],
                               const PetscReal Xp[], const PetscReal q[2], PetscReal w, PetscInt cap, TslContactOverlapPoint pt[], PetscInt *npt)
{
  PetscReal               xi[2], N[4], dN[8], Jp, a1[3] = {0, 0, 0}, a2[3] = {0, 0, 0}, cr[3];
  TslContactOverlapPoint *o;

  PetscFunctionBeginUser;
  PetscCall(PieceParameters(pg, P, q, xi, N, dN, &Jp));
  for (PetscInt a = 0; a < nc; a++)
    for (PetscInt d = 0; d < 3; d++) a1[d] += dN[2 * a] * Xp[3 * a + d], a2[d] += dN[2 * a + 1] * Xp[3 * a + d];
  Cross(a1, a2, cr);
  PetscCheck(*npt < cap, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "More than %" PetscInt_FMT " surface-to-surface points on a face pair", cap);
  o = &pt[(*npt)++];
  for (PetscInt b = 0; b < sg->nnode; b++) o->N[b] = 0;
  for (PetscInt a = 0; a < nc; a++) o->N[idx[a]] = N[a];
  o->w = w * PetscSqrtReal(Dot(cr, cr)) / Jp;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslContactOverlap3(PetscInt skind, const PetscReal X[], const PetscReal y[], PetscInt mkind, const PetscReal ym[], PetscInt cap,
                                  TslContactOverlapPoint pt[], PetscInt *npt, PetscReal *dist)
{
  const TslContactFace3 *sf = TslContactFace3Get(skind), *mf = TslContactFace3Get(mkind);
  const TslGeometry     *sg, *pg;
  PetscInt               npiece, mc;
  PetscBool              mlin;
  PetscReal              Am[3], nm[3], cm[3] = {0, 0, 0}, lm, dsum = 0, asum = 0;

  PetscFunctionBeginUser;
  PetscCheck(sf && mf, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Unknown 3D contact face family");
  sg     = sf->geom;
  pg     = sg->nsub ? sg->sub_geom : sg; /* the linear pieces: the face itself, or tri6's sub-triangles */
  npiece = sg->nsub ? sg->nsub : 1;
  mc     = mf->geom->ncorner;
  mlin   = (PetscBool)(mf->geom->nnode == mc);
  *npt   = 0;
  AreaVector(mc, ym, Am);
  lm = PetscSqrtReal(Dot(Am, Am));
  if (!(lm > 0)) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt d = 0; d < 3; d++) nm[d] = Am[d] / lm;
  for (PetscInt a = 0; a < mc; a++)
    for (PetscInt d = 0; d < 3; d++) cm[d] += ym[3 * a + d] / mc;
  for (PetscInt s = 0; s < npiece; s++) {
    PetscInt    idx[4], nc = pg->nnode, nq;
    PetscReal   yp[12], Xp[12], As[3], ns[3], c[3] = {0, 0, 0}, e1[3], e2[3], la, P[8], M[8], Q[2 * TSL_CONTACT_CLIP_MAX_VERTICES], ap, aq, qc[2] = {0, 0}, qm[2] = {0, 0};

    for (PetscInt a = 0; a < nc; a++) {
      idx[a] = sg->nsub ? sg->sub_node[s][a] : a;
      for (PetscInt d = 0; d < 3; d++) yp[3 * a + d] = y[3 * idx[a] + d], Xp[3 * a + d] = X[3 * idx[a] + d];
    }
    /* the piece's plane: centroid, unit area normal n_s, e1 along its first edge, e2 = n_s x e1 */
    AreaVector(nc, yp, As);
    la = PetscSqrtReal(Dot(As, As));
    PetscCheck(la > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "Surface-to-surface: a secondary face of zero area");
    for (PetscInt d = 0; d < 3; d++) ns[d] = As[d] / la;
    if (Dot(ns, nm) >= 0) continue; /* not facing */
    for (PetscInt a = 0; a < nc; a++)
      for (PetscInt d = 0; d < 3; d++) c[d] += yp[3 * a + d] / nc;
    for (PetscInt d = 0; d < 3; d++) e1[d] = yp[3 + d] - yp[d];
    {
      PetscReal t = Dot(e1, ns), l;
      for (PetscInt d = 0; d < 3; d++) e1[d] -= t * ns[d];
      l = PetscSqrtReal(Dot(e1, e1));
      for (PetscInt d = 0; d < 3; d++) e1[d] /= l;
    }
    Cross(ns, e1, e2);
    for (PetscInt a = 0; a < nc; a++) {
      PetscReal v[3];
      for (PetscInt d = 0; d < 3; d++) v[d] = yp[3 * a + d] - c[d];
      P[2 * a] = Dot(v, e1), P[2 * a + 1] = Dot(v, e2);
    }
    /* the main face's corners projected along n_s, counter-clockwise */
    for (PetscInt a = 0; a < mc; a++) {
      PetscReal v[3];
      for (PetscInt d = 0; d < 3; d++) v[d] = ym[3 * a + d] - c[d];
      M[2 * a] = Dot(v, e1), M[2 * a + 1] = Dot(v, e2);
    }
    if (TslContactPolygonArea(mc, M) < 0)
      for (PetscInt a = 0; a < mc / 2; a++)
        for (PetscInt d = 0; d < 2; d++) {
          PetscReal t             = M[2 * a + d];
          M[2 * a + d]            = M[2 * (mc - 1 - a) + d];
          M[2 * (mc - 1 - a) + d] = t;
        }
    ap = TslContactPolygonArea(nc, P);
    PetscCall(TslContactClipPolygon(mc, M, nc, P, TSL_CONTACT_CLIP_MAX_VERTICES, Q, &nq));
    if (nq < 3) continue;
    aq = TslContactPolygonArea(nq, Q);
    if (aq <= 1e-10 * ap) continue; /* faces that only touch along an edge or at a corner */
    /* fan from the vertex centroid (inside: the overlap is convex), the rule on each triangle: the points do
     * not depend on where the clipped polygon's vertex list starts, so mirror-symmetric faces get
     * mirror-symmetric points (a fan from a vertex integrated the nonlinear laws asymmetrically). An overlap
     * that is a triangle or a quadrilateral (after dropping repeated and collinear vertices; aligned
     * rectangular faces overlap in rectangles) takes one rule on the whole of it instead, as symmetric:
     * the 6-point rule on the triangle (6 instead of 18), a Gauss rule on the quadrilateral through its
     * bilinear map (its Jacobian, linear in each direction, in the weights): 2 x 2 points (4 instead of 24),
     * 3 x 3 for a quad4 piece on a quadratic (tri6) main face. The rules integrate N_b N_a, what a uniform
     * pressure and heat flux need, exactly on flat faces: on a triangle of the overlap it is of total degree
     * <= 4 (N_b of degree <= 2, bilinear; N_a <= 2, bilinear or quadratic), on a parallelogram of degree <= 3
     * in each direction (one face's parameters are affine along each of its directions, the other's constant
     * or affine), but 4 for a quad4 piece on a quadratic face. A deformed configuration rarely leaves the overlaps exact parallelograms: with those
     * alone taking one rule, a search after a converged solve of the benchmark block (N = 64) had made 444 528 points of 138 384 (docs/contact.md,
     * "3D surface-to-surface"). */
    for (PetscInt i = 0; i < nq; i++)
      for (PetscInt d = 0; d < 2; d++) qm[d] += Q[2 * i + d] / nq;
    {
      PetscReal       V[2 * TSL_CONTACT_CLIP_MAX_VERTICES];
      const PetscInt  nv    = Corners(nq, Q, aq, V);
      const PetscBool whole = (PetscBool)(nv == 3 || nv == 4), affine = (PetscBool)(nv == 4 && Parallelogram(V));

      if (whole) {
        /* quadrilaterals: 2 x 2 Gauss points, 3 x 3 for a quad4 piece on a quadratic main face */
        const PetscBool  q2 = (PetscBool)(!mlin && nc == 4);
        const PetscInt   ng = q2 ? 3 : 2, nr = nv == 3 ? TSL_CONTACT_TRI_GAUSS : ng * ng;
        const PetscReal *g3 = q2 ? G3 : G2, *w3 = q2 ? W3 : W2;
        for (PetscInt g = 0; g < nr; g++) {
          PetscReal q[2], w;
          if (nv == 3) {
            for (PetscInt d = 0; d < 2; d++) q[d] = TriL[g][0] * V[d] + TriL[g][1] * V[2 + d] + TriL[g][2] * V[4 + d];
            w = TriW[g] * aq;
          } else if (affine) { /* q = V0 + (1 + s)/2 (V1 - V0) + (1 + t)/2 (V3 - V0): affine, |det| = area / 4 */
            const PetscReal gs = g3[g % ng], gt = g3[g / ng];
            for (PetscInt d = 0; d < 2; d++) q[d] = V[d] + 0.5 * (1 + gs) * (V[2 + d] - V[d]) + 0.5 * (1 + gt) * (V[6 + d] - V[d]);
            w = w3[g % ng] * w3[g / ng] * aq / 4;
          } else { /* any other (convex) quadrilateral: its bilinear map from the square, the Jacobian in the weight */
            const PetscReal gs = g3[g % ng], gt = g3[g / ng],
                            Ns[4] = {(1 - gs) * (1 - gt), (1 + gs) * (1 - gt), (1 + gs) * (1 + gt), (1 - gs) * (1 + gt)};
            PetscReal xs[2], xt[2];
            for (PetscInt d = 0; d < 2; d++) {
              q[d]  = 0.25 * (Ns[0] * V[d] + Ns[1] * V[2 + d] + Ns[2] * V[4 + d] + Ns[3] * V[6 + d]);
              xs[d] = 0.25 * ((1 - gt) * (V[2 + d] - V[d]) + (1 + gt) * (V[4 + d] - V[6 + d]));
              xt[d] = 0.25 * ((1 - gs) * (V[6 + d] - V[d]) + (1 + gs) * (V[4 + d] - V[2 + d]));
            }
            w = w3[g % ng] * w3[g / ng] * (xs[0] * xt[1] - xs[1] * xt[0]);
          }
          PetscCall(AddPoint(sg, pg, nc, idx, P, Xp, q, w, cap, pt, npt));
        }
      }
      for (PetscInt i = 0; i < nq; i++) {
        const PetscReal *q0 = qm, *q1 = &Q[2 * i], *q2 = &Q[2 * ((i + 1) % nq)];
        PetscReal        at = 0.5 * ((q1[0] - q0[0]) * (q2[1] - q0[1]) - (q2[0] - q0[0]) * (q1[1] - q0[1]));

        if (at <= 1e-14 * aq) continue; /* a repeated or collinear vertex of the clipped polygon */
        for (PetscInt d = 0; d < 2; d++) qc[d] += at * (q0[d] + q1[d] + q2[d]) / 3;
        if (whole) continue; /* its points are above */
        for (PetscInt g = 0; g < TSL_CONTACT_TRI_GAUSS; g++) {
          PetscReal q[2];
          for (PetscInt d = 0; d < 2; d++) q[d] = TriL[g][0] * q0[d] + TriL[g][1] * q1[d] + TriL[g][2] * q2[d];
          PetscCall(AddPoint(sg, pg, nc, idx, P, Xp, q, TriW[g] * at, cap, pt, npt));
        }
      }
    }
    /* the main face's plane seen from the overlap's centroid, along n_s */
    {
      PetscReal q3[3], v[3];
      for (PetscInt d = 0; d < 3; d++) q3[d] = c[d] + (qc[0] * e1[d] + qc[1] * e2[d]) / aq, v[d] = cm[d] - q3[d];
      dsum += aq * Dot(v, nm) / Dot(ns, nm);
      asum += aq;
    }
  }
  if (dist) *dist = asum > 0 ? dsum / asum : 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

void TslContactPointSetUp3(PetscInt nsn, const PetscReal N[], const PetscReal X[], const PetscReal U[], TslContactInput3 *in)
{
  for (PetscInt d = 0; d < 3; d++) in->x[0][d] = 0;
  for (PetscInt c = 0; c < TSL_CONTACT3_NU; c++) in->u[0][c] = 0;
  for (PetscInt b = 0; b < nsn; b++) {
    for (PetscInt d = 0; d < 3; d++) in->x[0][d] += N[b] * X[3 * b + d];
    for (PetscInt c = 0; c < TSL_CONTACT3_NU; c++) in->u[0][c] += N[b] * U[TSL_CONTACT3_NU * b + c];
  }
}

PetscErrorCode TslContactPointElement3(const TslContactLaw *law, const TslContactInput3 *in, PetscInt nsn, const PetscReal N[], PetscReal R[],
                                       PetscReal K[], TslContactOutput *out)
{
#define NK3 (TSL_CONTACT3_NU * (1 + TSL_CONTACT3_MAX_FACE_NODES))
  PetscReal        Rk[NK3], Kk[NK3 * NK3];
  TslContactOutput o;

  PetscFunctionBeginUser;
  PetscCall(TslContactElement3(law, in, Rk, K ? Kk : NULL, &o));
  PetscCall(TslContactPointExpand(o.nu, o.nnode, nsn, N, Rk, K ? Kk : NULL, R, K));
  if (out) {
    *out       = o;
    out->nnode = nsn + o.nnode - 1;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
