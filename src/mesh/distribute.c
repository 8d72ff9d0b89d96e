/* Partition the model read on rank 0 and send each rank its part (see include/thermoslide/mesh.h). */
#include <thermoslide/mesh.h>
#include <thermoslide/element.h>
#include <thermoslide/contact.h>
#include <thermoslide/contact_s2s.h>
#include <metis.h>
#include <string.h>
#include <stdint.h>

typedef struct {
  const PetscInt  *key;
  const PetscReal *rkey;
} SortCtx;

/* Order of positions 0..n-1 by an integer key (ties keep position order). */
static PetscErrorCode SortByInt(PetscInt n, const PetscInt key[], PetscInt perm[])
{
  PetscInt *k;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(n, &k));
  for (PetscInt i = 0; i < n; i++) perm[i] = i, k[i] = key[i];
  PetscCall(PetscSortIntWithArray(n, k, perm));
  PetscCall(PetscFree(k));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The index of a point along a Hilbert curve: b bits per axis in x[0..n-1] (n = 2 or 3), n * b <= 63.
 * J. Skilling's transform (AIP Conf. Proc. 707, 2004): the axes' bits turned into the curve's
 * "transposed" index in place, then interleaved, most significant first. */
static uint64_t HilbertIndex(unsigned x[], PetscInt n, PetscInt b)
{
  const unsigned m = 1u << (b - 1);
  uint64_t       h = 0;
  unsigned       t;

  for (unsigned q = m; q > 1; q >>= 1) { /* inverse undo */
    const unsigned p = q - 1;
    for (PetscInt i = 0; i < n; i++) {
      if (x[i] & q)
        x[0] ^= p; /* invert */
      else
        t = (x[0] ^ x[i]) & p, x[0] ^= t, x[i] ^= t; /* exchange */
    }
  }
  for (PetscInt i = 1; i < n; i++) x[i] ^= x[i - 1]; /* Gray encode */
  t = 0;
  for (unsigned q = m; q > 1; q >>= 1)
    if (x[n - 1] & q) t ^= q - 1;
  for (PetscInt i = 0; i < n; i++) x[i] ^= t;
  for (PetscInt bit = b - 1; bit >= 0; bit--)
    for (PetscInt i = 0; i < n; i++) h = (h << 1) | ((x[i] >> bit) & 1u);
  return h;
}

typedef struct {
  uint64_t key;
  PetscInt part, id, pos;
} OrderKey;

static int CompareOrderKey(const void *a, const void *b)
{
  const OrderKey *p = a, *q = b;
  if (p->part != q->part) return p->part < q->part ? -1 : 1;
  if (p->key != q->key) return p->key < q->key ? -1 : 1;
  return p->id < q->id ? -1 : p->id > q->id;
}

/* The order in which each rank holds its elements: by part, then (locality) along a Hilbert curve through
 * the element centroids, so elements that share nodes are near one another in memory, or (input) by
 * element number. */
static PetscErrorCode ElementOrder(const TslModel *g, const PetscInt epart[], PetscBool locality, PetscInt order[])
{
  PetscReal      lo[3] = {PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_MAX_REAL}, hi[3] = {PETSC_MIN_REAL, PETSC_MIN_REAL, PETSC_MIN_REAL};
  const PetscInt b = g->dim == 3 ? 21 : 31;
  OrderKey      *k;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(g->nelem, &k));
  for (PetscInt p = 0; p < g->nnode; p++)
    for (PetscInt d = 0; d < 3; d++) lo[d] = PetscMin(lo[d], g->node_xyz[3 * p + d]), hi[d] = PetscMax(hi[d], g->node_xyz[3 * p + d]);
  for (PetscInt e = 0; e < g->nelem; e++) {
    PetscReal c[3] = {0, 0, 0};
    unsigned  x[3] = {0, 0, 0};
    PetscInt  n    = g->elem_ptr[e + 1] - g->elem_ptr[e];
    k[e].part = epart[e], k[e].id = g->elem_id[e], k[e].pos = e, k[e].key = 0;
    if (!locality) continue;
    for (PetscInt j = g->elem_ptr[e]; j < g->elem_ptr[e + 1]; j++)
      for (PetscInt d = 0; d < 3; d++) c[d] += g->node_xyz[3 * TslModelNodeIndex(g, g->elem_conn[j]) + d] / n;
    for (PetscInt d = 0; d < g->dim; d++) {
      const PetscReal s = hi[d] > lo[d] ? (c[d] - lo[d]) / (hi[d] - lo[d]) : 0;
      x[d]              = (unsigned)PetscMin(PetscMax(s, 0.0) * ((1u << b) - 1), (PetscReal)((1u << b) - 1));
    }
    k[e].key = HilbertIndex(x, g->dim, b);
  }
  qsort(k, (size_t)g->nelem, sizeof(*k), CompareOrderKey);
  for (PetscInt i = 0; i < g->nelem; i++) order[i] = k[i].pos;
  PetscCall(PetscFree(k));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode PartitionMetis(const TslModel *g, PetscInt nparts, PetscInt epart[])
{
  idx_t  ne = (idx_t)g->nelem, nn = (idx_t)g->nnode, ncommon = g->dim == 2 ? 2 : 3, np = (idx_t)nparts, objval;
  idx_t *eptr, *eind, *ep, *npart, opts[METIS_NOPTIONS];
  int    status;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc4(ne + 1, &eptr, g->elem_ptr[g->nelem], &eind, ne, &ep, nn, &npart));
  for (PetscInt e = 0; e <= g->nelem; e++) eptr[e] = (idx_t)g->elem_ptr[e];
  for (PetscInt k = 0; k < g->elem_ptr[g->nelem]; k++) eind[k] = (idx_t)TslModelNodeIndex(g, g->elem_conn[k]);
  METIS_SetDefaultOptions(opts);
  opts[METIS_OPTION_NUMBERING] = 0;
  opts[METIS_OPTION_SEED]      = 1;
  status                       = METIS_PartMeshDual(&ne, &nn, eptr, eind, NULL, NULL, &ncommon, &np, NULL, opts, &objval, ep, npart);
  PetscCheck(status == METIS_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "METIS_PartMeshDual failed (status %d)", status);
  for (PetscInt e = 0; e < g->nelem; e++) epart[e] = (PetscInt)ep[e];
  PetscCall(PetscFree4(eptr, eind, ep, npart));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Slabs of equal element count ordered by the centroid coordinate along one axis, or, given ncut = nparts - 1
 * increasing coordinates, the slabs between them: lets tests force a cut (e.g. between two bodies in contact,
 * whatever their element counts). */
