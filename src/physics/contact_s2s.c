/* Surface-to-surface contact in the assembly (2D: plane and axisymmetric models): *CONTACT PAIR,
 * TYPE=SURFACE TO SURFACE.
 *
 * Each secondary face held by this rank (every face with a node it owns: src/mesh/distribute.c; all its
 * nodes and the whole main surface are local) carries contact points: at every search its current
 * position is cut at the projections of the ends of the nearby main faces, each piece is paired with
 * the main face under its middle (none beyond the ends of the main surface: no force, no heat), and gets
 * the Gauss points of contact/segment.c. A point is the node-to-segment kernel's secondary node at
 * x = N_b x_b with the point's weight as its length, expanded to the face's nodes
 * (TslContactPointElement). The face's blocks are inserted by one rank (the owner of its first node);
 * the other ranks that hold it evaluate it too, identically, for their nodes' outputs.
 *
 * Segmentation and pairing are frozen during a Newton solve, like node-to-surface pairing; a point whose
 * projection leaves its main face after convergence triggers a new search and another solve.
 *
 * History (xi_old, sticking anchor, multiplier, twist anchors) lives at the points. When a search cuts a
 * face differently (the main surface moved along it), the points' history is carried over through
 * quantities that do not depend on the cut: the slip of the increment so far L (xi - xi_old), the elastic
 * slip from the anchor L (xi - xi_anchor), the multiplier lambda, and the twist's w - w_old, w - w_anchor,
 * each averaged to the face's nodes (weights N_b+ x point weight) and interpolated back with N_b at the new
 * points: exact for uniform fields (uniform sliding dissipates mu p |ds| exactly). A face cut the same way
 * keeps its points' history unchanged. A face with no point in contact before starts afresh.
 *
 * Outputs at a secondary node b: CPRESS and HFLA = sum over points of N_b w v / sum over its faces of
 * int N_b ds (consistent nodal force over tributary length: a uniform field is reproduced exactly),
 * CSTATUS the largest status of the points of its faces that it carries, CSLIP accumulated the same way
 * as CPRESS from the points' slips.
 */
#include "problem_impl.h"
#include "contact_s2s_impl.h"

#define S2S_BREAK_TOL  1e-6 /* breaks closer than this fraction of the secondary face are merged */
#define S2S_XI_TOL     1e-9 /* a piece's middle projects onto a main face within this fraction of it */
#define S2S_MAX_BREAKS 64
#define NH             5 /* portable history: slip, elastic slip, lambda, twist slip, twist elastic slip */

/* Reference coordinates X[2*b + d] and unknowns U[nu*b + c] of a face's nodes. */
static void FaceData(TslProblem p, const S2SFace *fc, const PetscScalar *xa, PetscReal X[], PetscReal U[])
{
  const TslContactSurface *cs = &p->csurf[fc->pair];
  for (PetscInt b = 0; b < fc->nsn; b++) TslProblemContactNodeData(p, cs, xa, fc->lnode[b], &X[2 * b], &U[cs->nu * b]);
}

/* Current coordinates of the nodes of main face seg of surface cs. */
static void MainFace(TslProblem p, const TslContactSurface *cs, const PetscScalar *xa, PetscInt seg, PetscReal y[])
{
  PetscReal u[TSL_CONTACT_MAX_NODE_DOF];
  for (PetscInt a = 0; a < cs->nper; a++) {
    TslProblemContactNodeData(p, cs, xa, cs->main_lnode[cs->nper * seg + a], &y[2 * a], u);
    y[2 * a] += u[0], y[2 * a + 1] += u[1];
  }
}

/* The kernel input of a point and the local nodes of its expanded element (the face's, then the kernel's
 * others): *n of them. */
static PetscErrorCode PointInput(TslProblem p, const S2SFace *fc, const S2SPoint *pt, const PetscScalar *xa, TslContactInput *in, PetscInt nodes[],
                                 PetscInt *n, TslContactNeighbourData *nb)
{
  TslContactNode cn;
  PetscInt       kn[TSL_CONTACT_MAX_NODES], nk;
  PetscReal      X[2 * TSL_CONTACT_MAX_FACE_NODES], U[TSL_CONTACT_MAX_NODE_DOF * TSL_CONTACT_MAX_FACE_NODES];

  PetscFunctionBeginUser;
  TslS2SPointNode(fc, pt, &cn);
  TslProblemContactElementInput(p, &cn, xa, in, kn, &nk, nb);
  FaceData(p, fc, xa, X, U);
  PetscCall(TslContactPointSetUp(fc->kind, X, U, pt->zeta, in));
  TslS2SPointNodes(fc, kn, nk, nodes, n);
  PetscFunctionReturn(PETSC_SUCCESS);
}

void TslS2SPointNode(const S2SFace *fc, const S2SPoint *pt, TslContactNode *cn)
{
  memset(cn, 0, sizeof(*cn));
  cn->pair   = fc->pair;
  cn->lnode  = fc->lnode[0];
  cn->length = pt->length;
  cn->seg    = pt->seg;
  cn->hist   = pt->hist;
}

