/* Every geometry family reachable from the catalogue (element families and their face families):
 * shape functions (partition of unity, sum of derivatives, Kronecker property, derivatives against
 * central differences), quadrature (weights, polynomial exactness) and outward face normals. */
#include "check.h"

#define MAX_FAMILIES 16

static void AddFamily(const TslGeometry *g, const TslGeometry *list[], PetscInt *n)
{
  for (PetscInt i = 0; i < *n; i++)
    if (list[i] == g) return;
  list[(*n)++] = g;
  for (PetscInt f = 0; f < g->nface; f++) AddFamily(g->face_geom[f], list, n);
}

/* A point inside the reference element: a fixed convex combination of the nodes, so it works for
 * any convex reference shape. */
static void InteriorPoint(const TslGeometry *g, PetscInt k, PetscReal xi[3])
{
  PetscReal wsum = 0;
  for (PetscInt d = 0; d < 3; d++) xi[d] = 0;
  for (PetscInt a = 0; a < g->nnode; a++) {
    const PetscReal w = 1.0 + 0.9 * PetscSinReal(1.7 * (a + 1) * (k + 1));
    for (PetscInt d = 0; d < 3; d++) xi[d] += w * g->node_xi[a][d];
    wsum += w;
  }
  for (PetscInt d = 0; d < 3; d++) xi[d] /= wsum;
}

