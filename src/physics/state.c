/* The problem's state for restart points (src/solve/restart.c): contact nodes, 3D main-surface normals, plastic
 * points and surface-to-surface points, packed as bytes in this rank's layout, and a digest of that layout. */
#include "contact_s2s_impl.h"

static void Put(char **at, const void *src, size_t n)
{
  if (n) memcpy(*at, src, n);
  *at += n;
}

static PetscErrorCode Take(const char **at, const char *end, void *dst, size_t n)
{
  PetscFunctionBeginUser;
  PetscCheck(*at + n <= end, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "the restart point's state of this rank is shorter than this model's");
  if (n) memcpy(dst, *at, n);
  *at += n;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Surface-to-surface pairs: the points, current and committed (their number varies with the cut), each face's share
 * of them and the accumulated slip */
static size_t S2SSize(TslProblem p)
{
  TslContactS2S s = p->s2s;
  if (!s) return 0;
  return 2 * sizeof(PetscInt) + 4 * (size_t)s->nface * sizeof(PetscInt) + (size_t)(s->npt + s->npt_c) * sizeof(S2SPoint) + 2 * (size_t)p->nn * sizeof(PetscReal);
}

static void S2SPack(TslProblem p, char **at)
{
  TslContactS2S s = p->s2s;
  if (!s) return;
  Put(at, &s->npt, sizeof(PetscInt));
  Put(at, &s->npt_c, sizeof(PetscInt));
  for (PetscInt i = 0; i < s->nface; i++) {
    const PetscInt f[4] = {s->face[i].first, s->face[i].npt, s->face[i].first_c, s->face[i].npt_c};
    Put(at, f, sizeof(f));
  }
  Put(at, s->pt, (size_t)s->npt * sizeof(S2SPoint));
  Put(at, s->pt_c, (size_t)s->npt_c * sizeof(S2SPoint));
  Put(at, s->cslip, (size_t)p->nn * sizeof(PetscReal));
  Put(at, s->cslip_c, (size_t)p->nn * sizeof(PetscReal));
}

static PetscErrorCode S2SUnpack(TslProblem p, const char **at, const char *end)
{
  TslContactS2S s = p->s2s;
  PetscInt      n[2];

  PetscFunctionBeginUser;
  if (!s) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(Take(at, end, n, sizeof(n)));
  PetscCheck(n[0] >= 0 && n[1] >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "the restart point's surface-to-surface state has negative counts");
  for (PetscInt i = 0; i < s->nface; i++) {
    PetscInt f[4];
    PetscCall(Take(at, end, f, sizeof(f)));
    PetscCheck(f[0] >= 0 && f[1] >= 0 && f[0] + f[1] <= n[0] && f[2] >= 0 && f[3] >= 0 && f[2] + f[3] <= n[1], PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
               "the restart point's surface-to-surface state has a face's points outside its list");
    s->face[i].first = f[0], s->face[i].npt = f[1], s->face[i].first_c = f[2], s->face[i].npt_c = f[3];
  }
  PetscCall(TslS2SReserve(&s->pt, &s->cap, n[0]));
  PetscCall(TslS2SReserve(&s->pt_c, &s->cap_c, n[1]));
  s->npt = n[0], s->npt_c = n[1];
  PetscCall(Take(at, end, s->pt, (size_t)n[0] * sizeof(S2SPoint)));
  PetscCall(Take(at, end, s->pt_c, (size_t)n[1] * sizeof(S2SPoint)));
  PetscCall(Take(at, end, s->cslip, (size_t)p->nn * sizeof(PetscReal)));
  PetscCall(Take(at, end, s->cslip_c, (size_t)p->nn * sizeof(PetscReal)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemStateSize(TslProblem p, size_t *bytes)
{
  size_t n = p->ncnode * sizeof(TslContactNode) + p->npstate * sizeof(PetscReal);

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < p->ncsurf; k++)
    if (p->csurf[k].nnormal) n += 3 * p->nn * sizeof(PetscReal);
  *bytes = n + S2SSize(p);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemStatePack(TslProblem p, void *buf)
{
  char *at = (char *)buf;

  PetscFunctionBeginUser;
  Put(&at, p->cnode, p->ncnode * sizeof(TslContactNode));
  for (PetscInt k = 0; k < p->ncsurf; k++)
    if (p->csurf[k].nnormal) Put(&at, p->csurf[k].nnormal, 3 * p->nn * sizeof(PetscReal));
  Put(&at, p->pstate, p->npstate * sizeof(PetscReal));
  S2SPack(p, &at);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemStateUnpack(TslProblem p, const void *buf, size_t nbytes)
{
  const char *at = (const char *)buf, *end = at + nbytes;

  PetscFunctionBeginUser;
  PetscCall(Take(&at, end, p->cnode, p->ncnode * sizeof(TslContactNode)));
  for (PetscInt k = 0; k < p->ncsurf; k++)
    if (p->csurf[k].nnormal) PetscCall(Take(&at, end, p->csurf[k].nnormal, 3 * p->nn * sizeof(PetscReal)));
  PetscCall(Take(&at, end, p->pstate, p->npstate * sizeof(PetscReal)));
  PetscCall(S2SUnpack(p, &at, end));
  if (p->npstate) PetscCall(PetscArraycpy(p->pstate_new, p->pstate, p->npstate));
  /* the current state as written, not rolled back to the committed one: an explicit increment searches the pairing
   * after its commit (TslProblemContactExplicitIncrement), and the next increment starts from the searched one */
  p->pattern_stale = PETSC_TRUE; /* the pairing is the point's, not the set-up's */
  PetscFunctionReturn(PETSC_SUCCESS);
}

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
