/* Surface-to-surface contact in 3D (*CONTACT PAIR, TYPE=SURFACE TO SURFACE between 3D elements): what
 * differs from 2D (src/physics/contact_s2s.c, which keeps the assembly, commit, rollback, augmentation and
 * outputs for both).
 *
 * At every search each secondary face held here (tri3, quad4, tri6) is clipped against every nearby main
 * face (contact/clip3.c: the main face's corners projected onto the plane of the secondary face, or of each
 * of tri6's linear sub-triangles, Sutherland-Hodgman, the overlap fanned into triangles with a degree-4
 * rule, or one rule on a triangle or quadrilateral overlap). Every overlap with a facing main face not behind
 * the secondary face by more than the search radius gives points on that main face; parts of a secondary
 * face over no main face get none (no force, no heat, as a node beyond the main surface). A point is the 3D
 * node-to-surface kernel's secondary node at x = sum_b N_b x_b, with its weight (reference area) as area,
 * expanded to the face's nodes (TslContactPointElement3). Cut and pairing are frozen during a Newton solve;
 * a point whose projection leaves its main face after convergence asks for a new search and another solve.
 *
 * History across a new cut (the 3D form of 2D's): at the search state each old point in contact gives the
 * vectors from the start-of-increment point and from the anchor to its current point on the main face,
 * x_m(xi) - x_m(xi_old) and x_m(xi) - x_m(xi_anchor) (the slip of the increment so far and the elastic
 * slip, tangential vectors), and lambda; they are averaged to the face's nodes (weights N_b+ x point weight)
 * and interpolated back with N_b at each new point, whose xi_old (xi_anchor) is the projection onto its
 * main face of its current main-face point minus that vector. Exact for uniform fields. A face cut the
 * same way (same points on the same main faces) keeps its points' history unchanged. */
#include "contact_s2s_impl.h"

#define NH3 7 /* portable history: slip vector, elastic slip vector, lambda */

static TslContactOverlapPoint Overlap[TSL_CONTACT_OVERLAP_MAX_POINTS];

static void NodeData(TslProblem p, const TslContactSurface *cs, const PetscScalar *xa, PetscInt l, PetscReal X[3], PetscReal U[4])
{
  for (PetscInt d = 0; d < 3; d++) X[d] = p->m->node_xyz[3 * l + d];
  for (PetscInt c = 0; c < TSL_CONTACT3_NU; c++) U[c] = TslProblemSlotValue(p, xa, l, cs->slot[c]);
}