static void CheckShape(TestLog *log, const TslGeometry *g)
{
  const PetscInt  n = g->nnode, dim = g->dim;
  PetscReal       N[TSL_MAX_ELEM_NODES], dN[TSL_MAX_ELEM_NODES * 3], Np[TSL_MAX_ELEM_NODES], Nm[TSL_MAX_ELEM_NODES];
  PetscReal       scratch[TSL_MAX_ELEM_NODES * 3], unity = 0, dsum = 0, kron = 0, fd = 0;
  const PetscReal h = 1e-6;

  for (PetscInt k = 0; k < 5; k++) {
    PetscReal xi[3];
    InteriorPoint(g, k, xi);
    g->shape(xi, N, dN);
    PetscReal s = 0;
    for (PetscInt a = 0; a < n; a++) s += N[a];
    unity = PetscMax(unity, PetscAbsReal(s - 1));
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
  Check(log, dsum, 0, 1e-14, "%s max|sum dN/dxi|", g->name);
  Check(log, kron, 0, 1e-14, "%s max|N_a(xi_b) - delta_ab|", g->name);
  Check(log, fd, 0, 1e-8, "%s max|dN - central difference|", g->name);
}

/* Integral of prod xi_d^p_d over [-1,1]^dim. */
static PetscReal MonomialExact(PetscInt dim, const PetscInt p[])
{
  PetscReal v = 1;
  for (PetscInt d = 0; d < dim; d++) v *= (p[d] % 2) ? 0 : 2.0 / (p[d] + 1);
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

static void CheckQuadrature(TestLog *log, const TslGeometry *g, const TslQuadrature *Q, const char *which)
{
  const PetscInt dim  = g->dim;
  PetscReal      wsum = 0, err = 0;
  PetscInt       p[3] = {0, 0, 0}, top = 1;

  for (PetscInt q = 0; q < Q->n; q++) wsum += Q->w[q];
  Check(log, wsum, g->ref_volume, 1e-13, "%s %s quadrature weight sum", g->name, which);
  if (PetscAbsReal(g->ref_volume - PetscPowRealInt(2, dim)) > 1e-14) {
    Check(log, 1, 0, 0, "%s %s: no exactness check written for a non-hypercube reference element", g->name, which);
    return;
  }
  /* tensor-product rule: every monomial with each exponent <= degree is exact ... */
  for (PetscInt d = 0; d < dim; d++) top *= Q->degree + 1;
  for (PetscInt m = 0; m < top; m++) {
    for (PetscInt d = 0, r = m; d < dim; d++, r /= Q->degree + 1) p[d] = r % (Q->degree + 1);
    err = PetscMax(err, PetscAbsReal(MonomialRule(Q, dim, p) - MonomialExact(dim, p)));
  }
  Check(log, err, 0, 1e-13, "%s %s quadrature exact to degree %" PetscInt_FMT " per coordinate", g->name, which, Q->degree);
  /* ... and the degree is not understated: the next even power is not integrated exactly */
  for (PetscInt d = 0; d < dim; d++) p[d] = 0;
  p[0] = Q->degree + 1 + (Q->degree + 1) % 2;
  Check(log, PetscAbsReal(MonomialRule(Q, dim, p) - MonomialExact(dim, p)) > 1e-8, 1, 0, "%s %s quadrature inexact for xi^%" PetscInt_FMT, g->name,
        which, p[0]);
}

/* Normal of face f at the face's reference centre, mapped through the parent's reference nodes, must
 * point from the element centre towards the face centre (right-hand rule in 3D, body on the left in 2D). */
static void CheckFaceNormals(TestLog *log, const TslGeometry *g)
{
  PetscReal cen[3] = {0, 0, 0};
  for (PetscInt a = 0; a < g->nnode; a++)
    for (PetscInt d = 0; d < 3; d++) cen[d] += g->node_xi[a][d] / g->nnode;
  for (PetscInt f = 0; f < g->nface; f++) {
    const TslGeometry *fg     = g->face_geom[f];
    PetscReal          fxi[3] = {0, 0, 0}, N[TSL_MAX_FACE_NODES], dN[TSL_MAX_FACE_NODES * 3], T[2][3] = {{0}}, n[3], c[3] = {0, 0, 0};
    PetscReal          nn, cc, cosine;

    for (PetscInt a = 0; a < fg->nnode; a++)
      for (PetscInt d = 0; d < 3; d++) fxi[d] += fg->node_xi[a][d] / fg->nnode;
    fg->shape(fxi, N, dN);
    for (PetscInt a = 0; a < g->face_nnode[f]; a++) {
      const PetscReal *x = g->node_xi[g->face_node[f][a]];
      for (PetscInt d = 0; d < 3; d++) {
        c[d] += N[a] * x[d] - cen[d] / g->face_nnode[f];
        for (PetscInt j = 0; j < fg->dim; j++) T[j][d] += dN[fg->dim * a + j] * x[d];
      }
    }
    if (fg->dim == 1) {
      n[0] = T[0][1], n[1] = -T[0][0], n[2] = 0;
    } else {
      n[0] = T[0][1] * T[1][2] - T[0][2] * T[1][1];
      n[1] = T[0][2] * T[1][0] - T[0][0] * T[1][2];
      n[2] = T[0][0] * T[1][1] - T[0][1] * T[1][0];
    }
    nn     = PetscSqrtReal(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    cc     = PetscSqrtReal(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    cosine = (n[0] * c[0] + n[1] * c[1] + n[2] * c[2]) / (nn * cc);
    Check(log, cosine, 1, 1e-12, "%s face S%" PetscInt_FMT " normal . outward direction", g->name, f + 1);
  }
}

int main(int argc, char **argv)
{
  const TslGeometry *fam[MAX_FAMILIES];
  PetscInt           nfam = 0;
  TestLog            log  = {0, 0};

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  for (PetscInt t = 0; t < TslElementTypeCount(); t++) AddFamily(TslElementTypeGet(t)->geom, fam, &nfam);
  for (PetscInt i = 0; i < nfam; i++) {
    CheckShape(&log, fam[i]);
    CheckQuadrature(&log, fam[i], &fam[i]->full, "full");
    CheckQuadrature(&log, fam[i], &fam[i]->reduced, "reduced");
    CheckFaceNormals(&log, fam[i]);
  }
  Check(&log, TslElementTypeFind("cpe4t"), TslElementTypeFind("CPE4T"), 0, "case-insensitive lookup of cpe4t");
  Check(&log, TslElementTypeFind("CPE4T") >= 0, 1, 0, "CPE4T is in the catalogue");
  Check(&log, TslElementTypeFind("NOPE"), -1, 0, "unknown type name gives -1");
  PetscCall(PetscFinalize());
  return Summary(&log);
}
