/* The problem's state for restart points (src/solve/restart.c): contact nodes, plastic points and surface-to-surface
 * points as blobs under natural keys (whatever the rank count), digests of this rank's layout, of the mesh and of the
 * model. */
#include "contact_s2s_impl.h"

static void Mix(uint64_t *h, const void *data, size_t n)
{
  const unsigned char *c = (const unsigned char *)data;
  for (size_t i = 0; i < n; i++) *h = (*h ^ c[i]) * 1099511628211ull; /* FNV-1a */
}

PetscErrorCode TslProblemLayoutDigest(TslProblem p, uint64_t *digest)
{
  const TslModel *m = p->m;
  uint64_t        h = 14695981039346656037ull;
  PetscInt        sizes[6];

  PetscFunctionBeginUser;
  sizes[0] = p->nn, sizes[1] = p->nown, sizes[2] = p->ndof, sizes[3] = m->nelem, sizes[4] = p->ncnode, sizes[5] = p->npstate;
  Mix(&h, sizes, sizeof(sizes));
  Mix(&h, m->node_id, p->nn * sizeof(PetscInt));
  Mix(&h, m->node_xyz, 3 * p->nn * sizeof(PetscReal));
  Mix(&h, m->elem_id, m->nelem * sizeof(PetscInt));
  Mix(&h, m->elem_type, m->nelem * sizeof(m->elem_type[0]));
  Mix(&h, p->elem_lnode, m->elem_ptr[m->nelem] * sizeof(PetscInt));
  for (PetscInt i = 0; i < p->ncnode; i++) Mix(&h, &p->cnode[i].lnode, sizeof(PetscInt));
  *digest = h;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static void MixInt(uint64_t *h, PetscInt v)
{
  Mix(h, &v, sizeof(v));
}

static void MixReals(uint64_t *h, const PetscReal *v, PetscInt n)
{
  if (n > 0 && v) Mix(h, v, (size_t)n * sizeof(PetscReal));
}

/* The model's data a continuation must share with the run that wrote its point, beyond the mesh: materials (every
 * table), sections, contact interactions (normal behaviour, friction, conductance, radiation, heat generation) and
 * the pairs. Names, lines and the steps are left out: a comment or a renamed material does not change the physics,
 * and the steps after the point's may differ. The same on every rank. */
PetscErrorCode TslProblemModelDigest(TslProblem p, uint64_t *digest)
{
  const TslModel *m = p->m;
  uint64_t        h = 14695981039346656037ull;

  PetscFunctionBeginUser;
  MixInt(&h, m->nmaterial);
  for (PetscInt k = 0; k < m->nmaterial; k++) {
    const TslMaterial *mt = &m->materials[k];
    for (PetscInt q = 0; q < TSL_NPROP; q++) {
      const TslPropertyTable *t = &mt->prop[q];
      MixInt(&h, t->n);
      for (PetscInt r = 0; r < t->n; r++) MixReals(&h, t->value[r], 2), MixReals(&h, &t->theta[r], 1);
    }
    MixReals(&h, &mt->alpha_zero, 1);
    MixInt(&h, mt->plastic.n);
    for (PetscInt r = 0; r < mt->plastic.n; r++) MixReals(&h, mt->plastic.row[r], 3);
    MixInt(&h, mt->plastic.nvoce);
    for (PetscInt r = 0; r < mt->plastic.nvoce; r++) MixReals(&h, mt->plastic.voce[r], 4);
    MixInt(&h, mt->plastic.nback);
    MixInt(&h, mt->plastic.rate_law);
    MixReals(&h, mt->plastic.rate, 2);
    MixReals(&h, &mt->heat_fraction, 1);
    if (mt->damp_alpha != 0 || mt->damp_beta != 0) MixReals(&h, &mt->damp_alpha, 1), MixReals(&h, &mt->damp_beta, 1); /* undamped: the digest as before */
  }
  MixInt(&h, m->nsection);
  for (PetscInt k = 0; k < m->nsection; k++) {
    const TslSection *sc = &m->sections[k];
    MixInt(&h, sc->material_index);
    MixReals(&h, &sc->thickness, 1);
    MixInt(&h, sc->shell);
    MixInt(&h, sc->shell_points);
    MixReals(&h, &sc->thickness_modulus, 1);
    MixReals(&h, &sc->shell_thickness, 1);
    MixReals(&h, &sc->shell_offset, 1);
  }
  MixInt(&h, m->ninteraction);
  for (PetscInt k = 0; k < m->ninteraction; k++) {
    const TslInteraction *it = &m->interactions[k];
    MixReals(&h, &it->thickness, 1);
    MixInt(&h, it->behavior.enforcement);
    MixReals(&h, &it->behavior.penalty_stiffness, 1);
    MixInt(&h, it->friction.given);
    MixReals(&h, &it->friction.mu, 1);
    MixInt(&h, it->friction.lagrange);
    MixInt(&h, it->friction.rough);
    MixReals(&h, &it->friction.slip_tolerance, 1);
    MixReals(&h, &it->friction.elastic_slip, 1);
    MixReals(&h, &it->friction.stick_slope, 1);
    MixInt(&h, it->conductance.n);
    MixInt(&h, it->conductance.by_pressure);
    MixReals(&h, it->conductance.value, it->conductance.n);
    MixReals(&h, it->conductance.abscissa, it->conductance.n);
    MixInt(&h, it->radiation.n);
    MixReals(&h, &it->radiation.emissivity_main, 1);
    MixReals(&h, &it->radiation.emissivity_secondary, 1);
    MixReals(&h, it->radiation.view_factor, it->radiation.n);
    MixReals(&h, it->radiation.clearance, it->radiation.n);
    MixReals(&h, &it->heat_generation.fraction, 1);
    MixReals(&h, &it->heat_generation.weight_secondary, 1);
  }
  MixInt(&h, m->npair);
  for (PetscInt k = 0; k < m->npair; k++) {
    const TslContactPair *cp = &m->pairs[k];
    MixInt(&h, cp->interaction_index);
    MixInt(&h, cp->type);
    MixInt(&h, cp->small_sliding);
    MixInt(&h, cp->kinematic);
    MixReals(&h, &cp->smooth, 1);
    MixReals(&h, &cp->adjust, 1);
  }
  *digest = h;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- The state in the deck's own terms, for a continuation on another rank count (restart.c) ----
 * Blobs of reals under keys of natural indices: a contact node's under (1, pair, node), with its pairing's main faces
 * as their first three nodes; a plastic element's points under (2, element); a surface-to-surface face's point counts
 * under (3, pair, its first three nodes) and its points under (4, ...); a node's surface-to-surface slip under (5,
 * node). Local indices are translated on the way in: a node's or point's face found among the faces held here. */
enum { B_CNODE = 1, B_PLASTIC, B_S2SFACE, B_S2SPOINTS, B_S2SSLIP };
#define NR(T) ((PetscInt)((sizeof(T) + sizeof(PetscReal) - 1) / sizeof(PetscReal)))

typedef struct {
  PetscInt n, cap, nval, capval;
  int64_t *key;
  PetscInt *len;
  PetscReal *val;
} Blobs;

static PetscErrorCode BlobAdd(Blobs *b, int64_t k0, int64_t k1, int64_t k2, int64_t k3, int64_t k4, PetscInt len, PetscReal **val)
{
  PetscFunctionBeginUser;
  if (b->n == b->cap) {
    b->cap = PetscMax(64, 2 * b->cap);
    PetscCall(PetscRealloc(sizeof(int64_t) * TSL_BLOB_KEY * b->cap, &b->key));
    PetscCall(PetscRealloc(sizeof(PetscInt) * b->cap, &b->len));
  }
  if (b->nval + len > b->capval) {
    b->capval = PetscMax(b->nval + len, 2 * b->capval);
    PetscCall(PetscRealloc(sizeof(PetscReal) * (b->capval + 1), &b->val));
  }
  {
    int64_t *k = &b->key[TSL_BLOB_KEY * b->n];
    k[0] = k0, k[1] = k1, k[2] = k2, k[3] = k3, k[4] = k4;
  }
  b->len[b->n++] = len;
  *val           = NULL; /* the caller fills it through BlobLast: the array may move with the next blob */
  b->nval += len;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscReal *BlobLast(Blobs *b)
{
  return &b->val[b->nval - b->len[b->n - 1]];
}

/* The first three nodes of face f of a main surface (natural indices; -1 past its nodes), or -1s for no face */
static void MainFace(TslProblem p, const TslContactSurface *cs, PetscInt f, int64_t t[3])
{
  for (PetscInt a = 0; a < 3; a++) {
    PetscInt l = f >= 0 && a < cs->nper ? cs->main_lnode[cs->nper * f + a] : -1;
    t[a]       = l >= 0 ? p->m->node_nat[l] : -1;
  }
}

static void FaceNodes3(TslProblem p, const PetscInt lnode[], PetscInt n, int64_t t[3])
{
  for (PetscInt a = 0; a < 3; a++) t[a] = a < n && lnode[a] >= 0 ? p->m->node_nat[lnode[a]] : -1;
}

/* The faces a main surface holds here in order of their first three nodes, for FindFace */
typedef struct {
  int64_t  t[3];
  PetscInt f;
} FaceKey;

static int FaceKeyCompare(const void *a, const void *b)
{
  const FaceKey *x = a, *y = b;
  for (int i = 0; i < 3; i++)
    if (x->t[i] != y->t[i]) return x->t[i] < y->t[i] ? -1 : 1;
  return 0;
}

static PetscErrorCode FaceKeys(TslProblem p, PetscInt k, FaceKey **fk)
{
  const TslContactSurface *cs = &p->csurf[k];

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(cs->nmain + 1, fk));
  for (PetscInt f = 0; f < cs->nmain; f++) MainFace(p, cs, f, (*fk)[f].t), (*fk)[f].f = f;
  qsort(*fk, (size_t)cs->nmain, sizeof(FaceKey), FaceKeyCompare);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The local face of pair k with first nodes t (-1: none given), -1 when it is not held here (*lost counts those) */
static PetscInt FindFace(TslProblem p, FaceKey *const *fk, PetscInt k, const PetscReal t[3], PetscInt *lost)
{
  FaceKey key, *hit;
  if (t[0] < 0) return -1;
  for (int i = 0; i < 3; i++) key.t[i] = (int64_t)t[i];
  hit = p->csurf[k].nmain ? bsearch(&key, fk[k], (size_t)p->csurf[k].nmain, sizeof(FaceKey), FaceKeyCompare) : NULL;
  if (!hit) (*lost)++;
  return hit ? hit->f : -1;
}

static PetscInt PlasticLength(TslProblem p, PetscInt e)
{
  return TslMaterialPlasticState(p->esec[e].mat) * TslElementTypeMechanicalPoints(TslElementTypeGet(p->m->elem_type[e]), &p->esec[e]);
}

PetscErrorCode TslProblemStateBlobs(TslProblem p, PetscInt *n, int64_t **key, PetscInt **len, PetscReal **val)
{
  const TslModel *m = p->m;
  Blobs           b = {0};
  PetscReal      *v;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < p->ncnode; i++) {
    const TslContactNode    *cn = &p->cnode[i];
    const TslContactSurface *cs = &p->csurf[cn->pair];
    int64_t                  t[6];
    PetscCall(BlobAdd(&b, B_CNODE, cn->pair, m->node_nat[cn->lnode], 0, 0, NR(TslContactNode) + 6, &v));
    v = BlobLast(&b);
    memcpy(v, cn, sizeof(*cn));
    MainFace(p, cs, cn->seg, t), MainFace(p, cs, cn->seg_c, t + 3);
    for (int a = 0; a < 6; a++) v[NR(TslContactNode) + a] = (PetscReal)t[a];
  }
  for (PetscInt e = 0; p->pstate_off && e < m->nelem; e++) {
    if (p->pstate_off[e] < 0) continue;
    PetscCall(BlobAdd(&b, B_PLASTIC, m->elem_nat[e], 0, 0, 0, PlasticLength(p, e), &v));
    v = BlobLast(&b);
    PetscCall(PetscArraycpy(v, p->pstate + p->pstate_off[e], PlasticLength(p, e)));
  }
  if (p->s2s) {
    TslContactS2S s = p->s2s;
    for (PetscInt i = 0; i < s->nface; i++) {
      const S2SFace *fc = &s->face[i];
      int64_t        t[3];
      const PetscInt np = fc->npt + fc->npt_c, w = NR(S2SPoint) + 3;
      if (!fc->assemble) continue; /* held here for its nodes' outputs: the rank that inserts it writes it */
      FaceNodes3(p, fc->lnode, fc->nsn, t);
      PetscCall(BlobAdd(&b, B_S2SFACE, fc->pair, t[0], t[1], t[2], 2, &v));
      v    = BlobLast(&b);
      v[0] = (PetscReal)fc->npt, v[1] = (PetscReal)fc->npt_c;
      if (!np) continue;
      PetscCall(BlobAdd(&b, B_S2SPOINTS, fc->pair, t[0], t[1], t[2], np * w, &v));
      v = BlobLast(&b);
      for (PetscInt q = 0; q < np; q++) {
        const S2SPoint *pt = q < fc->npt ? &s->pt[fc->first + q] : &s->pt_c[fc->first_c + q - fc->npt];
        int64_t         mt[3];
        memcpy(&v[q * w], pt, sizeof(*pt));
        MainFace(p, &p->csurf[fc->pair], pt->seg, mt);
        for (int a = 0; a < 3; a++) v[q * w + NR(S2SPoint) + a] = (PetscReal)mt[a];
      }
    }
    for (PetscInt l = 0; l < p->nown; l++) { /* the nodes that slipped (a node without a blob has none) */
      if (s->cslip[l] == 0 && s->cslip_c[l] == 0) continue;
      PetscCall(BlobAdd(&b, B_S2SSLIP, m->node_nat[l], 0, 0, 0, 2, &v));
      v    = BlobLast(&b);
      v[0] = s->cslip[l], v[1] = s->cslip_c[l];
    }
  }
  *n = b.n, *key = b.key, *len = b.len, *val = b.val;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemStateFromBlobs(TslProblem p, TslBlobFetch fetch, void *ctx)
{
  const TslModel *m = p->m;
  Blobs           b = {0};
  PetscBool      *found;
  PetscInt        missing = 0, lost = 0, at = 0;
  char           *onface = NULL;
  FaceKey       **fk;
  PetscReal      *v;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(p->ncsurf + 1, &fk));
  for (PetscInt k = 0; k < p->ncsurf; k++) PetscCall(FaceKeys(p, k, &fk[k]));
  /* the first round: contact nodes, plastic elements, surface-to-surface faces' counts and slip */
  for (PetscInt i = 0; i < p->ncnode; i++) PetscCall(BlobAdd(&b, B_CNODE, p->cnode[i].pair, m->node_nat[p->cnode[i].lnode], 0, 0, NR(TslContactNode) + 6, &v));
  for (PetscInt e = 0; p->pstate_off && e < m->nelem; e++)
    if (p->pstate_off[e] >= 0) PetscCall(BlobAdd(&b, B_PLASTIC, m->elem_nat[e], 0, 0, 0, PlasticLength(p, e), &v));
  if (p->s2s) {
    for (PetscInt i = 0; i < p->s2s->nface; i++) {
      int64_t t[3];
      FaceNodes3(p, p->s2s->face[i].lnode, p->s2s->face[i].nsn, t);
      PetscCall(BlobAdd(&b, B_S2SFACE, p->s2s->face[i].pair, t[0], t[1], t[2], 2, &v));
    }
    PetscCall(PetscCalloc1(p->nn + 1, &onface)); /* the slip of the faces' nodes */
    for (PetscInt i = 0; i < p->s2s->nface; i++)
      for (PetscInt a = 0; a < p->s2s->face[i].nsn; a++)
        if (p->s2s->face[i].lnode[a] >= 0) onface[p->s2s->face[i].lnode[a]] = 1;
    for (PetscInt l = 0; l < p->nn; l++)
      if (onface[l]) PetscCall(BlobAdd(&b, B_S2SSLIP, m->node_nat[l], 0, 0, 0, 2, &v));
  }
  PetscCall(PetscMalloc1(b.n + 1, &found));
  PetscCall(fetch(ctx, b.n, b.key, b.len, b.val, found));
  v = b.val;
  for (PetscInt i = 0; i < p->ncnode; i++, at++) {
    TslContactNode *cn = &p->cnode[i], in;
    const PetscReal *t = v + NR(TslContactNode);
    if (!found[at]) missing++;
    else {
      memcpy(&in, v, sizeof(in));
      in.pair = cn->pair, in.lnode = cn->lnode, in.length = cn->length; /* this rank's own */
      in.seg   = FindFace(p, fk, cn->pair, t, &lost);
      in.seg_c = FindFace(p, fk, cn->pair, t + 3, &lost);
      *cn      = in;
    }
    v += b.len[at];
  }
  for (PetscInt e = 0; p->pstate_off && e < m->nelem; e++) {
    if (p->pstate_off[e] < 0) continue;
    if (!found[at]) missing++;
    else PetscCall(PetscArraycpy(p->pstate + p->pstate_off[e], v, PlasticLength(p, e)));
    v += b.len[at++];
  }
  if (p->s2s) {
    TslContactS2S s  = p->s2s;
    Blobs         b2 = {0};
    PetscInt      npt = 0, npt_c = 0, at2 = 0;
    const PetscInt w = NR(S2SPoint) + 3;
    for (PetscInt i = 0; i < s->nface; i++, at++) {
      S2SFace *fc = &s->face[i];
      fc->npt = fc->npt_c = 0;
      if (found[at]) fc->npt = (PetscInt)v[0], fc->npt_c = (PetscInt)v[1]; /* a face no rank inserted has no points */
      fc->first = npt, fc->first_c = npt_c;
      npt += fc->npt, npt_c += fc->npt_c;
      v += b.len[at];
    }
    for (PetscInt l = 0; l < p->nn; l++) {
      s->cslip[l] = s->cslip_c[l] = 0;
      if (!onface[l]) continue;
      if (found[at]) s->cslip[l] = v[0], s->cslip_c[l] = v[1];
      v += b.len[at++];
    }
    PetscCall(PetscFree(onface));
    /* the second round: each face's points */
    for (PetscInt i = 0; i < s->nface; i++) {
      const S2SFace *fc = &s->face[i];
      int64_t        t[3];
      if (!(fc->npt + fc->npt_c)) continue;
      FaceNodes3(p, fc->lnode, fc->nsn, t);
      PetscCall(BlobAdd(&b2, B_S2SPOINTS, fc->pair, t[0], t[1], t[2], (fc->npt + fc->npt_c) * w, &v));
    }
    PetscCall(PetscFree(found));
    PetscCall(PetscMalloc1(b2.n + 1, &found));
    PetscCall(fetch(ctx, b2.n, b2.key, b2.len, b2.val, found));
    PetscCall(TslS2SReserve(&s->pt, &s->cap, npt));
    PetscCall(TslS2SReserve(&s->pt_c, &s->cap_c, npt_c));
    s->npt = npt, s->npt_c = npt_c;
    v = b2.val;
    for (PetscInt i = 0; i < s->nface; i++) {
      S2SFace *fc = &s->face[i];
      if (!(fc->npt + fc->npt_c)) continue;
      if (!found[at2]) missing++;
      for (PetscInt q = 0; found[at2] && q < fc->npt + fc->npt_c; q++) {
        S2SPoint *pt = q < fc->npt ? &s->pt[fc->first + q] : &s->pt_c[fc->first_c + q - fc->npt];
        memcpy(pt, &v[q * w], sizeof(*pt));
        pt->seg = FindFace(p, fk, fc->pair, &v[q * w + NR(S2SPoint)], &lost);
      }
      v += b2.len[at2++];
    }
    PetscCall(PetscFree(b2.key));
    PetscCall(PetscFree(b2.len));
    PetscCall(PetscFree(b2.val));
  }
  PetscCall(PetscFree(found));
  PetscCall(PetscFree(b.key));
  PetscCall(PetscFree(b.len));
  PetscCall(PetscFree(b.val));
  for (PetscInt k = 0; k < p->ncsurf; k++) PetscCall(PetscFree(fk[k]));
  PetscCall(PetscFree(fk));
  {
    PetscInt c[2] = {missing, lost};
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, c, 2, MPIU_INT, MPI_SUM, p->comm));
    PetscCheck(!c[0], p->comm, PETSC_ERR_FILE_UNEXPECTED, "the restart point holds no state for %" PetscInt_FMT " of this model's contact nodes, plastic elements or contact faces", c[0]);
    PetscCheck(!c[1], p->comm, PETSC_ERR_FILE_UNEXPECTED,
               "the restart point pairs %" PetscInt_FMT " contact nodes or points with main faces this partition does not hold: continue it on the rank count it was written with", c[1]);
  }
  if (p->npstate) PetscCall(PetscArraycpy(p->pstate_new, p->pstate, p->npstate));
  /* 3D main surfaces' nodal normals: from the point's solution, as its commit computed them */
  {
    Vec                xl;
    const PetscScalar *xa;
    PetscCall(TslProblemGetLocalSolution(p, &xl, &xa));
    for (PetscInt k = 0; k < p->ncsurf; k++)
      if (p->csurf[k].nnormal) PetscCall(TslProblemContact3Normals(p, &p->csurf[k], xa));
    if (p->s2s && p->dim == 3) PetscCall(TslS2S3Normals(p, xa));
    PetscCall(TslProblemRestoreLocalSolution(p, &xl, &xa));
  }
  p->pattern_stale = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective: the mesh and the contact nodes, independent of the rank count (an order-independent sum of each owned
 * node's, element's and contact node's digest) */
PetscErrorCode TslProblemMeshDigest(TslProblem p, uint64_t *digest)
{
  const TslModel *m   = p->m;
  uint64_t        sum = 0;

  PetscFunctionBeginUser;
  for (PetscInt l = 0; l < p->nown; l++) {
    uint64_t h = 14695981039346656037ull;
    MixInt(&h, m->node_nat[l]);
    MixInt(&h, m->node_id[l]);
    MixReals(&h, &m->node_xyz[3 * l], 3);
    sum += h;
  }
  for (PetscInt e = 0; e < m->nelem; e++) {
    uint64_t h = 14695981039346656037ull;
    MixInt(&h, m->elem_nat[e]);
    MixInt(&h, m->elem_id[e]);
    Mix(&h, &m->elem_type[e], sizeof(m->elem_type[e]));
    for (PetscInt a = m->elem_ptr[e]; a < m->elem_ptr[e + 1]; a++) MixInt(&h, m->node_nat[p->elem_lnode[a]]);
    sum += h * 3;
  }
  for (PetscInt i = 0; i < p->ncnode; i++) {
    uint64_t h = 14695981039346656037ull;
    MixInt(&h, p->cnode[i].pair);
    MixInt(&h, m->node_nat[p->cnode[i].lnode]);
    sum += h * 5;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &sum, 1, MPI_UINT64_T, MPI_SUM, p->comm));
  *digest = sum;
  PetscFunctionReturn(PETSC_SUCCESS);
}
