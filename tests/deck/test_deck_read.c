/* Reads tests/deck/data/full.inp (every supported keyword, an include with a nested include, continuation
 * lines, Fortran numbers) and checks the parsed model field by field; then a Pack/Unpack round trip and
 * TslModelSubset filtering. Exits non-zero on the first group with a failed check. */
#include <thermoslide/model.h>
#include <thermoslide/element.h>
#include <string.h>

#ifndef TSL_DECK_DATA
#error "TSL_DECK_DATA (the tests/deck/data directory) must be defined"
#endif

#include "expect.h"

static PetscBool EndsWith(const char *s, const char *tail)
{
  size_t n = strlen(s), m = strlen(tail);
  return (n >= m && !strcmp(s + n - m, tail)) ? PETSC_TRUE : PETSC_FALSE;
}

static PetscBool IdsAre(PetscInt n, const PetscInt *ids, PetscInt m, const PetscInt *want)
{
  if (n != m) return PETSC_FALSE;
  for (PetscInt i = 0; i < n; i++)
    if (ids[i] != want[i]) return PETSC_FALSE;
  return PETSC_TRUE;
}

static PetscBool SetIs(const TslModel *m, PetscBool node, const char *name, PetscInt n, const PetscInt *want)
{
  PetscInt      i = node ? TslModelFindNodeSet(m, name) : TslModelFindElementSet(m, name);
  const TslSet *s;
  if (i < 0) return PETSC_FALSE;
  s = node ? &m->nsets[i] : &m->elsets[i];
  return IdsAre(s->n, s->ids, n, want);
}

