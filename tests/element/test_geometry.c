/* Every geometry family of src/element/geometry.c, from one table: shape functions (partition of
 * unity, linear completeness, Kronecker property, derivatives against central differences at random
 * points), quadrature (positive weights inside the element, weight sum, exactness up to the stated
 * degree and not beyond; the full, reduced and, for face families, as-face rules), faces (trace of the element on each face equals the face family's
 * interpolation, outward normals, closed boundary), linear sub-elements (positive volumes that tile
 * the element, positive nodal weights) and the XDMF cell type. The catalogue may only use families of
 * the table. */
#include "check.h"
#include "element_impl.h"

/* nsimplex: the first nsimplex reference coordinates span the unit simplex (xi_d >= 0, sum <= 1), the
 * others [-1, 1]. It fixes the exact monomial integrals and the meaning of the quadrature degree:
 * per coordinate for tensor products (nsimplex = 0), total degree otherwise. */
typedef struct {
  const TslGeometry *g;
  PetscInt           nsimplex;
} Family;

static const Family Families[] = {
    {&TslGeomLine2, 0}, {&TslGeomLine3, 0}, {&TslGeomTri3, 2},   {&TslGeomTri6, 2},    {&TslGeomQuad4, 0}, {&TslGeomQuad8, 0},
    {&TslGeomTet4, 3},  {&TslGeomTet10, 3}, {&TslGeomWedge6, 2}, {&TslGeomWedge15, 2}, {&TslGeomHex8, 0},  {&TslGeomHex20, 0},
};
#define NFAMILY ((PetscInt)(sizeof(Families) / sizeof(Families[0])))

#define NSAMPLE 200

/* ---- helpers ----------------------------------------------------------------------------------- */

/* Deterministic pseudo-random numbers in (0, 1) (64-bit LCG, top 53 bits). */
static PetscReal Random(unsigned long long *state)
{
  *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
  return ((PetscReal)(*state >> 11) + 0.5) / 9007199254740992.0;
}

/* A random point strictly inside the reference element: a random convex combination of the corners. */
static void RandomPoint(const TslGeometry *g, unsigned long long *state, PetscReal xi[3])
{
  PetscReal w[TSL_MAX_ELEM_NODES], wsum = 0;

  for (PetscInt a = 0; a < g->ncorner; a++) wsum += (w[a] = -PetscLogReal(Random(state)));
  for (PetscInt d = 0; d < 3; d++) {
    xi[d] = 0;
    for (PetscInt a = 0; a < g->ncorner; a++) xi[d] += w[a] / wsum * g->node_xi[a][d];
  }
}

static PetscBool InReference(const Family *f, const PetscReal xi[3], PetscReal tol)
{
  PetscReal sum = 0;

  for (PetscInt d = 0; d < f->g->dim; d++) {
    if (d < f->nsimplex) {
      if (xi[d] < -tol) return PETSC_FALSE;
      sum += xi[d];
    } else if (PetscAbsReal(xi[d]) > 1 + tol)
      return PETSC_FALSE;
  }
  return (PetscBool)(sum <= 1 + tol);
}

static PetscReal Det(PetscInt dim, const PetscReal J[3][3])
{
  if (dim == 1) return J[0][0];
  if (dim == 2) return J[0][0] * J[1][1] - J[0][1] * J[1][0];
  return J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
         J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
}

/* Solves J x = b by Cramer's rule. */
static void Solve(PetscInt dim, const PetscReal J[3][3], const PetscReal b[3], PetscReal x[3])
{
  const PetscReal det = Det(dim, J);

  for (PetscInt c = 0; c < dim; c++) {
    PetscReal Jc[3][3];
    for (PetscInt i = 0; i < 3; i++)
      for (PetscInt j = 0; j < 3; j++) Jc[i][j] = j == c ? b[i] : J[i][j];
    x[c] = Det(dim, Jc) / det;
  }
}

/* Position X = sum_k N_k(xi) X_k and Jacobian J[i][j] = dX_i/dxi_j of the map of family g whose
 * nodes sit at the parent's reference points node_xi[node[k]]. */
