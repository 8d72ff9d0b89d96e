/* Ties (*TIE, tied *CONTACT PAIR): each secondary node's unknowns as a combination of the main surface's,
 * turned into equations on rank 0 while the whole model is there (include/thermoslide/mesh.h, TslMeshTies).
 *
 * The weights are those of a mortar tie with the dual (biorthogonal) basis of the secondary surface
 * (Wohlmuth, "A mortar finite element method using dual spaces for the Lagrange multiplier", SIAM J. Numer.
 * Anal. 38, 2000): on each secondary face e the basis Phi_a = sum_b A_ab N_b with A = D_e M_e^-1 (M_e the
 * face's consistent mass matrix int N_a N_b, D_e its row sums) is biorthogonal, int Phi_a N_b = delta_ab
 * int N_a, and
 *   u_s = sum_k c_sk u_k,  c_sk = int Phi_s N_k / sum_k int Phi_s N_k   (integrals over the overlap of the
 *                                                                         secondary with the main faces).
 * Both halves of the patch test hold with it on any non-matching interface that one surface covers: a
 * linear field satisfies the equations (int Phi_s u = u(x_s) int N_s for u in the secondary space), and the
 * uniform traction's nodal forces int N_s t, moved to the main nodes by c_sk, are the main side's int N_k t
 * (sum_s Phi_s = 1). The dialect's *TIE, each secondary node projected on the nearest main face, u_s =
 * sum N_k(xi_s) u_k, passes neither on a non-matching mesh (docs/design.md, "Ties"); its projection is kept
 * for what it is needed for: the position tolerance (and its error), ADJUST, node surfaces, the secondary
 * faces the mortar integrals do not cover (3D second-order faces), and a node whose faces meet no main face.
 * The overlap is found face by face through contact's bin grid over the main faces, never over all pairs. */
#include <thermoslide/mesh.h>
#include <thermoslide/element.h>
#include <thermoslide/contact.h>
#include <thermoslide/contact_s2s.h>
#include <stdlib.h>
#include <string.h>

#define TIE_GAUSS 5 /* Gauss points per overlap interval in 2D: exact for Phi_a N_k of two line3 faces (degree 4) */

typedef struct {
  const TslGeometry *fg;                       /* face family (line2, line3, tri3, tri6, quad4, quad8) */
  PetscInt           nn;                       /* nodes */
  PetscInt           node[TSL_MAX_FACE_NODES]; /* model positions, face order */
} Face;

typedef struct {
  PetscInt  s, k; /* secondary and main node positions */
  PetscReal w;
} Term;

typedef struct {
  Term  *t;
  size_t n, cap;
} Terms;

