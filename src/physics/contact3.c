/* 3D node-to-surface contact in the assembly: what differs from 2D (src/physics/contact.c) is the face
 * families (tri3, quad4, tri6, one per face), the pairing (a 3D bin grid; a node is paired with the face
 * whose closest point contains it: faces carry no neighbour list, a node whose projection leaves its face
 * is simply searched again), the history transfer between faces (by projecting the history's face points
 * onto the new face) and the smoothing (nodal normals of the converged state). Everything else (laws,
 * commit, rollback, augmentation, outputs) is shared with 2D. */
#include "problem_impl.h"

/* Tolerance (reference units of a face) within which a projection counts as on the face when pairing. */
#define TSL_CONTACT3_XI_TOL 1e-9

static PetscInt FaceNodes(const TslContactSurface *cs, PetscInt f)
{
  return TslContactFace3Nodes(cs->kind[f]);
}

static void NodeData(TslProblem p, const TslContactSurface *cs, const PetscScalar *xa, PetscInt l, PetscReal x[3], PetscReal u[4])
{
  for (PetscInt c = 0; c < 3; c++) x[c] = p->m->node_xyz[3 * l + c];
  for (PetscInt c = 0; c < 4; c++) u[c] = TslProblemSlotValue(p, xa, l, cs->slot[c]);
}

/* Current coordinates x[3*a + d] of the nodes of main face f. */
static void FacePosition(TslProblem p, const TslContactSurface *cs, const PetscScalar *xa, PetscInt f, PetscReal x[])
{
  for (PetscInt a = 0; a < FaceNodes(cs, f); a++) {
    PetscReal X[3], u[4];
    NodeData(p, cs, xa, cs->main_lnode[cs->nper * f + a], X, u);
    for (PetscInt d = 0; d < 3; d++) x[3 * a + d] = X[d] + u[d];
  }
}

