/* TslModelCheck: the consistency checks that need the whole model. Each error names the deck line
 * that made the reference (a section, a load, an element...). */
#include "deck_impl.h"
#include <thermoslide/element.h>
#include <thermoslide/material.h>
#include <string.h>

#define CHECK(c, loc, fmt, ...) PetscCheck(c, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, TSL_LOC_FMT fmt, TSL_LOC_ARGS(m, loc), __VA_ARGS__)

static TslLoc ElemLoc(const TslModel *m, PetscInt e)
{
  TslLoc l = {-1, 0};
  if (m->elem_line) l.file = m->elem_line[2 * e], l.line = m->elem_line[2 * e + 1];
  return l;
}

static PetscInt Dim(const TslModel *m)
{
  return m->dim ? m->dim : 3;
}

/* A dof the model's elements carry (every row of a model carries the same ones). */
static PetscBool DofValid(const TslModel *m, PetscInt dof)
{
  if (m->nelem > 0 && m->elem_type[0] >= 0) return TslElementTypeHasDof(TslElementTypeGet(m->elem_type[0]), dof);
  return ((dof >= 1 && dof <= Dim(m)) || dof == 11) ? PETSC_TRUE : PETSC_FALSE;
}

static const char *DofList(const TslModel *m, char *buf, size_t len)
{
  if (m->nelem > 0 && m->elem_type[0] >= 0) return TslElementTypeDofList(TslElementTypeGet(m->elem_type[0]), buf, len);
  return "1..3, 11";
}

/* The element's edges as (corner, corner, midside or -1) in element-local positions, from its faces (in 2D the
 * faces are the edges; in 3D each face's corner cycle, its midside nodes following the corners). Returns their
 * number (an edge shared by two faces is listed twice). */
static PetscInt FamilyEdges(const TslGeometry *g, PetscInt edge[][3])
{
  PetscInt ne = 0;

  for (PetscInt f = 0; f < g->nface; f++) {
    const TslGeometry *fg = g->face_geom[f];
    const PetscInt    *v  = g->face_node[f];
    if (g->dim == 2) {
      edge[ne][0] = v[0], edge[ne][1] = v[1], edge[ne][2] = g->face_nnode[f] > 2 ? v[2] : -1, ne++;
      continue;
    }
    for (PetscInt k = 0; k < fg->ncorner; k++)
      edge[ne][0] = v[k], edge[ne][1] = v[(k + 1) % fg->ncorner], edge[ne][2] = fg->nnode > fg->ncorner ? v[fg->ncorner + k] : -1, ne++;
  }
  return ne;
}

/* Collapsed elements as Abaqus/CAE writes them: a node id given at several positions of a quadrilateral or a
 * brick (CPE4T 1, 2, 3, 3: a triangle at a sweep's axis; C3D8T with 3 = 4 and 7 = 8: a wedge). They are
 * integrated as they are (docs/elements.md, "Collapsed elements"): the positions of one id must be the corners
 * of edges of the element joined to one another (never a diagonal), with the midside node of such an edge among
 * them, and the element must keep a positive Jacobian at every integration point (no zero volume). Two different
 * node ids at the same place are refused: closer than 1e-10 of the element's size, which no mesh means (the
 * Jacobian is singular at that corner, yet the Gauss points may not see it). Needs the node index and every node
 * defined. */
