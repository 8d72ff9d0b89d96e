/* The plain-data model: lifetime, lookups, amplitude evaluation, serialisation and subsets. */
#include "deck_impl.h"
#include <ctype.h>
#include <string.h>

PetscErrorCode TslModelCreate(TslModel **model)
{
  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(1, model));
  (*model)->absolute_zero = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ModelFreeIndex(TslModel *m)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(m->index_node_id));
  PetscCall(PetscFree(m->index_node_pos));
  PetscCall(PetscFree(m->index_elem_id));
  PetscCall(PetscFree(m->index_elem_pos));
  m->index_nnode = m->index_nelem = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslModelDestroy(TslModel **model)
{
  TslModel *m;

  PetscFunctionBeginUser;
  if (!model || !*model) PetscFunctionReturn(PETSC_SUCCESS);
  m = *model;
  for (PetscInt i = 0; i < m->nfile; i++) PetscCall(PetscFree(m->files[i]));
  PetscCall(PetscFree(m->files));
  PetscCall(PetscFree(m->post));
  PetscCall(PetscFree(m->post_out));
  PetscCall(PetscFree(m->node_id));
  PetscCall(PetscFree(m->node_xyz));
  PetscCall(PetscFree(m->elem_id));
  PetscCall(PetscFree(m->elem_type));
  PetscCall(PetscFree(m->elem_ptr));
  PetscCall(PetscFree(m->elem_conn));
  PetscCall(PetscFree(m->elem_line));
  for (PetscInt i = 0; i < m->nnset; i++) PetscCall(PetscFree(m->nsets[i].ids));
  for (PetscInt i = 0; i < m->nelset; i++) PetscCall(PetscFree(m->elsets[i].ids));
  PetscCall(PetscFree(m->nsets));
  PetscCall(PetscFree(m->elsets));
  for (PetscInt i = 0; i < m->nsurface; i++) {
    PetscCall(PetscFree(m->surfaces[i].elem));
    PetscCall(PetscFree(m->surfaces[i].face));
  }
  PetscCall(PetscFree(m->surfaces));
  PetscCall(PetscFree(m->materials));
  PetscCall(PetscFree(m->sections));
  PetscCall(PetscFree(m->init));
  PetscCall(PetscFree(m->vinit));
  PetscCall(PetscFree(m->nodal_thickness));
  for (PetscInt i = 0; i < m->namplitude; i++) {
    PetscCall(PetscFree(m->amplitudes[i].t));
    PetscCall(PetscFree(m->amplitudes[i].a));
    PetscCall(PetscFree(m->amplitudes[i].cosc));
    PetscCall(PetscFree(m->amplitudes[i].sinc));
  }
  PetscCall(PetscFree(m->amplitudes));
  for (PetscInt i = 0; i < m->nequation; i++) {
    PetscCall(PetscFree(m->equations[i].node));
    PetscCall(PetscFree(m->equations[i].dof));
    PetscCall(PetscFree(m->equations[i].coef));
    PetscCall(PetscFree(m->equations[i].gdof));
  }
  PetscCall(PetscFree(m->equations));
  for (PetscInt i = 0; i < m->ninteraction; i++) {
    TslInteraction *it = &m->interactions[i];
    PetscCall(PetscFree(it->conductance.value));
    PetscCall(PetscFree(it->conductance.abscissa));
    PetscCall(PetscFree(it->radiation.view_factor));
    PetscCall(PetscFree(it->radiation.clearance));
  }
  PetscCall(PetscFree(m->interactions));
  for (PetscInt i = 0; i < m->npair; i++) {
    TslContactPair *c = &m->pairs[i];
    PetscCall(PetscFree(c->main_node));
    PetscCall(PetscFree(c->main_kind));
    PetscCall(PetscFree(c->main_prev));
    PetscCall(PetscFree(c->main_next));
    PetscCall(PetscFree(c->sec_node));
    PetscCall(PetscFree(c->sec_length));
    PetscCall(PetscFree(c->sface_node));
    PetscCall(PetscFree(c->sface_asm));
    PetscCall(PetscFree(c->main_ring));
    PetscCall(PetscFree(c->main_own));
  }
  PetscCall(PetscFree(m->pairs));
  PetscCall(PetscFree(m->ties));
  for (PetscInt i = 0; i < m->nstep; i++) {
    PetscCall(PetscFree(m->steps[i].loads));
    PetscCall(PetscFree(m->steps[i].out));
  }
  PetscCall(PetscFree(m->steps));
  PetscCall(PetscFree(m->node_gnum));
  PetscCall(PetscFree(m->node_nat));
  PetscCall(PetscFree(m->elem_nat));
  PetscCall(ModelFreeIndex(m));
  PetscCall(PetscFree(*model));
  PetscFunctionReturn(PETSC_SUCCESS);
}