static void MapPoint(const TslGeometry *g, const TslGeometry *parent, const PetscInt node[], const PetscReal xi[], PetscReal X[3], PetscReal J[3][3],
                     PetscReal N[])
{
  PetscReal dN[TSL_MAX_ELEM_NODES * 3];

  g->shape(xi, N, dN);
  for (PetscInt i = 0; i < 3; i++) {
    X[i] = 0;
    for (PetscInt j = 0; j < 3; j++) J[i][j] = 0;
  }
  for (PetscInt k = 0; k < g->nnode; k++) {
    const PetscReal *Xk = parent->node_xi[node[k]];
    for (PetscInt i = 0; i < 3; i++) {
      X[i] += N[k] * Xk[i];
      for (PetscInt j = 0; j < g->dim; j++) J[i][j] += Xk[i] * dN[g->dim * k + j];
    }
  }
}

/* ---- shape functions --------------------------------------------------------------------------- */

static void CheckShape(TestLog *log, const TslGeometry *g)
{
  const PetscInt     n = g->nnode, dim = g->dim;
  const PetscReal    h = 1e-6;
  PetscReal          N[TSL_MAX_ELEM_NODES], dN[TSL_MAX_ELEM_NODES * 3], Np[TSL_MAX_ELEM_NODES], Nm[TSL_MAX_ELEM_NODES];
  PetscReal          scratch[TSL_MAX_ELEM_NODES * 3], unity = 0, dsum = 0, kron = 0, fd = 0, lin = 0;
  unsigned long long state = 1;

  for (PetscInt k = 0; k < NSAMPLE; k++) {
    PetscReal xi[3], s = 0;
    RandomPoint(g, &state, xi);
    g->shape(xi, N, dN);
    for (PetscInt a = 0; a < n; a++) s += N[a];
    unity = PetscMax(unity, PetscAbsReal(s - 1));
    for (PetscInt i = 0; i < dim; i++) {
      PetscReal x = 0; /* sum_a N_a xi_a = xi and sum_a xi_a dN_a/dxi_j = delta_ij */
      for (PetscInt a = 0; a < n; a++) x += N[a] * g->node_xi[a][i];
      lin = PetscMax(lin, PetscAbsReal(x - xi[i]));
      for (PetscInt j = 0; j < dim; j++) {
        PetscReal dx = 0;
        for (PetscInt a = 0; a < n; a++) dx += g->node_xi[a][i] * dN[dim * a + j];
        lin = PetscMax(lin, PetscAbsReal(dx - (i == j ? 1 : 0)));
      }
    }
    for (PetscInt j = 0; j < dim; j++) {
      PetscReal ds = 0, xp[3] = {xi[0], xi[1], xi[2]}, xm[3] = {xi[0], xi[1], xi[2]};
      for (PetscInt a = 0; a < n; a++) ds += dN[dim * a + j];
      dsum = PetscMax(dsum, PetscAbsReal(ds));
      xp[j] += h;
      xm[j] -= h;
      g->shape(xp, Np, scratch);
      g->shape(xm, Nm, scratch);
      for (PetscInt a = 0; a < n; a++) fd = PetscMax(fd, PetscAbsReal((Np[a] - Nm[a]) / (2 * h) - dN[dim * a + j]));
    }
  }
  for (PetscInt b = 0; b < n; b++) {
    g->shape(g->node_xi[b], N, dN);
    for (PetscInt a = 0; a < n; a++) kron = PetscMax(kron, PetscAbsReal(N[a] - (a == b ? 1 : 0)));
  }
  Check(log, unity, 0, 1e-14, "%s partition of unity max|sum N - 1|", g->name);
  Check(log, dsum, 0, 1e-13, "%s max|sum dN/dxi|", g->name);
  Check(log, lin, 0, 1e-13, "%s linear completeness max|sum N_a xi_a - xi|, |sum xi_a dN_a - I|", g->name);
  Check(log, kron, 0, 1e-14, "%s max|N_a(xi_b) - delta_ab|", g->name);
  Check(log, fd, 0, 1e-8, "%s max|dN - central difference|", g->name);
}