static PetscErrorCode CheckCollapsed(TslModel *m, PetscInt e)
{
  const TslElementType *t        = TslElementTypeGet(m->elem_type[e]);
  const TslGeometry    *g        = t->geom;
  const PetscInt       *conn     = &m->elem_conn[m->elem_ptr[e]];
  PetscInt              n        = m->elem_ptr[e + 1] - m->elem_ptr[e], idx[27], edge[24][3], ne;
  PetscReal             size     = 0;
  PetscBool             repeated = PETSC_FALSE;

  PetscFunctionBeginUser;
  if (n > 27) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt a = 0; a < n; a++) {
    idx[a] = TslModelNodeIndex(m, conn[a]);
    if (idx[a] < 0) PetscFunctionReturn(PETSC_SUCCESS); /* reported as an undefined node */
  }
  for (PetscInt a = 0; a < n; a++)
    for (PetscInt c = 0; c < 3; c++) size = PetscMax(size, PetscAbsReal(m->node_xyz[3 * idx[a] + c] - m->node_xyz[3 * idx[0] + c]));
  for (PetscInt a = 0; a < n; a++)
    for (PetscInt b = a + 1; b < n; b++) {
      PetscReal dist = 0;
      if (conn[a] == conn[b]) {
        repeated = PETSC_TRUE;
        continue;
      }
      for (PetscInt c = 0; c < 3; c++) dist = PetscMax(dist, PetscAbsReal(m->node_xyz[3 * idx[a] + c] - m->node_xyz[3 * idx[b] + c]));
      CHECK(dist > 1e-10 * size, ElemLoc(m, e),
            "element %" PetscInt_FMT ": nodes %" PetscInt_FMT " and %" PetscInt_FMT
            " are at the same place (a collapsed element repeats one node id; "
            "two ids at one place are not supported)",
            m->elem_id[e], conn[a], conn[b]);
    }
  if (!repeated) PetscFunctionReturn(PETSC_SUCCESS);
  CHECK(n <= g->nnode + t->nextra && n >= g->nnode, ElemLoc(m, e), "element %" PetscInt_FMT " has %" PetscInt_FMT " nodes", m->elem_id[e], n);
  ne = FamilyEdges(g, edge);
  for (PetscInt a = 0; a < g->nnode; a++) {
    PetscInt  group[27], ng = 0, reached[27], nr = 1, pair[2] = {-1, -1};
    PetscBool grew = PETSC_TRUE, ok = PETSC_TRUE;
    for (PetscInt b = 0; b < g->nnode; b++)
      if (conn[b] == conn[a]) group[ng++] = b;
    if (ng < 2 || group[0] != a) continue; /* each id once, from its first position */
    if (a >= g->ncorner) {
      /* midside nodes only: those of edges that collapse onto one another (a brick's 19 = 20 when 3 = 4 and
       * 7 = 8), each edge's corners the same two ids */
      for (PetscInt i = 0; i < ng; i++) {
        PetscInt k = 0;
        while (k < ne && edge[k][2] != group[i]) k++;
        if (k == ne)
          ok = PETSC_FALSE;
        else {
          const PetscInt p = conn[edge[k][0]], q = conn[edge[k][1]];
          if (i == 0)
            pair[0] = PetscMin(p, q), pair[1] = PetscMax(p, q);
          else if (pair[0] != PetscMin(p, q) || pair[1] != PetscMax(p, q))
            ok = PETSC_FALSE;
        }
      }
      CHECK(ok && pair[0] != pair[1], ElemLoc(m, e),
            "element %" PetscInt_FMT " repeats node %" PetscInt_FMT " at midside positions whose edges do not collapse onto one another",
            m->elem_id[e], conn[a]);
      continue;
    }
    /* corners: those reached from the first one along edges inside the group; a midside node must be the midside
     * of such an edge, and such an edge's midside must be in the group */
    reached[0] = a;
    while (grew) {
      grew = PETSC_FALSE;
      for (PetscInt k = 0; k < ne; k++)
        for (PetscInt s = 0; s < 2; s++) {
          const PetscInt p = edge[k][s], q = edge[k][1 - s];
          PetscBool      hasp = PETSC_FALSE, hasq = PETSC_FALSE;
          for (PetscInt r = 0; r < nr; r++) hasp = (PetscBool)(hasp || reached[r] == p), hasq = (PetscBool)(hasq || reached[r] == q);
          if (hasp && !hasq && conn[q] == conn[a]) reached[nr++] = q, grew = PETSC_TRUE;
        }
    }
    for (PetscInt k = 0; k < ne; k++) {
      const PetscInt mid   = edge[k][2];
      PetscBool      known = PETSC_FALSE;
      if (conn[edge[k][0]] != conn[a] || conn[edge[k][1]] != conn[a] || mid < 0) continue;
      CHECK(conn[mid] == conn[a], ElemLoc(m, e),
            "element %" PetscInt_FMT " repeats node %" PetscInt_FMT " at the ends of an edge whose midside node %" PetscInt_FMT
            " is another (a collapsed %s edge takes one id for all three nodes)",
            m->elem_id[e], conn[a], conn[mid], t->name);
      for (PetscInt r = 0; r < nr; r++) known = (PetscBool)(known || reached[r] == mid);
      if (!known) reached[nr++] = mid;
    }
    for (PetscInt i = 0; i < ng; i++) {
      PetscBool found = PETSC_FALSE;
      for (PetscInt r = 0; r < nr; r++) found = (PetscBool)(found || reached[r] == group[i]);
      CHECK(found, ElemLoc(m, e),
            "element %" PetscInt_FMT " repeats node %" PetscInt_FMT " at positions %" PetscInt_FMT " and %" PetscInt_FMT
            ", which no edge of a %s joins (a collapsed element repeats a node along its edges only)",
            m->elem_id[e], conn[a], a + 1, group[i] + 1, t->name);
    }
  }
  {
    PetscReal         x[3 * TSL_MAX_ELEM_NODES] = {0};
    TslElementSection sec                       = {0};
    TslElementInput   in;
    for (PetscInt a = 0; a < n; a++)
      for (PetscInt c = 0; c < 3; c++) x[3 * a + c] = m->node_xyz[3 * idx[a] + c];
    in = (TslElementInput){.type = t, .sec = &sec, .x = x};
    CHECK(TslElementValid(&in), ElemLoc(m, e),
          "element %" PetscInt_FMT " (%s) repeats a node and collapses to no volume, or is inverted, at an integration point", m->elem_id[e],
          t->name);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One kinematics per body, one set of nodal unknowns per model: elements that share a node must have the
 * same kinematics (a plane-stress element glued to a plane-strain one, or an axisymmetric one to a planar
 * one, has no meaning), and every element must carry the same unknowns per node (the dof layout is the
 * rows'). The first element that breaks either rule is named with the element it conflicts with. */
static PetscErrorCode CheckKinematics(TslModel *m)
{
  PetscInt *first;

  PetscFunctionBeginUser;
  if (m->nelem == 0) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscMalloc1(m->nnode, &first));
  for (PetscInt i = 0; i < m->nnode; i++) first[i] = -1;
  for (PetscInt e = 0; e < m->nelem; e++) {
    const TslElementType *a = TslElementTypeGet(m->elem_type[e]), *t0 = TslElementTypeGet(m->elem_type[0]);
    char                  where[PETSC_MAX_PATH_LEN];
    PetscBool             same = TslElementTypeSameModel(a, t0);
    if (!same) PetscCall(PetscFree(first));
    CHECK(same, ElemLoc(m, e), "element %" PetscInt_FMT " (%s, %s) cannot be in one model with element %" PetscInt_FMT " (%s, %s) at %s", m->elem_id[e], a->name,
          TslElementTypeKinematicsName(a), m->elem_id[0], t0->name, TslElementTypeKinematicsName(t0), TslLocString(m, ElemLoc(m, 0), where, sizeof(where)));
    for (PetscInt j = m->elem_ptr[e]; j < m->elem_ptr[e + 1]; j++) {
      PetscInt              n = TslModelNodeIndex(m, m->elem_conn[j]);
      const TslElementType *b;
      if (n < 0) continue;
      if (first[n] < 0) {
        first[n] = e;
        continue;
      }
      b = TslElementTypeGet(m->elem_type[first[n]]);
      if (TslElementTypeSameKinematics(a, b)) continue;
      {
        PetscInt other = first[n];
        PetscCall(PetscFree(first));
        CHECK(PETSC_FALSE, ElemLoc(m, e),
              "element %" PetscInt_FMT " (%s, %s) shares node %" PetscInt_FMT " with element %" PetscInt_FMT " (%s, %s) at %s: one body, one kinematics",
              m->elem_id[e], a->name, TslElementTypeKinematicsName(a), m->elem_conn[j], m->elem_id[other], b->name, TslElementTypeKinematicsName(b),
              TslLocString(m, ElemLoc(m, other), where, sizeof(where)));
      }
    }
  }
  PetscCall(PetscFree(first));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckMesh(TslModel *m)
{
  PetscFunctionBeginUser;
  for (PetscInt i = 1; i < m->nnode; i++) {
    TslLoc none = {0, 0};
    CHECK(m->index_node_id[i] != m->index_node_id[i - 1], none, "duplicate node id %" PetscInt_FMT, m->index_node_id[i]);
  }
  for (PetscInt i = 1; i < m->nelem; i++) {
    if (m->index_elem_id[i] == m->index_elem_id[i - 1]) {
      PetscInt a = PetscMin(m->index_elem_pos[i], m->index_elem_pos[i - 1]), b = PetscMax(m->index_elem_pos[i], m->index_elem_pos[i - 1]);
      char     first[PETSC_MAX_PATH_LEN];
      CHECK(PETSC_FALSE, ElemLoc(m, b), "duplicate element id %" PetscInt_FMT " (first defined at %s)", m->elem_id[b],
            TslLocString(m, ElemLoc(m, a), first, sizeof(first)));
    }
  }
  for (PetscInt e = 0; e < m->nelem; e++) {
    const TslElementType *et = TslElementTypeGet(m->elem_type[e]);
    CHECK(et, ElemLoc(m, e), "element %" PetscInt_FMT " has no valid type", m->elem_id[e]);
    CHECK(m->elem_ptr[e + 1] - m->elem_ptr[e] == et->geom->nnode || m->elem_ptr[e + 1] - m->elem_ptr[e] == TslElementTypeNodes(et), ElemLoc(m, e),
          "element %" PetscInt_FMT " has %" PetscInt_FMT " nodes but type %s needs %" PetscInt_FMT, m->elem_id[e],
          m->elem_ptr[e + 1] - m->elem_ptr[e], et->name, et->geom->nnode);
    for (PetscInt j = m->elem_ptr[e]; j < m->elem_ptr[e + 1]; j++)
      CHECK(TslModelNodeIndex(m, m->elem_conn[j]) >= 0, ElemLoc(m, e), "element %" PetscInt_FMT " references undefined node %" PetscInt_FMT,
            m->elem_id[e], m->elem_conn[j]);
  }
  for (PetscInt e = 0; e < m->nelem; e++) PetscCall(CheckCollapsed(m, e));
  PetscCall(CheckKinematics(m));
  for (PetscInt s = 0; s < m->nnset; s++)
    for (PetscInt k = 0; k < m->nsets[s].n; k++)
      CHECK(TslModelNodeIndex(m, m->nsets[s].ids[k]) >= 0, m->nsets[s].loc, "node set %s contains undefined node %" PetscInt_FMT, m->nsets[s].name,
            m->nsets[s].ids[k]);
  for (PetscInt s = 0; s < m->nelset; s++)
    for (PetscInt k = 0; k < m->elsets[s].n; k++)
      CHECK(TslModelElementIndex(m, m->elsets[s].ids[k]) >= 0, m->elsets[s].loc, "element set %s contains undefined element %" PetscInt_FMT,
            m->elsets[s].name, m->elsets[s].ids[k]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Element e exists and has a face number face (0 = body, always valid). */
static PetscErrorCode CheckFace(TslModel *m, TslLoc loc, PetscInt id, PetscInt face)
{
  PetscInt e = TslModelElementIndex(m, id);

  PetscFunctionBeginUser;
  CHECK(e >= 0, loc, "undefined element %" PetscInt_FMT, id);
  CHECK(face <= TslElementTypeGet(m->elem_type[e])->geom->nface, loc, "element %" PetscInt_FMT " (%s) has no face %" PetscInt_FMT, id,
        TslElementTypeGet(m->elem_type[e])->name, face);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A surface's face of a collapsed element must keep an area (a length in 2D): the face a collapse flattens onto an
 * edge or a point (a C3D8T's S5 when 3 = 4 and 7 = 8) has no normal for contact to take. Loads on such a face
 * integrate to zero and need no check. */
static PetscErrorCode CheckFaceArea(TslModel *m, const TslSurface *sf, PetscInt id, PetscInt face)
{
  const PetscInt        e  = TslModelElementIndex(m, id);
  const TslElementType *t  = TslElementTypeGet(m->elem_type[e]);
  const TslGeometry    *g  = t->geom;
  const PetscInt        nc = g->face_geom[face - 1]->ncorner, *conn = &m->elem_conn[m->elem_ptr[e]];
  PetscInt              distinct = 0;

  PetscFunctionBeginUser;
  for (PetscInt a = 0; a < nc; a++) {
    PetscBool seen = PETSC_FALSE;
    for (PetscInt b = 0; b < a; b++) seen = (PetscBool)(seen || conn[g->face_node[face - 1][a]] == conn[g->face_node[face - 1][b]]);
    if (!seen) distinct++;
  }
  CHECK(distinct >= g->dim, sf->loc,
        "surface %s: face S%" PetscInt_FMT " of element %" PetscInt_FMT " (%s) is collapsed onto %s (its corners repeat a node): it has no %s",
        sf->name, face, id, t->name, distinct == 1 ? "a point" : "an edge", g->dim == 2 ? "length" : "area");
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckSurfaces(TslModel *m)
{
  PetscFunctionBeginUser;
  for (PetscInt s = 0; s < m->nsurface; s++) {
    const TslSurface *sf = &m->surfaces[s];
    for (PetscInt k = 0; k < sf->n; k++) {
      if (sf->kind == TSL_SURFACE_ELEMENT) {
        PetscCall(CheckFace(m, sf->loc, sf->elem[k], sf->face[k]));
        if (sf->face[k] >= 1 && sf->face[k] <= TslElementTypeGet(m->elem_type[TslModelElementIndex(m, sf->elem[k])])->geom->nface)
          PetscCall(CheckFaceArea(m, sf, sf->elem[k], sf->face[k]));
      } else
        CHECK(TslModelNodeIndex(m, sf->elem[k]) >= 0, sf->loc, "surface %s: undefined node %" PetscInt_FMT, sf->name, sf->elem[k]);
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* What the steps need of a material: the elasticity unless every step is *HEAT TRANSFER, the conductivity where some
 * step transfers heat (any but *STATIC, which holds the temperatures), the density and specific heat where some step
 * is transient (capacity, mass). A
 * property a model does not need may be left out: it evaluates to 0 (CalculiX's mechanical decks give none). */
static PetscErrorCode CheckMaterial(TslModel *m, const TslMaterial *mat, const TslSection *sec, PetscBool heat, PetscBool transient)
{
  char      where[PETSC_MAX_PATH_LEN];
  PetscBool mech = (PetscBool)!(m->nstep && m->steps[0].heat); /* a heat-transfer model has no stress (DeckHeatTransferModel) */

  PetscFunctionBeginUser;
  (void)TslLocString(m, sec->loc, where, sizeof(where));
  CHECK(!mech || mat->prop[TSL_PROP_ELASTIC].n, mat->loc, "material %s (used by the *SOLID SECTION at %s) has no *ELASTIC", mat->name, where);
  CHECK(!heat || mat->prop[TSL_PROP_CONDUCTIVITY].n, mat->loc, "material %s (used by the *SOLID SECTION at %s) has no *CONDUCTIVITY", mat->name,
        where);
  CHECK(!transient || mat->prop[TSL_PROP_DENSITY].n, mat->loc, "material %s (used by the *SOLID SECTION at %s) has no *DENSITY", mat->name, where);
  CHECK(!transient || mat->prop[TSL_PROP_SPECIFIC_HEAT].n, mat->loc, "material %s (used by the *SOLID SECTION at %s) has no *SPECIFIC HEAT",
        mat->name, where);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckMaterialsAndSections(TslModel *m)
{
  PetscBool *covered, heat = PETSC_FALSE, transient = PETSC_FALSE;
  PetscInt   bad = -1;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < m->nstep; i++) { /* what the steps need of the materials (CheckMaterial) */
    heat      = (PetscBool)(heat || !m->steps[i].statik);
    transient = (PetscBool)(transient || !m->steps[i].steady);
  }
  /* the property values are range-checked where they are read (deck.c, the Properties table) */
  for (PetscInt s = 0; s < m->nsection; s++) {
    TslSection *sec = &m->sections[s];
    CHECK(TslModelFindElementSet(m, sec->elset) >= 0, sec->loc, "undefined element set %s", sec->elset);
    sec->material_index = TslModelFindMaterial(m, sec->material);
    CHECK(sec->material_index >= 0, sec->loc, "undefined material %s", sec->material);
    PetscCall(CheckMaterial(m, &m->materials[sec->material_index], sec, heat, transient));
  }
  PetscCall(PetscCalloc1(m->nelem, &covered));
  for (PetscInt s = 0; s < m->nsection; s++) {
    const TslSection *sec = &m->sections[s];
    const TslSet     *set = &m->elsets[TslModelFindElementSet(m, sec->elset)];
    const char       *kw  = sec->shell ? "SHELL SECTION" : "SOLID SECTION";
    for (PetscInt k = 0; k < set->n; k++) {
      PetscInt              e = TslModelElementIndex(m, set->ids[k]);
      const TslElementType *t = e >= 0 ? TslElementTypeGet(m->elem_type[e]) : NULL;
      if (e < 0) continue;
      covered[e] = PETSC_TRUE;
      const PetscBool same_kw = strcmp(TslElementTypeSectionKeyword(t), kw) ? PETSC_FALSE : PETSC_TRUE;
      const PetscBool stack   = !sec->shell || TslElementTypeStackAllowed(t, sec->shell_stack - 1);
      const char     *why     = NULL;
      if (TslMaterialIsPlastic(&m->materials[sec->material_index]) && !TslElementTypePlasticSupported(t, &why)) {
        PetscCall(PetscFree(covered));
        CHECK(PETSC_FALSE, sec->loc, "material %s has *PLASTIC, and element %" PetscInt_FMT " of type %s has no plasticity yet (%s)", sec->material,
              m->elem_id[e], t->name, why);
      }
      if (same_kw && stack) continue;
      PetscCall(PetscFree(covered));
      CHECK(same_kw, sec->loc, "*%s on element %" PetscInt_FMT " of type %s (%s): its section is *%s", kw, m->elem_id[e], t->name,
            TslElementTypeKinematicsName(t), TslElementTypeSectionKeyword(t));
      CHECK(stack, sec->loc, "STACK DIRECTION=%d is not possible for element %" PetscInt_FMT " of type %s: it stacks along its third direction only",
            (int)sec->shell_stack, m->elem_id[e], t->name);
    }
  }
  for (PetscInt e = 0; e < m->nelem && bad < 0; e++)
    if (!covered[e]) bad = e;
  PetscCall(PetscFree(covered));
  CHECK(bad < 0, ElemLoc(m, bad), "element %" PetscInt_FMT " is not in any section (*SOLID SECTION or *SHELL SECTION)", m->elem_id[bad]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckNodeTarget(TslModel *m, const TslTarget *t, TslLoc loc)
{
  PetscFunctionBeginUser;
  if (t->set[0])
    CHECK(TslModelFindNodeSet(m, t->set) >= 0, loc, "undefined node set %s", t->set);
  else
    CHECK(TslModelNodeIndex(m, t->id) >= 0, loc, "undefined node %" PetscInt_FMT, t->id);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Initial velocities: a defined node or node set and a displacement dof the model's elements carry; a node
 * given alone must belong to an element (a node of none has no unknowns, so its velocity would silently be
 * nothing). Members of a set that belong to no element are passed over, as loads pass them. When no step is
 * explicit the velocities are never used: a warning (once) says so. */
static PetscErrorCode CheckInitialVelocities(TslModel *m)
{
  char     *used         = NULL;
  PetscBool any_explicit = PETSC_FALSE;

  PetscFunctionBeginUser;
  if (!m->nvinit) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscCalloc1(m->nnode, &used));
  for (PetscInt k = 0; m->elem_ptr && k < m->elem_ptr[m->nelem]; k++) {
    PetscInt p = TslModelNodeIndex(m, m->elem_conn[k]);
    if (p >= 0) used[p] = 1;
  }
  for (PetscInt i = 0; i < m->nvinit; i++) {
    const TslInitialVelocity *iv = &m->vinit[i];
    PetscErrorCode            ierr;
    char                      buf[64];
    PetscBool                 dof_ok = DofValid(m, iv->dof), node_ok = PETSC_TRUE;
    ierr = CheckNodeTarget(m, &iv->target, iv->loc);
    if (!ierr && !iv->target.set[0]) node_ok = (PetscBool)used[TslModelNodeIndex(m, iv->target.id)];
    if (ierr || !dof_ok || !node_ok) PetscCall(PetscFree(used));
    PetscCall(ierr);
    CHECK(dof_ok, iv->loc, "*INITIAL CONDITIONS, TYPE=VELOCITY: the model's %s elements have no dof %" PetscInt_FMT " (their dofs: %s)",
          m->nelem > 0 ? TslElementTypeGet(m->elem_type[0])->name : "", iv->dof, DofList(m, buf, sizeof(buf)));
    CHECK(node_ok, iv->loc, "*INITIAL CONDITIONS, TYPE=VELOCITY: node %" PetscInt_FMT " belongs to no element, so it has no dof %" PetscInt_FMT,
          iv->target.id, iv->dof);
  }
  PetscCall(PetscFree(used));
  for (PetscInt i = 0; i < m->nstep; i++) any_explicit = (PetscBool)(any_explicit || m->steps[i].explicit_dynamics);
  if (!any_explicit)
    PetscCall(PetscPrintf(
        PETSC_COMM_SELF,
        TSL_LOC_FMT "warning: *INITIAL CONDITIONS, TYPE=VELOCITY is ignored: no step is explicit (*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT), "
                    "and implicit steps are static\n",
        TSL_LOC_ARGS(m, m->vinit[0].loc)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A body force (*DLOAD GRAV, CENTRIF) is rho times an acceleration, so the materials of its elements ids[n]
 * (sorted) need a *DENSITY (a model without transient steps may leave it out, and it would be 0): each section
 * whose material has none is met with the ids in one merge of the two sorted lists. */
static PetscErrorCode CheckBodyDensity(TslModel *m, const TslLoad *l, const PetscInt ids[], PetscInt n)
{
  PetscFunctionBeginUser;
  for (PetscInt s = 0; s < m->nsection; s++) {
    const TslSection  *sec = &m->sections[s];
    const PetscInt     k   = TslModelFindElementSet(m, sec->elset);
    const TslMaterial *mat = sec->material_index >= 0 ? &m->materials[sec->material_index] : NULL;
    if (k < 0 || !mat || mat->prop[TSL_PROP_DENSITY].n) continue;
    for (PetscInt i = 0, j = 0; i < n && j < m->elsets[k].n;) {
      const PetscInt a = ids[i], b = m->elsets[k].ids[j];
      CHECK(a != b, l->loc, "*DLOAD %s on element %" PetscInt_FMT ": its material %s has no *DENSITY (the load is rho times the acceleration)",
            l->dload == TSL_DLOAD_GRAV ? "GRAV" : "CENTRIF", a, mat->name);
      if (a < b)
        i++;
      else
        j++;
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A body force (*DLOAD GRAV, CENTRIF) on element id: the acceleration must lie in the model's plane (2D) or be
 * symmetric about the axis (axisymmetric elements: gravity along the axis, the spin axis the symmetry axis x = 0
 * along y), or part of it would be dropped without a word. */
static PetscErrorCode CheckBodyForce(TslModel *m, const TslLoad *l, PetscInt id)
{
  const PetscInt        e = TslModelElementIndex(m, id);
  const TslElementType *t;
  const PetscReal      *a = l->axis;

  PetscFunctionBeginUser;
  CHECK(e >= 0, l->loc, "undefined element %" PetscInt_FMT, id);
  t = TslElementTypeGet(m->elem_type[e]);
  if (TslKinematicsRevolves(t->kin)) {
    if (l->dload == TSL_DLOAD_GRAV)
      CHECK(a[0] == 0 && a[2] == 0, l->loc,
            "*DLOAD GRAV on the axisymmetric element %" PetscInt_FMT " (%s): the gravity must point along the axis (0, +-1, 0)", id, t->name);
    else
      CHECK(a[0] == 0 && a[2] == 0 && a[3] == 0 && a[5] == 0, l->loc,
            "*DLOAD CENTRIF on the axisymmetric element %" PetscInt_FMT
            " (%s): the axis must be the symmetry axis (point 0, y, 0, direction 0, 1, 0)",
            id, t->name);
  } else if (t->dim == 2) {
    if (l->dload == TSL_DLOAD_GRAV)
      CHECK(a[2] == 0, l->loc, "*DLOAD GRAV on the plane element %" PetscInt_FMT " (%s): the gravity must lie in the x-y plane (nz = 0)", id,
            t->name);
    else
      CHECK((a[5] == 0 && a[2] == 0) || (a[3] == 0 && a[4] == 0), l->loc,
            "*DLOAD CENTRIF on the plane element %" PetscInt_FMT
            " (%s): the axis must lie in the x-y plane (z0 = az = 0) or be normal to it (ax = ay = 0)",
            id, t->name);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckLoad(TslModel *m, const TslLoad *l)
{
  PetscFunctionBeginUser;
  if (!l->target.set[0] && l->target.id < 0) PetscFunctionReturn(PETSC_SUCCESS); /* OP=NEW alone: only removes */
  CHECK(l->amplitude >= -1 && l->amplitude < m->namplitude, l->loc, "bad amplitude index %" PetscInt_FMT, l->amplitude);
  CHECK(l->film_amplitude >= -1 && l->film_amplitude < m->namplitude, l->loc, "bad amplitude index %" PetscInt_FMT, l->film_amplitude);
  switch (l->kind) {
  case TSL_LOAD_BOUNDARY:
  case TSL_LOAD_CLOAD:
  case TSL_LOAD_CFLUX:
    PetscCall(CheckNodeTarget(m, &l->target, l->loc));
    {
      char buf[64];
      for (PetscInt dof = l->dof_first; dof <= l->dof_last; dof++)
        CHECK(DofValid(m, dof) || (dof > 3 && dof < 11 && dof != l->dof_first && dof != l->dof_last), l->loc,
              "bad degree of freedom %" PetscInt_FMT " (valid: %s)", dof, DofList(m, buf, sizeof(buf)));
    }
    break;
  default:
    if (l->target_is_surface) {
      PetscInt s = TslModelFindSurface(m, l->target.set);
      CHECK(s >= 0, l->loc, "undefined surface %s", l->target.set);
      CHECK(m->surfaces[s].kind == TSL_SURFACE_ELEMENT, l->loc, "surface %s must be an element surface (TYPE=ELEMENT)", l->target.set);
    } else if (l->target.set[0]) {
      PetscInt s = TslModelFindElementSet(m, l->target.set);
      CHECK(s >= 0, l->loc, "undefined element set %s", l->target.set);
      for (PetscInt k = 0; k < m->elsets[s].n; k++) PetscCall(CheckFace(m, l->loc, m->elsets[s].ids[k], l->face));
      for (PetscInt k = 0; l->dload != TSL_DLOAD_FACE && k < m->elsets[s].n; k++) PetscCall(CheckBodyForce(m, l, m->elsets[s].ids[k]));
      if (l->dload != TSL_DLOAD_FACE) PetscCall(CheckBodyDensity(m, l, m->elsets[s].ids, m->elsets[s].n));
    } else {
      PetscCall(CheckFace(m, l->loc, l->target.id, l->face));
      if (l->dload != TSL_DLOAD_FACE) PetscCall(CheckBodyForce(m, l, l->target.id));
      if (l->dload != TSL_DLOAD_FACE) PetscCall(CheckBodyDensity(m, l, &l->target.id, 1));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* What an explicit step cannot do: mass scaling outside one, *EQUATION (no constraint rows without a
 * matrix), kinematic surface-to-surface contact, element types without a positive lumped mass at every node (the reference node of generalized
 * plane strain, the twist of CGAX; the element rows say so), and element sets of mass scaling defined. */
static PetscErrorCode CheckExplicitStep(TslModel *m, const TslStep *s)
{
  char where[PETSC_MAX_PATH_LEN];

  PetscFunctionBeginUser;
  (void)TslLocString(m, s->loc, where, sizeof(where));
  for (PetscInt k = 0; k < s->nmass; k++) {
    const TslMassScaling *ms = &s->mass[k];
    CHECK(s->explicit_dynamics, ms->loc, "mass scaling belongs to an explicit step (*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT); step %s is not one",
          s->name);
    CHECK(!ms->elset[0] || TslModelFindElementSet(m, ms->elset) >= 0, ms->loc, "undefined element set %s", ms->elset);
  }
  if (s->bv_given)
    CHECK(s->explicit_dynamics, s->bv_loc, "*BULK VISCOSITY belongs to an explicit step (*DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT); step %s is not one", s->name);
  if (!s->explicit_dynamics) PetscFunctionReturn(PETSC_SUCCESS);
  CHECK(!s->tfile.given, s->tfile.loc, "*TEMPERATURE, FILE= belongs to a *STATIC or *COUPLED TEMPERATURE-DISPLACEMENT step; step %s is explicit", s->name);
  if (m->nequation) CHECK(PETSC_FALSE, m->equations[0].loc, "*EQUATION is not supported in explicit steps (step %s at %s)", s->name, where);
  /* the kinematic predictor-corrector works on secondary nodes: surface-to-surface pairs take the penalty */
  for (PetscInt k = 0; k < m->npair; k++) {
    CHECK(m->pairs[k].type != TSL_CONTACT_SURFACE_TO_SURFACE || !m->pairs[k].kinematic, m->pairs[k].loc,
          "*CONTACT PAIR, TYPE=SURFACE TO SURFACE with MECHANICAL CONSTRAINT=KINEMATIC is not supported in explicit steps (PENALTY is, or a node-to-surface pair; step %s at %s)",
          s->name, where);
  }
  for (PetscInt e = 0; e < m->nelem; e++) {
    const TslElementType *t = TslElementTypeGet(m->elem_type[e]);
    TslLoc                l = {m->elem_line[2 * e], m->elem_line[2 * e + 1]};
    CHECK(t->nextra == 0 && !TslKinematicsTwists(t->kin), l,
          "element type %s (%s) is not supported in explicit steps (its extra unknowns have no lumped mass; step %s at %s)", t->name,
          TslElementTypeKinematicsName(t), s->name, where);
    CHECK(!t->pore, l, "element type %s is not supported in explicit steps (Abaqus/Explicit has no pore pressure elements; step %s at %s)", t->name,
          s->name, where);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *STEP, NLGEOM: once on, on in the steps that follow (the dialect; NLGEOM=NO after it is overruled, with a
 * warning). An explicit step without NLGEOM= takes it, as Abaqus/Explicit does (NLGEOM=NO keeps small strain); that
 * default is the procedure's and does not carry into a later implicit step. What keeps small strain in such a step
 * says so at its *STEP line: the plastic and incompatible-mode elements (docs/elements.md "Finite strain"). */
static PetscErrorCode CheckNlgeom(TslModel *m)
{
  char where[PETSC_MAX_PATH_LEN];

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < m->nstep; i++) {
    TslStep  *s = &m->steps[i];
    PetscInt  plastic = -1, incompatible = -1;
    if (i > 0 && m->steps[i - 1].nlgeom && !m->steps[i - 1].nlgeom_default && !s->nlgeom) {
      (void)TslLocString(m, s->loc, where, sizeof(where));
      if (s->nlgeom_given)
        PetscCall(PetscPrintf(PETSC_COMM_SELF, "%s: warning: *STEP, NLGEOM=NO: step %s keeps finite strain, as every step after one with NLGEOM does\n",
                              where, s->name));
      s->nlgeom = PETSC_TRUE;
    }
    if (!s->nlgeom && !s->nlgeom_given && s->explicit_dynamics) s->nlgeom = s->nlgeom_default = PETSC_TRUE;
    if (!s->nlgeom) continue;
    (void)TslLocString(m, s->loc, where, sizeof(where));
    for (PetscInt e = 0; e < m->nelem && (plastic < 0 || incompatible < 0); e++) {
      const TslElementType *t = TslElementTypeGet(m->elem_type[e]);
      if (incompatible < 0 && !TslElementTypeFiniteStrain(t)) incompatible = e;
    }
    for (PetscInt k = 0; k < m->nsection && plastic < 0; k++)
      if (TslMaterialIsPlastic(&m->materials[m->sections[k].material_index])) plastic = k;
    for (PetscInt k = 0; k < m->nsection && s->explicit_dynamics; k++) {
      const TslMaterial *mt = &m->materials[m->sections[k].material_index];
      /* the damping stress is the small-strain beta D : B v on the reference configuration: it would resist a rigid rotation */
      CHECK(mt->damp_beta == 0, mt->damping_loc,
            "*DAMPING, BETA= (material %s) %s explicit step %s%s: its damping stress is the small-strain one, which resists rigid rotations; %s",
            mt->name, s->nlgeom_default ? "is not supported at finite strain, and the" : "in the finite-strain", s->name,
            s->nlgeom_default ? " takes finite strain by default (NLGEOM, as in Abaqus/Explicit)" : " is not supported",
            s->nlgeom_default ? "write NLGEOM=NO on the step's *STEP line for small strain, or use ALPHA=" : "use ALPHA= or leave NLGEOM off");
    }
    if (plastic >= 0)
      PetscCall(PetscPrintf(PETSC_COMM_SELF,
                            "%s: warning: *STEP, NLGEOM: in step %s the elements of material %s (*PLASTIC) keep small-strain kinematics (finite-strain "
                            "plasticity is not available yet): their rotations or strains of more than a few percent will be wrong\n",
                            where, s->name, m->sections[plastic].material));
    if (incompatible >= 0)
      PetscCall(PetscPrintf(PETSC_COMM_SELF,
                            "%s: warning: *STEP, NLGEOM: in step %s the incompatible-mode elements (%s, element %" PetscInt_FMT ") keep small-strain "
                            "kinematics: their rotations or strains of more than a few percent will be wrong\n",
                            where, s->name, TslElementTypeGet(m->elem_type[incompatible])->name, m->elem_id[incompatible]));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The sets that output requests name exist. */
static PetscErrorCode CheckRequestSets(TslModel *m, const TslOutputRequest *out, PetscInt nout)
{
  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < nout; k++) {
    const TslOutputRequest *r = &out[k];
    if (!r->set[0]) continue;
    if (r->node)
      CHECK(TslModelFindNodeSet(m, r->set) >= 0, r->loc, "undefined node set %s", r->set);
    else
      CHECK(TslModelFindElementSet(m, r->set) >= 0, r->loc, "undefined element set %s", r->set);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *DAMPING acts in explicit steps only: a model with implicit steps is told once, at the first *DAMPING line, that
 * those steps ignore it (no inertia there: the dialect ignores it too). */
static PetscErrorCode NoteDamping(TslModel *m)
{
  PetscInt implicit = -1;
  char     where[PETSC_MAX_PATH_LEN];

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < m->nstep && implicit < 0; i++)
    if (!m->steps[i].explicit_dynamics) implicit = i;
  if (implicit < 0) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt k = 0; k < m->nmaterial; k++) {
    const TslMaterial *mt = &m->materials[k];
    if (mt->damp_alpha == 0 && mt->damp_beta == 0) continue;
    (void)TslLocString(m, mt->damping_loc, where, sizeof(where));
    PetscCall(PetscPrintf(PETSC_COMM_SELF,
                          "%s: note: *DAMPING (material %s) acts in explicit steps only; step %s and the other steps without inertia ignore it\n",
                          where, mt->name, m->steps[implicit].name[0] ? m->steps[implicit].name : "1"));
    break;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckSteps(TslModel *m)
{
  PetscFunctionBeginUser;
  {
    TslLoc first = {0, 1};
    CHECK(m->nstep > 0, first, "the deck has no *STEP%s", "");
  }
  for (PetscInt i = 0; i < m->nstep; i++) {
    const TslStep *s = &m->steps[i];
    CHECK(s->coupled, s->loc,
          "step %s has no procedure (*COUPLED TEMPERATURE-DISPLACEMENT, *STATIC, *HEAT TRANSFER or *DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT)",
          s->name);
    PetscCall(CheckExplicitStep(m, s));
    for (PetscInt k = 0; k < s->nload; k++) {
      const TslLoad     *l                   = &s->loads[k];
      static const char *kw[TSL_LOAD_NKINDS] = {NULL, NULL, "*CFLUX", NULL, "*DFLUX or *DSFLUX", "*FILM or *SFILM", "*RADIATE or *SRADIATE"};
      CHECK(!s->statik || !kw[l->kind] || (!l->target.set[0] && l->target.id < 0), l->loc,
            "%s in a *STATIC step: a static step holds the temperatures (no heat transfer); thermal loads need *COUPLED TEMPERATURE-DISPLACEMENT "
            "(step %s)",
            kw[l->kind] ? kw[l->kind] : "", s->name);
      CHECK(!s->heat || l->kind != TSL_LOAD_DLOAD || (!l->target.set[0] && l->target.id < 0), l->loc,
            "*DLOAD in the *HEAT TRANSFER step %s: a heat-transfer model has no displacement for a pressure or body force to act on", s->name);
      CHECK(s->statik || !l->temperature, l->loc,
            "*TEMPERATURE in step %s: the temperature is an unknown of a coupled step; prescribe it with *BOUNDARY on dof 11 (*TEMPERATURE is for "
            "*STATIC steps)",
            s->name);
      PetscCall(CheckLoad(m, l));
    }
    PetscCall(CheckRequestSets(m, s->out, s->nout));
  }
  PetscCall(CheckRequestSets(m, m->post_out, m->npost_out)); /* a POST OUTPUT deck's own */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A table's abscissae (clearance or pressure) must increase strictly: the reader sorts them, so what
 * remains to catch is a value given twice (or a table built unsorted by other code). */
static PetscErrorCode CheckTableAbscissae(TslModel *m, TslLoc loc, const char *inter, const char *kw, const char *what, PetscInt n,
                                          const PetscReal x[])
{
  PetscFunctionBeginUser;
  for (PetscInt k = 1; k < n; k++) {
    CHECK(x[k] != x[k - 1], loc, "surface interaction %s: *%s gives the %s %g twice", inter, kw, what, (double)x[k]);
    CHECK(x[k] > x[k - 1], loc, "surface interaction %s: *%s %s values must increase (%g after %g)", inter, kw, what, (double)x[k], (double)x[k - 1]);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckInteraction(TslModel *m, const TslInteraction *it)
{
  const TslGapConductance    *g = &it->conductance;
  const TslGapRadiation      *r = &it->radiation;
  const TslGapHeatGeneration *h = &it->heat_generation;

  PetscFunctionBeginUser;
  if (it->friction.given)
    CHECK(it->friction.mu >= 0, it->friction.loc, "surface interaction %s: the friction coefficient must not be negative (got %g)", it->name,
          (double)it->friction.mu);
  if (g->given) {
    for (PetscInt k = 0; k < g->n; k++)
      CHECK(g->value[k] >= 0, g->loc, "surface interaction %s: the gap conductance must not be negative (got %g)", it->name, (double)g->value[k]);
    PetscCall(CheckTableAbscissae(m, g->loc, it->name, "GAP CONDUCTANCE", g->by_pressure ? "pressure" : "clearance", g->n, g->abscissa));
  }
  if (r->given) {
    CHECK(r->emissivity_main > 0 && r->emissivity_main <= 1 && r->emissivity_secondary > 0 && r->emissivity_secondary <= 1, r->loc,
          "surface interaction %s: emissivities must lie in (0, 1] (got %g, %g)", it->name, (double)r->emissivity_main,
          (double)r->emissivity_secondary);
    for (PetscInt k = 0; k < r->n; k++)
      CHECK(r->view_factor[k] >= 0 && r->view_factor[k] <= 1, r->loc, "surface interaction %s: the effective view factor must lie in [0, 1] (got %g)",
            it->name, (double)r->view_factor[k]);
    PetscCall(CheckTableAbscissae(m, r->loc, it->name, "GAP RADIATION", "clearance", r->n, r->clearance));
  }
  CHECK(h->fraction >= 0 && h->fraction <= 1, h->loc,
        "surface interaction %s: the fraction of dissipation converted to heat must lie in [0, 1] (got %g)", it->name, (double)h->fraction);
  CHECK(h->weight_secondary >= 0 && h->weight_secondary <= 1, h->loc,
        "surface interaction %s: the heat weight of the secondary surface must lie in [0, 1] (got %g)", it->name, (double)h->weight_secondary);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckContactPair(TslModel *m, TslContactPair *p)
{
  PetscInt s, mn;

  PetscFunctionBeginUser;
  p->interaction_index = TslModelFindInteraction(m, p->interaction);
  CHECK(p->interaction_index >= 0, p->loc, "undefined surface interaction %s", p->interaction);
  s  = TslModelFindSurface(m, p->secondary);
  mn = TslModelFindSurface(m, p->main);
  CHECK(s >= 0, p->loc, "undefined surface %s", p->secondary);
  CHECK(mn >= 0, p->loc, "undefined surface %s", p->main);
  CHECK(s != mn, p->loc, "contact pair: the secondary and the main surface are both %s", p->main);
  CHECK(m->surfaces[mn].kind == TSL_SURFACE_ELEMENT, p->loc,
        "main surface %s must be an element surface (TYPE=ELEMENT); node surfaces can only be secondary", p->main);
  CHECK(p->type != TSL_CONTACT_SURFACE_TO_SURFACE || m->surfaces[s].kind == TSL_SURFACE_ELEMENT, p->loc,
        "TYPE=SURFACE TO SURFACE needs an element surface as secondary; %s is a node surface", p->secondary);
  if (p->adjust_set[0]) CHECK(TslModelFindNodeSet(m, p->adjust_set) >= 0, p->loc, "undefined node set %s", p->adjust_set);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Pairs whose interaction has PRESSURE-OVERCLOSURE=TIED become ties (TslTie, at the pair's data line), as a
 * *CONTACT PAIR, TIED does when it is read: the interface is tied, its interaction's laws do not apply. */
static PetscErrorCode TiedPairs(TslModel *m)
{
  PetscInt k = 0;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < m->npair; i++) {
    const TslContactPair *p = &m->pairs[i];
    if (!m->interactions[p->interaction_index].behavior.tied) {
      m->pairs[k++] = m->pairs[i];
      continue;
    }
    PetscCall(TslDeckGrow(&m->ties, sizeof(TslTie), m->ntie));
    TslTie *t = &m->ties[m->ntie++];
    PetscCall(PetscMemzero(t, sizeof(*t)));
    PetscCall(PetscStrncpy(t->secondary, p->secondary, sizeof(t->secondary)));
    PetscCall(PetscStrncpy(t->main, p->main, sizeof(t->main)));
    t->adjust    = (PetscBool)(p->adjust_given && (p->adjust > 0 || p->adjust_set[0]));
    t->from_pair = PETSC_TRUE;
    t->loc       = p->loc;
  }
  m->npair = k;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A tie's surfaces: defined, distinct, the main one of element faces (the dialect's rule; the secondary may be
 * a node surface). */
static PetscErrorCode CheckTie(TslModel *m, const TslTie *t)
{
  PetscInt s, mn;

  PetscFunctionBeginUser;
  s  = TslModelFindSurface(m, t->secondary);
  mn = TslModelFindSurface(m, t->main);
  CHECK(s >= 0, t->loc, "%s: undefined surface %s", t->from_pair ? "tied contact pair" : "*TIE", t->secondary);
  CHECK(mn >= 0, t->loc, "%s: undefined surface %s", t->from_pair ? "tied contact pair" : "*TIE", t->main);
  CHECK(s != mn, t->loc, "%s: the secondary and the main surface are both %s", t->from_pair ? "tied contact pair" : "*TIE", t->main);
  CHECK(m->surfaces[mn].kind == TSL_SURFACE_ELEMENT, t->loc,
        "%s: main surface %s must be an element surface (TYPE=ELEMENT); node surfaces can only be secondary", t->from_pair ? "tied contact pair" : "*TIE",
        t->main);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The reference node of a generalized plane strain section (REF NODE=): a defined node that no element
 * uses; position in the model, or -1 when the section has none. */
static PetscErrorCode SectionReferenceNode(TslModel *m, const TslSection *sec, const char *uses, PetscInt *pos)
{
  PetscInt id = sec->ref_node.id;

  PetscFunctionBeginUser;
  *pos = -1;
  if (sec->ref_node.set[0]) {
    PetscInt k = TslModelFindNodeSet(m, sec->ref_node.set);
    CHECK(k >= 0, sec->loc, "REF NODE=%s: undefined node set", sec->ref_node.set);
    CHECK(m->nsets[k].n == 1, sec->loc, "REF NODE=%s: the node set must hold exactly one node (it holds %" PetscInt_FMT ")", sec->ref_node.set,
          m->nsets[k].n);
    id = m->nsets[k].ids[0];
  }
  if (id < 0) PetscFunctionReturn(PETSC_SUCCESS);
  *pos = TslModelNodeIndex(m, id);
  CHECK(*pos >= 0, sec->loc, "REF NODE=%" PetscInt_FMT ": undefined node", id);
  CHECK(!uses[*pos], sec->loc, "REF NODE=%" PetscInt_FMT ": the reference node must not belong to an element", id);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Generalized plane strain: every element of such a type gets its section's reference node appended to
 * its nodes (the row's extra node), so that distribution, ghosting and assembly carry the reference
 * node's dofs with the element like any other node. A section of such elements without REF NODE=, or a
 * REF NODE= on a section of other elements, is an error at the section's line. */
static PetscErrorCode AttachReferenceNodes(TslModel *m)
{
  PetscInt *ref, *ptr, *conn, nextra = 0;
  char     *uses;

  PetscFunctionBeginUser;
  for (PetscInt e = 0; e < m->nelem; e++) nextra += TslElementTypeGet(m->elem_type[e])->nextra;
  if (!nextra) {
    for (PetscInt s = 0; s < m->nsection; s++)
      CHECK(m->sections[s].ref_node.id < 0 && !m->sections[s].ref_node.set[0], m->sections[s].loc,
            "REF NODE= is for generalized plane strain elements (CPEG...); the section's elements are not%s", "");
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscCalloc1(m->nnode, &uses));
  PetscCall(PetscMalloc1(m->nelem, &ref));
  for (PetscInt k = 0; k < m->elem_ptr[m->nelem]; k++) uses[TslModelNodeIndex(m, m->elem_conn[k])] = 1;
  for (PetscInt e = 0; e < m->nelem; e++) ref[e] = -1;
  for (PetscInt s = 0; s < m->nsection; s++) {
    const TslSection *sec = &m->sections[s];
    const TslSet     *set = &m->elsets[TslModelFindElementSet(m, sec->elset)];
    PetscInt          pos;
    PetscErrorCode    ierr = SectionReferenceNode(m, sec, uses, &pos);
    if (ierr) {
      PetscCall(PetscFree(uses));
      PetscCall(PetscFree(ref));
    }
    PetscCall(ierr);
    for (PetscInt k = 0; k < set->n; k++) {
      PetscInt              e = TslModelElementIndex(m, set->ids[k]);
      const TslElementType *t = TslElementTypeGet(m->elem_type[e]);
      if ((t->nextra && pos < 0) || (!t->nextra && pos >= 0)) {
        PetscCall(PetscFree(uses));
        PetscCall(PetscFree(ref));
      }
      CHECK(!t->nextra || pos >= 0, sec->loc, "*SOLID SECTION for %s elements needs REF NODE= (the generalized plane strain reference node)", t->name);
      CHECK(t->nextra || pos < 0, sec->loc, "REF NODE= is for generalized plane strain elements (CPEG...), not %s", t->name);
      ref[e] = pos;
    }
  }
  PetscCall(PetscMalloc2(m->nelem + 1, &ptr, m->elem_ptr[m->nelem] + nextra, &conn));
  ptr[0] = 0;
  for (PetscInt e = 0; e < m->nelem; e++) {
    PetscInt k = ptr[e];
    for (PetscInt j = m->elem_ptr[e]; j < m->elem_ptr[e + 1]; j++) conn[k++] = m->elem_conn[j];
    if (TslElementTypeGet(m->elem_type[e])->nextra) conn[k++] = m->node_id[ref[e]];
    ptr[e + 1] = k;
  }
  /* the model's arrays are single allocations (TslDeckGrow): replace them */
  PetscCall(PetscFree(m->elem_ptr));
  PetscCall(PetscFree(m->elem_conn));
  PetscCall(PetscMalloc1(m->nelem + 1, &m->elem_ptr));
  PetscCall(PetscMalloc1(ptr[m->nelem], &m->elem_conn));
  PetscCall(PetscArraycpy(m->elem_ptr, ptr, m->nelem + 1));
  PetscCall(PetscArraycpy(m->elem_conn, conn, ptr[m->nelem]));
  PetscCall(PetscFree2(ptr, conn));
  PetscCall(PetscFree(uses));
  PetscCall(PetscFree(ref));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslModelCheck(TslModel *m)
{
  PetscFunctionBeginUser;
  PetscCall(TslModelIndex(m));
  PetscCall(CheckMesh(m));
  PetscCall(CheckSurfaces(m));
  PetscCall(CheckMaterialsAndSections(m));
  for (PetscInt i = 0; i < m->ninit; i++) PetscCall(CheckNodeTarget(m, &m->init[i].target, m->init[i].loc));
  PetscCall(CheckInitialVelocities(m));
  for (PetscInt i = 0; i < m->nequation; i++) {
    const TslEquation *e = &m->equations[i];
    for (PetscInt k = 0; k < e->n; k++) {
      CHECK(TslModelNodeIndex(m, e->node[k]) >= 0, e->loc, "*EQUATION refers to undefined node %" PetscInt_FMT, e->node[k]);
      CHECK(DofValid(m, e->dof[k]), e->loc, "*EQUATION: bad degree of freedom %" PetscInt_FMT, e->dof[k]);
    }
  }
  for (PetscInt i = 0; i < m->namplitude; i++) {
    const TslAmplitude *a = &m->amplitudes[i];
    for (PetscInt k = 1; k < a->n; k++) CHECK(a->t[k] >= a->t[k - 1], a->loc, "amplitude %s: times must not decrease", a->name);
  }
  for (PetscInt i = 0; i < m->ninteraction; i++) PetscCall(CheckInteraction(m, &m->interactions[i]));
  for (PetscInt i = 0; i < m->npair; i++) PetscCall(CheckContactPair(m, &m->pairs[i]));
  PetscCall(TiedPairs(m));
  for (PetscInt i = 0; i < m->ntie; i++) PetscCall(CheckTie(m, &m->ties[i]));
  PetscCall(CheckSteps(m));
  PetscCall(CheckNlgeom(m));
  PetscCall(NoteDamping(m));
  PetscCall(AttachReferenceNodes(m));
  PetscFunctionReturn(PETSC_SUCCESS);
}