static PetscErrorCode TestMesh(const TslModel *m)
{
  const PetscInt all[] = {1, 2, 3, 4, 5, 6}, left[] = {1, 4, 6}, bottom[] = {1, 2, 3}, corners[] = {1, 3, 4, 6};
  const PetscInt eall[] = {1, 2}, e1[] = {1}, conn1[] = {1, 2, 5, 4}, conn2[] = {2, 3, 6, 5};

  PetscFunctionBeginUser;
  EXPECT(m->nfile == 3);
  EXPECT(EndsWith(m->files[0], "data/full.inp"));
  EXPECT(EndsWith(m->files[1], "data/inc/mesh.inp"));
  EXPECT(EndsWith(m->files[2], "data/inc/nodes2.inp"));
  EXPECT(!strcmp(m->heading, "Full deck, with commas, for the reader test"));
  EXPECT(m->dim == 2);
  EXPECT(IdsAre(m->nnode, m->node_id, 6, all));
  EXPECT(m->node_xyz[3 * 2] == 2.0 && m->node_xyz[3 * 2 + 1] == 0.0 && m->node_xyz[3 * 2 + 2] == 0.0);
  EXPECT(m->node_xyz[3 * 4] == 1.0 && m->node_xyz[3 * 4 + 1] == 1.0 && m->node_xyz[3 * 4 + 2] == 0.0); /* blank z, then a normal */
  EXPECT(m->node_xyz[3 * 4] == 1.0 && m->node_xyz[3 * 4 + 1] == 1.0);
  EXPECT(m->nelem == 2 && m->elem_id[0] == 1 && m->elem_id[1] == 2);
  EXPECT(m->elem_type[0] == TslElementTypeFind("CPE4T") && m->elem_type[1] == m->elem_type[0]);
  EXPECT(m->elem_ptr[0] == 0 && m->elem_ptr[1] == 4 && m->elem_ptr[2] == 8);
  EXPECT(IdsAre(4, m->elem_conn, 4, conn1)); /* continued over two lines */
  EXPECT(IdsAre(4, m->elem_conn + 4, 4, conn2));
  EXPECT(m->elem_line[0] == 1 && m->elem_line[1] == 9 && m->elem_line[2] == 1 && m->elem_line[3] == 11);
  EXPECT(TslModelNodeIndex(m, 5) == 4 && TslModelNodeIndex(m, 7) == -1);
  EXPECT(TslModelElementIndex(m, 2) == 1 && TslModelElementIndex(m, 3) == -1);

  EXPECT(m->nnset == 4 && m->nelset == 2);
  EXPECT(SetIs(m, PETSC_TRUE, "nall", 6, all));
  EXPECT(SetIs(m, PETSC_TRUE, "LEFT", 3, left)); /* appended by the second *NSET, NSET=left */
  EXPECT(SetIs(m, PETSC_TRUE, "BOTTOM", 3, bottom));
  EXPECT(!strcmp(m->nsets[TslModelFindNodeSet(m, "bottom")].name, "Bottom"));
  EXPECT(SetIs(m, PETSC_TRUE, "Corners", 4, corners)); /* nested name, sorted unique */
  EXPECT(SetIs(m, PETSC_FALSE, "EALL", 2, eall));
  EXPECT(SetIs(m, PETSC_FALSE, "E1", 1, e1));
  EXPECT(TslModelFindNodeSet(m, "NOPE") == -1);

  EXPECT(m->nsurface == 2);
  {
    const TslSurface *s = &m->surfaces[TslModelFindSurface(m, "top")];
    EXPECT(s->kind == TSL_SURFACE_ELEMENT && s->n == 2 && s->elem[0] == 1 && s->elem[1] == 2 && s->face[0] == 3 && s->face[1] == 3);
    s = &m->surfaces[TslModelFindSurface(m, "RIGHTN")];
    EXPECT(s->kind == TSL_SURFACE_NODE && s->n == 2 && s->elem[0] == 3 && s->elem[1] == 6 && !s->face);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestModelData(const TslModel *m)
{
  const TslMaterial  *mat;
  const TslAmplitude *a;

  PetscFunctionBeginUser;
  EXPECT(m->nmaterial == 1 && TslModelFindMaterial(m, "STEEL") == 0);
  mat = &m->materials[0];
  for (PetscInt k = 0; k < TSL_NPROP; k++) EXPECT(mat->prop[k].n == 1);
  EXPECT(NEAR(mat->prop[TSL_PROP_ELASTIC].value[0][0], 210e3) && NEAR(mat->prop[TSL_PROP_ELASTIC].value[0][1], 0.3));
  EXPECT(NEAR(mat->prop[TSL_PROP_CONDUCTIVITY].value[0][0], 50) && NEAR(mat->prop[TSL_PROP_DENSITY].value[0][0], 7.8e-9));
  EXPECT(NEAR(mat->prop[TSL_PROP_SPECIFIC_HEAT].value[0][0], 4.6e8) && NEAR(mat->prop[TSL_PROP_EXPANSION].value[0][0], 1.2e-5) &&
         NEAR(mat->alpha_zero, 20));
  EXPECT(mat->loc.file == 0 && mat->loc.line == 24);
  EXPECT(m->nsection == 1 && m->sections[0].material_index == 0 && NEAR(m->sections[0].thickness, 2.5));
  EXPECT(!strcmp(m->sections[0].elset, "EALL"));

  EXPECT(m->ninit == 2);
  EXPECT(!strcmp(m->init[0].target.set, "BOTTOM") && NEAR(m->init[0].value, 20));
  EXPECT(!m->init[1].target.set[0] && m->init[1].target.id == 5 && NEAR(m->init[1].value, 25));

  EXPECT(m->namplitude == 2);
  a = &m->amplitudes[TslModelFindAmplitude(m, "a1")];
  EXPECT(a->n == 5 && a->total_time && NEAR(a->t[4], 4));
  EXPECT(NEAR(TslAmplitudeEval(a, -1), 0) && NEAR(TslAmplitudeEval(a, 0.5), 0.5) && NEAR(TslAmplitudeEval(a, 1.5), 1));
  EXPECT(NEAR(TslAmplitudeEval(a, 2.5), 0.5) && NEAR(TslAmplitudeEval(a, 10), 0));
  { /* the integral (velocity boundary conditions) against a fine midpoint rule, tabular and smooth step */
    PetscReal    tt[2] = {0, 2}, aa[2] = {0, 3}, sum = 0, h = 11.0 / 200000;
    TslAmplitude sm = {.n = 2, .t = tt, .a = aa, .smooth = PETSC_TRUE};
    for (PetscInt k = 0; k < 200000; k++) sum += h * TslAmplitudeEval(a, -1 + (k + 0.5) * h);
    EXPECT(PetscAbsReal(TslAmplitudeIntegral(a, -1, 10) - sum) < 1e-8);
    sum = 0, h = 2.5 / 200000;
    for (PetscInt k = 0; k < 200000; k++) sum += h * TslAmplitudeEval(&sm, 0.5 + (k + 0.5) * h);
    EXPECT(PetscAbsReal(TslAmplitudeIntegral(&sm, 0.5, 3) - sum) < 1e-8 && NEAR(TslAmplitudeIntegral(&sm, 0, 2), 3));
  }
  a = &m->amplitudes[TslModelFindAmplitude(m, "SINK")];
  EXPECT(a->n == 1 && !a->total_time && NEAR(TslAmplitudeEval(a, 3), 1));

  EXPECT(m->has_absolute_zero && NEAR(m->absolute_zero, -273.15));
  EXPECT(m->has_stefan_boltzmann && NEAR(m->stefan_boltzmann, 5.669e-8));

  EXPECT(m->nequation == 2);
  {
    const TslEquation *e = &m->equations[0];
    EXPECT(e->n == 2 && e->node[0] == 5 && e->dof[0] == 2 && NEAR(e->coef[0], 1) && e->node[1] == 2 && NEAR(e->coef[1], -1) && !e->gdof);
    e = &m->equations[1]; /* triples continued over two lines */
    EXPECT(e->n == 3 && e->node[0] == 6 && e->node[1] == 4 && e->node[2] == 1 && e->dof[2] == 11 && NEAR(e->coef[2], -0.5));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscBool LoadIs(const TslLoad *l, TslLoadKind kind, const char *set, PetscInt id, PetscInt d0, PetscInt d1, PetscInt face, PetscReal value)
{
  if (l->kind != kind || l->dof_first != d0 || l->dof_last != d1 || l->face != face || !NEAR(l->value, value)) return PETSC_FALSE;
  if (set) return strcmp(l->target.set, set) ? PETSC_FALSE : PETSC_TRUE;
  return (!l->target.set[0] && l->target.id == id) ? PETSC_TRUE : PETSC_FALSE;
}

static PetscErrorCode TestSteps(const TslModel *m)
{
  const TslStep *s;
  const TslLoad *l;
  PetscInt       a1 = TslModelFindAmplitude(m, "A1"), sink = TslModelFindAmplitude(m, "SINK");

  PetscFunctionBeginUser;
  EXPECT(m->nstep == 3);
  s = &m->steps[0];
  EXPECT(!strcmp(s->name, "heat up") && s->max_inc == 50 && s->nlgeom && s->coupled && !s->steady && !s->direct);
  EXPECT(NEAR(s->deltmx, 5) && NEAR(s->dt0, 0.1) && NEAR(s->period, 10) && NEAR(s->dtmin, 1e-4) && NEAR(s->dtmax, 10));
  EXPECT(s->amp_default == TSL_AMP_STEP && !s->amp_given);
  EXPECT(s->nload == 14);
  l = s->loads;
  EXPECT(LoadIs(&l[0], TSL_LOAD_BOUNDARY, "LEFT", 0, 1, 2, 0, 0) && !l[0].op_new && l[0].amplitude == -1);
  EXPECT(LoadIs(&l[1], TSL_LOAD_BOUNDARY, "BOTTOM", 0, 2, 2, 0, 0.5));
  EXPECT(LoadIs(&l[2], TSL_LOAD_BOUNDARY, NULL, 1, 11, 11, 0, 100));
  EXPECT(LoadIs(&l[3], TSL_LOAD_BOUNDARY, "LEFT", 0, 1, 2, 0, 0) && l[3].op_new && l[3].amplitude == a1); /* ENCASTRE in 2D */
  EXPECT(LoadIs(&l[4], TSL_LOAD_BOUNDARY, NULL, 3, 1, 1, 0, 0) && l[4].op_new);                           /* XSYMM */
  EXPECT(LoadIs(&l[5], TSL_LOAD_CLOAD, NULL, 3, 2, 2, 0, -1000) && l[5].loc.line == 64);
  EXPECT(LoadIs(&l[6], TSL_LOAD_CFLUX, "CORNERS", 0, 11, 11, 0, 5));
  EXPECT(LoadIs(&l[7], TSL_LOAD_DLOAD, NULL, 1, 0, 0, 3, 10) && !l[7].target_is_surface);
  EXPECT(LoadIs(&l[8], TSL_LOAD_DLOAD, "TOP", 0, 0, 0, 0, 20) && l[8].target_is_surface);
  EXPECT(LoadIs(&l[9], TSL_LOAD_DFLUX, "EALL", 0, 0, 0, 0, 3) && !l[9].target_is_surface && l[9].amplitude == a1);
  EXPECT(LoadIs(&l[10], TSL_LOAD_DFLUX, NULL, 2, 0, 0, 2, 4));
  EXPECT(LoadIs(&l[11], TSL_LOAD_DFLUX, "TOP", 0, 0, 0, 0, 7) && l[11].target_is_surface && l[11].amplitude == -1);
  EXPECT(LoadIs(&l[12], TSL_LOAD_FILM, "E1", 0, 0, 0, 4, 15) && NEAR(l[12].sink, 20) && l[12].amplitude == sink && l[12].film_amplitude == a1);
  EXPECT(LoadIs(&l[13], TSL_LOAD_FILM, "TOP", 0, 0, 0, 0, 25) && NEAR(l[13].sink, 30) && l[13].target_is_surface && l[13].film_amplitude == -1);

  EXPECT(s->nout == 4);
  EXPECT(s->out[0].node && !s->out[0].print && !s->out[0].set[0] && s->out[0].nvar == 4 && s->out[0].frequency == 2);
  EXPECT(!strcmp(s->out[0].var[0], "U") && !strcmp(s->out[0].var[1], "NT") && !strcmp(s->out[0].var[3], "RFL"));
  EXPECT(!s->out[1].node && !strcmp(s->out[1].set, "EALL") && s->out[1].nvar == 3 && !strcmp(s->out[1].var[2], "HFL"));
  EXPECT(s->out[2].node && s->out[2].print && !strcmp(s->out[2].set, "LEFT") && s->out[2].frequency == 2);
  EXPECT(!s->out[3].node && s->out[3].print && s->out[3].frequency == 3);

  s = &m->steps[1];
  EXPECT(!strcmp(s->name, "Step-2") && s->steady && s->amp_given && s->amp_default == TSL_AMP_RAMP && s->max_inc == 100 && s->nlgeom && !s->nlgeom_given); /* NLGEOM inherited */
  EXPECT(NEAR(s->dt0, 1) && NEAR(s->period, 1) && NEAR(s->dtmin, 1e-5) && NEAR(s->dtmax, 1));
  EXPECT(s->nout == 2 && s->out[0].node && s->out[0].frequency == 1 && !s->out[1].node);
  s = &m->steps[2];
  EXPECT(s->steady && !s->amp_given && s->amp_default == TSL_AMP_RAMP);
  EXPECT(NEAR(s->dt0, 0.25) && NEAR(s->period, 2) && NEAR(s->dtmin, 2e-5) && NEAR(s->dtmax, 0.5));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Field-by-field equality of two models (pointers differ, contents must not). */
#define SAME(a, b, n) ((n) == 0 || (!(a) && !(b)) || ((a) && (b) && !memcmp((a), (b), (size_t)(n) * sizeof(*(a)))))
static PetscBool ModelsEqual(const TslModel *x, const TslModel *y)
{
  if (x->nfile != y->nfile || strcmp(x->heading, y->heading) || x->dim != y->dim || x->nnode != y->nnode || x->nelem != y->nelem) return PETSC_FALSE;
  for (PetscInt i = 0; i < x->nfile; i++)
    if (strcmp(x->files[i], y->files[i])) return PETSC_FALSE;
  if (!SAME(x->node_id, y->node_id, x->nnode) || !SAME(x->node_xyz, y->node_xyz, 3 * x->nnode)) return PETSC_FALSE;
  if (!SAME(x->elem_id, y->elem_id, x->nelem) || !SAME(x->elem_type, y->elem_type, x->nelem) || !SAME(x->elem_ptr, y->elem_ptr, x->nelem + 1))
    return PETSC_FALSE;
  if (!SAME(x->elem_conn, y->elem_conn, x->elem_ptr[x->nelem]) || !SAME(x->elem_line, y->elem_line, 2 * x->nelem)) return PETSC_FALSE;
  if (!!x->node_gnum != !!y->node_gnum || !SAME(x->node_gnum, y->node_gnum, x->nnode) || !SAME(x->node_nat, y->node_nat, x->nnode) ||
      !SAME(x->elem_nat, y->elem_nat, x->nelem))
    return PETSC_FALSE;
  if (x->nnset != y->nnset || x->nelset != y->nelset || x->nsurface != y->nsurface) return PETSC_FALSE;
  for (PetscInt i = 0; i < x->nnset; i++)
    if (strcmp(x->nsets[i].name, y->nsets[i].name) || x->nsets[i].n != y->nsets[i].n || !SAME(x->nsets[i].ids, y->nsets[i].ids, x->nsets[i].n))
      return PETSC_FALSE;
  for (PetscInt i = 0; i < x->nelset; i++)
    if (strcmp(x->elsets[i].name, y->elsets[i].name) || x->elsets[i].n != y->elsets[i].n || !SAME(x->elsets[i].ids, y->elsets[i].ids, x->elsets[i].n))
      return PETSC_FALSE;
  for (PetscInt i = 0; i < x->nsurface; i++) {
    const TslSurface *a = &x->surfaces[i], *b = &y->surfaces[i];
    if (strcmp(a->name, b->name) || a->kind != b->kind || a->n != b->n || !SAME(a->elem, b->elem, a->n) || !!a->face != !!b->face ||
        !SAME(a->face, b->face, a->n))
      return PETSC_FALSE;
  }
  if (x->nmaterial != y->nmaterial || !SAME(x->materials, y->materials, x->nmaterial)) return PETSC_FALSE;
  if (x->nsection != y->nsection || !SAME(x->sections, y->sections, x->nsection)) return PETSC_FALSE;
  if (x->ninit != y->ninit || !SAME(x->init, y->init, x->ninit)) return PETSC_FALSE;
  if (x->namplitude != y->namplitude) return PETSC_FALSE;
  for (PetscInt i = 0; i < x->namplitude; i++) {
    const TslAmplitude *a = &x->amplitudes[i], *b = &y->amplitudes[i];
    if (strcmp(a->name, b->name) || a->n != b->n || a->total_time != b->total_time || !SAME(a->t, b->t, a->n) || !SAME(a->a, b->a, a->n))
      return PETSC_FALSE;
  }
  if (x->nequation != y->nequation) return PETSC_FALSE;
  for (PetscInt i = 0; i < x->nequation; i++) {
    const TslEquation *a = &x->equations[i], *b = &y->equations[i];
    if (a->n != b->n || !SAME(a->node, b->node, a->n) || !SAME(a->dof, b->dof, a->n) || !SAME(a->coef, b->coef, a->n)) return PETSC_FALSE;
    if (!!a->gdof != !!b->gdof || !SAME(a->gdof, b->gdof, a->n) || a->loc.line != b->loc.line) return PETSC_FALSE;
  }
  if (x->has_absolute_zero != y->has_absolute_zero || x->absolute_zero != y->absolute_zero || x->stefan_boltzmann != y->stefan_boltzmann)
    return PETSC_FALSE;
  if (x->nnode_global != y->nnode_global || x->nelem_global != y->nelem_global || x->nnode_owned != y->nnode_owned) return PETSC_FALSE;
  if (x->nstep != y->nstep) return PETSC_FALSE;
  for (PetscInt i = 0; i < x->nstep; i++) {
    const TslStep *a = &x->steps[i], *b = &y->steps[i];
    if (strcmp(a->name, b->name) || a->coupled != b->coupled || a->steady != b->steady || a->dt0 != b->dt0 || a->period != b->period)
      return PETSC_FALSE;
    if (a->dtmin != b->dtmin || a->dtmax != b->dtmax || a->deltmx != b->deltmx || a->max_inc != b->max_inc || a->amp_default != b->amp_default)
      return PETSC_FALSE;
    if (a->nlgeom != b->nlgeom || a->direct != b->direct || a->amp_given != b->amp_given || a->loc.line != b->loc.line) return PETSC_FALSE;
    if (a->nload != b->nload || !SAME(a->loads, b->loads, a->nload) || a->nout != b->nout || !SAME(a->out, b->out, a->nout)) return PETSC_FALSE;
  }
  return PETSC_TRUE;
}

static PetscErrorCode TestPack(TslModel *m)
{
  char     *buf, *buf2;
  size_t    len, len2;
  TslModel *u;

  PetscFunctionBeginUser;
  PetscCall(TslModelPack(m, &buf, &len));
  PetscCall(TslModelUnpack(buf, len, &u));
  EXPECT(ModelsEqual(m, u));
  EXPECT(TslModelNodeIndex(u, 6) == 5 && TslModelElementIndex(u, 1) == 0);
  PetscCall(TslModelDestroy(&u));
  PetscCall(PetscFree(buf));

  /* the distributed arrays and equation gdof travel too when present */
  m->nnode_global = 6, m->nelem_global = 2, m->nnode_owned = 4;
  PetscCall(PetscMalloc1(m->nnode, &m->node_gnum));
  PetscCall(PetscMalloc1(m->nnode, &m->node_nat));
  PetscCall(PetscMalloc1(m->nelem, &m->elem_nat));
  for (PetscInt i = 0; i < m->nnode; i++) m->node_gnum[i] = 10 + i, m->node_nat[i] = 5 - i;
  for (PetscInt i = 0; i < m->nelem; i++) m->elem_nat[i] = 1 - i;
  PetscCall(PetscMalloc1(m->equations[1].n, &m->equations[1].gdof));
  for (PetscInt i = 0; i < m->equations[1].n; i++) m->equations[1].gdof[i] = 100 + i;
  PetscCall(TslModelPack(m, &buf, &len));
  PetscCall(TslModelUnpack(buf, len, &u));
  EXPECT(ModelsEqual(m, u));
  EXPECT(u->node_gnum && u->node_gnum[5] == 15 && u->elem_nat[1] == 0 && u->equations[1].gdof[2] == 102 && !u->equations[0].gdof);
  PetscCall(TslModelPack(u, &buf2, &len2));
  EXPECT(len2 == len);
  PetscCall(PetscFree(buf2));
  PetscCall(TslModelDestroy(&u));
  PetscCall(PetscFree(buf));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestSubset(const TslModel *m)
{
  const PetscInt elems[] = {1}, nodes[] = {5, 1, 2, 4}; /* element 2; nodes 6, 2, 3, 5 in that order */
  const PetscInt ids[] = {6, 2, 3, 5}, left[] = {6}, bottom[] = {2, 3}, corners[] = {3, 6}, eall[] = {2};
  TslModel      *s;

  PetscFunctionBeginUser;
  PetscCall(TslModelSubset(m, 1, elems, 4, nodes, &s));
  EXPECT(IdsAre(s->nnode, s->node_id, 4, ids));
  EXPECT(s->node_xyz[0] == 2.0 && s->node_xyz[1] == 1.0 && s->node_xyz[3] == 1.0 && s->node_xyz[4] == 0.0);
  EXPECT(s->nelem == 1 && s->elem_id[0] == 2 && s->elem_ptr[1] == 4 && s->elem_conn[2] == 6 && s->elem_line[1] == 11);
  EXPECT(s->node_gnum && s->node_gnum[0] == 15 && s->elem_nat[0] == 0);
  EXPECT(TslModelNodeIndex(s, 6) == 0 && TslModelNodeIndex(s, 1) == -1 && TslModelElementIndex(s, 2) == 0);
  EXPECT(s->nnset == 4 && SetIs(s, PETSC_TRUE, "LEFT", 1, left) && SetIs(s, PETSC_TRUE, "BOTTOM", 2, bottom) &&
         SetIs(s, PETSC_TRUE, "CORNERS", 2, corners));
  EXPECT(s->nelset == 2 && SetIs(s, PETSC_FALSE, "EALL", 1, eall) && SetIs(s, PETSC_FALSE, "E1", 0, NULL));
  {
    const TslSurface *t = &s->surfaces[TslModelFindSurface(s, "TOP")], *r = &s->surfaces[TslModelFindSurface(s, "RIGHTN")];
    EXPECT(t->n == 1 && t->elem[0] == 2 && t->face[0] == 3);
    EXPECT(r->n == 2 && r->elem[0] == 3 && r->elem[1] == 6 && !r->face);
  }
  EXPECT(s->nequation == 2 && s->equations[1].gdof && s->equations[1].gdof[0] == 100);
  /* non-mesh data whole */
  EXPECT(s->nmaterial == 1 && s->nstep == 3 && s->steps[0].nload == 14 && s->namplitude == 2 && s->ninit == 2 && s->nfile == 3);
  EXPECT(!strcmp(s->steps[0].name, "heat up") && s->amplitudes[0].n == 5 && !strcmp(s->heading, m->heading));
  PetscCall(TslModelDestroy(&s));

  /* a single node that no equation touches: both equations go, sets empty out but keep their names */
  {
    const PetscInt one[] = {2}; /* node 3 */
    PetscCall(TslModelSubset(m, 0, NULL, 1, one, &s));
    EXPECT(s->nnode == 1 && s->node_id[0] == 3 && s->nelem == 0 && s->nequation == 0);
    EXPECT(SetIs(s, PETSC_TRUE, "LEFT", 0, NULL) && s->surfaces[0].n == 0 && s->surfaces[1].n == 1);
    PetscCall(TslModelDestroy(&s));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  TslModel *m;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(TslDeckRead(TSL_DECK_DATA "/full.inp", &m));
  PetscCall(TestMesh(m));
  PetscCall(TestModelData(m));
  PetscCall(TestSteps(m));
  PetscCall(TestPack(m));
  PetscCall(TestSubset(m));
  PetscCall(TslModelDestroy(&m));
  EXPECT(m == NULL);
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "%s: %d failed check(s)\n", nfail ? "FAILED" : "PASSED", nfail));
  PetscCall(PetscFinalize());
  return nfail ? 1 : 0;
}