const char *TslDeckFileName(const TslModel *model, PetscInt f)
{
  if (!model || f < 0 || f >= model->nfile || !model->files[f]) return "<unknown>";
  return model->files[f];
}

const char *TslLocString(const TslModel *model, TslLoc loc, char *buf, size_t len)
{
  if (!buf || !len) return buf;
  (void)PetscSNPrintf(buf, len, "%s:%" PetscInt_FMT, TslDeckFileName(model, loc.file), loc.line);
  return buf;
}

PetscBool TslDeckNameEqual(const char *a, const char *b)
{
  while (*a && *b && toupper((unsigned char)*a) == toupper((unsigned char)*b)) a++, b++;
  return (!*a && !*b) ? PETSC_TRUE : PETSC_FALSE;
}

PetscErrorCode TslDeckGrow(void *ptr, size_t sz, PetscInt n)
{
  void   **p = (void **)ptr;
  PetscInt cap, want;

  PetscFunctionBeginUser;
  for (cap = 8; cap < n; cap *= 2) {
  }
  if (n > 0 && n + 1 <= cap && *p) PetscFunctionReturn(PETSC_SUCCESS);
  PetscInt keep = *p ? n : 0; /* a first allocation is zeroed whole (elem_ptr[0] must read 0) */
  for (want = 8; want < n + 1; want *= 2) {
  }
  PetscCall(PetscRealloc((size_t)want * sz, p));
  memset((char *)*p + (size_t)keep * sz, 0, (size_t)(want - keep) * sz);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- lookups --------------------------------------------------------------------------------- */

#define FIND_BY_NAME(arr, cnt)                                                                                                                       \
  do {                                                                                                                                               \
    if (!model || !name) return -1;                                                                                                                  \
    for (PetscInt i = 0; i < model->cnt; i++)                                                                                                        \
      if (TslDeckNameEqual(model->arr[i].name, name)) return i;                                                                                      \
    return -1;                                                                                                                                       \
  } while (0)

PetscInt TslModelFindNodeSet(const TslModel *model, const char *name)
{
  FIND_BY_NAME(nsets, nnset);
}
PetscInt TslModelFindElementSet(const TslModel *model, const char *name)
{
  FIND_BY_NAME(elsets, nelset);
}
PetscInt TslModelFindSurface(const TslModel *model, const char *name)
{
  FIND_BY_NAME(surfaces, nsurface);
}
PetscInt TslModelFindMaterial(const TslModel *model, const char *name)
{
  FIND_BY_NAME(materials, nmaterial);
}
PetscInt TslModelFindAmplitude(const TslModel *model, const char *name)
{
  FIND_BY_NAME(amplitudes, namplitude);
}
PetscInt TslModelFindInteraction(const TslModel *model, const char *name)
{
  FIND_BY_NAME(interactions, ninteraction);
}

static PetscErrorCode BuildIndex(PetscInt n, const PetscInt ids[], PetscInt **sid, PetscInt **pos)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(n, sid));
  PetscCall(PetscMalloc1(n, pos));
  for (PetscInt i = 0; i < n; i++) {
    (*sid)[i] = ids[i];
    (*pos)[i] = i;
  }
  PetscCall(PetscSortIntWithArray(n, *sid, *pos));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslModelIndex(TslModel *model)
{
  PetscFunctionBeginUser;
  PetscCall(ModelFreeIndex(model));
  PetscCall(BuildIndex(model->nnode, model->node_id, &model->index_node_id, &model->index_node_pos));
  PetscCall(BuildIndex(model->nelem, model->elem_id, &model->index_elem_id, &model->index_elem_pos));
  model->index_nnode = model->nnode;
  model->index_nelem = model->nelem;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscInt IndexLookup(PetscInt n, const PetscInt *sid, const PetscInt *pos, PetscInt nidx, const PetscInt *ids, PetscInt id)
{
  if (sid && nidx == n) {
    PetscInt lo = 0, hi = n - 1, k = n > 0 ? id - sid[0] : -1;
    if (k >= 0 && k < n && sid[k] == id) return pos[k]; /* ids numbered without gaps from the first (most decks): no search */
    while (lo <= hi) {
      PetscInt mid = lo + (hi - lo) / 2;
      if (sid[mid] == id) return pos[mid];
      if (sid[mid] < id)
        lo = mid + 1;
      else
        hi = mid - 1;
    }
    return -1;
  }
  for (PetscInt i = 0; i < n; i++)
    if (ids[i] == id) return i;
  return -1;
}

PetscInt TslModelNodeIndex(const TslModel *model, PetscInt id)
{
  return IndexLookup(model->nnode, model->index_node_id, model->index_node_pos, model->index_nnode, model->node_id, id);
}

PetscInt TslModelElementIndex(const TslModel *model, PetscInt id)
{
  return IndexLookup(model->nelem, model->index_elem_id, model->index_elem_pos, model->index_nelem, model->elem_id, id);
}

/* ---- amplitudes ------------------------------------------------------------------------------ */

/* A closed form at t (primitive = 0) or its primitive from t0 (primitive = 1); before t0 the constant A0 and its integral.
 * PERIODIC: A0 tau + sum A_k sin(k w tau)/(k w) + B_k (1 - cos(k w tau))/(k w); DECAY: A0 tau + A td (1 - exp(-tau/td));
 * MODULATED: sin a tau sin b tau = (cos (a - b) tau - cos (a + b) tau) / 2, whose primitive takes sin(x tau)/x -> tau at x = 0. */
static PetscReal SinOver(PetscReal x, PetscReal tau)
{
  return PetscAbsReal(x * tau) < 1e-8 ? tau : PetscSinReal(x * tau) / x;
}

static PetscReal AmplitudeClosed(const TslAmplitude *amp, PetscReal t, PetscBool primitive)
{
  const PetscReal tau = t - amp->t0;
  PetscReal       s   = primitive ? amp->a0 * tau : amp->a0;

  if (tau <= 0) return s;
  switch (amp->form) {
  case TSL_AMP_PERIODIC:
    for (PetscInt k = 0; k < amp->nterm; k++) {
      const PetscReal w = (k + 1) * amp->omega, c = PetscCosReal(w * tau), sn = PetscSinReal(w * tau);
      s += primitive ? (amp->cosc[k] * sn + amp->sinc[k] * (1 - c)) / w : amp->cosc[k] * c + amp->sinc[k] * sn;
    }
    break;
  case TSL_AMP_DECAY:
    s += primitive ? -amp->A * amp->td * expm1(-tau / amp->td) : amp->A * PetscExpReal(-tau / amp->td);
    break;
  case TSL_AMP_MODULATED:
    s += primitive ? 0.5 * amp->A * (SinOver(amp->omega - amp->omega2, tau) - SinOver(amp->omega + amp->omega2, tau))
                   : amp->A * PetscSinReal(amp->omega * tau) * PetscSinReal(amp->omega2 * tau);
    break;
  default:
    break;
  }
  return s;
}

PetscReal TslAmplitudeBound(const TslAmplitude *amp)
{
  PetscReal b = 0;

  if (!amp) return 1.0;
  if (amp->form != TSL_AMP_POINTS) {
    b = PetscAbsReal(amp->a0) + PetscAbsReal(amp->A);
    for (PetscInt k = 0; k < amp->nterm; k++) b += PetscAbsReal(amp->cosc[k]) + PetscAbsReal(amp->sinc[k]);
    return b;
  }
  for (PetscInt i = 0; i < amp->n; i++) b = PetscMax(b, PetscAbsReal(amp->a[i]));
  return b;
}

/* Piecewise linear through (t_i, a_i), constant beyond the ends. At a repeated time (a jump) the
 * later value wins, so a jump at t takes effect at t. */
PetscReal TslAmplitudeEval(const TslAmplitude *amp, PetscReal t)
{
  if (amp && amp->form != TSL_AMP_POINTS) return AmplitudeClosed(amp, t, PETSC_FALSE);
  if (!amp || amp->n < 1) return 1.0;
  if (t < amp->t[0]) return amp->a[0];
  for (PetscInt i = 0; i + 1 < amp->n; i++) {
    if (t < amp->t[i + 1]) {
      PetscReal dt = amp->t[i + 1] - amp->t[i];
      PetscReal xi;
      if (dt <= 0) return amp->a[i + 1];
      xi = (t - amp->t[i]) / dt;
      /* SMOOTH STEP: zero first and second derivative at every data point (Abaqus's definition), so a
       * prescribed motion has no velocity or acceleration jumps (explicit steps: no waves from them) */
      if (amp->smooth) xi = xi * xi * xi * (10 - 15 * xi + 6 * xi * xi);
      return amp->a[i] + (amp->a[i + 1] - amp->a[i]) * xi;
    }
  }
  return amp->a[amp->n - 1];
}

/* The amplitude's integral over [ta, tb] (ta <= tb), exact for its pieces: trapezoids, the smooth step's
 * polynomial (its integral over a piece from 0 to xi is xi^4 (5/2 - 3 xi + xi^2) of the piece's length), and
 * the constant ends. A velocity boundary condition's displacement is the velocity times this. */
static PetscReal AmplitudePrimitive(const TslAmplitude *amp, PetscReal t)
{
  PetscReal s = 0;

  if (t <= amp->t[0]) return (t - amp->t[0]) * amp->a[0];
  for (PetscInt i = 0; i + 1 < amp->n; i++) {
    const PetscReal dt = amp->t[i + 1] - amp->t[i], end = PetscMin(t, amp->t[i + 1]);
    if (dt > 0) {
      const PetscReal xi = (end - amp->t[i]) / dt;
      const PetscReal f  = amp->smooth ? xi * xi * xi * xi * (2.5 - 3 * xi + xi * xi) : 0.5 * xi * xi; /* the rise's integral / dt */
      s += dt * (amp->a[i] * xi + (amp->a[i + 1] - amp->a[i]) * f);
    }
    if (t <= amp->t[i + 1]) return s;
  }
  return s + (t - amp->t[amp->n - 1]) * amp->a[amp->n - 1];
}

PetscReal TslAmplitudeIntegral(const TslAmplitude *amp, PetscReal ta, PetscReal tb)
{
  if (amp && amp->form != TSL_AMP_POINTS) return AmplitudeClosed(amp, tb, PETSC_TRUE) - AmplitudeClosed(amp, ta, PETSC_TRUE);
  if (!amp || amp->n < 1) return tb - ta;
  return AmplitudePrimitive(amp, tb) - AmplitudePrimitive(amp, ta);
}

/* ---- serialisation ----------------------------------------------------------------------------
 * One walker, ModelWalk(), visits every field in a fixed order; the packer's mode decides whether a
 * visit appends the bytes to the buffer or reads them back. Structs are copied whole as bytes (so
 * scalar fields need no listing) and every pointer inside them is then visited explicitly, which in
 * unpack mode replaces the stale pointer read with the struct by a fresh allocation. */

typedef struct {
  PetscBool   unpack;
  char       *out; /* pack: growing buffer */
  size_t      cap;
  const char *in; /* unpack: source */
  size_t      pos, len;
} Packer;

static PetscErrorCode PackBytes(Packer *p, void *x, size_t n)
{
  PetscFunctionBeginUser;
  if (!n) PetscFunctionReturn(PETSC_SUCCESS);
  if (p->unpack) {
    PetscCheck(p->pos + n <= p->len, PETSC_COMM_SELF, PETSC_ERR_ARG_CORRUPT, "Model buffer too short");
    memcpy(x, p->in + p->pos, n);
  } else {
    if (p->pos + n > p->cap) {
      size_t cap = p->cap ? p->cap : 1024;
      while (cap < p->pos + n) cap *= 2;
      PetscCall(PetscRealloc(cap, &p->out));
      p->cap = cap;
    }
    memcpy(p->out + p->pos, x, n);
  }
  p->pos += n;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode PackInt(Packer *p, PetscInt *x)
{
  PetscFunctionBeginUser;
  PetscCall(PackBytes(p, x, sizeof(*x)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* An array of n elements of size sz at *ptr; NULL-ness is kept (a NULL array stays NULL). */
static PetscErrorCode PackArray(Packer *p, void *ptr, PetscInt n, size_t sz)
{
  void   **a       = (void **)ptr;
  PetscInt present = *a ? 1 : 0;

  PetscFunctionBeginUser;
  PetscCall(PackInt(p, &present));
  if (p->unpack) {
    *a = NULL;
    if (present && n > 0) PetscCall(PetscMalloc((size_t)n * sz, a));
  }
  if (present && n > 0) PetscCall(PackBytes(p, *a, (size_t)n * sz));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode PackString(Packer *p, char **s)
{
  PetscInt n = (!p->unpack && *s) ? (PetscInt)strlen(*s) + 1 : 0; /* on unpack *s holds the sender's pointer */

  PetscFunctionBeginUser;
  PetscCall(PackInt(p, &n));
  if (p->unpack) {
    *s = NULL;
    if (n) PetscCall(PetscMalloc1(n, s));
  }
  if (n) PetscCall(PackBytes(p, *s, (size_t)n));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ModelWalk(Packer *p, TslModel *m)
{
  PetscFunctionBeginUser;
  PetscCall(PackBytes(p, m, sizeof(*m)));
  if (p->unpack) { /* the derived index is rebuilt, never transported */
    m->index_node_id = m->index_node_pos = m->index_elem_id = m->index_elem_pos = NULL;
    m->index_nnode = m->index_nelem = 0;
  }
  PetscCall(PackArray(p, &m->files, m->nfile, sizeof(char *)));
  for (PetscInt i = 0; i < m->nfile; i++) PetscCall(PackString(p, &m->files[i]));

  PetscCall(PackArray(p, &m->node_id, m->nnode, sizeof(PetscInt)));
  PetscCall(PackArray(p, &m->node_xyz, 3 * m->nnode, sizeof(PetscReal)));
  PetscCall(PackArray(p, &m->elem_id, m->nelem, sizeof(PetscInt)));
  PetscCall(PackArray(p, &m->elem_type, m->nelem, sizeof(PetscInt)));
  PetscCall(PackArray(p, &m->elem_ptr, m->elem_ptr ? m->nelem + 1 : 0, sizeof(PetscInt)));
  PetscCall(PackArray(p, &m->elem_conn, m->elem_ptr ? m->elem_ptr[m->nelem] : 0, sizeof(PetscInt)));
  PetscCall(PackArray(p, &m->elem_line, 2 * m->nelem, sizeof(PetscInt)));

  PetscCall(PackArray(p, &m->nsets, m->nnset, sizeof(TslSet)));
  for (PetscInt i = 0; i < m->nnset; i++) PetscCall(PackArray(p, &m->nsets[i].ids, m->nsets[i].n, sizeof(PetscInt)));
  PetscCall(PackArray(p, &m->elsets, m->nelset, sizeof(TslSet)));
  for (PetscInt i = 0; i < m->nelset; i++) PetscCall(PackArray(p, &m->elsets[i].ids, m->elsets[i].n, sizeof(PetscInt)));
  PetscCall(PackArray(p, &m->surfaces, m->nsurface, sizeof(TslSurface)));
  for (PetscInt i = 0; i < m->nsurface; i++) {
    PetscCall(PackArray(p, &m->surfaces[i].elem, m->surfaces[i].n, sizeof(PetscInt)));
    PetscCall(PackArray(p, &m->surfaces[i].face, m->surfaces[i].n, sizeof(PetscInt)));
  }

  PetscCall(PackArray(p, &m->materials, m->nmaterial, sizeof(TslMaterial)));
  PetscCall(PackArray(p, &m->sections, m->nsection, sizeof(TslSection)));
  PetscCall(PackArray(p, &m->init, m->ninit, sizeof(TslInitialTemperature)));
  PetscCall(PackArray(p, &m->vinit, m->nvinit, sizeof(TslInitialVelocity)));
  PetscCall(PackArray(p, &m->nodal_thickness, m->nnodal_thickness, sizeof(TslNodalThickness)));
  PetscCall(PackArray(p, &m->amplitudes, m->namplitude, sizeof(TslAmplitude)));
  for (PetscInt i = 0; i < m->namplitude; i++) {
    PetscCall(PackArray(p, &m->amplitudes[i].t, m->amplitudes[i].n, sizeof(PetscReal)));
    PetscCall(PackArray(p, &m->amplitudes[i].a, m->amplitudes[i].n, sizeof(PetscReal)));
    PetscCall(PackArray(p, &m->amplitudes[i].cosc, m->amplitudes[i].nterm, sizeof(PetscReal)));
    PetscCall(PackArray(p, &m->amplitudes[i].sinc, m->amplitudes[i].nterm, sizeof(PetscReal)));
  }
  PetscCall(PackArray(p, &m->ties, m->ntie, sizeof(TslTie)));
  PetscCall(PackArray(p, &m->equations, m->nequation, sizeof(TslEquation)));
  for (PetscInt i = 0; i < m->nequation; i++) {
    TslEquation *e = &m->equations[i];
    PetscCall(PackArray(p, &e->node, e->n, sizeof(PetscInt)));
    PetscCall(PackArray(p, &e->dof, e->n, sizeof(PetscInt)));
    PetscCall(PackArray(p, &e->coef, e->n, sizeof(PetscReal)));
    PetscCall(PackArray(p, &e->gdof, e->n, sizeof(PetscInt)));
  }
  PetscCall(PackArray(p, &m->interactions, m->ninteraction, sizeof(TslInteraction)));
  for (PetscInt i = 0; i < m->ninteraction; i++) {
    TslInteraction *it = &m->interactions[i];
    PetscCall(PackArray(p, &it->conductance.value, it->conductance.n, sizeof(PetscReal)));
    PetscCall(PackArray(p, &it->conductance.abscissa, it->conductance.n, sizeof(PetscReal)));
    PetscCall(PackArray(p, &it->radiation.view_factor, it->radiation.n, sizeof(PetscReal)));
    PetscCall(PackArray(p, &it->radiation.clearance, it->radiation.n, sizeof(PetscReal)));
  }
  PetscCall(PackArray(p, &m->pairs, m->npair, sizeof(TslContactPair)));
  for (PetscInt i = 0; i < m->npair; i++) {
    TslContactPair *c = &m->pairs[i];
    PetscCall(PackArray(p, &c->main_node, c->nper * c->nmain, sizeof(PetscInt)));
    PetscCall(PackArray(p, &c->main_kind, c->nmain, sizeof(PetscInt)));
    PetscCall(PackArray(p, &c->main_prev, c->nmain, sizeof(PetscInt)));
    PetscCall(PackArray(p, &c->main_next, c->nmain, sizeof(PetscInt)));
    PetscCall(PackArray(p, &c->sec_node, c->nsec, sizeof(PetscInt)));
    PetscCall(PackArray(p, &c->sec_length, c->nsec, sizeof(PetscReal)));
    PetscCall(PackArray(p, &c->sface_node, c->snper * c->nsface, sizeof(PetscInt)));
    PetscCall(PackArray(p, &c->sface_asm, c->nsface, sizeof(PetscInt)));
    PetscCall(PackArray(p, &c->main_ring, c->nmain, sizeof(PetscInt)));
    PetscCall(PackArray(p, &c->main_own, c->nmain_own, sizeof(PetscInt)));
  }
  PetscCall(PackArray(p, &m->steps, m->nstep, sizeof(TslStep)));
  for (PetscInt i = 0; i < m->nstep; i++) {
    PetscCall(PackArray(p, &m->steps[i].loads, m->steps[i].nload, sizeof(TslLoad)));
    PetscCall(PackArray(p, &m->steps[i].out, m->steps[i].nout, sizeof(TslOutputRequest)));
  }
  PetscCall(PackArray(p, &m->post, 2 * m->npost, sizeof(PetscInt)));
  PetscCall(PackArray(p, &m->post_out, m->npost_out, sizeof(TslOutputRequest)));
  PetscCall(PackArray(p, &m->node_gnum, m->nnode, sizeof(PetscInt)));
  PetscCall(PackArray(p, &m->node_nat, m->nnode, sizeof(PetscInt)));
  PetscCall(PackArray(p, &m->elem_nat, m->nelem, sizeof(PetscInt)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslModelPack(const TslModel *model, char **buf, size_t *len)
{
  Packer   p = {0};
  TslModel copy;

  PetscFunctionBeginUser;
  copy = *model; /* the walker takes a non-const model; in pack mode it only reads */
  PetscCall(ModelWalk(&p, &copy));
  *buf = p.out;
  *len = p.pos;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslModelUnpack(const char *buf, size_t len, TslModel **model)
{
  Packer    p = {0};
  TslModel *m;

  PetscFunctionBeginUser;
  p.unpack = PETSC_TRUE;
  p.in     = buf;
  p.len    = len;
  PetscCall(TslModelCreate(&m));
  PetscCall(ModelWalk(&p, m));
  PetscCheck(p.pos == len, PETSC_COMM_SELF, PETSC_ERR_ARG_CORRUPT, "Model buffer has %zu trailing bytes", len - p.pos);
  PetscCall(TslModelIndex(m));
  *model = m;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- subsets --------------------------------------------------------------------------------- */

static PetscErrorCode FilterIds(PetscInt n, const PetscInt ids[], PetscInt nkeep, const PetscInt keep_sorted[], PetscInt *nout, PetscInt **out)
{
  PetscInt k = 0, loc;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(n, out));
  for (PetscInt i = 0; i < n; i++) {
    PetscCall(PetscFindInt(ids[i], nkeep, keep_sorted, &loc));
    if (loc >= 0) (*out)[k++] = ids[i];
  }
  *nout = k;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode SubsetSets(PetscInt nset, const TslSet *src, TslSet *dst, PetscInt nkeep, const PetscInt keep[])
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < nset; i++) {
    dst[i] = src[i];
    PetscCall(FilterIds(src[i].n, src[i].ids, nkeep, keep, &dst[i].n, &dst[i].ids));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode SubsetSurface(const TslSurface *src, TslSurface *dst, PetscInt nnk, const PetscInt nkeep[], PetscInt nek,
                                    const PetscInt ekeep[])
{
  PetscInt        k = 0, loc, nkp = src->kind == TSL_SURFACE_NODE ? nnk : nek;
  const PetscInt *kp = src->kind == TSL_SURFACE_NODE ? nkeep : ekeep;

  PetscFunctionBeginUser;
  *dst = *src;
  PetscCall(PetscMalloc1(src->n, &dst->elem));
  dst->face = NULL;
  if (src->face) PetscCall(PetscMalloc1(src->n, &dst->face));
  for (PetscInt i = 0; i < src->n; i++) {
    PetscCall(PetscFindInt(src->elem[i], nkp, kp, &loc));
    if (loc < 0) continue;
    dst->elem[k] = src->elem[i];
    if (src->face) dst->face[k] = src->face[i];
    k++;
  }
  dst->n = k;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CopyEquation(const TslEquation *src, TslEquation *dst)
{
  PetscFunctionBeginUser;
  *dst = *src;
  PetscCall(PetscMalloc1(src->n, &dst->node));
  PetscCall(PetscMalloc1(src->n, &dst->dof));
  PetscCall(PetscMalloc1(src->n, &dst->coef));
  PetscCall(PetscArraycpy(dst->node, src->node, src->n));
  PetscCall(PetscArraycpy(dst->dof, src->dof, src->n));
  PetscCall(PetscArraycpy(dst->coef, src->coef, src->n));
  dst->gdof = NULL;
  if (src->gdof) {
    PetscCall(PetscMalloc1(src->n, &dst->gdof));
    PetscCall(PetscArraycpy(dst->gdof, src->gdof, src->n));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode SubsetMesh(const TslModel *m, PetscInt ne, const PetscInt elems[], PetscInt nn, const PetscInt nodes[], TslModel *s)
{
  PetscInt nconn = 0;

  PetscFunctionBeginUser;
  s->nnode = nn;
  s->nelem = ne;
  PetscCall(PetscMalloc1(nn, &s->node_id));
  PetscCall(PetscMalloc1(3 * nn, &s->node_xyz));
  for (PetscInt i = 0; i < nn; i++) {
    PetscCheck(nodes[i] >= 0 && nodes[i] < m->nnode, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Node position %" PetscInt_FMT " out of range",
               nodes[i]);
    s->node_id[i] = m->node_id[nodes[i]];
    for (PetscInt c = 0; c < 3; c++) s->node_xyz[3 * i + c] = m->node_xyz[3 * nodes[i] + c];
  }
  for (PetscInt i = 0; i < ne; i++) {
    PetscCheck(elems[i] >= 0 && elems[i] < m->nelem, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Element position %" PetscInt_FMT " out of range",
               elems[i]);
    nconn += m->elem_ptr[elems[i] + 1] - m->elem_ptr[elems[i]];
  }
  PetscCall(PetscMalloc1(ne, &s->elem_id));
  PetscCall(PetscMalloc1(ne, &s->elem_type));
  PetscCall(PetscMalloc1(ne + 1, &s->elem_ptr));
  PetscCall(PetscMalloc1(nconn, &s->elem_conn));
  PetscCall(PetscMalloc1(2 * ne, &s->elem_line));
  s->elem_ptr[0] = 0;
  for (PetscInt i = 0; i < ne; i++) {
    PetscInt e = elems[i], k = s->elem_ptr[i];
    s->elem_id[i]           = m->elem_id[e];
    s->elem_type[i]         = m->elem_type[e];
    s->elem_line[2 * i]     = m->elem_line ? m->elem_line[2 * e] : -1;
    s->elem_line[2 * i + 1] = m->elem_line ? m->elem_line[2 * e + 1] : 0;
    for (PetscInt j = m->elem_ptr[e]; j < m->elem_ptr[e + 1]; j++) s->elem_conn[k++] = m->elem_conn[j];
    s->elem_ptr[i + 1] = k;
  }
  if (m->node_gnum) PetscCall(PetscMalloc1(nn, &s->node_gnum));
  if (m->node_nat) PetscCall(PetscMalloc1(nn, &s->node_nat));
  if (m->elem_nat) PetscCall(PetscMalloc1(ne, &s->elem_nat));
  for (PetscInt i = 0; i < nn; i++) {
    if (m->node_gnum) s->node_gnum[i] = m->node_gnum[nodes[i]];
    if (m->node_nat) s->node_nat[i] = m->node_nat[nodes[i]];
  }
  for (PetscInt i = 0; i < ne; i++)
    if (m->elem_nat) s->elem_nat[i] = m->elem_nat[elems[i]];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The initial-condition lines (temperatures, velocities: arrays of structs whose first member is their
 * TslTarget) that concern the subset's nodes (s's sets already filtered): a line for a node it holds or for
 * a set with members among them, in deck order. A deck may give one line per node (temperatures mapped from
 * another analysis), so a rank keeps only its share, as it does of the mesh. */
static PetscErrorCode SubsetTargetLines(TslModel *s, void **lines, PetscInt *n, size_t size, PetscInt nn, const PetscInt nkeep[])
{
  char    *a = (char *)*lines;
  PetscInt k = 0;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < *n; i++) {
    const TslTarget *t    = (const TslTarget *)(a + i * size);
    PetscBool        keep = PETSC_FALSE;
    if (t->set[0]) {
      PetscInt set = TslModelFindNodeSet(s, t->set);
      keep         = (PetscBool)(set >= 0 && s->nsets[set].n > 0);
    } else {
      PetscInt loc;
      PetscCall(PetscFindInt(t->id, nn, nkeep, &loc));
      keep = (PetscBool)(loc >= 0);
    }
    if (keep) memmove(a + k++ * size, a + i * size, size);
  }
  if (k < *n) { /* rank 0 keeps its part: not the whole deck's list */
    void *kept = NULL;
    if (k) PetscCall(PetscMalloc(k * size, &kept));
    if (k) memcpy(kept, a, k * size);
    PetscCall(PetscFree(*lines));
    *lines = kept;
  }
  *n = k;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslModelSubset(const TslModel *model, PetscInt ne, const PetscInt elems[], PetscInt nn, const PetscInt nodes[], TslModel **sub)
{
  TslModel  meta = *model, *s;
  PetscInt *nkeep, *ekeep, k = 0;
  char     *buf;
  size_t    len;

  PetscFunctionBeginUser;
  /* Deep-copy everything but the mesh-dependent data through the packer, then add the filtered parts. */
  meta.nnode = meta.nelem = meta.nnset = meta.nelset = meta.nsurface = meta.nequation = 0;
  meta.node_id = meta.elem_id = meta.elem_type = meta.elem_ptr = meta.elem_conn = meta.elem_line = NULL;
  meta.node_xyz                                                                                  = NULL;
  meta.nsets = meta.elsets = NULL;
  meta.surfaces            = NULL;
  meta.equations           = NULL;
  meta.node_gnum = meta.node_nat = meta.elem_nat = NULL;
  PetscCall(TslModelPack(&meta, &buf, &len));
  PetscCall(TslModelUnpack(buf, len, &s));
  PetscCall(PetscFree(buf));

  PetscCall(SubsetMesh(model, ne, elems, nn, nodes, s));
  PetscCall(PetscMalloc1(nn, &nkeep));
  PetscCall(PetscMalloc1(ne, &ekeep));
  PetscCall(PetscArraycpy(nkeep, s->node_id, nn));
  PetscCall(PetscArraycpy(ekeep, s->elem_id, ne));
  PetscCall(PetscSortInt(nn, nkeep));
  PetscCall(PetscSortInt(ne, ekeep));

  s->nnset  = model->nnset;
  s->nelset = model->nelset;
  PetscCall(PetscCalloc1(model->nnset, &s->nsets));
  PetscCall(PetscCalloc1(model->nelset, &s->elsets));
  PetscCall(SubsetSets(model->nnset, model->nsets, s->nsets, nn, nkeep));
  PetscCall(SubsetSets(model->nelset, model->elsets, s->elsets, ne, ekeep));
  s->nsurface = model->nsurface;
  PetscCall(PetscCalloc1(model->nsurface, &s->surfaces));
  for (PetscInt i = 0; i < model->nsurface; i++) PetscCall(SubsetSurface(&model->surfaces[i], &s->surfaces[i], nn, nkeep, ne, ekeep));

  PetscCall(PetscCalloc1(model->nequation, &s->equations));
  for (PetscInt i = 0; i < model->nequation; i++) {
    const TslEquation *e    = &model->equations[i];
    PetscBool          keep = PETSC_FALSE;
    for (PetscInt j = 0; j < e->n && !keep; j++) {
      PetscInt loc;
      PetscCall(PetscFindInt(e->node[j], nn, nkeep, &loc));
      keep = loc >= 0 ? PETSC_TRUE : PETSC_FALSE;
    }
    if (keep) PetscCall(CopyEquation(e, &s->equations[k++]));
  }
  s->nequation = k;
  PetscCall(SubsetTargetLines(s, (void **)&s->init, &s->ninit, sizeof(TslInitialTemperature), nn, nkeep));
  PetscCall(SubsetTargetLines(s, (void **)&s->vinit, &s->nvinit, sizeof(TslInitialVelocity), nn, nkeep));
  PetscCall(PetscFree(nkeep));
  PetscCall(PetscFree(ekeep));
  PetscCall(TslModelIndex(s));
  *sub = s;
  PetscFunctionReturn(PETSC_SUCCESS);
}
