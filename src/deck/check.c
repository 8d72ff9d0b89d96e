/* TslModelCheck: the consistency checks that need the whole model. Each error names the deck line
 * that made the reference (a section, a load, an element...). */
#include "deck_impl.h"
#include <thermoslide/element.h>
#include <string.h>

#define CHECK(c, loc, fmt, ...)                                                                                        \
  PetscCheck(c, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, TSL_LOC_FMT fmt, TSL_LOC_ARGS(m, loc), __VA_ARGS__)

static TslLoc ElemLoc(const TslModel *m, PetscInt e) {
  TslLoc l = {-1, 0};
  if (m->elem_line) l.file = m->elem_line[2 * e], l.line = m->elem_line[2 * e + 1];
  return l;
}

static PetscInt Dim(const TslModel *m) {
  return m->dim ? m->dim : 3;
}

static PetscBool DofValid(const TslModel *m, PetscInt dof) {
  return ((dof >= 1 && dof <= Dim(m)) || dof == 11) ? PETSC_TRUE : PETSC_FALSE;
}

static PetscErrorCode CheckMesh(TslModel *m) {
  PetscFunctionBeginUser;
  for (PetscInt i = 1; i < m->nnode; i++) {
    TslLoc none = {0, 0};
    CHECK(m->index_node_id[i] != m->index_node_id[i - 1], none, "duplicate node id %" PetscInt_FMT,
          m->index_node_id[i]);
  }
  for (PetscInt i = 1; i < m->nelem; i++) {
    if (m->index_elem_id[i] == m->index_elem_id[i - 1]) {
      PetscInt a = PetscMin(m->index_elem_pos[i], m->index_elem_pos[i - 1]),
               b = PetscMax(m->index_elem_pos[i], m->index_elem_pos[i - 1]);
      char first[PETSC_MAX_PATH_LEN];
      CHECK(PETSC_FALSE, ElemLoc(m, b), "duplicate element id %" PetscInt_FMT " (first defined at %s)", m->elem_id[b],
            TslLocString(m, ElemLoc(m, a), first, sizeof(first)));
    }
  }
  for (PetscInt e = 0; e < m->nelem; e++) {
    const TslElementType *et = TslElementTypeGet(m->elem_type[e]);
    CHECK(et, ElemLoc(m, e), "element %" PetscInt_FMT " has no valid type", m->elem_id[e]);
    CHECK(m->elem_ptr[e + 1] - m->elem_ptr[e] == et->geom->nnode, ElemLoc(m, e),
          "element %" PetscInt_FMT " has %" PetscInt_FMT " nodes but type %s needs %" PetscInt_FMT, m->elem_id[e],
          m->elem_ptr[e + 1] - m->elem_ptr[e], et->name, et->geom->nnode);
    for (PetscInt j = m->elem_ptr[e]; j < m->elem_ptr[e + 1]; j++)
      CHECK(TslModelNodeIndex(m, m->elem_conn[j]) >= 0, ElemLoc(m, e),
            "element %" PetscInt_FMT " references undefined node %" PetscInt_FMT, m->elem_id[e], m->elem_conn[j]);
  }
  for (PetscInt s = 0; s < m->nnset; s++)
    for (PetscInt k = 0; k < m->nsets[s].n; k++)
      CHECK(TslModelNodeIndex(m, m->nsets[s].ids[k]) >= 0, m->nsets[s].loc,
            "node set %s contains undefined node %" PetscInt_FMT, m->nsets[s].name, m->nsets[s].ids[k]);
  for (PetscInt s = 0; s < m->nelset; s++)
    for (PetscInt k = 0; k < m->elsets[s].n; k++)
      CHECK(TslModelElementIndex(m, m->elsets[s].ids[k]) >= 0, m->elsets[s].loc,
            "element set %s contains undefined element %" PetscInt_FMT, m->elsets[s].name, m->elsets[s].ids[k]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Element e exists and has a face number face (0 = body, always valid). */
static PetscErrorCode CheckFace(TslModel *m, TslLoc loc, PetscInt id, PetscInt face) {
  PetscInt e = TslModelElementIndex(m, id);

  PetscFunctionBeginUser;
  CHECK(e >= 0, loc, "undefined element %" PetscInt_FMT, id);
  CHECK(face <= TslElementTypeGet(m->elem_type[e])->geom->nface, loc,
        "element %" PetscInt_FMT " (%s) has no face %" PetscInt_FMT, id, TslElementTypeGet(m->elem_type[e])->name,
        face);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckSurfaces(TslModel *m) {
  PetscFunctionBeginUser;
  for (PetscInt s = 0; s < m->nsurface; s++) {
    const TslSurface *sf = &m->surfaces[s];
    for (PetscInt k = 0; k < sf->n; k++) {
      if (sf->kind == TSL_SURFACE_ELEMENT)
        PetscCall(CheckFace(m, sf->loc, sf->elem[k], sf->face[k]));
      else
        CHECK(TslModelNodeIndex(m, sf->elem[k]) >= 0, sf->loc, "surface %s: undefined node %" PetscInt_FMT, sf->name,
              sf->elem[k]);
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckMaterial(TslModel *m, const TslMaterial *mat, const TslSection *sec) {
  char where[PETSC_MAX_PATH_LEN];

  PetscFunctionBeginUser;
  (void)TslLocString(m, sec->loc, where, sizeof(where));
  CHECK(mat->has_elastic, mat->loc, "material %s (used by the *SOLID SECTION at %s) has no *ELASTIC", mat->name, where);
  CHECK(mat->has_conductivity, mat->loc, "material %s (used by the *SOLID SECTION at %s) has no *CONDUCTIVITY",
        mat->name, where);
  CHECK(mat->has_density, mat->loc, "material %s (used by the *SOLID SECTION at %s) has no *DENSITY", mat->name, where);
  CHECK(mat->has_specific_heat, mat->loc, "material %s (used by the *SOLID SECTION at %s) has no *SPECIFIC HEAT",
        mat->name, where);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckMaterialsAndSections(TslModel *m) {
  PetscBool *covered;
  PetscInt bad = -1;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < m->nmaterial; i++) {
    const TslMaterial *mat = &m->materials[i];
    if (mat->has_elastic) {
      CHECK(mat->E > 0, mat->loc, "material %s: Young's modulus must be positive (got %g)", mat->name, (double)mat->E);
      CHECK(mat->nu > -1 && mat->nu < 0.5, mat->loc, "material %s: Poisson's ratio must lie in (-1, 0.5) (got %g)",
            mat->name, (double)mat->nu);
    }
    if (mat->has_conductivity)
      CHECK(mat->conductivity > 0, mat->loc, "material %s: conductivity must be positive (got %g)", mat->name,
            (double)mat->conductivity);
  }
  for (PetscInt s = 0; s < m->nsection; s++) {
    TslSection *sec = &m->sections[s];
    CHECK(TslModelFindElementSet(m, sec->elset) >= 0, sec->loc, "undefined element set %s", sec->elset);
    sec->material_index = TslModelFindMaterial(m, sec->material);
    CHECK(sec->material_index >= 0, sec->loc, "undefined material %s", sec->material);
    PetscCall(CheckMaterial(m, &m->materials[sec->material_index], sec));
  }
  PetscCall(PetscCalloc1(m->nelem, &covered));
  for (PetscInt s = 0; s < m->nsection; s++) {
    const TslSet *set = &m->elsets[TslModelFindElementSet(m, m->sections[s].elset)];
    for (PetscInt k = 0; k < set->n; k++) {
      PetscInt e = TslModelElementIndex(m, set->ids[k]);
      if (e >= 0) covered[e] = PETSC_TRUE;
    }
  }
  for (PetscInt e = 0; e < m->nelem && bad < 0; e++)
    if (!covered[e]) bad = e;
  PetscCall(PetscFree(covered));
  CHECK(bad < 0, ElemLoc(m, bad), "element %" PetscInt_FMT " is not in any *SOLID SECTION", m->elem_id[bad]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckNodeTarget(TslModel *m, const TslTarget *t, TslLoc loc) {
  PetscFunctionBeginUser;
  if (t->set[0])
    CHECK(TslModelFindNodeSet(m, t->set) >= 0, loc, "undefined node set %s", t->set);
  else
    CHECK(TslModelNodeIndex(m, t->id) >= 0, loc, "undefined node %" PetscInt_FMT, t->id);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckLoad(TslModel *m, const TslLoad *l) {
  PetscFunctionBeginUser;
  if (!l->target.set[0] && l->target.id < 0) PetscFunctionReturn(PETSC_SUCCESS); /* OP=NEW alone: only removes */
  CHECK(l->amplitude >= -1 && l->amplitude < m->namplitude, l->loc, "bad amplitude index %" PetscInt_FMT, l->amplitude);
  CHECK(l->film_amplitude >= -1 && l->film_amplitude < m->namplitude, l->loc, "bad amplitude index %" PetscInt_FMT,
        l->film_amplitude);
  switch (l->kind) {
  case TSL_LOAD_BOUNDARY:
  case TSL_LOAD_CLOAD:
  case TSL_LOAD_CFLUX:
    PetscCall(CheckNodeTarget(m, &l->target, l->loc));
    CHECK(DofValid(m, l->dof_first) && DofValid(m, l->dof_last), l->loc,
          "bad degree of freedom %" PetscInt_FMT " (valid: 1..%" PetscInt_FMT ", 11)",
          DofValid(m, l->dof_first) ? l->dof_last : l->dof_first, Dim(m));
    break;
  default:
    if (l->target_is_surface) {
      PetscInt s = TslModelFindSurface(m, l->target.set);
      CHECK(s >= 0, l->loc, "undefined surface %s", l->target.set);
      CHECK(m->surfaces[s].kind == TSL_SURFACE_ELEMENT, l->loc, "surface %s must be an element surface (TYPE=ELEMENT)",
            l->target.set);
    } else if (l->target.set[0]) {
      PetscInt s = TslModelFindElementSet(m, l->target.set);
      CHECK(s >= 0, l->loc, "undefined element set %s", l->target.set);
      for (PetscInt k = 0; k < m->elsets[s].n; k++) PetscCall(CheckFace(m, l->loc, m->elsets[s].ids[k], l->face));
    } else
      PetscCall(CheckFace(m, l->loc, l->target.id, l->face));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckSteps(TslModel *m) {
  PetscFunctionBeginUser;
  {
    TslLoc first = {0, 1};
    CHECK(m->nstep > 0, first, "the deck has no *STEP%s", "");
  }
  for (PetscInt i = 0; i < m->nstep; i++) {
    const TslStep *s = &m->steps[i];
    CHECK(s->coupled, s->loc, "step %s has no procedure (*COUPLED TEMPERATURE-DISPLACEMENT)", s->name);
    for (PetscInt k = 0; k < s->nload; k++) PetscCall(CheckLoad(m, &s->loads[k]));
    for (PetscInt k = 0; k < s->nout; k++) {
      const TslOutputRequest *r = &s->out[k];
      if (!r->set[0]) continue;
      if (r->node)
        CHECK(TslModelFindNodeSet(m, r->set) >= 0, r->loc, "undefined node set %s", r->set);
      else
        CHECK(TslModelFindElementSet(m, r->set) >= 0, r->loc, "undefined element set %s", r->set);
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslModelCheck(TslModel *m) {
  PetscFunctionBeginUser;
  PetscCall(TslModelIndex(m));
  PetscCall(CheckMesh(m));
  PetscCall(CheckSurfaces(m));
  PetscCall(CheckMaterialsAndSections(m));
  for (PetscInt i = 0; i < m->ninit; i++) PetscCall(CheckNodeTarget(m, &m->init[i].target, m->init[i].loc));
  for (PetscInt i = 0; i < m->nequation; i++) {
    const TslEquation *e = &m->equations[i];
    for (PetscInt k = 0; k < e->n; k++) {
      CHECK(TslModelNodeIndex(m, e->node[k]) >= 0, e->loc, "*EQUATION refers to undefined node %" PetscInt_FMT,
            e->node[k]);
      CHECK(DofValid(m, e->dof[k]), e->loc, "*EQUATION: bad degree of freedom %" PetscInt_FMT, e->dof[k]);
    }
  }
  for (PetscInt i = 0; i < m->namplitude; i++) {
    const TslAmplitude *a = &m->amplitudes[i];
    for (PetscInt k = 1; k < a->n; k++)
      CHECK(a->t[k] >= a->t[k - 1], a->loc, "amplitude %s: times must not decrease", a->name);
  }
  PetscCall(CheckSteps(m));
  PetscFunctionReturn(PETSC_SUCCESS);
}