static PetscErrorCode PartitionAxis(const TslModel *g, PetscInt axis, PetscInt nparts, PetscInt ncut, const PetscReal cut[], PetscInt epart[])
{
  PetscReal *c;
  PetscInt  *perm;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc2(g->nelem, &c, g->nelem, &perm));
  for (PetscInt e = 0; e < g->nelem; e++) {
    PetscInt n = g->elem_ptr[e + 1] - g->elem_ptr[e];
    c[e]       = 0;
    for (PetscInt k = g->elem_ptr[e]; k < g->elem_ptr[e + 1]; k++) c[e] += g->node_xyz[3 * TslModelNodeIndex(g, g->elem_conn[k]) + axis];
    c[e] /= n;
    perm[e] = e;
  }
  if (ncut) { /* given cuts: part k holds the centroids between cut k-1 and cut k */
    for (PetscInt e = 0; e < g->nelem; e++) {
      epart[e] = 0;
      for (PetscInt k = 0; k < ncut; k++) epart[e] += c[e] > cut[k];
    }
  } else {
    PetscCall(PetscSortRealWithArrayInt(g->nelem, c, perm));
    for (PetscInt i = 0; i < g->nelem; i++) epart[perm[i]] = (i * nparts) / g->nelem;
  }
  PetscCall(PetscFree2(c, perm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Local dof offset of a dialect dof number. */
/* Slot of a dialect dof among a node's unknowns: the element rows say which unknowns a node has (all
 * rows of a model share them; the deck check rejects a mix). -1 if the model has no such dof. */
static PetscInt DofSlot(const TslModel *g, PetscBool extra, PetscInt dof)
{
  const TslElementType *t    = TslElementTypeGet(g->elem_type[0]);
  const PetscInt       *list = extra ? t->extra_dof : t->node_dof;
  if (dof <= 0) return -1;
  for (PetscInt i = 0; i < t->ndof; i++)
    if (list[i] == dof) return i;
  return -1;
}

/* Is node position p an extra node (a generalized plane strain reference node) of some element? */
static PetscBool IsExtraNode(const TslModel *g, PetscInt p)
{
  for (PetscInt e = 0; e < g->nelem; e++) {
    const TslElementType *t = TslElementTypeGet(g->elem_type[e]);
    for (PetscInt k = g->elem_ptr[e + 1] - t->nextra; k < g->elem_ptr[e + 1]; k++)
      if (TslModelNodeIndex(g, g->elem_conn[k]) == p) return PETSC_TRUE;
  }
  return PETSC_FALSE;
}

/* Does rank r hold secondary face i of a surface-to-surface pair: does it own one of its nodes? */
static PetscBool SecondaryFaceHeld(const TslModel *g, const TslContactPair *c, PetscInt i, const PetscInt owner[], PetscInt r)
{
  for (PetscInt a = 0; a < c->snper; a++)
    if (owner[TslModelNodeIndex(g, c->sface_node[c->snper * i + a])] == r) return PETSC_TRUE;
  return PETSC_FALSE;
}

/* Reference box (lower corner [0..2], upper corner [3..5]) of main face i of pair c: the box of its
 * control hull, as the search builds it from the current coordinates. */
static PetscErrorCode MainFaceBox(const TslModel *g, const TslContactPair *c, PetscInt i, PetscReal box[6])
{
  const PetscInt dim = g->dim, nf = dim == 2 ? c->nper : TslContactFace3Nodes(c->main_kind[i]);
  PetscReal      x[3 * TSL_MAX_FACE_NODES], b[6];

  PetscFunctionBeginUser;
  for (PetscInt a = 0; a < nf; a++)
    for (PetscInt d = 0; d < dim; d++) x[dim * a + d] = g->node_xyz[3 * TslModelNodeIndex(g, c->main_node[c->nper * i + a]) + d];
  if (dim == 2) PetscCall(TslContactFaceBox((TslContactFaceKind)c->main_face, x, b));
  else PetscCall(TslContactFace3Box(c->main_kind[i], x, b));
  for (PetscInt d = 0; d < 3; d++) box[d] = d < dim ? b[d] : 0, box[3 + d] = d < dim ? b[dim + d] : 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The held region of rank r for pair c (model.h): the reference box of the secondary nodes it owns and of
 * the nodes of the secondary faces it holds, inflated by c->margin; PETSC_FALSE if it has neither. */
static PetscBool HeldRegion(const TslModel *g, const TslContactPair *c, const PetscInt owner[], PetscInt r, PetscReal box[6])
{
  PetscBool held = PETSC_FALSE;

  for (PetscInt d = 0; d < 3; d++) box[d] = PETSC_MAX_REAL, box[3 + d] = -PETSC_MAX_REAL;
  for (PetscInt i = 0; i < c->nsec + c->nsface; i++) {
    const PetscBool node = (PetscBool)(i < c->nsec);
    const PetscInt  f = i - c->nsec, n = node ? 1 : c->snper;
    if (node ? owner[TslModelNodeIndex(g, c->sec_node[i])] != r : !SecondaryFaceHeld(g, c, f, owner, r)) continue;
    held = PETSC_TRUE;
    for (PetscInt a = 0; a < n; a++) {
      const PetscReal *x = &g->node_xyz[3 * TslModelNodeIndex(g, node ? c->sec_node[i] : c->sface_node[c->snper * f + a])];
      for (PetscInt d = 0; d < g->dim; d++) box[d] = PetscMin(box[d], x[d]), box[3 + d] = PetscMax(box[3 + d], x[d]);
    }
  }
  for (PetscInt d = 0; d < 3; d++) {
    box[d]     = !held || d >= g->dim ? 0 : box[d] - c->margin;
    box[3 + d] = !held || d >= g->dim ? 0 : box[3 + d] + c->margin;
  }
  return held;
}

/* The main faces rank r holds for pair c: sel[i] = 1 for a face whose reference box meets the held region
 * B (a face the rank's nodes can pair with), 2 for a neighbour of such a face (2D: the previous and next
 * face; 3D: a face sharing a node with one), held only so that smoothing sees what it sees on one rank,
 * 0 otherwise. */
static PetscErrorCode SelectMainFaces(const TslModel *g, const TslContactPair *c, const PetscReal B[6], PetscInt sel[])
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < c->nmain; i++) {
    PetscReal b[6];
    PetscCall(MainFaceBox(g, c, i, b));
    sel[i] = 1;
    for (PetscInt d = 0; d < g->dim; d++)
      if (b[3 + d] < B[d] || b[d] > B[3 + d]) sel[i] = 0;
  }
  if (g->dim == 2) {
    for (PetscInt i = 0; i < c->nmain; i++)
      if (sel[i] == 1) {
        if (c->main_prev[i] >= 0 && !sel[c->main_prev[i]]) sel[c->main_prev[i]] = 2;
        if (c->main_next[i] >= 0 && !sel[c->main_next[i]]) sel[c->main_next[i]] = 2;
      }
  } else {
    PetscInt *core, n = 0;
    PetscCall(PetscMalloc1(c->nper * c->nmain + 1, &core));
    for (PetscInt i = 0; i < c->nmain; i++)
      for (PetscInt a = 0; sel[i] == 1 && a < c->nper; a++)
        if (c->main_node[c->nper * i + a] >= 0) core[n++] = c->main_node[c->nper * i + a];
    PetscCall(PetscSortRemoveDupsInt(&n, core));
    for (PetscInt i = 0; i < c->nmain; i++)
      for (PetscInt a = 0; !sel[i] && a < c->nper; a++) {
        PetscInt at = -1;
        if (c->main_node[c->nper * i + a] >= 0) PetscCall(PetscFindInt(c->main_node[c->nper * i + a], n, core, &at));
        if (at >= 0) sel[i] = 2;
      }
    PetscCall(PetscFree(core));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Keeps in pair c (a copy of the whole model's pair gc in rank r's part) the main faces sel[] selects,
 * renumbered locally in their global order: neighbours a rank does not hold become -2, not -1 (which is an
 * end of the surface, where a node beyond it is out of contact), and the main-surface nodes r owns are
 * listed. */
static PetscErrorCode KeepMainFaces(const TslModel *g, const TslContactPair *gc, const PetscInt sel[], const PetscInt owner[], PetscInt r,
                                    TslContactPair *c)
{
  PetscInt *newid, n = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(gc->nmain + 1, &newid));
  for (PetscInt i = 0; i < gc->nmain; i++) newid[i] = sel && sel[i] ? n++ : -1;
  for (PetscInt i = 0; i < gc->nmain; i++) {
    const PetscInt j = newid[i], pv = gc->main_prev[i], nx = gc->main_next[i];
    if (j < 0) continue;
    for (PetscInt a = 0; a < gc->nper; a++) c->main_node[gc->nper * j + a] = gc->main_node[gc->nper * i + a];
    c->main_kind[j] = gc->main_kind[i];
    c->main_ring[j] = sel[i] == 2;
    c->main_prev[j] = pv < 0 ? -1 : newid[pv] >= 0 ? newid[pv] : -2;
    c->main_next[j] = nx < 0 ? -1 : newid[nx] >= 0 ? newid[nx] : -2;
  }
  c->nmain        = n;
  c->nmain_global = gc->nmain;
  PetscCall(PetscFree(c->main_own));
  PetscCall(PetscMalloc1(gc->nper * gc->nmain + 1, &c->main_own));
  n = 0;
  for (PetscInt i = 0; i < gc->nper * gc->nmain; i++)
    if (gc->main_node[i] >= 0 && owner[TslModelNodeIndex(g, gc->main_node[i])] == r) c->main_own[n++] = gc->main_node[i];
  PetscCall(PetscSortRemoveDupsInt(&n, c->main_own));
  c->nmain_own = n;
  PetscCall(PetscFree(newid));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Builds the part of rank r: its elements, nodes (owned, then ghosts), numbering arrays. */
static PetscErrorCode BuildPart(const TslModel *g, PetscInt r, const PetscInt epart[], const PetscInt owner[], const PetscInt gnum[],
                                const PetscInt node_nat[], const PetscInt elem_nat[], const PetscInt elem_order[], PetscInt nnode_used,
                                PetscInt *mark, TslModel **part)
{
  PetscInt  *elems, *nodes, *key, ne = 0, nn = 0, nown = 0, **sel, *held;
  PetscReal *hbox;
  TslModel  *sub;

  PetscFunctionBeginUser;
  PetscCall(PetscArrayzero(mark, g->nnode));
  PetscCall(PetscMalloc1(g->nelem, &elems));
  for (PetscInt i = 0; i < g->nelem; i++) {
    PetscInt e = elem_order[i];
    if (epart[e] != r) continue;
    elems[ne++] = e;
    for (PetscInt k = g->elem_ptr[e]; k < g->elem_ptr[e + 1]; k++) mark[TslModelNodeIndex(g, g->elem_conn[k])] = 1;
  }
  /* constraint closure: every node of an equation that touches this part */
  for (PetscInt q = 0; q < g->nequation; q++) {
    PetscBool touch = PETSC_FALSE;
    for (PetscInt t = 0; t < g->equations[q].n; t++)
      if (mark[TslModelNodeIndex(g, g->equations[q].node[t])] == 1) touch = PETSC_TRUE;
    if (touch)
      for (PetscInt t = 0; t < g->equations[q].n; t++) {
        PetscInt p = TslModelNodeIndex(g, g->equations[q].node[t]);
        if (!mark[p]) mark[p] = 2;
      }
  }
  /* contact: a rank that owns secondary nodes of a pair holds the main faces they can reach (their nodes
   * as ghosts: the main-surface data it needs arrives with every ghost update), those whose reference box
   * meets its held region, and their neighbours (SelectMainFaces); surface-to-surface: a rank that owns a
   * node of a secondary face holds the face (all its nodes) */
  PetscCall(PetscCalloc1(g->npair + 1, &sel));
  PetscCall(PetscCalloc1(g->npair + 1, &held));
  PetscCall(PetscMalloc1(6 * g->npair + 1, &hbox));
  for (PetscInt k = 0; k < g->npair; k++) {
    const TslContactPair *c = &g->pairs[k];
    for (PetscInt i = 0; i < c->nsface; i++)
      if (SecondaryFaceHeld(g, c, i, owner, r)) {
        for (PetscInt a = 0; a < c->snper; a++) {
          PetscInt q = TslModelNodeIndex(g, c->sface_node[c->snper * i + a]);
          if (!mark[q]) mark[q] = 2;
        }
      }
    held[k] = HeldRegion(g, c, owner, r, &hbox[6 * k]);
    if (!held[k]) continue;
    PetscCall(PetscMalloc1(c->nmain + 1, &sel[k]));
    PetscCall(SelectMainFaces(g, c, &hbox[6 * k], sel[k]));
    for (PetscInt i = 0; i < c->nper * c->nmain; i++) {
      PetscInt q = sel[k][i / c->nper] && c->main_node[i] >= 0 ? TslModelNodeIndex(g, c->main_node[i]) : -1;
      if (q >= 0 && !mark[q]) mark[q] = 2;
    }
  }
  PetscCall(PetscMalloc2(g->nnode, &nodes, g->nnode, &key));
  for (PetscInt p = 0; p < g->nnode; p++)
    if (mark[p] && owner[p] == r) nodes[nn] = p, key[nn++] = gnum[p];
  nown = nn;
  for (PetscInt p = 0; p < g->nnode; p++)
    if (mark[p] && owner[p] != r) nodes[nn] = p, key[nn++] = gnum[p];
  PetscCall(PetscSortIntWithArray(nown, key, nodes));
  PetscCall(PetscSortIntWithArray(nn - nown, key + nown, nodes + nown));

  PetscCall(TslModelSubset(g, ne, elems, nn, nodes, &sub));
  for (PetscInt k = 0; k < sub->npair; k++) {
    TslContactPair *c = &sub->pairs[k];
    PetscInt        n = 0;
    for (PetscInt i = 0; i < c->nsec; i++)
      if (owner[TslModelNodeIndex(g, c->sec_node[i])] == r) c->sec_node[n] = c->sec_node[i], c->sec_length[n++] = c->sec_length[i];
    c->nsec = n;
    n       = 0;
    for (PetscInt i = 0; i < c->nsface; i++)
      if (SecondaryFaceHeld(g, &g->pairs[k], i, owner, r)) {
        for (PetscInt a = 0; a < c->snper; a++) c->sface_node[c->snper * n + a] = c->sface_node[c->snper * i + a];
        c->sface_asm[n++] = owner[TslModelNodeIndex(g, c->sface_node[c->snper * i])] == r;
      }
    c->nsface = n;
    c->held   = held[k];
    for (PetscInt d = 0; d < 6; d++) c->held_box[d] = hbox[6 * k + d];
    PetscCall(KeepMainFaces(g, &g->pairs[k], sel[k], owner, r, c));
    PetscCall(PetscFree(sel[k]));
  }
  PetscCall(PetscFree(sel));
  PetscCall(PetscFree(held));
  PetscCall(PetscFree(hbox));
  sub->nnode_global = nnode_used;
  sub->nelem_global = g->nelem;
  sub->nnode_owned  = nown;
  PetscCall(PetscMalloc1(nn, &sub->node_gnum));
  PetscCall(PetscMalloc1(nn, &sub->node_nat));
  PetscCall(PetscMalloc1(ne, &sub->elem_nat));
  for (PetscInt i = 0; i < nn; i++) sub->node_gnum[i] = gnum[nodes[i]], sub->node_nat[i] = node_nat[nodes[i]];
  for (PetscInt i = 0; i < ne; i++) sub->elem_nat[i] = elem_nat[elems[i]];
  PetscCall(PetscFree(elems));
  PetscCall(PetscFree2(nodes, key));
  *part = sub;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The section of an element (its thickness and material), or -1. */
static PetscInt ElementSection(const TslModel *g, PetscInt id)
{
  for (PetscInt s = 0; s < g->nsection; s++) {
    PetscInt k = TslModelFindElementSet(g, g->sections[s].elset), loc;
    if (k < 0) continue;
    PetscCallAbort(PETSC_COMM_SELF, PetscFindInt(id, g->elsets[k].n, g->elsets[k].ids, &loc));
    if (loc >= 0) return s;
  }
  return -1;
}

/* Nodes of face f (1-based) of element position e: the catalogue's face list, in its orientation. */
static PetscInt FaceNodes(const TslModel *g, PetscInt e, PetscInt f, PetscInt nodes[])
{
  const TslGeometry *geom = TslElementTypeGet(g->elem_type[e])->geom;
  for (PetscInt a = 0; a < geom->face_nnode[f - 1]; a++) nodes[a] = g->elem_conn[g->elem_ptr[e] + geom->face_node[f - 1][a]];
  return geom->face_nnode[f - 1];
}

/* The contact face family of face f of element position e (2D: a TslContactFaceKind, 3D: a
 * TslContactFace3Find family), its nodes in face order (nodes[], *nf) and their reference coordinates
 * x[dim*a + d]. A face family contact does not support is a user error at the pair's data line. */
static PetscErrorCode ContactFace(const TslModel *g, const TslContactPair *c, PetscInt e, PetscInt f, PetscInt nodes[], PetscInt *nf, PetscReal x[],
                                  PetscInt *family)
{
  const TslGeometry *fg  = TslElementTypeGet(g->elem_type[e])->geom->face_geom[f - 1];
  const PetscInt     dim = g->dim;
  PetscInt           nn  = -1;
  char               loc[PETSC_MAX_PATH_LEN + 32];

  PetscFunctionBeginUser;
  *nf = FaceNodes(g, e, f, nodes);
  if (dim == 2) {
    *family = fg ? TslContactFaceFind(fg->name) : -1;
    if (*family >= 0) nn = TslContactFaceGet((TslContactFaceKind)*family)->geom->nnode;
  } else {
    *family = fg ? TslContactFace3Find(fg->name) : -1;
    if (*family >= 0) nn = TslContactFace3Nodes(*family);
  }
  PetscCheck(*family >= 0 && nn == *nf, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: contact on %s faces (%" PetscInt_FMT " nodes) is not supported yet",
             TslLocString(g, c->loc, loc, sizeof(loc)), fg ? fg->name : "unknown", *nf);
  PetscCheck(*nf <= (dim == 2 ? TSL_CONTACT_MAX_FACE_NODES : TSL_CONTACT3_MAX_FACE_NODES), PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "contact face with too many nodes");
  for (PetscInt a = 0; a < *nf; a++)
    for (PetscInt d = 0; d < dim; d++) x[dim * a + d] = g->node_xyz[3 * TslModelNodeIndex(g, nodes[a]) + d];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A quad8 face (C3D20T, C3D20RT, the expanded S8RT) as contact pieces, contact having no quad8 family: its four
 * corner triangles and the quad of its midside nodes, whose tributary weights are symmetric (A/24 per corner,
 * 5A/24 per midside node of a flat face) and positive: the serendipity functions' corner weights are negative
 * (-A/12), which loads the corners against a contact pressure. With tris, for the one family a surface-to-surface
 * secondary surface takes, the catalogue's linear subdivision of the face instead (TslGeomQuad8's six tri3, as
 * the expanded S8RT takes its pressure). Piece nodes in the face's order (corners 0..3, then the midsides of
 * edges 0-1, 1-2, 2-3, 3-0), so each piece faces as the face. */
static const PetscInt Quad8Pieces[5][4] = {{0, 4, 7, -1}, {1, 5, 4, -1}, {2, 6, 5, -1}, {3, 7, 6, -1}, {4, 5, 6, 7}};

static PetscBool IsQuad8Face(const TslModel *g, PetscInt e, PetscInt f)
{
  const TslGeometry *fg = TslElementTypeGet(g->elem_type[e])->geom->face_geom[f - 1];
  return (PetscBool)(g->dim == 3 && fg && fg->nnode == 8);
}

static PetscErrorCode Quad8Parts(const TslModel *g, PetscInt e, PetscInt f, PetscBool tris, PetscInt *np, PetscInt nodes[][TSL_MAX_FACE_NODES],
                                 PetscInt nf[], PetscReal x[][3 * TSL_MAX_FACE_NODES], PetscInt family[])
{
  const TslGeometry *fg = TslElementTypeGet(g->elem_type[e])->geom->face_geom[f - 1];
  PetscInt           n[TSL_MAX_FACE_NODES];
  const PetscInt     tri = TslContactFace3Find("tri3"), quad = TslContactFace3Find("quad4");

  PetscFunctionBeginUser;
  (void)FaceNodes(g, e, f, n);
  *np = tris ? fg->nsub : 5;
  for (PetscInt s = 0; s < *np; s++) {
    const PetscInt *v = tris ? fg->sub_node[s] : Quad8Pieces[s];
    nf[s]             = tris || v[3] < 0 ? 3 : 4;
    family[s]         = nf[s] == 3 ? tri : quad;
    for (PetscInt a = 0; a < nf[s]; a++) {
      nodes[s][a] = n[v[a]];
      for (PetscInt d = 0; d < 3; d++) x[s][3 * a + d] = g->node_xyz[3 * TslModelNodeIndex(g, n[v[a]]) + d];
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The contact faces of main-surface face f (1-based) of element e: the face itself or, where the element's
 * type takes pressure on the face's linear subdivision (the modified types' tri6 faces: 4 tri3), its
 * sub-faces, each with its own nodes (corner and midside nodes of the parent), coordinates and family, in
 * the order of the geometry's sub_node table. The quadratic tri6 functions are negative near the corners:
 * contact forces spread with them load the corners against the element's own pressure weights, and the
 * explicit kinematic corrector, whose convergence rests on non-negative face weights, needed 6.45 passes per
 * increment at rest instead of 4.35 (docs/contact.md "3D pairs"). Returns the number of parts in *np. */
static PetscErrorCode MainFaceParts(const TslModel *g, const TslContactPair *c, PetscInt e, PetscInt f, PetscInt *np, PetscInt nodes[][TSL_MAX_FACE_NODES],
                                    PetscInt nf[], PetscReal x[][3 * TSL_MAX_FACE_NODES], PetscInt family[])
{
  const TslElementType *t = TslElementTypeGet(g->elem_type[e]);
  const TslGeometry    *fg;
  PetscInt              pn[TSL_MAX_FACE_NODES], pnf, pfam;
  PetscReal             px[3 * TSL_MAX_FACE_NODES];

  PetscFunctionBeginUser;
  if (IsQuad8Face(g, e, f)) {
    PetscCall(Quad8Parts(g, e, f, PETSC_FALSE, np, nodes, nf, x, family));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(ContactFace(g, c, e, f, pn, &pnf, px, &pfam));
  if (g->dim != 3 || !TslElementTypeSubdividedFace(t, f - 1)) {
    *np = 1, nf[0] = pnf, family[0] = pfam;
    for (PetscInt a = 0; a < pnf; a++) nodes[0][a] = pn[a];
    for (PetscInt a = 0; a < 3 * pnf; a++) x[0][a] = px[a];
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  fg  = t->geom->face_geom[f - 1];
  *np = fg->nsub;
  for (PetscInt s = 0; s < fg->nsub; s++) {
    family[s] = TslContactFace3Find(fg->sub_geom->name);
    nf[s]     = fg->sub_geom->nnode;
    PetscCheck(family[s] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "no contact family for the sub-faces of %s", fg->name);
    for (PetscInt a = 0; a < nf[s]; a++) {
      const PetscInt k = fg->sub_node[s][a];
      nodes[s][a]      = pn[k];
      for (PetscInt d = 0; d < 3; d++) x[s][3 * a + d] = px[3 * k + d];
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Tributary weights w[] of the nodes of a face (int N_a ds in 2D, int N_a dA in 3D) and its size (length
 * or area). */
static PetscErrorCode FaceWeights(PetscInt dim, PetscInt family, const PetscReal x[], PetscReal w[], PetscReal *size)
{
  PetscFunctionBeginUser;
  if (dim == 2) PetscCall(TslContactFaceIntegrate((TslContactFaceKind)family, x, w, size));
  else PetscCall(TslContactFace3Integrate(family, x, w, size));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Axisymmetric line2 face (x: r, z of its two nodes): the kernels take a node's area as w_a 2 pi r_a (r_a
 * its reference radius), so w_a = int N_a r ds / r_a makes it the consistent int N_a 2 pi r ds =
 * 2 pi L (2 r_a + r_b) / 6, as the face loads are integrated (the trapezoidal L / 2 loaded the outer node of a
 * face more than the element rows do, and a uniform pressure came out non-uniform). A node on the axis
 * (r_a = 0) keeps its L / 2 and so no area, as before. Straight line3 faces need no change: Simpson's rule on
 * N_a r is exact. */
static void AxisymmetricLine2Weights(const PetscReal x[], PetscReal w[])
{
  const PetscReal L = PetscHypotReal(x[2] - x[0], x[3] - x[1]);

  for (PetscInt a = 0; a < 2; a++) {
    const PetscReal ra = x[2 * a], rb = x[2 * (1 - a)];
    if (ra > 0) w[a] = L * (2 * ra + rb) / (6 * ra);
  }
}

/* Does the straight chord of secondary face xs (first two nodes) lie across the main face xm, facing it:
 * the main face's ends project onto the chord with an overlap of positive length, and the outward normals
 * (body on the left of both faces) oppose? */
static PetscBool FacesOverlap(const PetscReal xs[], const PetscReal xm[])
{
  PetscReal ts[2] = {xs[2] - xs[0], xs[3] - xs[1]}, tm[2] = {xm[2] - xm[0], xm[3] - xm[1]}, L2 = ts[0] * ts[0] + ts[1] * ts[1], z[2];

  if (L2 <= 0 || ts[0] * tm[0] + ts[1] * tm[1] >= 0) return PETSC_FALSE; /* opposing normals = opposing tangents */
  for (PetscInt e = 0; e < 2; e++) z[e] = ((xm[2 * e] - xs[0]) * ts[0] + (xm[2 * e + 1] - xs[1]) * ts[1]) / L2;
  return (PetscBool)(PetscMin(1, PetscMax(z[0], z[1])) - PetscMax(0, PetscMin(z[0], z[1])) > 1e-9);
}

/* 3D: does the secondary face xs (family ks) overlap main face j of the pair, facing it (contact/clip3.c, in
 * the reference configuration)? */
static PetscErrorCode FacesOverlap3(const TslModel *g, const TslContactPair *c, PetscInt ks, const PetscReal xs[], PetscInt j, PetscBool *overlap)
{
  static TslContactOverlapPoint pt[TSL_CONTACT_OVERLAP_MAX_POINTS];
  PetscReal                     ym[3 * TSL_CONTACT3_MAX_FACE_NODES];
  PetscInt                      n;

  PetscFunctionBeginUser;
  for (PetscInt a = 0; a < TslContactFace3Nodes(c->main_kind[j]); a++)
    for (PetscInt d = 0; d < 3; d++) ym[3 * a + d] = g->node_xyz[3 * TslModelNodeIndex(g, c->main_node[c->nper * j + a]) + d];
  PetscCall(TslContactOverlap3(ks, xs, xs, c->main_kind[j], ym, TSL_CONTACT_OVERLAP_MAX_POINTS, pt, &n, NULL));
  *overlap = (PetscBool)(n > 0);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Surface-to-surface pair: the secondary faces (one family per surface) instead of secondary nodes, and
 * the check that some secondary face lies across some main face in the reference configuration: a pair
 * with no face overlap at all can never transmit anything and is a user error at its data line. */
static PetscErrorCode SurfaceToSurfaceFaces(const TslModel *g, TslContactPair *c, const TslSurface *sec)
{
  PetscInt  nodes[TSL_MAX_FACE_NODES], nf, family;
  PetscReal x[3 * TSL_MAX_FACE_NODES], y[2 * TSL_MAX_FACE_NODES];
  PetscBool overlap = PETSC_FALSE;
  char      loc[PETSC_MAX_PATH_LEN + 32];

  PetscInt  np, pnf[TSL_MAX_SUB], pfam[TSL_MAX_SUB], pnodes[TSL_MAX_SUB][TSL_MAX_FACE_NODES], k = 0;
  PetscReal px[TSL_MAX_SUB][3 * TSL_MAX_FACE_NODES];

  PetscFunctionBeginUser;
  c->nsec       = 0;
  c->nsface     = 0;
  c->sface_kind = TSL_CONTACT_FACE_LINE2;
  /* the faces, a quad8 face as its six triangles (Quad8Parts) */
  for (PetscInt i = 0; i < sec->n; i++) {
    const PetscInt e = TslModelElementIndex(g, sec->elem[i]);
    np               = 1;
    if (IsQuad8Face(g, e, sec->face[i])) PetscCall(Quad8Parts(g, e, sec->face[i], PETSC_TRUE, &np, pnodes, pnf, px, pfam));
    c->nsface += np;
  }
  if (sec->n && IsQuad8Face(g, TslModelElementIndex(g, sec->elem[0]), sec->face[0]))
    c->sface_kind = TslContactFace3Find("tri3");
  else if (sec->n)
    PetscCall(ContactFace(g, c, TslModelElementIndex(g, sec->elem[0]), sec->face[0], nodes, &nf, x, &c->sface_kind));
  c->snper = g->dim == 3 ? TslContactFace3Nodes(c->sface_kind) : TslContactFaceGet((TslContactFaceKind)c->sface_kind)->geom->nnode;
  PetscCall(PetscMalloc1(c->snper * c->nsface, &c->sface_node));
  PetscCall(PetscMalloc1(c->nsface, &c->sface_asm));
  for (PetscInt i = 0; i < sec->n; i++) {
    const PetscInt e = TslModelElementIndex(g, sec->elem[i]);
    if (IsQuad8Face(g, e, sec->face[i]))
      PetscCall(Quad8Parts(g, e, sec->face[i], PETSC_TRUE, &np, pnodes, pnf, px, pfam));
    else {
      PetscCall(ContactFace(g, c, e, sec->face[i], nodes, &nf, x, &family));
      np = 1, pnf[0] = nf, pfam[0] = family;
      for (PetscInt a = 0; a < nf; a++) pnodes[0][a] = nodes[a];
      for (PetscInt a = 0; a < 3 * nf; a++) px[0][a] = x[a];
    }
    for (PetscInt s = 0; s < np; s++, k++) {
      PetscCheck(pfam[s] == c->sface_kind, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
                 "%s: the secondary surface %s mixes face families: surface-to-surface contact needs one per surface",
                 TslLocString(g, c->loc, loc, sizeof(loc)), c->secondary);
      for (PetscInt a = 0; a < pnf[s]; a++) c->sface_node[c->snper * k + a] = pnodes[s][a];
      c->sface_asm[k] = 1;
      for (PetscInt j = 0; j < c->nmain && !overlap; j++) {
        if (g->dim == 3) {
          PetscCall(FacesOverlap3(g, c, pfam[s], px[s], j, &overlap));
          continue;
        }
        for (PetscInt a = 0; a < 2; a++)
          for (PetscInt d = 0; d < 2; d++) y[2 * a + d] = g->node_xyz[3 * TslModelNodeIndex(g, c->main_node[c->nper * j + a]) + d];
        overlap = FacesOverlap(px[s], y);
      }
    }
  }
  PetscCheck(overlap, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
             "%s: *CONTACT PAIR, TYPE=SURFACE TO SURFACE: the surfaces %s and %s have no face overlap at all (no secondary face lies across a main "
             "face, facing it)",
             TslLocString(g, c->loc, loc, sizeof(loc)), c->secondary, c->main);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Contact pairs in the solver's terms (rank 0, whole model): main surfaces as oriented faces (2D: line2 or
 * line3 segments with their neighbours; 3D: tri3, quad4, tri6 faces, one family per face), secondary nodes
 * with tributary lengths or areas (the integrals of the secondary faces' shape functions) or, surface to
 * surface (2D), the secondary faces, thickness, kinematics. The default penalty is left to the contact
 * set-up, which has the materials (src/physics/contact.c). */
static PetscErrorCode PrepareContactPairs(TslModel *g)
{
  const PetscInt dim = g->dim;
  char           loc[PETSC_MAX_PATH_LEN + 32];

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < g->npair; k++) {
    TslContactPair   *c    = &g->pairs[k];
    const TslSurface *main = &g->surfaces[TslModelFindSurface(g, c->main)];
    const TslSurface *sec  = &g->surfaces[TslModelFindSurface(g, c->secondary)];
    PetscInt         *first, *perm, nsec = 0, e0 = -1, nf, family, np, pnf[TSL_MAX_SUB], pfam[TSL_MAX_SUB];
    PetscInt          nodes[TSL_MAX_FACE_NODES], pnodes[TSL_MAX_SUB][TSL_MAX_FACE_NODES];
    PetscReal         Lsum = 0, x[3 * TSL_MAX_FACE_NODES], w[TSL_MAX_FACE_NODES], L, px[TSL_MAX_SUB][3 * TSL_MAX_FACE_NODES];

    /* main faces: in 2D one family per pair (the first face's); nper nodes each (3D: the most of any face,
     * shorter faces padded with -1), in face order */
    c->nmain        = 0;
    c->main_face    = 0;
    c->main_element = main->n ? main->elem[0] : -1;
    c->nper         = 0;
    for (PetscInt i = 0; i < main->n; i++) {
      PetscCall(MainFaceParts(g, c, TslModelElementIndex(g, main->elem[i]), main->face[i], &np, pnodes, pnf, px, pfam));
      c->nmain += np;
    }
    PetscCall(PetscMalloc1(c->nmain, &c->main_kind));
    for (PetscInt i = 0, j = 0; i < main->n; i++) {
      PetscCall(MainFaceParts(g, c, TslModelElementIndex(g, main->elem[i]), main->face[i], &np, pnodes, pnf, px, pfam));
      for (PetscInt s = 0; s < np; s++, j++) {
        if (j == 0) c->main_face = pfam[s];
        c->main_kind[j] = pfam[s];
        c->nper         = PetscMax(c->nper, pnf[s]);
        PetscCheck(dim == 3 || pfam[s] == c->main_face, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
                   "%s: the main surface %s mixes %s and %s faces: contact needs one face family per main surface",
                   TslLocString(g, c->loc, loc, sizeof(loc)), c->main, TslContactFaceGet((TslContactFaceKind)c->main_face)->geom->name,
                   TslContactFaceGet((TslContactFaceKind)pfam[s])->geom->name);
      }
    }
    if (dim == 2 && !main->n) c->nper = TslContactFaceGet(TSL_CONTACT_FACE_LINE2)->geom->nnode;
    PetscCall(PetscMalloc1(c->nper * c->nmain, &c->main_node));
    PetscCall(PetscMalloc1(c->nmain, &c->main_prev));
    PetscCall(PetscMalloc1(c->nmain, &c->main_next));
    PetscCall(PetscCalloc1(c->nmain + 1, &c->main_ring));
    for (PetscInt i = 0, j = 0; i < main->n; i++) {
      const PetscInt e = TslModelElementIndex(g, main->elem[i]);
      PetscCall(MainFaceParts(g, c, e, main->face[i], &np, pnodes, pnf, px, pfam));
      for (PetscInt s = 0; s < np; s++, j++) {
        for (PetscInt a = 0; a < c->nper; a++) c->main_node[c->nper * j + a] = a < pnf[s] ? pnodes[s][a] : -1;
        c->main_prev[j] = c->main_next[j] = -1;
      }
      if (IsQuad8Face(g, e, main->face[i])) { /* its pieces' areas */
        PetscReal A = 0;
        for (PetscInt s = 0; s < np; s++) {
          PetscCall(FaceWeights(dim, pfam[s], px[s], w, &L));
          A += L;
        }
        Lsum += PetscSqrtReal(A);
        continue;
      }
      PetscCall(ContactFace(g, c, e, main->face[i], nodes, &nf, x, &family));
      PetscCall(FaceWeights(dim, family, x, w, &L));
      Lsum += dim == 2 ? L : PetscSqrtReal(L);
    }
    /* neighbours along a 2D surface: the face that starts where this one ends (3D faces find their
     * neighbours through the search) */
    if (dim == 2) {
      PetscCall(PetscMalloc2(c->nmain, &first, c->nmain, &perm));
      for (PetscInt i = 0; i < c->nmain; i++) first[i] = c->main_node[c->nper * i], perm[i] = i;
      PetscCall(PetscSortIntWithArray(c->nmain, first, perm));
      for (PetscInt i = 0; i < c->nmain; i++) {
        PetscInt at;
        PetscCall(PetscFindInt(c->main_node[c->nper * i + 1], c->nmain, first, &at));
        if (at >= 0) c->main_next[i] = perm[at], c->main_prev[perm[at]] = i;
      }
      PetscCall(PetscFree2(first, perm));
    }
    c->mean_length = main->n ? Lsum / main->n : 0;

    /* secondary nodes and their tributary lengths or areas: int N_a ds (dA) over each face, corner and
     * midside nodes alike (line3: L/6, L/6, 2L/3; tri6: the weights of its linear subdivision), so that a
     * uniform pressure gives the consistent nodal forces */
    if (c->type == TSL_CONTACT_SURFACE_TO_SURFACE) {
      /* surface-to-surface: the secondary faces themselves (src/deck/check.c requires an element surface) */
      PetscCall(SurfaceToSurfaceFaces(g, c, sec));
      e0 = sec->n ? sec->elem[0] : -1;
    } else if (sec->kind == TSL_SURFACE_NODE) {
      c->nsec = sec->n;
      PetscCall(PetscMalloc1(c->nsec, &c->sec_node));
      PetscCall(PetscMalloc1(c->nsec, &c->sec_length));
      for (PetscInt i = 0; i < sec->n; i++) c->sec_node[i] = sec->elem[i], c->sec_length[i] = 1.0; /* node surfaces: unit area per node */
    } else {
      PetscCall(PetscMalloc1(TSL_MAX_FACE_NODES * sec->n, &c->sec_node));
      PetscCall(PetscMalloc1(TSL_MAX_FACE_NODES * sec->n, &c->sec_length));
      PetscInt nq8 = 0;
      for (PetscInt i = 0; i < sec->n; i++) nq8 += IsQuad8Face(g, TslModelElementIndex(g, sec->elem[i]), sec->face[i]) ? 1 : 0;
      if (nq8) { /* a quad8 face's pieces give up to 15 (node, weight) entries, merged below */
        PetscCall(PetscRealloc(sizeof(PetscInt) * (TSL_MAX_FACE_NODES * sec->n + 8 * nq8), &c->sec_node));
        PetscCall(PetscRealloc(sizeof(PetscReal) * (TSL_MAX_FACE_NODES * sec->n + 8 * nq8), &c->sec_length));
      }
      for (PetscInt i = 0; i < sec->n; i++) {
        const PetscInt ei = TslModelElementIndex(g, sec->elem[i]);
        if (IsQuad8Face(g, ei, sec->face[i])) {
          PetscCall(Quad8Parts(g, ei, sec->face[i], PETSC_FALSE, &np, pnodes, pnf, px, pfam));
          for (PetscInt s = 0; s < np; s++) {
            PetscCall(FaceWeights(dim, pfam[s], px[s], w, NULL));
            for (PetscInt a = 0; a < pnf[s]; a++) c->sec_node[nsec] = pnodes[s][a], c->sec_length[nsec++] = w[a];
          }
          if (i == 0) e0 = sec->elem[i];
          continue;
        }
        PetscCall(ContactFace(g, c, ei, sec->face[i], nodes, &nf, x, &family));
        PetscCall(FaceWeights(dim, family, x, w, NULL));
        if (dim == 2 && nf == 2 && TslKinematicsRevolves(TslElementTypeGet(g->elem_type[TslModelElementIndex(g, sec->elem[i])])->kin))
          AxisymmetricLine2Weights(x, w);
        for (PetscInt a = 0; a < nf; a++) c->sec_node[nsec] = nodes[a], c->sec_length[nsec++] = w[a];
        if (i == 0) e0 = sec->elem[i];
      }
      /* merge duplicates: a node shared by two facets gets both parts */
      PetscCall(PetscSortIntWithScalarArray(nsec, c->sec_node, c->sec_length));
      c->nsec = 0;
      for (PetscInt i = 0; i < nsec; i++) {
        if (c->nsec > 0 && c->sec_node[c->nsec - 1] == c->sec_node[i])
          c->sec_length[c->nsec - 1] += c->sec_length[i];
        else
          c->sec_node[c->nsec] = c->sec_node[i], c->sec_length[c->nsec++] = c->sec_length[i];
      }
    }
    {
      /* a node on both surfaces would be paired with faces of its own: not a contact this code models */
      PetscInt *sorted;
      PetscCall(PetscMalloc1(c->nsec + 1, &sorted));
      PetscCall(PetscArraycpy(sorted, c->sec_node, c->nsec));
      PetscCall(PetscSortInt(c->nsec, sorted));
      for (PetscInt i = 0; i < c->nper * c->nmain; i++) {
        PetscInt at = -1;
        if (c->main_node[i] >= 0) PetscCall(PetscFindInt(c->main_node[i], c->nsec, sorted, &at));
        PetscCheck(at < 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
                   "%s: node %" PetscInt_FMT " belongs to both the secondary surface %s and the main surface %s: contact of a surface with "
                   "itself, or with a surface sharing its nodes, is not supported",
                   TslLocString(g, c->loc, loc, sizeof(loc)), c->main_node[i], c->secondary, c->main);
      }
      PetscCall(PetscFree(sorted));
    }
    if (sec->kind == TSL_SURFACE_ELEMENT && sec->n > 0) {
      PetscInt ps  = ElementSection(g, e0);
      c->kin       = TslElementTypeGet(g->elem_type[TslModelElementIndex(g, e0)])->kin;
      c->thickness = dim == 2 && ps >= 0 && g->sections[ps].thickness > 0 ? g->sections[ps].thickness : 1.0;
    } else {
      c->kin       = g->nelem ? TslElementTypeGet(g->elem_type[0])->kin : TSL_KIN_PLANE_STRAIN;
      c->thickness = 1.0;
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The search radius of a pair as the contact set-up takes it (src/physics/contact.c): one mean main face,
 * or the largest tabulated clearance of a gap conductance by clearance or of a gap radiation. */
static PetscReal PairSearchRadius(const TslModel *g, const TslContactPair *c)
{
  const TslInteraction *it = &g->interactions[c->interaction_index];
  PetscReal             r  = c->mean_length;

  if (it->conductance.given && !it->conductance.by_pressure && it->conductance.n > 0) r = PetscMax(r, it->conductance.abscissa[it->conductance.n - 1]);
  if (it->radiation.given && it->radiation.n > 0) r = PetscMax(r, it->radiation.clearance[it->radiation.n - 1]);
  return r;
}

/* The largest displacement a *BOUNDARY prescribes anywhere in any step (the vector of the largest value of
 * each displacement dof, an amplitude's largest |value| applied). */
static PetscReal LargestPrescribedDisplacement(const TslModel *g)
{
  PetscReal u[3] = {0, 0, 0};

  for (PetscInt s = 0; s < g->nstep; s++)
    for (PetscInt l = 0; l < g->steps[s].nload; l++) {
      const TslLoad *ld  = &g->steps[s].loads[l];
      PetscReal      amp = 1;
      if (ld->kind != TSL_LOAD_BOUNDARY) continue;
      if (ld->amplitude >= 0 && ld->amplitude < g->namplitude) amp = TslAmplitudeBound(&g->amplitudes[ld->amplitude]);
      if (ld->velocity) { /* a velocity moves the dof for as long as it holds: this step and every later one, at most */
        PetscReal T = 0;
        for (PetscInt r = s; r < g->nstep; r++) T += g->steps[r].period;
        amp *= T;
      }
      for (PetscInt d = PetscMax(ld->dof_first, 1); d <= PetscMin(ld->dof_last, 3); d++) u[d - 1] = PetscMax(u[d - 1], amp * PetscAbsReal(ld->value));
    }
  return PetscSqrtReal(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
}

/* The margin of each pair's held region: -tsl_contact_margin, or twice (the largest prescribed
 * displacement + the search radius): the secondary and the main body may each move by the prescribed
 * amount, one search radius is the query around a node and the other leaves room for motion nothing
 * prescribes (elastic and thermal deformation of up to a face size). */
static void SetContactMargins(TslModel *g, PetscReal option)
{
  const PetscReal U = LargestPrescribedDisplacement(g);
  for (PetscInt k = 0; k < g->npair; k++) {
    TslContactPair *c = &g->pairs[k];
    c->margin_disp    = U;
    c->margin_radius  = PairSearchRadius(g, c);
    c->margin_default = option < 0;
    c->margin         = option >= 0 ? option : 2 * (U + c->margin_radius);
  }
}

static PetscErrorCode DistributeRoot(MPI_Comm comm, TslModel *g, PetscMPIInt size, TslModel **local)
{
  PetscInt *epart, *owner, *gnum, *node_nat, *elem_nat, *node_by_id, *elem_by_id, *elem_order, *count, *offset, *mark, nused = 0;
  char      method[32] = "metis", order[32] = "locality";
  PetscReal margin     = -1, cut[64];
  PetscInt  ncut       = 64;
  PetscBool cuts_given = PETSC_FALSE;
  PetscInt  ndof       = g->nelem ? TslElementTypeGet(g->elem_type[0])->ndof : g->dim + 1;

  PetscFunctionBeginUser;
  PetscCall(TslModelIndex(g));
  PetscCall(TslMeshTies(g)); /* first: ADJUST moves nodes the contact preparation measures */
  PetscCall(PrepareContactPairs(g));
  /* rank 0 alone partitions, so the options block is its own (-help lists it) */
  PetscOptionsBegin(PETSC_COMM_SELF, NULL, "thermoslide mesh partition", NULL);
  PetscCall(PetscOptionsString("-tsl_partition", "element partition: metis, or slabs by element centroid axis_x|axis_y|axis_z", NULL, method, method,
                               sizeof(method), NULL));
  PetscCall(PetscOptionsRealArray("-tsl_partition_cuts", "axis_*: the slabs' bounds along the axis (one fewer than the ranks, increasing) instead of equal element counts", NULL,
                                  cut, &ncut, &cuts_given));
  PetscCall(PetscOptionsReal("-tsl_contact_margin", "contact: inflation of each rank's held region of the main surface (default 2 (largest prescribed displacement + search radius))", NULL, margin, &margin, NULL));
  PetscCall(PetscOptionsString("-tsl_mesh_order",
                               "order of each rank's elements and owned nodes in memory: locality (along a Hilbert curve) or input (by number)", NULL,
                               order, order, sizeof(order), NULL));
  PetscOptionsEnd();
  PetscCheck(!strcmp(order, "locality") || !strcmp(order, "input"), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
             "-tsl_mesh_order %s: expected locality or input", order);
  PetscCheck(margin == -1 || margin >= 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-tsl_contact_margin %g: expected a length >= 0", (double)margin);
  SetContactMargins(g, margin);
  PetscCall(PetscMalloc4(g->nelem, &epart, g->nnode, &owner, g->nnode, &gnum, g->nnode, &node_nat));
  PetscCall(PetscMalloc4(g->nelem, &elem_nat, g->nnode, &node_by_id, g->nelem, &elem_by_id, g->nnode, &mark));
  PetscCall(PetscCalloc2(size, &count, size + 1, &offset));
  PetscCall(PetscMalloc1(g->nelem, &elem_order));

  {
    PetscBool metis = (PetscBool)!strcmp(method, "metis"),
              axis  = (PetscBool)(!strncmp(method, "axis_", 5) && method[5] >= 'x' && method[5] <= 'z' && !method[6]);
    PetscInt *count_e;
    PetscBool empty = PETSC_FALSE;

    PetscCheck(metis || axis, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-tsl_partition %s: expected metis, axis_x, axis_y or axis_z", method);
    if (!cuts_given) ncut = 0;
    PetscCheck(!ncut || axis, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-tsl_partition_cuts: needs -tsl_partition axis_x, axis_y or axis_z (not %s)", method);
    PetscCheck(!ncut || size == 1 || ncut == size - 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-tsl_partition_cuts: %" PetscInt_FMT " value(s) for %d ranks; give %d",
               ncut, (int)size, (int)size - 1);
    for (PetscInt k = 1; k < ncut; k++)
      PetscCheck(cut[k] > cut[k - 1], PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-tsl_partition_cuts: the values must increase (%g after %g)", (double)cut[k], (double)cut[k - 1]);
    if (g->nelem <= size) { /* one element per rank; ranks beyond the elements hold nothing */
      for (PetscInt e = 0; e < g->nelem; e++) epart[e] = e;
    } else if (size == 1) {
      for (PetscInt e = 0; e < g->nelem; e++) epart[e] = 0;
    } else if (metis) {
      PetscCall(PartitionMetis(g, size, epart));
    } else {
      PetscCall(PartitionAxis(g, method[5] - 'x', size, ncut, cut, epart));
    }
    /* METIS may leave a part empty on very small meshes: fall back to slabs along x */
    PetscCall(PetscCalloc1(size, &count_e));
    for (PetscInt e = 0; e < g->nelem; e++) count_e[epart[e]]++;
    for (PetscMPIInt r = 0; r < size && g->nelem > size; r++) empty = (PetscBool)(empty || count_e[r] == 0); /* fewer: empty by design */
    PetscCall(PetscFree(count_e));
    PetscCheck(!empty || !ncut, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-tsl_partition_cuts: a slab holds no element centroid; every rank needs one");
    if (empty) {
      PetscCall(PetscInfo(NULL, "METIS left a part empty; partitioning along x instead\n"));
      PetscCall(PartitionAxis(g, 0, size, 0, NULL, epart));
    }
  }

  /* owner = lowest rank among the elements using the node; -1 for nodes no element uses */
  for (PetscInt p = 0; p < g->nnode; p++) owner[p] = -1;
  for (PetscInt e = 0; e < g->nelem; e++)
    for (PetscInt k = g->elem_ptr[e]; k < g->elem_ptr[e + 1]; k++) {
      PetscInt p = TslModelNodeIndex(g, g->elem_conn[k]);
      if (owner[p] < 0 || epart[e] < owner[p]) owner[p] = epart[e];
    }
  PetscCall(SortByInt(g->nnode, g->node_id, node_by_id));
  PetscCall(SortByInt(g->nelem, g->elem_id, elem_by_id));
  for (PetscInt i = 0; i < g->nnode; i++) {
    PetscInt p = node_by_id[i];
    if (owner[p] < 0) {
      gnum[p] = node_nat[p] = -1;
      continue;
    }
    node_nat[p] = nused++;
    count[owner[p]]++;
  }
  for (PetscMPIInt r = 0; r < size; r++) offset[r + 1] = offset[r] + count[r];
  for (PetscMPIInt r = 0; r < size; r++) count[r] = 0;
  /* each rank's elements in memory order; its owned nodes numbered as its elements first reach them
   * (locality), or by node number (input) */
  PetscCall(ElementOrder(g, epart, (PetscBool)!strcmp(order, "locality"), elem_order));
  if (!strcmp(order, "locality")) {
    for (PetscInt p = 0; p < g->nnode; p++) gnum[p] = -1;
    for (PetscInt i = 0; i < g->nelem; i++) {
      const PetscInt e = elem_order[i];
      for (PetscInt k = g->elem_ptr[e]; k < g->elem_ptr[e + 1]; k++) {
        const PetscInt p = TslModelNodeIndex(g, g->elem_conn[k]);
        if (owner[p] == epart[e] && gnum[p] < 0) gnum[p] = offset[owner[p]] + count[owner[p]]++;
      }
    }
  } else
    for (PetscInt i = 0; i < g->nnode; i++) {
      PetscInt p = node_by_id[i];
      if (owner[p] >= 0) gnum[p] = offset[owner[p]] + count[owner[p]]++;
    }
  for (PetscInt i = 0; i < g->nelem; i++) elem_nat[elem_by_id[i]] = i;

  /* equations in global dof numbers */
  for (PetscInt q = 0; q < g->nequation; q++) {
    TslEquation *eq = &g->equations[q];
    char         loc[PETSC_MAX_PATH_LEN + 32];
    if (!eq->gdof) PetscCall(PetscMalloc1(eq->n, &eq->gdof));
    for (PetscInt t = 0; t < eq->n; t++) {
      PetscInt p = TslModelNodeIndex(g, eq->node[t]);
      PetscCheck(p >= 0 && owner[p] >= 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
                 "%s: *EQUATION node %" PetscInt_FMT " does not belong to any element", TslLocString(g, eq->loc, loc, sizeof(loc)), eq->node[t]);
      {
        /* the rare equation on a reference node costs a scan of the elements */
        const PetscBool extra = TslElementTypeGet(g->elem_type[0])->nextra ? IsExtraNode(g, p) : PETSC_FALSE;
        const PetscInt  slot  = DofSlot(g, extra, eq->dof[t]);
        PetscCheck(slot >= 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: *EQUATION dof %" PetscInt_FMT " does not exist at node %" PetscInt_FMT " of %s elements",
                   TslLocString(g, eq->loc, loc, sizeof(loc)), eq->dof[t], eq->node[t], TslElementTypeGet(g->elem_type[0])->name);
        eq->gdof[t] = gnum[p] * ndof + slot;
      }
    }
  }

  for (PetscMPIInt r = size - 1; r >= 0; r--) {
    TslModel *part;
    PetscCall(BuildPart(g, r, epart, owner, gnum, node_nat, elem_nat, elem_order, nused, mark, &part));
    if (r == 0) {
      *local = part;
    } else {
      char         *buf;
      size_t        len;
      unsigned long n;
      PetscCall(TslModelPack(part, &buf, &len));
      n = (unsigned long)len;
      PetscCallMPI(MPI_Send(&n, 1, MPI_UNSIGNED_LONG, r, 0, comm));
      PetscCallMPI(MPI_Send(buf, (int)len, MPI_BYTE, r, 1, comm));
      PetscCall(PetscFree(buf));
      PetscCall(TslModelDestroy(&part));
    }
  }
  PetscCall(PetscFree4(epart, owner, gnum, node_nat));
  PetscCall(PetscFree4(elem_nat, node_by_id, elem_by_id, mark));
  PetscCall(PetscFree2(count, offset));
  PetscCall(PetscFree(elem_order));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslMeshDistribute(MPI_Comm comm, TslModel **global, TslModel **local)
{
  PetscMPIInt    rank, size;
  PetscErrorCode ierr = PETSC_SUCCESS;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  if (rank == 0) {
    /* errors on rank 0 must reach the others, which wait in MPI_Recv */
    ierr = DistributeRoot(comm, *global, size, local);
    if (ierr) {
      unsigned long zero = 0;
      for (PetscMPIInt r = 1; r < size; r++) PetscCallMPI(MPI_Send(&zero, 1, MPI_UNSIGNED_LONG, r, 0, comm));
    }
    PetscCall(TslModelDestroy(global));
  } else {
    unsigned long n;
    char         *buf;
    PetscCallMPI(MPI_Recv(&n, 1, MPI_UNSIGNED_LONG, 0, 0, comm, MPI_STATUS_IGNORE));
    if (n == 0)
      ierr = PETSC_ERR_USER_INPUT;
    else {
      PetscCall(PetscMalloc1(n, &buf));
      PetscCallMPI(MPI_Recv(buf, (int)n, MPI_BYTE, 0, 1, comm, MPI_STATUS_IGNORE));
      PetscCall(TslModelUnpack(buf, (size_t)n, local));
      PetscCall(PetscFree(buf));
    }
  }
  PetscCallMPI(MPI_Bcast(&ierr, 1, MPI_INT, 0, comm));
  PetscCheck(!ierr, comm, PETSC_ERR_USER_INPUT, " "); /* reported by rank 0 */
  PetscCall(TslModelIndex(*local));
  PetscFunctionReturn(PETSC_SUCCESS);
}