void TslS2SPointNodes(const S2SFace *fc, const PetscInt kn[], PetscInt nk, PetscInt nodes[], PetscInt *n)
{
  *n = 0;
  for (PetscInt b = 0; b < fc->nsn; b++) nodes[(*n)++] = fc->lnode[b];
  for (PetscInt k = 1; k < nk; k++) nodes[(*n)++] = kn[k];
}

/* Adds a point's R (and K, with a Jacobian) into the accumulated block of its face: the points that share
 * their node list (those on one main face) are inserted once, as their sum, when the list changes or the
 * secondary face ends (Flush); the insertion's search of the matrix rows was a tenth of a 3D run. */
typedef struct {
  PetscInt  n, ld[TSL_CONTACT_S2S3_MAX_DOF];
  PetscReal R[TSL_CONTACT_S2S3_MAX_DOF], K[TSL_CONTACT_S2S3_MAX_DOF * TSL_CONTACT_S2S3_MAX_DOF];
} S2SBlock;

static PetscErrorCode Flush(TslProblem p, AsmMode mode, Mat A, PetscScalar *f, S2SBlock *b)
{
  PetscFunctionBeginUser;
  if (b->n) PetscCall(TslProblemInsert(p, mode, A, f, b->n, b->ld, b->R, mode == ASM_JACOBIAN ? b->K : NULL));
  b->n = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The block the point with unknowns ld[n] adds to: the current one when it has the same unknowns (the points of
 * one face pair come one after the other), else a zeroed one after the current is inserted. */
static PetscErrorCode BlockFor(TslProblem p, AsmMode mode, Mat A, PetscScalar *f, PetscInt n, const PetscInt ld[], S2SBlock *b)
{
  PetscFunctionBeginUser;
  if (b->n == n && !memcmp(b->ld, ld, (size_t)n * sizeof(PetscInt))) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(Flush(p, mode, A, f, b));
  b->n = n;
  memcpy(b->ld, ld, (size_t)n * sizeof(PetscInt));
  PetscCall(PetscArrayzero(b->R, n));
  if (mode == ASM_JACOBIAN) PetscCall(PetscArrayzero(b->K, n * n));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* -info: a surface-to-surface point's state at a residual evaluation, by the global ids of its secondary face's
 * nodes, its index on that face and the main face's nodes (as node-to-surface prints each contact node). */
static PetscErrorCode InfoPoint(TslProblem p, const S2SFace *fc, const S2SPoint *pt, PetscInt k)
{
  const TslContactSurface *cs       = &p->csurf[fc->pair];
  char                     sec[128] = "", mainf[128] = "";
  size_t                   ls = 0, lm = 0;
  PetscBool                on;

  PetscFunctionBeginUser;
  PetscCall(PetscInfoEnabled(PETSC_SMALLEST_CLASSID, &on)); /* the class of PetscInfo(NULL, ...) */
  if (!on) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt a = 0; a < fc->nsn && ls + 24 < sizeof(sec); a++)
    ls += (size_t)snprintf(sec + ls, sizeof(sec) - ls, " %" PetscInt_FMT, p->m->node_id[fc->lnode[a]]);
  for (PetscInt a = 0; a < cs->nper && lm + 24 < sizeof(mainf); a++) {
    const PetscInt l = cs->main_lnode[cs->nper * pt->seg + a];
    if (l >= 0) lm += (size_t)snprintf(mainf + lm, sizeof(mainf) - lm, " %" PetscInt_FMT, p->m->node_id[l]);
  }
  PetscCall(PetscInfo(NULL,
                      "contact point %" PetscInt_FMT " of pair %" PetscInt_FMT
                      " secondary face [%s ] on main face [%s ]: gap %g p %g slip %g shear %g q %g status %d\n",
                      k, fc->pair + 1, sec, mainf, (double)pt->out.gap, (double)pt->out.pressure,
                      (double)PetscHypotReal(pt->out.slip, pt->out.slip_circ), (double)PetscHypotReal(pt->out.shear, pt->out.shear_circ),
                      (double)pt->out.heat_flux, (int)pt->out.status));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemContactS2SAssemble(TslProblem p, AsmMode mode, const PetscScalar *xa, PetscScalar *f, Mat A, AsmHeat *heat)
{
  TslContactS2S           s = p->s2s;
  static S2SBlock         block, scratch;
  static S2S3InputCache   cache; /* emptied below: xa changes between calls */
  TslContactNeighbourData nb;

  PetscFunctionBeginUser;
  if (!s) PetscFunctionReturn(PETSC_SUCCESS);
  block.n  = 0;
  cache.fc = NULL;
  for (PetscInt i = 0; i < s->nface; i++) {
    const S2SFace           *fc = &s->face[i];
    const TslContactSurface *cs = &p->csurf[fc->pair];
    const PetscInt           nu = cs->nu;

    if (mode == ASM_PATTERN && !fc->assemble) continue;
    for (PetscInt q = fc->first; q < fc->first + fc->npt; q++) {
      S2SPoint        *pt = &s->pt[q];
      TslContactInput  in;
      TslContactInput3 in3;
      PetscInt         nodes[TSL_CONTACT_S2S3_MAX_NODES], n, ld[TSL_CONTACT_S2S3_MAX_DOF];

      if (pt->seg < 0) continue;
      if (p->dim == 3)
        PetscCall(TslS2S3PointInput(p, fc, pt, xa, &cache, &in3, nodes, &n));
      else PetscCall(PointInput(p, fc, pt, xa, &in, nodes, &n, &nb));
      for (PetscInt a = 0; a < n; a++)
        for (PetscInt c = 0; c < nu; c++) ld[nu * a + c] = TslProblemSlotDof(p, nodes[a], cs->slot[c]);
      if (mode == ASM_PATTERN) { /* a face pair's node pairs once, when its block is flushed */
        PetscCall(BlockFor(p, mode, A, f, nu * n, ld, &block));
        continue;
      }
      {
        /* the point adds to its face pair's block, or (another rank inserts this face, or nothing is assembled)
         * to a scratch block: the outputs are kept here too */
        S2SBlock *b = &block;
        if (fc->assemble && (f || A))
          PetscCall(BlockFor(p, mode, A, f, nu * n, ld, b));
        else {
          b = &scratch, b->n = 0; /* never inserted */
          PetscCall(PetscArrayzero(b->R, nu * n));
          if (mode == ASM_JACOBIAN) PetscCall(PetscArrayzero(b->K, nu * n * nu * n));
        }
        const TslContactStatus was = pt->out.status;
        if (p->dim == 3)
          PetscCall(TslContactPointElement3(&cs->law, &in3, fc->nsn, pt->N, b->R, mode == ASM_JACOBIAN ? b->K : NULL, &pt->out));
        else
          PetscCall(TslContactPointElement(&cs->law, &in, fc->kind, pt->zeta, b->R, mode == ASM_JACOBIAN ? b->K : NULL, &pt->out));
        if (mode == ASM_RESIDUAL && fc->assemble) TslProblemContactChatterNote(p, was, pt->out.status, fc->lnode[0]);
      }
      if (!fc->assemble) continue;
      if (mode == ASM_RESIDUAL) PetscCall(InfoPoint(p, fc, pt, q - fc->first));
      if (heat) {
        heat->interface += pt->out.heat_flux * pt->out.area;
        heat->dissipation += pt->out.dissipation_rate * pt->out.area;
        heat->friction_heat += pt->out.heat_generation * pt->out.area;
      }
    }
    if (f || A) PetscCall(Flush(p, mode, A, f, &block));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The portable history of a face's points in contact at the state xa, averaged to the face's nodes:
 * H[NH*b + k], and the face mean Hm[k]; *any when some point was in contact. */
static PetscErrorCode PortableHistory(TslProblem p, const S2SFace *fc, const S2SPoint *pts, PetscInt npt, const PetscScalar *xa, PetscReal H[],
                                      PetscReal Hm[], PetscBool *any)
{
  const TslContactSurface *cs   = &p->csurf[fc->pair];
  const TslContactFace    *face = TslContactFaceGet(fc->kind);
  PetscReal                W[TSL_CONTACT_MAX_FACE_NODES] = {0}, Wm = 0;
  TslContactNeighbourData  nb;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < NH * TSL_CONTACT_MAX_FACE_NODES; k++) H[k] = 0;
  for (PetscInt k = 0; k < NH; k++) Hm[k] = 0;
  for (PetscInt q = 0; q < npt; q++) {
    const S2SPoint  *pt = &pts[q];
    TslContactInput  in;
    TslContactOutput out;
    PetscInt         nodes[TSL_CONTACT_S2S_MAX_NODES], n;
    PetscReal        L, v[NH], N[TSL_CONTACT_MAX_FACE_NODES], dN[TSL_CONTACT_MAX_FACE_NODES], d2N[TSL_CONTACT_MAX_FACE_NODES];

    if (pt->seg < 0) continue;
    PetscCall(PointInput(p, fc, pt, xa, &in, nodes, &n, &nb));
    PetscCall(TslContactElement(&cs->law, &in, NULL, NULL, &out));
    PetscCall(TslProblemContactFaceMetric(p, cs, xa, pt->seg, out.xi, &L));
    v[0] = L * (out.xi - pt->hist.xi_old);
    v[1] = L * (out.xi - pt->hist.xi_anchor);
    v[2] = pt->hist.lambda;
    v[3] = out.w - pt->hist.w_old;
    v[4] = out.w - pt->hist.w_anchor;
    TslContactFaceShape(face, pt->zeta, N, dN, d2N);
    for (PetscInt b = 0; b < fc->nsn; b++) {
      PetscReal wb = PetscMax(N[b], 0) * pt->length;
      W[b] += wb;
      for (PetscInt k = 0; k < NH; k++) H[NH * b + k] += wb * v[k];
    }
    Wm += pt->length;
    for (PetscInt k = 0; k < NH; k++) Hm[k] += pt->length * v[k];
  }
  *any = (PetscBool)(Wm > 0);
  if (!*any) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt k = 0; k < NH; k++) Hm[k] /= Wm;
  for (PetscInt b = 0; b < fc->nsn; b++)
    for (PetscInt k = 0; k < NH; k++) H[NH * b + k] = W[b] > 0 ? H[NH * b + k] / W[b] : Hm[k];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The main face under the point y (current) among the candidates: the nearest whose closest point lies
 * on it, not behind it by more than the search radius, facing the secondary face (tangent ts); -1 if none
 * (beyond the ends of the main surface). */
static PetscErrorCode PieceFace(TslProblem p, const TslContactSurface *cs, const PetscScalar *xa, const PetscReal y[], const PetscReal ts[],
                                PetscInt ncand, const PetscInt cand[], PetscInt *best)
{
  PetscReal best_d = PETSC_MAX_REAL;

  PetscFunctionBeginUser;
  *best = -1;
  for (PetscInt c = 0; c < ncand; c++) {
    PetscReal x[2 * TSL_CONTACT_MAX_FACE_NODES], xi, q[2], t[2], dist, gap;

    MainFace(p, cs, xa, cand[c], x);
    PetscCall(TslContactFaceProject(cs->face, x, y, &xi));
    if (xi < -S2S_XI_TOL || xi > 1 + S2S_XI_TOL) continue;
    PetscCall(TslContactFaceEvaluate(cs->face, x, PetscMin(1, PetscMax(0, xi)), q, t));
    if (t[0] * ts[0] + t[1] * ts[1] >= 0) continue; /* not facing: the faces of the two bodies run opposite ways */
    q[0] -= y[0], q[1] -= y[1];
    dist = PetscSqrtReal(q[0] * q[0] + q[1] * q[1]);
    gap  = (-q[0] * t[1] + q[1] * t[0]) / PetscSqrtReal(t[0] * t[0] + t[1] * t[1]);
    if (gap < -cs->search_radius) continue;
    if (dist < best_d) *best = cand[c], best_d = dist;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Appends a point to the current list. */
PetscErrorCode TslS2SPush(TslContactS2S s, const S2SPoint *pt)
{
  PetscFunctionBeginUser;
  if (s->npt == s->cap) {
    S2SPoint *a;
    s->cap = PetscMax(64, 2 * s->cap);
    PetscCall(PetscMalloc1(s->cap, &a));
    if (s->npt) PetscCall(PetscArraycpy(a, s->pt, s->npt));
    PetscCall(PetscFree(s->pt));
    s->pt = a;
  }
  s->pt[s->npt++] = *pt;
  PetscFunctionReturn(PETSC_SUCCESS);
}

void TslS2SCompareCut(const S2SPoint *old, PetscInt nold, const S2SPoint *pnew, PetscInt nnew, PetscBool *same, PetscBool *changed)
{
  *same = (PetscBool)(nnew == nold);
  for (PetscInt q = 0; q < nold && *same; q++) {
    *same = (PetscBool)(old[q].seg == pnew[q].seg && PetscAbsReal(old[q].zeta - pnew[q].zeta) < 1e-12);
    for (PetscInt b = 0; b < TSL_CONTACT3_MAX_FACE_NODES && *same; b++) *same = (PetscBool)(PetscAbsReal(old[q].N[b] - pnew[q].N[b]) < 1e-12);
  }
  *changed = PETSC_FALSE;
  if (!*same) {
    /* couplings: compare the sequences of main faces (a change of the matrix pattern) */
    PetscInt a = 0, b = 0;
    while (a < nold || b < nnew) {
      PetscInt sa = a < nold ? old[a].seg : -3, sb = b < nnew ? pnew[b].seg : -3;
      if (sa != sb) {
        *changed = PETSC_TRUE;
        break;
      }
      while (a < nold && old[a].seg == sa) a++;
      while (b < nnew && pnew[b].seg == sb) b++;
    }
  }
}

/* Cuts face fc at the state xa and appends its points (new list), carrying the history of its old points
 * (old[0..nold)); *changed when the main faces it couples to changed, *recut when the cut differs at all. */
static PetscErrorCode CutFace(TslProblem p, S2SFace *fc, const S2SPoint *old, PetscInt nold, TslContactBinGrid grid, const PetscScalar *xa,
                              PetscInt **cand, PetscInt *cap, PetscBool *changed, PetscBool *recut)
{
  TslContactS2S            s  = p->s2s;
  const TslContactSurface *cs = &p->csurf[fc->pair];
  const TslContactFace    *face = TslContactFaceGet(fc->kind);
  PetscReal X[2 * TSL_CONTACT_MAX_FACE_NODES], U[TSL_CONTACT_MAX_NODE_DOF * TSL_CONTACT_MAX_FACE_NODES], Y[2 * TSL_CONTACT_MAX_FACE_NODES];
  PetscReal box[4], c[2], rad, zeta[S2S_MAX_BREAKS], *ends, H[NH * TSL_CONTACT_MAX_FACE_NODES], Hm[NH];
  PetscInt  ncand, nb, start = s->npt;
  PetscBool any, same;

  PetscFunctionBeginUser;
  FaceData(p, fc, xa, X, U);
  for (PetscInt b = 0; b < fc->nsn; b++)
    for (PetscInt d = 0; d < 2; d++) Y[2 * b + d] = X[2 * b + d] + U[cs->nu * b + d];
  PetscCall(TslContactFaceBox(fc->kind, Y, box));
  c[0] = 0.5 * (box[0] + box[2]), c[1] = 0.5 * (box[1] + box[3]);
  rad  = 0.5 * PetscMax(box[2] - box[0], box[3] - box[1]) + cs->search_radius;
  /* every candidate, in face order (the query sorts): ties go the same way whichever faces are held here */
  PetscCall(TslContactBinGridQueryGrow(grid, c, rad, cap, cand, &ncand));
  /* the breaks: the ends of the candidate main faces (the kinks of the main surface and of its shape
   * functions; a line3 face is smooth inside) */
  PetscCall(PetscMalloc1(4 * ncand + 1, &ends));
  for (PetscInt k = 0; k < ncand; k++) {
    PetscReal y[2 * TSL_CONTACT_MAX_FACE_NODES];
    MainFace(p, cs, xa, (*cand)[k], y);
    for (PetscInt e = 0; e < 4; e++) ends[4 * k + e] = y[e];
  }
  PetscCall(TslContactSegmentBreaks(fc->kind, Y, 2 * ncand, ends, S2S_BREAK_TOL, S2S_MAX_BREAKS, zeta, &nb));
  PetscCall(PetscFree(ends));
  PetscCall(PortableHistory(p, fc, old, nold, xa, H, Hm, &any));
  for (PetscInt i = 0; i + 1 < nb; i++) {
    PetscReal ym[2], ts[2], zq[TSL_CONTACT_S2S_MAX_GAUSS], wq[TSL_CONTACT_S2S_MAX_GAUSS];
    PetscInt  seg, nq;

    PetscCall(TslContactFaceEvaluate(fc->kind, Y, 0.5 * (zeta[i] + zeta[i + 1]), ym, ts));
    PetscCall(PieceFace(p, cs, xa, ym, ts, ncand, *cand, &seg));
    if (seg < 0) continue;
    PetscCheck(!cs->ring[seg] && cs->prev[seg] != -2 && cs->next[seg] != -2, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "a secondary face reached main face %" PetscInt_FMT " at the edge of the part of the main surface held here", seg);
    PetscCall(TslContactSegmentRule(fc->kind, X, zeta[i], zeta[i + 1], &nq, zq, wq));
    for (PetscInt q = 0; q < nq; q++) {
      S2SPoint pt;
      memset(&pt, 0, sizeof(pt));
      pt.seg    = seg;
      pt.zeta   = zq[q];
      pt.length = wq[q];
      PetscCall(TslS2SPush(s, &pt));
    }
  }
  TslS2SCompareCut(old, nold, s->pt + start, s->npt - start, &same, changed);
  *recut = (PetscBool)!same;
  for (PetscInt q = start; q < s->npt; q++) {
    S2SPoint               *pt = &s->pt[q];
    TslContactInput         in;
    TslContactNeighbourData nbd;
    PetscInt                nodes[TSL_CONTACT_S2S_MAX_NODES], n;
    PetscReal               y[2 * TSL_CONTACT_MAX_FACE_NODES], xi, L, v[NH], N[TSL_CONTACT_MAX_FACE_NODES], dN[TSL_CONTACT_MAX_FACE_NODES],
      d2N[TSL_CONTACT_MAX_FACE_NODES];

    if (same) {
      pt->hist = old[q - start].hist;
      pt->out  = old[q - start].out;
      continue;
    }
    PetscCall(PointInput(p, fc, pt, xa, &in, nodes, &n, &nbd));
    MainFace(p, cs, xa, pt->seg, y);
    {
      PetscReal yp[2] = {in.x[0][0] + in.u[0][0], in.x[0][1] + in.u[0][1]};
      PetscCall(TslContactFaceProject(cs->face, y, yp, &xi));
    }
    xi = PetscMin(1, PetscMax(0, xi));
    PetscCall(TslContactStateStart(&in, xi, &pt->hist));
    if (!any) continue;
    /* carried over: interpolated from the face's nodes */
    PetscCall(TslProblemContactFaceMetric(p, cs, xa, pt->seg, xi, &L));
    TslContactFaceShape(face, pt->zeta, N, dN, d2N);
    for (PetscInt k = 0; k < NH; k++) {
      v[k] = 0;
      for (PetscInt b = 0; b < fc->nsn; b++) v[k] += N[b] * H[NH * b + k];
    }
    pt->hist.xi_old    = xi - v[0] / L;
    pt->hist.xi_anchor = xi - v[1] / L;
    pt->hist.lambda    = PetscMax(0, v[2]);
    pt->hist.w_anchor  = pt->hist.w_old - v[4];
    pt->hist.w_old     = pt->hist.w_old - v[3];
  }
  fc->first = start;
  fc->npt   = s->npt - start;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* For CheckHeldRegion (contact.c): how far the query boxes of this rank's secondary faces of pair k (the
 * square CutFace queries) reach beyond the box lo..hi (*excess, 0 if not at all), and the first node of
 * the face that reaches farthest. */
PetscErrorCode TslProblemContactS2SReach(TslProblem p, PetscInt k, const PetscScalar *xa, const PetscReal lo[], const PetscReal hi[], PetscReal *excess,
                                         PetscInt *node)
{
  TslContactS2S s = p->s2s;

  PetscFunctionBeginUser;
  *excess = 0, *node = -1;
  for (PetscInt i = 0; s && i < s->nface; i++) {
    const S2SFace           *fc  = &s->face[i];
    const TslContactSurface *cs  = &p->csurf[k];
    const PetscInt           dim = p->dim;
    /* sized for the 3D faces (3 coordinates and 4 unknowns per node; the 2D ones use the first 2 x 3): the
     * 2D arrays this loop had overflowed the stack on the quad faces of a 3D pair */
    PetscReal X[3 * TSL_CONTACT3_MAX_FACE_NODES], U[TSL_CONTACT3_NU * TSL_CONTACT3_MAX_FACE_NODES], Y[3 * TSL_CONTACT3_MAX_FACE_NODES], box[6], rad = 0;
    if (fc->pair != k) continue;
    if (dim == 3) PetscCall(TslS2S3FaceData(p, fc, xa, X, U));
    else FaceData(p, fc, xa, X, U);
    for (PetscInt b = 0; b < fc->nsn; b++)
      for (PetscInt d = 0; d < dim; d++) Y[dim * b + d] = X[dim * b + d] + U[(dim == 3 ? TSL_CONTACT3_NU : cs->nu) * b + d];
    if (dim == 3) PetscCall(TslContactFace3Box(fc->kind, Y, box));
    else PetscCall(TslContactFaceBox(fc->kind, Y, box));
    for (PetscInt d = 0; d < dim; d++) rad = PetscMax(rad, 0.5 * (box[dim + d] - box[d]));
    rad += cs->search_radius;
    for (PetscInt d = 0; d < dim; d++) {
      const PetscReal c = 0.5 * (box[d] + box[dim + d]), e = PetscMax(lo[d] - (c - rad), (c + rad) - hi[d]);
      if (e > *excess) *excess = e, *node = p->m->node_id[fc->lnode[0]];
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemContactS2SSearch(TslProblem p, const PetscScalar *xa, PetscInt *changed, PetscInt *recut)
{
  TslContactS2S s = p->s2s;
  S2SPoint     *old;
  PetscInt      nold, *cand, cap = 64;

  PetscFunctionBeginUser;
  *changed = *recut = 0;
  if (!s || !s->nface) PetscFunctionReturn(PETSC_SUCCESS);
  /* the old list moves aside; the new one is built face by face into one allocation sized for more points
   * than it will likely hold (a quarter more than the old list; at the first search 40 per face held, the
   * 3D benchmark's non-matching faces taking 34): the pages it leaves untouched are never resident, where
   * growing by doubling copies (at 138 k points the search had raised the malloc high-water mark by 285 MB
   * for 50 MB of points: the old list, the copy and its doubled successor) */
  old    = s->pt;
  nold   = s->npt;
  s->npt = 0;
  s->cap = nold ? nold + nold / 4 : 40 * s->nface;
  PetscCall(PetscMalloc1(s->cap, &s->pt));
  PetscCall(PetscMalloc1(cap, &cand));
  for (PetscInt k = 0; k < p->ncsurf; k++) {
    TslContactSurface *cs = &p->csurf[k];
    PetscReal         *box, y[2 * TSL_CONTACT_MAX_FACE_NODES];
    TslContactBinGrid  grid = NULL;

    if (p->dim == 3) {
      PetscInt ch;
      PetscCall(TslS2S3SearchPair(p, k, old, nold, xa, &ch));
      *changed += ch;
      *recut += s->nface; /* the 3D cut reports pattern changes only: count every face as possibly cut anew */
      continue;
    }
    for (PetscInt i = 0; i < s->nface; i++) {
      S2SFace  *fc = &s->face[i];
      PetscBool ch, rc;
      if (fc->pair != k) continue;
      if (!grid) {
        PetscCall(PetscMalloc1(4 * cs->nmain, &box));
        for (PetscInt m = 0; m < cs->nmain; m++) {
          MainFace(p, cs, xa, m, y);
          PetscCall(TslContactFaceBox(cs->face, y, &box[4 * m]));
        }
        PetscCall(TslContactBinGridCreate(cs->nmain, box, cs->search_radius, &grid));
        PetscCall(PetscFree(box));
      }
      PetscCall(CutFace(p, fc, old + fc->first, PetscMin(fc->npt, nold - fc->first), grid, xa, &cand, &cap, &ch, &rc));
      *changed += ch;
      *recut += rc;
    }
    if (grid) PetscCall(TslContactBinGridDestroy(&grid));
  }
  PetscCall(PetscFree(cand));
  PetscCall(PetscFree(old));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void TslProblemContactS2SCount(TslProblem p, PetscInt counts[])
{
  TslContactS2S s = p->s2s;

  for (PetscInt k = 0; k < 2 * p->ncsurf; k++) counts[k] = 0;
  for (PetscInt i = 0; s && i < s->nface; i++) {
    const S2SFace *fc = &s->face[i];
    if (!fc->assemble) continue; /* held here for its nodes' outputs, counted where it is inserted */
    counts[2 * fc->pair]++;
    for (PetscInt q = fc->first; q < fc->first + fc->npt; q++)
      if (s->pt[q].seg >= 0) counts[2 * fc->pair + 1]++;
  }
}

PetscErrorCode TslProblemContactS2SUpdate(TslProblem p, PetscInt *depart, PetscReal *change, PetscReal *scale)
{
  TslContactS2S s = p->s2s;

  PetscFunctionBeginUser;
  if (!s) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < s->nface; i++) {
    const S2SFace           *fc = &s->face[i];
    const TslContactSurface *cs = &p->csurf[fc->pair];
    for (PetscInt q = fc->first; q < fc->first + fc->npt; q++) {
      const S2SPoint *pt = &s->pt[q];
      if (pt->seg < 0) continue;
      if (p->dim == 3 ? TslS2S3Departed(p, pt, fc->pair) : TslContactProjectionSide(pt->out.xi_raw, S2S_DEPART_TOL) != 0) (*depart)++;
      if (cs->law.normal == TSL_CONTACT_NORMAL_AUGMENTED) {
        PetscReal c, lambda = pt->hist.lambda;
        PetscCall(TslContactAugmentedUpdate(cs->law.eps_n, pt->out.gap, &lambda, &c));
        *change = PetscMax(*change, c);
        *scale  = PetscMax(*scale, pt->out.pressure);
      }
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemContactS2SAugment(TslProblem p)
{
  TslContactS2S s = p->s2s;

  PetscFunctionBeginUser;
  if (!s) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < s->nface; i++) {
    const S2SFace           *fc = &s->face[i];
    const TslContactSurface *cs = &p->csurf[fc->pair];
    PetscReal                c;
    for (PetscInt q = fc->first; q < fc->first + fc->npt; q++)
      if (s->pt[q].seg >= 0 && cs->law.normal == TSL_CONTACT_NORMAL_AUGMENTED)
        PetscCall(TslContactAugmentedUpdate(cs->law.eps_n, s->pt[q].out.gap, &s->pt[q].hist.lambda, &c));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Nodal values over the local nodes: v[l] = sum over the points of N_b w value / trib[l] (CPRESS, HFLA,
 * slip), or the largest status of the points with N_b != 0 (which = 2). which: 0 pressure, 1 |slip|,
 * 2 status, 3 heat flux. */
static PetscErrorCode NodalValues(TslProblem p, TslContactField which, PetscReal v[])
{
  TslContactS2S s = p->s2s;

  PetscFunctionBeginUser;
  for (PetscInt l = 0; l < p->nn; l++) v[l] = 0;
  for (PetscInt i = 0; i < s->nface; i++) {
    const S2SFace        *fc   = &s->face[i];
    const TslContactFace *face = TslContactFaceGet(fc->kind);
    for (PetscInt q = fc->first; q < fc->first + fc->npt; q++) {
      const S2SPoint *pt = &s->pt[q];
      PetscReal       N[TSL_CONTACT3_MAX_FACE_NODES], dN[TSL_CONTACT_MAX_FACE_NODES], d2N[TSL_CONTACT_MAX_FACE_NODES], val;
      if (pt->seg < 0) continue;
      val = which == TSL_CONTACT_FIELD_PRESSURE ? pt->out.pressure
            : which == TSL_CONTACT_FIELD_SLIP   ? PetscHypotReal(pt->out.slip, pt->out.slip_circ)
            : which == TSL_CONTACT_FIELD_STATUS ? (PetscReal)pt->out.status
                                                : pt->out.heat_flux;
      if (p->dim == 3) PetscCall(PetscArraycpy(N, pt->N, fc->nsn));
      else TslContactFaceShape(face, pt->zeta, N, dN, d2N);
      for (PetscInt b = 0; b < fc->nsn; b++) {
        PetscInt l = fc->lnode[b];
        if (which == TSL_CONTACT_FIELD_STATUS) {
          if (N[b] != 0) v[l] = PetscMax(v[l], val);
        } else v[l] += N[b] * pt->length * val / s->trib[l];
      }
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslS2SReserve(S2SPoint **pts, PetscInt *cap, PetscInt n)
{
  PetscFunctionBeginUser;
  if (*cap < n) {
    PetscCall(PetscFree(*pts));
    *cap = n;
    PetscCall(PetscMalloc1(*cap, pts));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* dst[0..n) = src[0..n), dst grown as needed (committed <-> current point lists). */
static PetscErrorCode CopyPoints(const S2SPoint *src, PetscInt n, S2SPoint **dst, PetscInt *cap, PetscInt *ndst)
{
  PetscFunctionBeginUser;
  PetscCall(TslS2SReserve(dst, cap, n));
  if (n) PetscCall(PetscArraycpy(*dst, src, n));
  *ndst = n;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemContactS2SCommit(TslProblem p)
{
  TslContactS2S s = p->s2s;
  PetscReal    *slip;

  PetscFunctionBeginUser;
  if (!s) PetscFunctionReturn(PETSC_SUCCESS);
  if (p->dim == 3) {
    /* the converged configuration gives the next increment's nodal normals (smoothing) */
    Vec                xl;
    const PetscScalar *xa;
    PetscCall(TslProblemGetLocalSolution(p, &xl, &xa));
    PetscCall(TslS2S3Normals(p, xa));
    PetscCall(TslProblemRestoreLocalSolution(p, &xl, &xa));
  }
  PetscCall(PetscMalloc1(p->nn, &slip));
  PetscCall(NodalValues(p, TSL_CONTACT_FIELD_SLIP, slip));
  for (PetscInt l = 0; l < p->nn; l++) s->cslip[l] += slip[l];
  PetscCall(PetscFree(slip));
  for (PetscInt q = 0; q < s->npt; q++)
    if (s->pt[q].seg >= 0) PetscCall(TslContactStateUpdate(&s->pt[q].out, &s->pt[q].hist));
  PetscCall(CopyPoints(s->pt, s->npt, &s->pt_c, &s->cap_c, &s->npt_c));
  for (PetscInt i = 0; i < s->nface; i++) s->face[i].first_c = s->face[i].first, s->face[i].npt_c = s->face[i].npt;
  PetscCall(PetscArraycpy(s->cslip_c, s->cslip, p->nn));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemContactS2SRollback(TslProblem p)
{
  TslContactS2S s = p->s2s;

  PetscFunctionBeginUser;
  if (!s) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(CopyPoints(s->pt_c, s->npt_c, &s->pt, &s->cap, &s->npt));
  for (PetscInt i = 0; i < s->nface; i++) s->face[i].first = s->face[i].first_c, s->face[i].npt = s->face[i].npt_c;
  PetscCall(PetscArraycpy(s->cslip, s->cslip_c, p->nn));
  if (s->nface) p->pattern_stale = PETSC_TRUE; /* the attempt's cut may have coupled other main faces */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Node fields at the owned secondary-face nodes (see the top of this file); other nodes keep vals. */
PetscErrorCode TslProblemContactS2SNodeField(TslProblem p, TslContactField kind, PetscReal vals[])
{
  TslContactS2S s = p->s2s;
  PetscReal    *v;

  PetscFunctionBeginUser;
  if (!s || !s->nface) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscMalloc1(p->nn, &v));
  if (kind == TSL_CONTACT_FIELD_SLIP) PetscCall(PetscArraycpy(v, s->cslip, p->nn));
  else PetscCall(NodalValues(p, kind, v));
  for (PetscInt i = 0; i < s->nface; i++)
    for (PetscInt b = 0; b < s->face[i].nsn; b++)
      if (s->face[i].lnode[b] < p->nown) vals[s->face[i].lnode[b]] = v[s->face[i].lnode[b]];
  PetscCall(PetscFree(v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The secondary faces of the surface-to-surface pairs held here (after the node-to-surface set-up, whose
 * per-pair data, law and main surface, they share). */
PetscErrorCode TslProblemContactS2SSetUp(TslProblem p)
{
  const TslModel *m = p->m;
  TslContactS2S   s;
  PetscInt        n = 0;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < m->npair; k++) n += m->pairs[k].type == TSL_CONTACT_SURFACE_TO_SURFACE ? 1 : 0;
  if (!n) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscNew(&s));
  p->s2s = s;
  for (PetscInt k = 0; k < m->npair; k++) s->nface += m->pairs[k].nsface;
  PetscCall(PetscCalloc1(s->nface, &s->face));
  PetscCall(PetscCalloc3(p->nn, &s->trib, p->nn, &s->cslip, p->nn, &s->cslip_c));
  n = 0;
  for (PetscInt k = 0; k < m->npair; k++) {
    const TslContactPair *pair = &m->pairs[k];
    TslContactSurface    *cs   = &p->csurf[k];
    for (PetscInt i = 0; i < pair->nsface; i++) {
      S2SFace  *fc = &s->face[n++];
      PetscReal X[3 * TSL_CONTACT3_MAX_FACE_NODES], U[TSL_CONTACT_MAX_NODE_DOF * TSL_CONTACT3_MAX_FACE_NODES], w[TSL_CONTACT3_MAX_FACE_NODES];
      fc->pair     = k;
      fc->kind     = (TslContactFaceKind)pair->sface_kind;
      fc->nsn      = pair->snper;
      fc->assemble = (PetscBool)(pair->sface_asm[i] != 0);
      for (PetscInt b = 0; b < fc->nsn; b++) {
        fc->lnode[b] = TslModelNodeIndex(m, pair->sface_node[fc->nsn * i + b]);
        PetscCheck(fc->lnode[b] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "secondary face node %" PetscInt_FMT " is not local", pair->sface_node[fc->nsn * i + b]);
      }
      if (p->dim == 3) {
        /* int N_b dA with the points' interpolation (tri6: its linear sub-triangles) */
        PetscCall(TslS2S3FaceData(p, fc, NULL, X, U));
        PetscCall(TslContactFace3Integrate(fc->kind, X, w, NULL));
      } else {
        FaceData(p, fc, NULL, X, U);
        PetscCall(TslContactFaceIntegrate(fc->kind, X, w, NULL));
      }
      for (PetscInt b = 0; b < fc->nsn; b++) s->trib[fc->lnode[b]] += w[b];
    }
    for (PetscInt a = 0; pair->nsface && a < cs->nper * cs->nmain; a++)
      PetscCheck(cs->main_lnode[a] >= 0 || pair->main_node[a] < 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "main-surface node %" PetscInt_FMT " is not local", pair->main_node[a]);
  }
  if (p->dim == 3) PetscCall(TslS2S3Normals(p, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemContactS2SDestroy(TslProblem p)
{
  TslContactS2S s = p->s2s;

  PetscFunctionBeginUser;
  if (!s) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscFree(s->face));
  PetscCall(PetscFree(s->pt));
  PetscCall(PetscFree(s->pt_c));
  PetscCall(PetscFree3(s->trib, s->cslip, s->cslip_c));
  PetscCall(PetscFree(p->s2s));
  PetscFunctionReturn(PETSC_SUCCESS);
}