/* Node counts and numbering: corners first; a second-order family's other nodes are edge midpoints. */
static void CheckNodes(TestLog *log, const TslGeometry *g)
{
  PetscInt bad = 0;

  Check(log, g->nnode <= TSL_MAX_ELEM_NODES && g->ncorner >= g->dim + 1 && g->ncorner <= g->nnode, 1, 0,
        "%s node counts (nnode %" PetscInt_FMT ", ncorner %" PetscInt_FMT ")", g->name, g->nnode, g->ncorner);
  Check(log, (g->order == 1 && g->ncorner == g->nnode) || (g->order == 2 && g->ncorner < g->nnode), 1, 0,
        "%s order %" PetscInt_FMT " matches its node counts", g->name, g->order);
  for (PetscInt m = g->ncorner; m < g->nnode; m++) {
    PetscBool found = PETSC_FALSE;
    for (PetscInt a = 0; a < g->ncorner; a++)
      for (PetscInt b = a + 1; b < g->ncorner; b++) {
        PetscReal err = 0;
        for (PetscInt d = 0; d < 3; d++) err = PetscMax(err, PetscAbsReal(0.5 * (g->node_xi[a][d] + g->node_xi[b][d]) - g->node_xi[m][d]));
        if (err < 1e-15) found = PETSC_TRUE;
      }
    if (!found) bad++;
  }
  if (g->order == 2) Check(log, bad, 0, 0, "%s midside nodes that are not the midpoint of two corners", g->name);
}

/* ---- quadrature -------------------------------------------------------------------------------- */

static PetscReal Factorial(PetscInt n)
{
  PetscReal v = 1;
  for (PetscInt i = 2; i <= n; i++) v *= i;
  return v;
}

/* Integral of prod xi_d^p_d over the reference element: a! b! (c!) / (a + b (+ c) + k)! over the unit
 * k-simplex, 2/(p+1) or 0 along each [-1, 1] coordinate. */
static PetscReal MonomialExact(const Family *f, const PetscInt p[])
{
  PetscReal v   = 1;
  PetscInt  sum = 0;

  for (PetscInt d = 0; d < f->g->dim; d++) {
    if (d < f->nsimplex) {
      v *= Factorial(p[d]);
      sum += p[d];
    } else
      v *= (p[d] % 2) ? 0 : 2.0 / (p[d] + 1);
  }
  if (f->nsimplex) v /= Factorial(sum + f->nsimplex);
  return v;
}

static PetscReal MonomialRule(const TslQuadrature *Q, PetscInt dim, const PetscInt p[])
{
  PetscReal v = 0;
  for (PetscInt q = 0; q < Q->n; q++) {
    PetscReal m = Q->w[q];
    for (PetscInt d = 0; d < dim; d++) m *= PetscPowRealInt(Q->xi[q][d], p[d]);
    v += m;
  }
  return v;
}

static void CheckQuadrature(TestLog *log, const Family *f, const TslQuadrature *Q, const char *which)
{
  const TslGeometry *g   = f->g;
  const PetscInt     dim = g->dim, top = Q->degree + 2;
  PetscReal          wsum = 0, wmin = PETSC_MAX_REAL, exact = 0, beyond = 0;
  PetscInt           outside = 0, count = 1;

  for (PetscInt q = 0; q < Q->n; q++) {
    wsum += Q->w[q];
    wmin = PetscMin(wmin, Q->w[q]);
    if (!InReference(f, Q->xi[q], 1e-15)) outside++;
  }
  Check(log, Q->n >= 1 && Q->n <= TSL_MAX_QP, 1, 0, "%s %s quadrature has 1..TSL_MAX_QP points (%" PetscInt_FMT ")", g->name, which, Q->n);
  Check(log, wmin > 0, 1, 0, "%s %s quadrature weights positive (min %g)", g->name, which, (double)wmin);
  Check(log, outside, 0, 0, "%s %s quadrature points outside the element", g->name, which);
  Check(log, wsum, g->ref_volume, 1e-14, "%s %s quadrature weight sum", g->name, which);
  /* every monomial up to the degree is exact (per coordinate or total, see Family); some monomial of
   * the next two degrees is not, so the degree is not understated */
  for (PetscInt d = 0; d < dim; d++) count *= top + 1;
  for (PetscInt m = 0; m < count; m++) {
    PetscInt  p[3] = {0, 0, 0}, level = 0;
    PetscReal err;
    for (PetscInt d = 0, r = m; d < dim; d++, r /= top + 1) p[d] = r % (top + 1);
    for (PetscInt d = 0; d < dim; d++) level = f->nsimplex ? level + p[d] : PetscMax(level, p[d]);
    err = PetscAbsReal(MonomialRule(Q, dim, p) - MonomialExact(f, p));
    if (level <= Q->degree)
      exact = PetscMax(exact, err);
    else if (level <= top)
      beyond = PetscMax(beyond, err);
  }
  Check(log, exact, 0, 1e-14, "%s %s quadrature exact to degree %" PetscInt_FMT " (%s)", g->name, which, Q->degree,
        f->nsimplex ? "total" : "per coordinate");
  Check(log, beyond > 1e-8, 1, 0, "%s %s quadrature inexact beyond degree %" PetscInt_FMT " (max error %g)", g->name, which, Q->degree,
        (double)beyond);
}