PetscErrorCode TslProblemContact3Input(TslProblem p, const TslContactNode *cn, const PetscScalar *xa, TslContactInput3 *in, PetscInt nodes[], PetscInt *n)
{
  const TslContactSurface *cs = &p->csurf[cn->pair];
  const PetscInt           nf = FaceNodes(cs, cn->seg);

  PetscFunctionBeginUser;
  memset(in, 0, sizeof(*in));
  in->face = cs->kind[cn->seg];
  in->area = cn->length;
  nodes[0] = cn->lnode;
  for (PetscInt a = 0; a < nf; a++) nodes[1 + a] = cs->main_lnode[cs->nper * cn->seg + a];
  *n = 1 + nf;
  for (PetscInt a = 0; a < *n; a++) NodeData(p, cs, xa, nodes[a], in->x[a], in->u[a]);
  for (PetscInt a = 0; a < nf; a++)
    for (PetscInt d = 0; d < 3; d++) in->nodal_normal[a][d] = cs->nnormal[3 * nodes[1 + a] + d];
  in->smoothing = cs->smooth;
  in->dt        = p->dt > 0 ? p->dt : 1.0;
  in->hist      = cn->hist;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The vector area of a face from its corners: (x2 - x0) x (x1 - x0)-style cross products, exact for flat
 * triangles and for the bilinear quad (half the cross product of the diagonals); the right-hand normal of
 * the face order, out of the main body. */
static void FaceAreaVector(PetscInt nf, const PetscReal x[], PetscReal A[3])
{
  const PetscReal *a = &x[0], *b = &x[3], *c = &x[6], *d = nf == 4 ? &x[9] : NULL;
  PetscReal        e[3], g[3];

  for (PetscInt k = 0; k < 3; k++) {
    e[k] = d ? c[k] - a[k] : b[k] - a[k];
    g[k] = d ? d[k] - b[k] : c[k] - a[k];
  }
  A[0] = 0.5 * (e[1] * g[2] - e[2] * g[1]);
  A[1] = 0.5 * (e[2] * g[0] - e[0] * g[2]);
  A[2] = 0.5 * (e[0] * g[1] - e[1] * g[0]);
}

PetscErrorCode TslProblemContact3Normals(TslProblem p, TslContactSurface *cs, const PetscScalar *xa)
{
  PetscFunctionBeginUser;
  if (!cs->active) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt f = 0; f < cs->nmain; f++)
    for (PetscInt a = 0; a < FaceNodes(cs, f); a++)
      for (PetscInt d = 0; d < 3; d++) cs->nnormal[3 * cs->main_lnode[cs->nper * f + a] + d] = 0;
  /* area-weighted average of the faces around each node */
  for (PetscInt f = 0; f < cs->nmain; f++) {
    PetscReal x[3 * TSL_CONTACT3_MAX_FACE_NODES], A[3];
    FacePosition(p, cs, xa, f, x);
    FaceAreaVector(FaceNodes(cs, f) == 4 ? 4 : 3, x, A);
    for (PetscInt a = 0; a < FaceNodes(cs, f); a++)
      for (PetscInt d = 0; d < 3; d++) cs->nnormal[3 * cs->main_lnode[cs->nper * f + a] + d] += A[d];
  }
  for (PetscInt f = 0; f < cs->nmain; f++)
    for (PetscInt a = 0; a < FaceNodes(cs, f); a++) {
      PetscReal *v = &cs->nnormal[3 * cs->main_lnode[cs->nper * f + a]], len = PetscSqrtReal(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      if (len > 0 && PetscAbsReal(len - 1) > 0)
        for (PetscInt d = 0; d < 3; d++) v[d] /= len;
    }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscBool TslProblemContact3Departed(TslProblem p, const TslContactNode *cn, PetscReal tol)
{
  const TslContactSurface *cs    = &p->csurf[cn->pair];
  PetscReal                xi[2] = {cn->out.xi_raw, cn->out.eta_raw};
  return (PetscBool)!TslContactFace3Inside(cs->kind[cn->seg], xi, tol);
}

PetscErrorCode TslProblemContact3Search(TslProblem p, PetscInt k, const PetscScalar *xa, PetscInt *changed)
{
  TslContactSurface *cs = &p->csurf[k];
  const PetscInt     np = cs->nper;
  PetscReal         *box, *fx;
  PetscInt          *cand, cap = 64;
  TslContactBinGrid  grid;

  PetscFunctionBeginUser;
  if (!cs->active) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscMalloc2(6 * cs->nmain + 1, &box, 3 * np * cs->nmain + 1, &fx));
  PetscCall(PetscMalloc1(cap, &cand)); /* grown by the queries */
  for (PetscInt f = 0; f < cs->nmain; f++) {
    FacePosition(p, cs, xa, f, &fx[3 * np * f]);
    PetscCall(TslContactFace3Box(cs->kind[f], &fx[3 * np * f], &box[6 * f]));
  }
  PetscCall(TslContactBinGridCreateDim(3, cs->nmain, box, cs->search_radius, &grid));
  for (PetscInt i = 0; i < p->ncnode; i++) {
    TslContactNode *cn = &p->cnode[i];
    PetscReal       y[3], X[3], u[4], best_d = PETSC_MAX_REAL, best_xi[2] = {0, 0}, bound;
    PetscInt        ncand, best = -1;

    if (cn->pair != k) continue;
    NodeData(p, cs, xa, cn->lnode, X, u);
    for (PetscInt d = 0; d < 3; d++) y[d] = X[d] + u[d];
    PetscCall(TslContactBinGridQueryGrow(grid, y, cs->search_radius, &cap, &cand, &ncand));
    /* a bound first: the face nearest by its box, projected; a face farther than that by more than the tie
     * tolerance cannot be the nearest, and is not projected below (the projection is most of the search) */
    bound = PETSC_MAX_REAL;
    for (PetscInt c = 0, c0 = -1; c <= ncand; c++) {
      if (c < ncand) {
        const PetscReal *b = &box[6 * cand[c]];
        PetscReal        lb = 0;
        for (PetscInt d = 0; d < 3; d++) lb += PetscSqr(PetscMax(0, PetscMax(b[d] - y[d], y[d] - b[3 + d])));
        if (c0 < 0 || lb < bound) c0 = c, bound = lb;
      } else if (c0 >= 0) {
        const PetscReal *x = &fx[3 * np * cand[c0]];
        PetscReal        xi[2], q[3], n[3];
        bound = PETSC_MAX_REAL;
        PetscCall(TslContactFace3Project(cs->kind[cand[c0]], x, y, xi));
        if (TslContactFace3Inside(cs->kind[cand[c0]], xi, TSL_CONTACT3_XI_TOL)) {
          PetscCall(TslContactFace3Evaluate(cs->kind[cand[c0]], x, xi, q, n));
          for (PetscInt d = 0; d < 3; d++) q[d] = y[d] - q[d];
          if (q[0] * n[0] + q[1] * n[1] + q[2] * n[2] >= -cs->search_radius) bound = PetscSqrtReal(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
        }
      }
    }
    for (PetscInt c = 0; c < ncand; c++) {
      const PetscReal *x = &fx[3 * np * cand[c]], *b = &box[6 * cand[c]];
      PetscReal        xi[2], q[3], n[3], dist, gap, lb = 0;

      /* the face lies in its box, so the distance to the box bounds the distance to the face from below: a
       * face that cannot beat the best so far is not projected (the projection is most of the search) */
      for (PetscInt d = 0; d < 3; d++) lb += PetscSqr(PetscMax(0, PetscMax(b[d] - y[d], y[d] - b[3 + d])));
      if (best >= 0 && PetscSqrtReal(lb) >= best_d - TSL_CONTACT3_XI_TOL * cs->search_radius) continue;
      if (bound < PETSC_MAX_REAL && PetscSqrtReal(lb) > bound + 2 * TSL_CONTACT3_XI_TOL * cs->search_radius) continue;

      PetscCall(TslContactFace3Project(cs->kind[cand[c]], x, y, xi));
      /* only a face that contains the closest point pairs: a node beyond every face (off the main surface,
       * or in the shadow of a convex edge) is out of contact */
      if (!TslContactFace3Inside(cs->kind[cand[c]], xi, TSL_CONTACT3_XI_TOL)) continue;
      PetscCall(TslContactFace3Evaluate(cs->kind[cand[c]], x, xi, q, n));
      for (PetscInt d = 0; d < 3; d++) q[d] = y[d] - q[d];
      gap  = q[0] * n[0] + q[1] * n[1] + q[2] * n[2];
      dist = PetscSqrtReal(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
      if (gap < -cs->search_radius) continue; /* behind the surface: another body, not a contact */
      /* equal distances are a tie (the first face wins), whatever the round-off of large coordinates */
      if (dist < best_d - TSL_CONTACT3_XI_TOL * cs->search_radius) best = cand[c], best_d = dist, best_xi[0] = xi[0], best_xi[1] = xi[1];
    }
    /* a face held only for its nodal normals never pairs: CheckHeldRegion (contact.c) guarantees that no
     * node reaches one, so this is a defect, not a node out of contact */
    PetscCheck(best < 0 || !cs->ring[best], PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "contact node %" PetscInt_FMT " reached main face %" PetscInt_FMT " at the edge of the part of the main surface held here",
               p->m->node_id[cn->lnode], best);
    if (best != cn->seg) {
      (*changed)++;
      if (best >= 0 && cn->seg >= 0) {
        /* the history follows the node: its face points projected onto the new face */
        PetscReal xo[3 * TSL_CONTACT3_MAX_FACE_NODES];
        FacePosition(p, cs, xa, cn->seg, xo);
        PetscCall(TslContactStateTransfer3(cs->kind[cn->seg], xo, cs->kind[best], &fx[3 * np * best], &cn->hist));
      } else if (best >= 0) {
        PetscCall(TslContactStateStart3(best_xi, &cn->hist)); /* a new contact starts stress-free */
      }
      cn->seg = best;
    }
  }
  PetscCall(TslContactBinGridDestroy(&grid));
  PetscCall(PetscFree2(box, fx));
  PetscCall(PetscFree(cand));
  PetscFunctionReturn(PETSC_SUCCESS);
}