PetscErrorCode TslS2S3FaceData(TslProblem p, const S2SFace *fc, const PetscScalar *xa, PetscReal X[], PetscReal U[])
{
  PetscFunctionBeginUser;
  for (PetscInt b = 0; b < fc->nsn; b++) NodeData(p, &p->csurf[fc->pair], xa, fc->lnode[b], &X[3 * b], &U[TSL_CONTACT3_NU * b]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Current coordinates y[3*a + d] of the nodes of main face f. */
static void MainFace(TslProblem p, const TslContactSurface *cs, const PetscScalar *xa, PetscInt f, PetscReal y[])
{
  for (PetscInt a = 0; a < TslContactFace3Nodes(cs->kind[f]); a++) {
    PetscReal X[3], U[4];
    NodeData(p, cs, xa, cs->main_lnode[cs->nper * f + a], X, U);
    for (PetscInt d = 0; d < 3; d++) y[3 * a + d] = X[d] + U[d];
  }
}

PetscErrorCode TslS2S3PointInput(TslProblem p, const S2SFace *fc, const S2SPoint *pt, const PetscScalar *xa, S2S3InputCache *cache,
                                 TslContactInput3 *in, PetscInt nodes[], PetscInt *n)
{
  S2S3InputCache local, *c = cache ? cache : &local;

  PetscFunctionBeginUser;
  if (!cache || c->fc != fc || c->seg != pt->seg) { /* another face pair than the last point's */
    TslContactNode cn;
    PetscInt       kn[1 + TSL_CONTACT3_MAX_FACE_NODES], nk;

    TslS2SPointNode(fc, pt, &cn);
    PetscCall(TslProblemContact3Input(p, &cn, xa, &c->in, kn, &nk));
    PetscCall(TslS2S3FaceData(p, fc, xa, c->X, c->U));
    TslS2SPointNodes(fc, kn, nk, c->nodes, &c->n);
    c->fc = fc, c->seg = pt->seg;
  }
  *in      = c->in; /* then the point's own weight, history, place and projection start */
  in->area = pt->length;
  in->hist = pt->hist;
  TslContactPointSetUp3(fc->nsn, pt->N, c->X, c->U, in);
  if (pt->out.nnode > 0) { /* evaluated before, on this main face (a point keeps its face): start from there */
    in->guess[0] = pt->out.xi_raw, in->guess[1] = pt->out.eta_raw;
    in->has_guess = PETSC_TRUE;
  }
  *n = c->n;
  PetscCall(PetscArraycpy(nodes, c->nodes, c->n));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscBool TslS2S3Departed(TslProblem p, const S2SPoint *pt, PetscInt pair)
{
  const PetscReal xi[2] = {pt->out.xi_raw, pt->out.eta_raw};
  return (PetscBool)!TslContactFace3Inside(p->csurf[pair].kind[pt->seg], xi, S2S_DEPART_TOL);
}

PetscErrorCode TslS2S3Normals(TslProblem p, const PetscScalar *xa)
{
  TslContactS2S s = p->s2s;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < p->ncsurf; k++) {
    TslContactSurface *cs   = &p->csurf[k];
    PetscBool          held = PETSC_FALSE, active;

    for (PetscInt i = 0; i < s->nface && !held; i++) held = (PetscBool)(s->face[i].pair == k);
    if (!held || cs->smooth <= 0) continue;
    /* TslProblemContact3Normals skips pairs without secondary nodes here (whose main surface may not be
     * local); a rank holding secondary faces holds the whole main surface */
    active     = cs->active;
    cs->active = PETSC_TRUE;
    PetscCall(TslProblemContact3Normals(p, cs, xa));
    cs->active = active;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The portable history of a face's points in contact at the state xa (main faces' current coordinates fx,
 * nper nodes each), averaged to the face's nodes: H[NH3*b + k]; *any when some point was in contact. */
static PetscErrorCode PortableHistory(TslProblem p, const S2SFace *fc, const S2SPoint *pts, PetscInt npt, const PetscScalar *xa, const PetscReal fx[],
                                      PetscReal H[], PetscBool *any)
{
  const TslContactSurface *cs = &p->csurf[fc->pair];
  PetscReal                W[TSL_CONTACT3_MAX_FACE_NODES] = {0}, Wm = 0, Hm[NH3] = {0};

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < NH3 * TSL_CONTACT3_MAX_FACE_NODES; k++) H[k] = 0;
  for (PetscInt q = 0; q < npt; q++) {
    const S2SPoint  *pt = &pts[q];
    const PetscReal *ym;
    TslContactInput3 in;
    TslContactOutput out;
    PetscInt         nodes[TSL_CONTACT_S2S3_MAX_NODES], n, kind;
    PetscReal        v[NH3], x0[3], xo[3], xa_[3], xi[2];

    if (pt->seg < 0) continue;
    kind = cs->kind[pt->seg];
    ym   = &fx[3 * cs->nper * pt->seg];
    PetscCall(TslS2S3PointInput(p, fc, pt, xa, NULL, &in, nodes, &n));
    PetscCall(TslContactElement3(&cs->law, &in, NULL, NULL, &out));
    xi[0] = out.xi, xi[1] = out.eta;
    PetscCall(TslContactFace3Evaluate(kind, ym, xi, x0, NULL));
    xi[0] = pt->hist.xi_old, xi[1] = pt->hist.eta_old;
    PetscCall(TslContactFace3Evaluate(kind, ym, xi, xo, NULL));
    xi[0] = pt->hist.xi_anchor, xi[1] = pt->hist.eta_anchor;
    PetscCall(TslContactFace3Evaluate(kind, ym, xi, xa_, NULL));
    for (PetscInt d = 0; d < 3; d++) v[d] = x0[d] - xo[d], v[3 + d] = x0[d] - xa_[d];
    v[6] = pt->hist.lambda;
    for (PetscInt b = 0; b < fc->nsn; b++) {
      PetscReal wb = PetscMax(pt->N[b], 0) * pt->length;
      W[b] += wb;
      for (PetscInt k = 0; k < NH3; k++) H[NH3 * b + k] += wb * v[k];
    }
    Wm += pt->length;
    for (PetscInt k = 0; k < NH3; k++) Hm[k] += pt->length * v[k];
  }
  *any = (PetscBool)(Wm > 0);
  if (!*any) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt b = 0; b < fc->nsn; b++)
    for (PetscInt k = 0; k < NH3; k++) H[NH3 * b + k] = W[b] > 0 ? H[NH3 * b + k] / W[b] : Hm[k] / Wm;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Clips face fc against the main faces near it at the state xa (main faces' current coordinates fx) and
 * appends its points (new list), carrying the history of its old points old[0..nold); *changed when the
 * main faces it couples to changed. */
static PetscErrorCode CutFace(TslProblem p, S2SFace *fc, const S2SPoint *old, PetscInt nold, TslContactBinGrid grid, const PetscReal fx[],
                              const PetscScalar *xa, PetscInt **cand, PetscInt *cap, PetscBool *changed)
{
  TslContactS2S            s  = p->s2s;
  const TslContactSurface *cs = &p->csurf[fc->pair];
  PetscReal X[3 * TSL_CONTACT3_MAX_FACE_NODES], U[TSL_CONTACT3_NU * TSL_CONTACT3_MAX_FACE_NODES], Y[3 * TSL_CONTACT3_MAX_FACE_NODES];
  PetscReal box[6], c[3], rad = 0, H[NH3 * TSL_CONTACT3_MAX_FACE_NODES];
  PetscInt  ncand, start = s->npt;
  PetscBool any, same;

  PetscFunctionBeginUser;
  PetscCall(TslS2S3FaceData(p, fc, xa, X, U));
  for (PetscInt b = 0; b < fc->nsn; b++)
    for (PetscInt d = 0; d < 3; d++) Y[3 * b + d] = X[3 * b + d] + U[TSL_CONTACT3_NU * b + d];
  PetscCall(TslContactFace3Box(fc->kind, Y, box));
  for (PetscInt d = 0; d < 3; d++) c[d] = 0.5 * (box[d] + box[3 + d]), rad = PetscMax(rad, 0.5 * (box[3 + d] - box[d]));
  rad += cs->search_radius;
  /* every candidate, in face order (the query sorts): ties go the same way whichever faces are held here */
  PetscCall(TslContactBinGridQueryGrow(grid, c, rad, cap, cand, &ncand));
  PetscCall(PortableHistory(p, fc, old, nold, xa, fx, H, &any));
  for (PetscInt k = 0; k < ncand; k++) {
    const PetscInt m = (*cand)[k];
    PetscInt       nov;
    PetscReal      dist;

    PetscCall(TslContactOverlap3(fc->kind, X, Y, cs->kind[m], &fx[3 * cs->nper * m], TSL_CONTACT_OVERLAP_MAX_POINTS, Overlap, &nov, &dist));
    if (!nov || dist < -cs->search_radius) continue; /* no overlap, or behind the secondary face: another body */
    for (PetscInt q = 0; q < nov; q++) {
      S2SPoint pt;
      memset(&pt, 0, sizeof(pt));
      pt.seg    = m;
      pt.length = Overlap[q].w;
      for (PetscInt b = 0; b < fc->nsn; b++) pt.N[b] = Overlap[q].N[b];
      PetscCall(TslS2SPush(s, &pt));
    }
  }
  TslS2SCompareCut(old, nold, s->pt + start, s->npt - start, &same, changed);
  for (PetscInt q = start; q < s->npt; q++) {
    S2SPoint        *pt   = &s->pt[q];
    const PetscInt   kind = cs->kind[pt->seg];
    const PetscReal *ym   = &fx[3 * cs->nper * pt->seg];
    TslContactInput3 in;
    PetscInt         nodes[TSL_CONTACT_S2S3_MAX_NODES], n;
    PetscReal        yp[3], xi[2], x0[3], v[NH3], t[3];

    if (same) {
      pt->hist = old[q - start].hist;
      pt->out  = old[q - start].out;
      continue;
    }
    PetscCall(TslS2S3PointInput(p, fc, pt, xa, NULL, &in, nodes, &n));
    for (PetscInt d = 0; d < 3; d++) yp[d] = in.x[0][d] + in.u[0][d];
    PetscCall(TslContactFace3Project(kind, ym, yp, xi));
    PetscCall(TslContactStateStart3(xi, &pt->hist));
    if (!any) continue;
    /* carried over: interpolated from the face's nodes, turned into points of the new main face */
    for (PetscInt k = 0; k < NH3; k++) {
      v[k] = 0;
      for (PetscInt b = 0; b < fc->nsn; b++) v[k] += pt->N[b] * H[NH3 * b + k];
    }
    PetscCall(TslContactFace3Evaluate(kind, ym, xi, x0, NULL));
    for (PetscInt d = 0; d < 3; d++) t[d] = x0[d] - v[d];
    PetscCall(TslContactFace3Project(kind, ym, t, xi));
    pt->hist.xi_old = xi[0], pt->hist.eta_old = xi[1];
    for (PetscInt d = 0; d < 3; d++) t[d] = x0[d] - v[3 + d];
    PetscCall(TslContactFace3Project(kind, ym, t, xi));
    pt->hist.xi_anchor = xi[0], pt->hist.eta_anchor = xi[1];
    pt->hist.lambda = PetscMax(0, v[6]);
  }
  fc->first = start;
  fc->npt   = s->npt - start;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslS2S3SearchPair(TslProblem p, PetscInt k, S2SPoint *old, PetscInt nold, const PetscScalar *xa, PetscInt *changed)
{
  TslContactS2S      s  = p->s2s;
  TslContactSurface *cs = &p->csurf[k];
  const PetscInt     np = cs->nper;
  PetscReal         *box, *fx;
  PetscInt          *cand, cap = 64;
  TslContactBinGrid  grid = NULL;

  PetscFunctionBeginUser;
  *changed = 0;
  for (PetscInt i = 0; i < s->nface; i++) {
    S2SFace  *fc = &s->face[i];
    PetscBool ch;

    if (fc->pair != k) continue;
    if (!grid) {
      PetscCall(PetscMalloc2(6 * cs->nmain + 1, &box, 3 * np * cs->nmain + 1, &fx));
      PetscCall(PetscMalloc1(cap, &cand));
      for (PetscInt f = 0; f < cs->nmain; f++) {
        MainFace(p, cs, xa, f, &fx[3 * np * f]);
        PetscCall(TslContactFace3Box(cs->kind[f], &fx[3 * np * f], &box[6 * f]));
      }
      PetscCall(TslContactBinGridCreateDim(3, cs->nmain, box, cs->search_radius, &grid));
    }
    PetscCall(CutFace(p, fc, old + fc->first, PetscMax(0, PetscMin(fc->npt, nold - fc->first)), grid, fx, xa, &cand, &cap, &ch));
    *changed += ch;
  }
  if (grid) {
    PetscCall(TslContactBinGridDestroy(&grid));
    PetscCall(PetscFree2(box, fx));
    PetscCall(PetscFree(cand));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