/* ---- faces ------------------------------------------------------------------------------------- */

/* Outward normal n = x_eta1 x x_eta2 (3D) or (dy, -dx) (2D) from the face's own shape functions. */
static void FaceNormal(PetscInt fdim, const PetscReal J[3][3], PetscReal n[3])
{
  if (fdim == 1) {
    n[0] = J[1][0], n[1] = -J[0][0], n[2] = 0;
  } else {
    n[0] = J[1][0] * J[2][1] - J[2][0] * J[1][1];
    n[1] = J[2][0] * J[0][1] - J[0][0] * J[2][1];
    n[2] = J[0][0] * J[1][1] - J[1][0] * J[0][1];
  }
}

static PetscReal Dot(const PetscReal a[3], const PetscReal b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* For each face: the parent's interpolation restricted to the face equals the face family's one (so
 * the face lists the right nodes in the face family's order, and the other shape functions vanish
 * there); the face's nodes lie in its plane, every node of the element behind it, the centroid
 * strictly behind the normal. Over all faces: sum n dA = 0 and sum x.n dA = dim V (divergence
 * theorem), i.e. the faces close the boundary, all outward. */
static void CheckFaces(TestLog *log, const Family *fam)
{
  const TslGeometry *g      = fam->g;
  PetscReal          cen[3] = {0, 0, 0}, u[TSL_MAX_ELEM_NODES], nsum[3] = {0, 0, 0}, xn = 0;
  unsigned long long state = 7;

  if (!g->nface) return;
  for (PetscInt a = 0; a < g->ncorner; a++)
    for (PetscInt d = 0; d < 3; d++) cen[d] += g->node_xi[a][d] / g->ncorner;
  for (PetscInt a = 0; a < g->nnode; a++) u[a] = 2 * Random(&state) - 1;
  for (PetscInt f = 0; f < g->nface; f++) {
    const TslGeometry *fg    = g->face_geom[f];
    const PetscInt    *node  = g->face_node[f];
    PetscReal          trace = 0, plane = 0, behind = -PETSC_MAX_REAL, outward = PETSC_MAX_REAL;
    PetscInt           badnode = 0;

    Check(log, fg && fg->dim == g->dim - 1 && fg->nnode == g->face_nnode[f] && fg->order == g->order, 1, 0,
          "%s face S%" PetscInt_FMT " family %s fits (dimension, nodes, order)", g->name, f + 1, fg ? fg->name : "none");
    if (!fg) continue;
    /* film and flux are integrated with the face family's as_face rule (formulations.c) */
    Check(log, fg->as_face.n > 0 && fg->as_face.degree >= 2 * fg->order + (fg->dim == 1 ? 1 : 0), 1, 0,
          "%s face S%" PetscInt_FMT " family %s has a face rule exact for N_a N_b (times r on a line): degree %" PetscInt_FMT, g->name, f + 1,
          fg->name, fg->as_face.degree);
    for (PetscInt k = 0; k < g->face_nnode[f]; k++)
      if (node[k] < 0 || node[k] >= g->nnode) badnode++;
    Check(log, badnode, 0, 0, "%s face S%" PetscInt_FMT " node positions out of range", g->name, f + 1);
    if (badnode) continue;
    for (PetscInt k = 0; k < NSAMPLE / 10; k++) {
      PetscReal eta[3], X[3], J[3][3], Nf[TSL_MAX_FACE_NODES], N[TSL_MAX_ELEM_NODES], dN[TSL_MAX_ELEM_NODES * 3], n[3], uf = 0, ue = 0;
      RandomPoint(fg, &state, eta);
      MapPoint(fg, g, node, eta, X, J, Nf);
      g->shape(X, N, dN);
      for (PetscInt a = 0; a < g->nnode; a++) ue += N[a] * u[a];
      for (PetscInt b = 0; b < fg->nnode; b++) uf += Nf[b] * u[node[b]];
      trace = PetscMax(trace, PetscAbsReal(ue - uf));
      FaceNormal(fg->dim, J, n);
      for (PetscInt b = 0; b < fg->nnode; b++) {
        PetscReal r[3] = {g->node_xi[node[b]][0] - X[0], g->node_xi[node[b]][1] - X[1], g->node_xi[node[b]][2] - X[2]};
        plane          = PetscMax(plane, PetscAbsReal(Dot(n, r)) / PetscSqrtReal(Dot(n, n)));
      }
      for (PetscInt a = 0; a < g->nnode; a++) {
        PetscReal r[3] = {g->node_xi[a][0] - X[0], g->node_xi[a][1] - X[1], g->node_xi[a][2] - X[2]};
        behind         = PetscMax(behind, Dot(n, r) / PetscSqrtReal(Dot(n, n)));
      }
      {
        PetscReal r[3] = {X[0] - cen[0], X[1] - cen[1], X[2] - cen[2]};
        outward        = PetscMin(outward, Dot(n, r) / PetscSqrtReal(Dot(n, n) * Dot(r, r)));
      }
    }
    for (PetscInt q = 0; q < fg->full.n; q++) {
      PetscReal X[3], J[3][3], Nf[TSL_MAX_FACE_NODES], n[3];
      MapPoint(fg, g, node, fg->full.xi[q], X, J, Nf);
      FaceNormal(fg->dim, J, n);
      for (PetscInt d = 0; d < 3; d++) nsum[d] += fg->full.w[q] * n[d];
      xn += fg->full.w[q] * Dot(X, n);
    }
    Check(log, trace, 0, 1e-13, "%s face S%" PetscInt_FMT " max|element interpolation - %s interpolation| on the face", g->name, f + 1, fg->name);
    Check(log, plane, 0, 1e-14, "%s face S%" PetscInt_FMT " face nodes off the face plane", g->name, f + 1);
    Check(log, behind <= 1e-14, 1, 0, "%s face S%" PetscInt_FMT " all element nodes behind the face (max n.(x_a - x) = %g)", g->name, f + 1,
          (double)behind);
    Check(log, outward > 0, 1, 0, "%s face S%" PetscInt_FMT " normal points away from the centroid (min cosine %g)", g->name, f + 1, (double)outward);
  }
  Check(log, PetscSqrtReal(Dot(nsum, nsum)), 0, 1e-14, "%s |sum over faces of n dA|", g->name);
  Check(log, xn, g->dim * g->ref_volume, 1e-14, "%s sum over faces of x.n dA = dim * volume", g->name);
}

/* ---- sub-elements ------------------------------------------------------------------------------ */

/* Linear sub-elements (simplices of sub_geom): positive Jacobians, volumes adding up to the element's,
 * every random point of the element in exactly one sub-element, positive nodal weights (row sums of
 * the sub-elements' N) adding up to the volume. */
static void CheckSubElements(TestLog *log, const TslGeometry *g)
{
  const TslGeometry *sg   = g->sub_geom;
  PetscReal          vsum = 0, detmin = PETSC_MAX_REAL, wmin = PETSC_MAX_REAL, wsum = 0, weight[TSL_MAX_ELEM_NODES] = {0};
  PetscInt           badnode = 0, miscount = 0;
  unsigned long long state = 11;

  if (g->order == 1) {
    Check(log, g->nsub == 0 && !sg, 1, 0, "%s (linear) has no sub-elements", g->name);
    return;
  }
  if (g->nsub == 0) {
    Check(log, !sg, 1, 0, "%s has no sub-elements and no sub-element family", g->name);
    return;
  }
  Check(log, g->nsub <= TSL_MAX_SUB && sg && sg->dim == g->dim && sg->order == 1 && sg->nnode == g->dim + 1 && sg->nnode <= TSL_MAX_SUB_NODES, 1, 0,
        "%s %" PetscInt_FMT " sub-elements of a linear simplex family (%s)", g->name, g->nsub, sg ? sg->name : "none");
  if (!sg || sg->nnode != g->dim + 1 || g->nsub > TSL_MAX_SUB) return;
  for (PetscInt s = 0; s < g->nsub; s++)
    for (PetscInt k = 0; k < sg->nnode; k++) {
      if (g->sub_node[s][k] < 0 || g->sub_node[s][k] >= g->nnode) badnode++;
      for (PetscInt l = 0; l < k; l++)
        if (g->sub_node[s][l] == g->sub_node[s][k]) badnode++;
    }
  Check(log, badnode, 0, 0, "%s sub-element node positions out of range or repeated", g->name);
  if (badnode) return;
  for (PetscInt s = 0; s < g->nsub; s++) {
    for (PetscInt q = 0; q < sg->full.n; q++) {
      PetscReal X[3], J[3][3], N[TSL_MAX_SUB_NODES], det;
      MapPoint(sg, g, g->sub_node[s], sg->full.xi[q], X, J, N);
      det    = Det(g->dim, J);
      detmin = PetscMin(detmin, det);
      vsum += sg->full.w[q] * det;
      for (PetscInt k = 0; k < sg->nnode; k++) weight[g->sub_node[s][k]] += sg->full.w[q] * det * N[k];
    }
  }
  for (PetscInt a = 0; a < g->nnode; a++) {
    wmin = PetscMin(wmin, weight[a]);
    wsum += weight[a];
  }
  for (PetscInt k = 0; k < NSAMPLE; k++) {
    PetscReal xi[3];
    PetscInt  inside = 0;
    RandomPoint(g, &state, xi);
    for (PetscInt s = 0; s < g->nsub; s++) {
      /* the sub-element map is affine: one Newton step from any point inverts it */
      PetscReal X[3], J[3][3], N[TSL_MAX_SUB_NODES], dN[TSL_MAX_SUB_NODES * 3], eta[3] = {0, 0, 0}, r[3], deta[3], nmin = PETSC_MAX_REAL;
      MapPoint(sg, g, g->sub_node[s], eta, X, J, N);
      for (PetscInt d = 0; d < 3; d++) r[d] = xi[d] - X[d];
      Solve(g->dim, J, r, deta);
      for (PetscInt d = 0; d < g->dim; d++) eta[d] += deta[d];
      sg->shape(eta, N, dN); /* barycentric coordinates of a linear simplex */
      for (PetscInt j = 0; j < sg->nnode; j++) nmin = PetscMin(nmin, N[j]);
      if (nmin > 0) inside++;
    }
    if (inside != 1) miscount++;
  }
  Check(log, detmin > 0, 1, 0, "%s sub-element Jacobians positive (min %g)", g->name, (double)detmin);
  Check(log, vsum, g->ref_volume, 1e-14, "%s sub-element volumes add up to the element's", g->name);
  Check(log, miscount, 0, 0, "%s random points not in exactly one sub-element (of %d)", g->name, NSAMPLE);
  Check(log, wmin > 0, 1, 0, "%s sub-element nodal weights positive (min %g)", g->name, (double)wmin);
  Check(log, wsum, g->ref_volume, 1e-14, "%s sub-element nodal weights add up to the volume", g->name);
}

/* ---- XDMF cell type and the catalogue ---------------------------------------------------------- */

/* Nodes of an XDMF cell type id (XdmfTopologyType), 0 for the variable-length Polyline. */
static PetscInt XdmfNodes(PetscInt type)
{
  static const PetscInt table[][2] = {{2, 0}, {4, 3}, {5, 4}, {6, 4}, {8, 6}, {9, 8}, {34, 3}, {36, 6}, {37, 8}, {38, 10}, {40, 15}, {48, 20}};
  for (size_t i = 0; i < sizeof(table) / sizeof(table[0]); i++)
    if (table[i][0] == type) return table[i][1];
  return -1;
}

static void AddReachable(const TslGeometry *g, const TslGeometry *list[], PetscInt *n, PetscInt max)
{
  if (!g) return;
  for (PetscInt i = 0; i < *n; i++)
    if (list[i] == g) return;
  if (*n == max) return;
  list[(*n)++] = g;
  for (PetscInt f = 0; f < g->nface; f++) AddReachable(g->face_geom[f], list, n, max);
  AddReachable(g->sub_geom, list, n, max);
}

static void CheckCatalogue(TestLog *log)
{
  const TslGeometry *used[64];
  PetscInt           nused = 0;

  for (PetscInt t = 0; t < TslElementTypeCount(); t++) {
    const TslElementType *type = TslElementTypeGet(t);
    /* the writer puts [type, nodes...] records: a cell family needs a fixed-size XDMF type, or the Polyline (type 2) of
     * the links DC1D2, whose records the writer gives their node count */
    Check(log, XdmfNodes(type->geom->xdmf_type) == type->geom->nnode || type->geom->xdmf_type == 2, 1, 0,
          "%s: XDMF cell type %" PetscInt_FMT " has the %" PetscInt_FMT " nodes of %s", type->name, type->geom->xdmf_type, type->geom->nnode,
          type->geom->name);
    /* a link (a line family) lies in a planar or 3D model: its row says 3 */
    Check(log, type->dim == type->geom->dim || (type->geom->dim == 1 && type->dim == 3), 1, 0, "%s: model dimension %" PetscInt_FMT " is that of %s", type->name,
          type->dim, type->geom->name);
    AddReachable(type->geom, used, &nused, 64);
  }
  for (PetscInt i = 0; i < nused; i++) {
    PetscBool found = PETSC_FALSE;
    for (PetscInt k = 0; k < NFAMILY; k++)
      if (Families[k].g == used[i]) found = PETSC_TRUE;
    Check(log, found, 1, 0, "family %s used by the catalogue is tested here", used[i]->name);
  }
  Check(log, TslElementTypeFind("cpe4t"), TslElementTypeFind("CPE4T"), 0, "case-insensitive lookup of cpe4t");
  Check(log, TslElementTypeFind("CPE4T") >= 0, 1, 0, "CPE4T is in the catalogue");
  Check(log, TslElementTypeFind("NOPE"), -1, 0, "unknown type name gives -1");
}

int main(int argc, char **argv)
{
  TestLog log = {0, 0};

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  for (PetscInt i = 0; i < NFAMILY; i++) {
    const Family      *f  = &Families[i];
    const TslGeometry *g  = f->g;
    const PetscInt     nx = XdmfNodes(g->xdmf_type);

    CheckNodes(&log, g);
    CheckShape(&log, g);
    CheckQuadrature(&log, f, &g->full, "full");
    CheckQuadrature(&log, f, &g->reduced, "reduced");
    if (g->as_face.n) CheckQuadrature(&log, f, &g->as_face, "as-face");
    if (g->lump.n) CheckQuadrature(&log, f, &g->lump, "lumping");
    Check(&log, g->full.degree >= g->reduced.degree, 1, 0, "%s full rule at least as exact as the reduced one", g->name);
    CheckFaces(&log, f);
    CheckSubElements(&log, g);
    Check(&log, nx == 0 || nx == g->nnode, 1, 0, "%s XDMF cell type %" PetscInt_FMT " fits its %" PetscInt_FMT " nodes", g->name, g->xdmf_type,
          g->nnode);
  }
  CheckCatalogue(&log);
  PetscCall(PetscFinalize());
  return Summary(&log);
}