static PetscErrorCode TermAdd(Terms *T, PetscInt s, PetscInt k, PetscReal w)
{
  PetscFunctionBeginUser;
  if (T->n == T->cap) {
    Term *t;
    T->cap = T->cap ? 2 * T->cap : 256;
    PetscCall(PetscMalloc1(T->cap, &t));
    if (T->n) PetscCall(PetscArraycpy(t, T->t, T->n));
    PetscCall(PetscFree(T->t));
    T->t = t;
  }
  T->t[T->n].s = s, T->t[T->n].k = k, T->t[T->n].w = w;
  T->n++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static int CompareTerm(const void *a, const void *b)
{
  const Term *x = (const Term *)a, *y = (const Term *)b;
  if (x->s != y->s) return x->s < y->s ? -1 : 1;
  return x->k < y->k ? -1 : (x->k > y->k);
}

static PetscBool Simplex(const TslGeometry *fg)
{
  return (PetscBool)(fg->dim == 2 && fg->ncorner == 3);
}

/* The face's point p, its parameter derivatives J[d][i] and shape values N at xi (coordinates X[3*a + d]). */
static void FacePoint(const Face *f, const PetscReal X[], const PetscReal xi[], PetscReal p[3], PetscReal J[3][2], PetscReal N[])
{
  PetscReal dN[TSL_MAX_FACE_NODES * 2], x3[3] = {xi[0], f->fg->dim > 1 ? xi[1] : 0, 0};

  f->fg->shape(x3, N, dN);
  for (PetscInt d = 0; d < 3; d++) {
    p[d] = J[d][0] = J[d][1] = 0;
    for (PetscInt a = 0; a < f->nn; a++) {
      p[d] += N[a] * X[3 * a + d];
      for (PetscInt i = 0; i < f->fg->dim; i++) J[d][i] += dN[a * f->fg->dim + i] * X[3 * a + d];
    }
  }
}

/* xi moved into the reference face ([-1, 1] per coordinate, or the unit triangle). */
static void Clamp(const TslGeometry *fg, PetscReal xi[])
{
  if (!Simplex(fg)) {
    for (PetscInt i = 0; i < fg->dim; i++) xi[i] = PetscMax(-1.0, PetscMin(1.0, xi[i]));
    return;
  }
  xi[0] = PetscMax(0.0, xi[0]), xi[1] = PetscMax(0.0, xi[1]);
  if (xi[0] + xi[1] > 1) {
    PetscReal s = PetscMax(0.0, PetscMin(1.0, 0.5 * (xi[0] - xi[1] + 1)));
    xi[0] = s, xi[1] = 1 - s;
  }
}

/* Closest point of p on face f (coordinates X): Gauss-Newton on |x(xi) - p|^2 from the face's centre, the
 * iterate clamped to the reference face when clamp is set (the closest point of the face itself; otherwise of
 * its extension, as the 2D overlap bounds need). Returns the parameters, the shape values there and the
 * distance. */
static void Project(const Face *f, const PetscReal X[], const PetscReal p[3], PetscBool clamp, PetscReal xi[2], PetscReal N[], PetscReal *dist)
{
  PetscReal x[3], J[3][2];

  xi[0] = xi[1] = Simplex(f->fg) ? 1.0 / 3 : 0;
  for (PetscInt it = 0; it < 30; it++) {
    PetscReal r[3], A[2][2] = {{0, 0}, {0, 0}}, b[2] = {0, 0}, step[2] = {0, 0};
    FacePoint(f, X, xi, x, J, N);
    for (PetscInt d = 0; d < 3; d++) r[d] = p[d] - x[d];
    for (PetscInt i = 0; i < f->fg->dim; i++) {
      for (PetscInt d = 0; d < 3; d++) b[i] += J[d][i] * r[d];
      for (PetscInt j = 0; j < f->fg->dim; j++)
        for (PetscInt d = 0; d < 3; d++) A[i][j] += J[d][i] * J[d][j];
    }
    if (f->fg->dim == 1) {
      if (A[0][0] <= 0) break;
      step[0] = b[0] / A[0][0];
    } else {
      const PetscReal det = A[0][0] * A[1][1] - A[0][1] * A[1][0];
      if (det == 0) break;
      step[0] = (A[1][1] * b[0] - A[0][1] * b[1]) / det;
      step[1] = (A[0][0] * b[1] - A[1][0] * b[0]) / det;
    }
    xi[0] += step[0], xi[1] += step[1];
    if (clamp) Clamp(f->fg, xi);
    if (PetscAbsReal(step[0]) + PetscAbsReal(step[1]) < 1e-14) break;
  }
  FacePoint(f, X, xi, x, J, N);
  *dist = PetscSqrtReal(PetscSqr(p[0] - x[0]) + PetscSqr(p[1] - x[1]) + PetscSqr(p[2] - x[2]));
}

static void FaceCoordinates(const TslModel *g, const Face *f, PetscReal X[])
{
  for (PetscInt a = 0; a < f->nn; a++)
    for (PetscInt d = 0; d < 3; d++) X[3 * a + d] = g->node_xyz[3 * f->node[a] + d];
}

/* The faces of element surface s (model positions of their nodes). */
static PetscErrorCode SurfaceFaces(const TslModel *g, const TslSurface *s, Face **faces)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(s->n, faces));
  for (PetscInt i = 0; i < s->n; i++) {
    const PetscInt     e    = TslModelElementIndex(g, s->elem[i]);
    const TslGeometry *geom = TslElementTypeGet(g->elem_type[e])->geom;
    Face              *f    = &(*faces)[i];
    f->fg                   = geom->face_geom[s->face[i] - 1];
    f->nn                   = geom->face_nnode[s->face[i] - 1];
    for (PetscInt a = 0; a < f->nn; a++) f->node[a] = TslModelNodeIndex(g, g->elem_conn[g->elem_ptr[e] + geom->face_node[s->face[i] - 1][a]]);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The box of face f's nodes, lower corner then upper (dim coordinates each), the layout of the contact bin grid. */
static void FaceBox(const TslModel *g, const Face *f, PetscReal box[6])
{
  for (PetscInt d = 0; d < g->dim; d++) box[d] = PETSC_MAX_REAL, box[g->dim + d] = -PETSC_MAX_REAL;
  for (PetscInt a = 0; a < f->nn; a++)
    for (PetscInt d = 0; d < g->dim; d++) {
      box[d]          = PetscMin(box[d], g->node_xyz[3 * f->node[a] + d]);
      box[g->dim + d] = PetscMax(box[g->dim + d], g->node_xyz[3 * f->node[a] + d]);
    }
}

/* The dual basis of a secondary face: A = D M^-1 (row-major, n x n), M_ab = int N_a N_b (times r when the
 * measure revolves), by the face's own rule. FALSE when M is singular or some int N_a is not positive (the
 * second-order 3D faces: tri6 corners integrate to zero, quad8 corners below it), where no dual basis exists. */
static PetscBool DualBasis(const Face *f, const PetscReal X[], PetscBool revolves, PetscReal A[], PetscReal D[])
{
  const TslQuadrature *q                                          = &f->fg->as_face;
  const PetscInt       n                                          = f->nn;
  PetscReal            M[TSL_MAX_FACE_NODES * TSL_MAX_FACE_NODES] = {0}, Minv[TSL_MAX_FACE_NODES * TSL_MAX_FACE_NODES];

  if (q->n == 0) return PETSC_FALSE;
  for (PetscInt g = 0; g < q->n; g++) {
    PetscReal p[3], J[3][2], N[TSL_MAX_FACE_NODES], dA;
    FacePoint(f, X, q->xi[g], p, J, N);
    if (f->fg->dim == 1)
      dA = PetscSqrtReal(J[0][0] * J[0][0] + J[1][0] * J[1][0] + J[2][0] * J[2][0]);
    else {
      const PetscReal c[3] = {J[1][0] * J[2][1] - J[2][0] * J[1][1], J[2][0] * J[0][1] - J[0][0] * J[2][1], J[0][0] * J[1][1] - J[1][0] * J[0][1]};
      dA                   = PetscSqrtReal(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    }
    if (revolves) dA *= p[0];
    for (PetscInt a = 0; a < n; a++)
      for (PetscInt b = 0; b < n; b++) M[a * n + b] += q->w[g] * dA * N[a] * N[b];
  }
  for (PetscInt a = 0; a < n; a++) {
    D[a] = 0;
    for (PetscInt b = 0; b < n; b++) D[a] += M[a * n + b];
    if (!(D[a] > 0)) return PETSC_FALSE;
  }
  /* Gauss-Jordan with partial pivoting (n <= 9) */
  for (PetscInt a = 0; a < n; a++)
    for (PetscInt b = 0; b < n; b++) Minv[a * n + b] = a == b;
  for (PetscInt c = 0; c < n; c++) {
    PetscInt  piv = c;
    PetscReal big = 0;
    for (PetscInt r = c; r < n; r++)
      if (PetscAbsReal(M[r * n + c]) > big) big = PetscAbsReal(M[r * n + c]), piv = r;
    if (big <= 1e-14 * D[c]) return PETSC_FALSE;
    for (PetscInt k = 0; k < n; k++) {
      PetscReal t  = M[c * n + k];
      M[c * n + k] = M[piv * n + k], M[piv * n + k] = t;
      t = Minv[c * n + k], Minv[c * n + k] = Minv[piv * n + k], Minv[piv * n + k] = t;
    }
    for (PetscInt r = 0; r < n; r++) {
      const PetscReal s = M[r * n + c] / M[c * n + c];
      if (r == c) continue;
      for (PetscInt k = 0; k < n; k++) M[r * n + k] -= s * M[c * n + k], Minv[r * n + k] -= s * Minv[c * n + k];
    }
  }
  for (PetscInt a = 0; a < n; a++)
    for (PetscInt b = 0; b < n; b++) A[a * n + b] = D[a] * Minv[a * n + b] / M[a * n + a];
  return PETSC_TRUE;
}

/* Adds the overlap integrals int Phi_a N_k of secondary face e (coordinates Xe, dual basis A) with main face f
 * (Xm) to T, at points closer than tol to f. 2D: the interval of e between the projections of f's ends, TIE_GAUSS
 * points; 3D: the clipped overlap's points (contact/clip3.c: linear secondary faces). */
static PetscErrorCode Overlap(const TslModel *g, const Face *e, const PetscReal Xe[], const PetscReal A[], const Face *f, const PetscReal Xm[],
                              PetscReal tol, PetscBool revolves, Terms *T)
{
  PetscReal xs[TSL_CONTACT_OVERLAP_MAX_POINTS][3], w[TSL_CONTACT_OVERLAP_MAX_POINTS];
  PetscInt  np = 0;

  PetscFunctionBeginUser;
  if (g->dim == 2) {
    static const PetscReal gx[TIE_GAUSS] = {-0.9061798459386640, -0.5384693101056831, 0, 0.5384693101056831, 0.9061798459386640};
    static const PetscReal gw[TIE_GAUSS] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665, 0.2369268850561891};
    PetscReal              z[2], N[TSL_MAX_FACE_NODES], dist, lo, hi;
    for (PetscInt end = 0; end < 2; end++) {
      PetscReal xi[2];
      Project(e, Xe, &Xm[3 * end], PETSC_FALSE, xi, N, &dist);
      z[end] = xi[0];
    }
    lo = PetscMax(-1.0, PetscMin(z[0], z[1])), hi = PetscMin(1.0, PetscMax(z[0], z[1]));
    if (hi - lo < 1e-12) PetscFunctionReturn(PETSC_SUCCESS);
    for (PetscInt q = 0; q < TIE_GAUSS; q++) {
      PetscReal xi[2] = {0.5 * (lo + hi) + 0.5 * (hi - lo) * gx[q], 0}, J[3][2];
      FacePoint(e, Xe, xi, xs[np], J, N);
      w[np++] = gw[q] * 0.5 * (hi - lo) * PetscSqrtReal(J[0][0] * J[0][0] + J[1][0] * J[1][0]);
    }
  } else {
    TslContactOverlapPoint pt[TSL_CONTACT_OVERLAP_MAX_POINTS];
    PetscReal              ym[3 * TSL_CONTACT3_MAX_FACE_NODES], dist;
    PetscInt               skind = TslContactFace3Find(e->fg->name), mkind = TslContactFace3Find(f->fg->name), nm = f->nn, npt;
    if (mkind < 0) { /* a main face contact has no family for (quad8): its corners bound the overlap */
      mkind = TslContactFace3Find(f->fg->ncorner == 4 ? "quad4" : "tri3");
      nm    = f->fg->ncorner;
    }
    for (PetscInt k = 0; k < 3 * nm; k++) ym[k] = Xm[k];
    PetscCall(TslContactOverlap3(skind, Xe, Xe, mkind, ym, TSL_CONTACT_OVERLAP_MAX_POINTS, pt, &npt, &dist));
    if (npt == 0 || PetscAbsReal(dist) > tol) PetscFunctionReturn(PETSC_SUCCESS);
    for (PetscInt q = 0; q < npt; q++) {
      for (PetscInt d = 0; d < 3; d++) {
        xs[np][d] = 0;
        for (PetscInt a = 0; a < e->nn; a++) xs[np][d] += pt[q].N[a] * Xe[3 * a + d];
      }
      w[np++] = pt[q].w;
    }
  }
  for (PetscInt q = 0; q < np; q++) {
    PetscReal xi[2], Ne[TSL_MAX_FACE_NODES], Nm[TSL_MAX_FACE_NODES], dist, p[3], J[3][2];
    Project(f, Xm, xs[q], PETSC_TRUE, xi, Nm, &dist);
    if (dist > tol) continue;
    Project(e, Xe, xs[q], PETSC_TRUE, xi, Ne, &dist);
    FacePoint(e, Xe, xi, p, J, Ne);
    const PetscReal wq = revolves ? w[q] * p[0] : w[q];
    for (PetscInt a = 0; a < e->nn; a++) {
      PetscReal phi = 0;
      for (PetscInt b = 0; b < e->nn; b++) phi += A[a * e->nn + b] * Ne[b];
      for (PetscInt k = 0; k < f->nn; k++)
        if (Nm[k] != 0) PetscCall(TermAdd(T, e->node[a], f->node[k], wq * phi * Nm[k]));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Mean size of the faces (2D: length of the chord; 3D: the square root of the corners' polygon area, by its
 * diagonals): the dialect's "typical element size" of the default position tolerance. */
static PetscReal MeanFaceSize(const TslModel *g, PetscInt nf, const Face faces[])
{
  PetscReal sum = 0;
  for (PetscInt i = 0; i < nf; i++) {
    const PetscReal *a = &g->node_xyz[3 * faces[i].node[0]], *b = &g->node_xyz[3 * faces[i].node[1]];
    if (g->dim == 2)
      sum += PetscSqrtReal(PetscSqr(b[0] - a[0]) + PetscSqr(b[1] - a[1]));
    else {
      /* quadrilateral: half the cross product of the diagonals; triangle: of two edges */
      const PetscBool  quad = (PetscBool)(faces[i].fg->ncorner == 4);
      const PetscReal *c = &g->node_xyz[3 * faces[i].node[2]], *d = quad ? &g->node_xyz[3 * faces[i].node[3]] : a, *e = quad ? b : a;
      const PetscReal  u[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]},
                      v[3]  = {quad ? d[0] - e[0] : b[0] - a[0], quad ? d[1] - e[1] : b[1] - a[1], quad ? d[2] - e[2] : b[2] - a[2]};
       const PetscReal n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
      sum += PetscSqrtReal(0.5 * PetscSqrtReal(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]));
    }
  }
  return nf ? sum / nf : 0;
}

/* What the ties gather before the rows are made (node positions of the whole model, rank 0): the projection of
 * each secondary node (P, from the first tie that has the node: tie[p] its index, -1 for a node no tie holds),
 * the mortar integrals of every secondary face of every tie (M), and the nodes' full int N_s (Dfull), so that a node
 * on the secondary surfaces of two ties takes the integrals of all its faces. */
typedef struct {
  Terms      M, P;
  PetscReal *Dfull;
  PetscInt  *tie;
} Gather;

/* Tie ti: the projections of its secondary nodes that no earlier tie holds (ADJUST moves them), and the mortar
 * integrals of its secondary faces. A node of both its surfaces is not tied by it. */
static PetscErrorCode TieGather(TslModel *g, PetscInt ti, Gather *G)
{
  const TslTie     *t   = &g->ties[ti];
  const TslSurface *sec = &g->surfaces[TslModelFindSurface(g, t->secondary)], *mainsurf = &g->surfaces[TslModelFindSurface(g, t->main)];
  const PetscBool   revolves = g->nelem ? TslKinematicsRevolves(TslElementTypeGet(g->elem_type[0])->kin) : PETSC_FALSE;
  Face             *mf, *sf = NULL;
  TslContactBinGrid grid;
  PetscInt         *snode, ns = 0, *cand = NULL, cap = 0, nc;
  char             *onmain, *seen, loc[PETSC_MAX_PATH_LEN + 32];
  PetscReal         size, tol, X[3 * TSL_MAX_FACE_NODES], Xm[3 * TSL_MAX_FACE_NODES];
  size_t            m0 = G->M.n;

  PetscFunctionBeginUser;
  (void)TslLocString(g, t->loc, loc, sizeof(loc));
  PetscCall(SurfaceFaces(g, mainsurf, &mf));
  size = MeanFaceSize(g, mainsurf->n, mf);
  tol  = t->tolerance > 0 ? t->tolerance : 0.025 * size;
  {
    PetscReal *boxes;
    PetscCall(PetscMalloc1(2 * g->dim * mainsurf->n, &boxes));
    for (PetscInt i = 0; i < mainsurf->n; i++) FaceBox(g, &mf[i], &boxes[2 * g->dim * i]);
    PetscCall(TslContactBinGridCreateDim(g->dim, mainsurf->n, boxes, tol, &grid)); /* boxes inflated by the tolerance */
    PetscCall(PetscFree(boxes));
  }
  PetscCall(PetscCalloc1(g->nnode, &onmain));
  PetscCall(PetscCalloc1(g->nnode, &seen));
  for (PetscInt i = 0; i < mainsurf->n; i++)
    for (PetscInt a = 0; a < mf[i].nn; a++) onmain[mf[i].node[a]] = 1;
  /* the secondary nodes, each once */
  if (sec->kind == TSL_SURFACE_ELEMENT) {
    PetscInt cnt = 0;
    PetscCall(SurfaceFaces(g, sec, &sf));
    for (PetscInt i = 0; i < sec->n; i++) cnt += sf[i].nn;
    PetscCall(PetscMalloc1(cnt, &snode));
    for (PetscInt i = 0; i < sec->n; i++)
      for (PetscInt a = 0; a < sf[i].nn; a++)
        if (!seen[sf[i].node[a]]) seen[sf[i].node[a]] = 1, snode[ns++] = sf[i].node[a];
  } else {
    PetscCall(PetscMalloc1(sec->n, &snode));
    for (PetscInt i = 0; i < sec->n; i++) {
      const PetscInt p = TslModelNodeIndex(g, sec->elem[i]);
      PetscCheck(p >= 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: node %" PetscInt_FMT " of surface %s is not defined", loc, sec->elem[i],
                 sec->name);
      if (!seen[p]) seen[p] = 1, snode[ns++] = p;
    }
  }
  /* projection of each node on the nearest main face within the tolerance: the dialect's test, ADJUST, and the
   * weights where the mortar integrals give none */
  for (PetscInt i = 0; i < ns; i++) {
    const PetscInt p = snode[i];
    PetscReal     *x = &g->node_xyz[3 * p], best = PETSC_MAX_REAL, bxi[2] = {0, 0}, bN[TSL_MAX_FACE_NODES], bp[3];
    PetscInt       bf = -1;
    if (G->tie[p] >= 0 || onmain[p]) continue;
    PetscCall(TslContactBinGridQueryGrow(grid, x, 0, &cap, &cand, &nc));
    for (PetscInt c = 0; c < nc; c++) {
      PetscReal xi[2], N[TSL_MAX_FACE_NODES], dist;
      FaceCoordinates(g, &mf[cand[c]], Xm);
      Project(&mf[cand[c]], Xm, x, PETSC_TRUE, xi, N, &dist);
      if (dist < best) best = dist, bf = cand[c], bxi[0] = xi[0], bxi[1] = xi[1];
    }
    PetscCheck(bf >= 0 && best <= tol, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
               "%s: %s: node %" PetscInt_FMT " of secondary surface %s finds no face of main surface %s within the position tolerance %g%s", loc,
               t->from_pair ? "tied contact pair" : "*TIE", g->node_id[p], sec->name, mainsurf->name, (double)tol,
               bf >= 0 ? " (the nearest one is farther)" : " (none nearby)");
    {
      PetscReal J[3][2];
      FaceCoordinates(g, &mf[bf], Xm);
      FacePoint(&mf[bf], Xm, bxi, bp, J, bN);
    }
    for (PetscInt k = 0; k < mf[bf].nn; k++)
      if (bN[k] != 0) PetscCall(TermAdd(&G->P, p, mf[bf].node[k], bN[k]));
    G->tie[p] = ti;
    if (t->adjust)
      for (PetscInt d = 0; d < g->dim; d++) x[d] = bp[d];
  }
  /* mortar integrals over the secondary faces (after ADJUST: on the adjusted faces) */
  for (PetscInt i = 0; sf && i < sec->n; i++) {
    PetscReal A[TSL_MAX_FACE_NODES * TSL_MAX_FACE_NODES], D[TSL_MAX_FACE_NODES], box[6];
    if (g->dim == 3 && TslContactFace3Find(sf[i].fg->name) < 0) continue;
    if (g->dim == 3 && sf[i].fg->order > 1) continue; /* no dual basis: tri6, quad8 (projection weights) */
    FaceCoordinates(g, &sf[i], X);
    if (!DualBasis(&sf[i], X, revolves, A, D)) continue;
    for (PetscInt a = 0; a < sf[i].nn; a++) G->Dfull[sf[i].node[a]] += D[a];
    {
      PetscReal c[3], radius = 0;
      FaceBox(g, &sf[i], box); /* the faces whose inflated boxes come within its half diagonal of its centre */
      for (PetscInt d = 0; d < g->dim; d++) c[d] = 0.5 * (box[d] + box[g->dim + d]), radius += PetscSqr(0.5 * (box[g->dim + d] - box[d]));
      PetscCall(TslContactBinGridQueryGrow(grid, c, PetscSqrtReal(radius), &cap, &cand, &nc));
    }
    for (PetscInt c = 0; c < nc; c++) {
      FaceCoordinates(g, &mf[cand[c]], Xm);
      PetscCall(Overlap(g, &sf[i], X, A, &mf[cand[c]], Xm, tol, revolves, &G->M));
    }
  }
  /* a node of both surfaces is one node: no integrals of this tie for it */
  for (size_t k = m0; k < G->M.n; k++)
    if (onmain[G->M.t[k].s]) G->M.t[k].w = 0;
  PetscCall(PetscFree(snode));
  PetscCall(PetscFree(cand));
  PetscCall(PetscFree(onmain));
  PetscCall(PetscFree(seen));
  PetscCall(TslContactBinGridDestroy(&grid));
  PetscCall(PetscFree(mf));
  PetscCall(PetscFree(sf));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The rows u_s = sum_k c_sk u_k of every tied node, in R (sorted by node): the mortar weights where the node's
 * faces meet the main surfaces over at least half their weight (sum_k int Phi_s N_k >= int N_s / 2), normalised
 * to sum to one; otherwise the projection. count[2 * ti + 0/1]: nodes of tie ti by mortar / by projection. */
static PetscErrorCode TieRows(const TslModel *g, Gather *G, Terms *R, PetscInt count[])
{
  PetscReal *Dsum;
  size_t     im = 0, ip = 0;

  PetscFunctionBeginUser;
  qsort(G->M.t, G->M.n, sizeof(Term), CompareTerm);
  qsort(G->P.t, G->P.n, sizeof(Term), CompareTerm);
  PetscCall(PetscCalloc1(g->nnode, &Dsum));
  for (size_t k = 0; k < G->M.n; k++) Dsum[G->M.t[k].s] += G->M.t[k].w;
  while (ip < G->P.n) {
    const PetscInt  s   = G->P.t[ip].s;
    const PetscReal sum = Dsum[s];
    size_t          m0, m1, p1 = ip;
    while (p1 < G->P.n && G->P.t[p1].s == s) p1++;
    while (im < G->M.n && G->M.t[im].s < s) im++;
    m0 = m1 = im;
    while (m1 < G->M.n && G->M.t[m1].s == s) m1++;
    if (m1 > m0 && G->Dfull[s] > 0 && sum >= 0.5 * G->Dfull[s]) {
      for (size_t k = m0; k < m1; k++) {
        PetscReal c = G->M.t[k].w / sum;
        while (k + 1 < m1 && G->M.t[k + 1].k == G->M.t[k].k) c += G->M.t[++k].w / sum; /* repeated main nodes (sorted) */
        if (PetscAbsReal(c) > 1e-13) PetscCall(TermAdd(R, s, G->M.t[k].k, c));
      }
      count[2 * G->tie[s]]++;
    } else {
      for (size_t k = ip; k < p1; k++) PetscCall(TermAdd(R, s, G->P.t[k].k, G->P.t[k].w));
      count[2 * G->tie[s] + 1]++;
    }
    ip = p1;
    im = m1;
  }
  PetscCall(PetscFree(Dsum));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Room for one more equation (capacity doubled; *cap the current one). */
static PetscErrorCode GrowEquations(TslModel *g, PetscInt *cap)
{
  TslEquation *e;

  PetscFunctionBeginUser;
  if (g->nequation < *cap) PetscFunctionReturn(PETSC_SUCCESS);
  *cap = 2 * *cap + 64;
  PetscCall(PetscCalloc1(*cap, &e));
  if (g->nequation) PetscCall(PetscArraycpy(e, g->equations, g->nequation));
  PetscCall(PetscFree(g->equations));
  g->equations = e;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslMeshTies(TslModel *g)
{
  const TslElementType *type;
  char                 *tied, *dep, loc[PETSC_MAX_PATH_LEN + 32];
  PetscInt              dofs[TSL_MAX_NODE_DOF], nd = 0, first = g->nequation, cap = g->nequation;

  PetscFunctionBeginUser;
  if (!g->ntie || !g->nelem) PetscFunctionReturn(PETSC_SUCCESS);
  type = TslElementTypeGet(g->elem_type[0]);
  for (PetscInt i = 0; i < type->ndof; i++)
    if (type->node_dof[i] > 0) dofs[nd++] = type->node_dof[i];
  PetscCall(PetscCalloc1(g->nnode, &tied));
  /* dep: the node's dofs eliminated by a user *EQUATION (bit per slot) */
  PetscCall(PetscCalloc1(g->nnode, &dep));
  for (PetscInt q = 0; q < g->nequation; q++) {
    const PetscInt p = TslModelNodeIndex(g, g->equations[q].node[0]);
    for (PetscInt i = 0; i < nd; i++)
      if (p >= 0 && dofs[i] == g->equations[q].dof[0]) dep[p] |= (char)(1 << i);
  }
  {
    Gather    G = {{NULL, 0, 0}, {NULL, 0, 0}, NULL, NULL};
    Terms     R = {NULL, 0, 0};
    PetscInt *count;
    PetscCall(PetscCalloc1(g->nnode, &G.Dfull));
    PetscCall(PetscMalloc1(g->nnode, &G.tie));
    PetscCall(PetscCalloc1(2 * g->ntie, &count));
    for (PetscInt p = 0; p < g->nnode; p++) G.tie[p] = -1;
    for (PetscInt ti = 0; ti < g->ntie; ti++) PetscCall(TieGather(g, ti, &G));
    PetscCall(TieRows(g, &G, &R, count));
    for (PetscInt ti = 0; ti < g->ntie; ti++) {
      const TslTie *t = &g->ties[ti];
      PetscCall(PetscPrintf(PETSC_COMM_SELF,
                            "%s: %s%s%s, %s to %s: %" PetscInt_FMT " secondary nodes tied (%" PetscInt_FMT " by the mortar weights, %" PetscInt_FMT
                            " by projection)\n",
                            TslLocString(g, t->loc, loc, sizeof(loc)), t->from_pair ? "tied contact pair" : "*TIE", t->name[0] ? " " : "", t->name,
                            t->secondary, t->main, count[2 * ti] + count[2 * ti + 1], count[2 * ti], count[2 * ti + 1]));
    }
    for (size_t k0 = 0; k0 < R.n;) {
      const PetscInt s  = R.t[k0].s;
      size_t         k1 = k0;
      while (k1 < R.n && R.t[k1].s == s) k1++;
      tied[s] = 1;
      (void)TslLocString(g, g->ties[G.tie[s]].loc, loc, sizeof(loc));
      PetscCheck(!dep[s], PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
                 "%s: node %" PetscInt_FMT
                 " of secondary surface %s is the dependent node of an *EQUATION as well; the dialect allows one constraint per dependent node",
                 loc, g->node_id[s], g->ties[G.tie[s]].secondary);
      for (PetscInt i = 0; i < nd; i++) {
        TslEquation *e;
        PetscCall(GrowEquations(g, &cap));
        e = &g->equations[g->nequation++];
        PetscCall(PetscMemzero(e, sizeof(*e)));
        e->n   = (PetscInt)(k1 - k0) + 1;
        e->tie = PETSC_TRUE;
        e->loc = g->ties[G.tie[s]].loc;
        PetscCall(PetscMalloc1(e->n, &e->node));
        PetscCall(PetscMalloc1(e->n, &e->dof));
        PetscCall(PetscMalloc1(e->n, &e->coef));
        e->node[0] = g->node_id[s], e->dof[0] = dofs[i], e->coef[0] = 1;
        for (size_t k = k0; k < k1; k++) {
          const PetscInt j = 1 + (PetscInt)(k - k0);
          e->node[j] = g->node_id[R.t[k].k], e->dof[j] = dofs[i], e->coef[j] = -R.t[k].w;
        }
      }
      k0 = k1;
    }
    PetscCall(PetscFree(R.t));
    PetscCall(PetscFree(G.M.t));
    PetscCall(PetscFree(G.P.t));
    PetscCall(PetscFree(G.Dfull));
    PetscCall(PetscFree(G.tie));
    PetscCall(PetscFree(count));
  }
  /* chains: a main node tied as a secondary node of another tie (or the dependent node of an *EQUATION) */
  for (PetscInt q = first; q < g->nequation; q++)
    for (PetscInt k = 1; k < g->equations[q].n; k++) {
      const PetscInt p = TslModelNodeIndex(g, g->equations[q].node[k]);
      PetscCheck(!tied[p] && !dep[p], PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
                 "%s: main node %" PetscInt_FMT
                 " is itself constrained (a secondary node of a tie, or the dependent node of an *EQUATION): chained constraints are not supported",
                 TslLocString(g, g->equations[q].loc, loc, sizeof(loc)), g->equations[q].node[k]);
    }
  PetscCall(PetscInfo(NULL, "ties: %" PetscInt_FMT " equations\n", g->nequation - first));
  PetscCall(PetscFree(tied));
  PetscCall(PetscFree(dep));
  PetscFunctionReturn(PETSC_SUCCESS);
}
