/* Conventional shells (S8RT, SAX2T) as continuum elements.
 *
 * The reader takes a conventional shell with its own nodes, on the shell's reference surface, and the type
 * it becomes (the catalogue's S8RT, C3D20RT with its pressure on linear sub-faces, or CAX8T for SAX2T). Before the model is checked, each shell is
 * expanded into two of those quadratic elements stacked through its thickness, the way CalculiX expands its shells into C3D20R: every shell node gets
 * a fibre of nodes along its normal (the average of the elements' normals there) at -1/2, -1/4, 0, 1/4 and 1/2 of the thickness about the mid-surface
 * (the quarter points only where the node is a corner, since a quadratic element has midside nodes only at the corners of its thickness edges). The
 * deck's node stays where it is, one of the fibre's nodes (the middle one, or the bottom / top with OFFSET=SNEG / SPOS), so whatever the deck says of
 * it (output, *EQUATION, *CLOAD, *CFLUX) holds there. The temperature is quadratic through each half of the thickness, as in the dialect's shells
 * (piecewise quadratic between five points at the corners).
 *
 * What follows the expansion (docs/elements.md, "Conventional shells"):
 *  - the element id is the bottom (SNEG side) element's, the top one gets a new id above the deck's
 *    ids, and joins every element set the shell is in; new nodes get ids above the deck's;
 *  - faces SPOS / SNEG (surfaces, *DFLUX labels SPOS / SNEG, *FILM labels FPOS / FNEG, *RADIATE labels RPOS / RNEG) become the top
 *    element's top face and the bottom element's bottom face; *DLOAD's P on an element set of shells is a
 *    pressure on their SPOS faces (pushing against the normal, as the dialect's shell pressure); a body load
 *    (*DFLUX BF, *DLOAD GRAV, CENTRIF) on a shell's id loads both of its elements;
 *  - a *BOUNDARY, *TEMPERATURE or initial condition on a shell node holds its whole fibre (the shell's
 *    thickness moves with it, its temperature is the node's through the thickness).
 */
#include "deck_impl.h"
#include <thermoslide/element.h>
#include <string.h>

#define USER_ERR(...)      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, __VA_ARGS__)
#define USER_CHECK(c, ...) PetscCheck(c, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, __VA_ARGS__)
#define NLEV               5 /* fibre levels: -1/2, -1/4, 0, 1/4, 1/2 of the thickness */

typedef struct {
  const char *name, *alias, *expanded; /* the alias is CalculiX's mechanical name (read as the coupled type) */
  PetscInt    nnode;
  const char *what; /* the two elements each becomes, for the log */
} ShellRow;

static const ShellRow Shells[] = {
    /* the catalogue's S8RT row: C3D20RT with its pressure on the faces' linear pieces */
    {"S8RT", "S8R", "S8RT", 8, "two 20-node bricks (C3D20RT, with pressure on the faces' linear pieces)"},
    {"SAX2T", "SAX2", "CAX8T", 3, "two CAX8T"},
};

PetscErrorCode TslDeckShellType(const char *name, const char **shell, PetscInt *type, PetscInt *nnode, const char **what)
{
  PetscFunctionBeginUser;
  *shell = NULL;
  for (size_t i = 0; i < sizeof(Shells) / sizeof(Shells[0]); i++)
    if (TslDeckNameEqual(name, Shells[i].name) || TslDeckNameEqual(name, Shells[i].alias)) {
      *shell = Shells[i].name;
      *type  = TslElementTypeFind(Shells[i].expanded);
      *nnode = Shells[i].nnode;
      *what  = Shells[i].what;
      PetscCheck(*type >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "shell type %s: no %s in the catalogue", Shells[i].name, Shells[i].expanded);
      break;
    }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Element e was read as a shell: with fewer nodes than the type it becomes. */
static PetscBool IsShell(const TslModel *m, PetscInt e)
{
  return m->elem_ptr[e + 1] - m->elem_ptr[e] != TslElementTypeGet(m->elem_type[e])->geom->nnode ? PETSC_TRUE : PETSC_FALSE;
}

static const char *ShellName(const TslModel *m, PetscInt e)
{
  return m->elem_ptr[e + 1] - m->elem_ptr[e] == 3 ? "SAX2T" : "S8RT";
}

static TslLoc ElemLoc(const TslModel *m, PetscInt e)
{
  TslLoc l = {m->elem_line[2 * e], m->elem_line[2 * e + 1]};
  return l;
}

/* The shell's reference-surface geometry (quad8 for S8RT, line3 for SAX2T: the expanded type's first face
 * family) and the geometry's node k as a shell node: the line3 family lists its ends first, SAX2T its
 * nodes along the line (end, middle, end). */
static const TslGeometry *ShellGeometry(const TslModel *m, PetscInt e, const PetscInt **order)
{
  static const PetscInt line3[3] = {0, 2, 1}, quad8[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  const TslGeometry    *g = TslElementTypeGet(m->elem_type[e])->geom->face_geom[0];
  *order                  = g->nnode == 3 ? line3 : quad8;
  return g;
}

/* Unit normal of shell e at its local node a (0 when degenerate): quad8, the right-hand normal of the
 * surface's two tangents; line3 in the (r, z) plane, the tangent turned by +90 degrees. */
static void ShellNormal(const TslModel *m, PetscInt e, const PetscInt pos[], PetscInt a, PetscReal n[3])
{
  const PetscInt    *order;
  const TslGeometry *g = ShellGeometry(m, e, &order);
  PetscReal          N[8], dN[16], t[2][3] = {{0}}, len;
  PetscInt           k0 = 0;

  for (PetscInt k = 0; k < g->nnode; k++)
    if (order[k] == a) k0 = k;
  g->shape(g->node_xi[k0], N, dN);
  for (PetscInt k = 0; k < g->nnode; k++)
    for (PetscInt j = 0; j < g->dim; j++)
      for (PetscInt c = 0; c < 3; c++) t[j][c] += dN[k * g->dim + j] * m->node_xyz[3 * pos[order[k]] + c];
  if (g->dim == 2) {
    n[0] = t[0][1] * t[1][2] - t[0][2] * t[1][1];
    n[1] = t[0][2] * t[1][0] - t[0][0] * t[1][2];
    n[2] = t[0][0] * t[1][1] - t[0][1] * t[1][0];
  } else {
    n[0] = -t[0][1];
    n[1] = t[0][0];
    n[2] = 0;
  }
  len = PetscSqrtReal(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (PetscInt c = 0; c < 3; c++) n[c] = len > 0 ? n[c] / len : 0;
}

/* The shell's corners (nodes that need the quarter levels): S8RT's first four, SAX2T's ends. */
static PetscBool IsCorner(PetscInt nn, PetscInt a)
{
  return nn == 8 ? (a < 4 ? PETSC_TRUE : PETSC_FALSE) : (a != 1 ? PETSC_TRUE : PETSC_FALSE);
}

/* Shell positions and the id of each one's top element, by shell id, for the set and face maps. */
typedef struct {
  PetscInt  n;
  PetscInt *id, *top; /* sorted shell ids, the top element's id of each */
} TwinMap;

static PetscInt TwinOf(const TwinMap *tw, PetscInt id)
{
  PetscInt k;
  if (PetscFindInt(id, tw->n, tw->id, &k) || k < 0) return -1;
  return tw->top[k];
}

/* The element set (node set) called name, created empty when new; *index its position. */
static PetscErrorCode DerivedSet(TslSet **sets, PetscInt *nset, const char *name, TslLoc loc, PetscInt *index, PetscBool *created)
{
  PetscFunctionBeginUser;
  *created = PETSC_FALSE;
  for (PetscInt i = 0; i < *nset; i++)
    if (TslDeckNameEqual((*sets)[i].name, name)) {
      *index = i;
      PetscFunctionReturn(PETSC_SUCCESS);
    }
  PetscCall(TslDeckGrow(sets, sizeof(TslSet), *nset));
  PetscCall(PetscStrncpy((*sets)[*nset].name, name, TSL_NAME_LEN));
  (*sets)[*nset].loc = loc;
  *index             = (*nset)++;
  *created           = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode SetAdd(TslSet *s, PetscInt id)
{
  PetscFunctionBeginUser;
  PetscCall(TslDeckGrow(&s->ids, sizeof(PetscInt), s->n));
  s->ids[s->n++] = id;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A name for a set derived from base: base~suffix, or ~suffix<index> when that is too long. */
static PetscErrorCode DerivedName(char name[TSL_NAME_LEN], const char *base, const char *suffix, PetscInt index)
{
  PetscFunctionBeginUser;
  if (strlen(base) + strlen(suffix) + 2 <= TSL_NAME_LEN) {
    PetscCall(PetscStrncpy(name, base, TSL_NAME_LEN));
    PetscCall(PetscStrlcat(name, "~", TSL_NAME_LEN));
    PetscCall(PetscStrlcat(name, suffix, TSL_NAME_LEN));
  } else
    PetscCall(PetscSNPrintf(name, TSL_NAME_LEN, "~%s%" PetscInt_FMT, suffix, index));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Face f (1..6 or TSL_FACE_POS / NEG) of element id, as the expanded model has it: a shell's side becomes
 * the top element's top face or the bottom element's bottom face; a numbered face of a shell, or a side of
 * a non-shell, is an error at loc. */
static PetscErrorCode MapFace(const TslModel *m, const TwinMap *tw, PetscInt dim, PetscInt id, PetscInt *face, PetscInt *out, TslLoc loc)
{
  const PetscInt top = TwinOf(tw, id), side = *face == TSL_FACE_POS || *face == TSL_FACE_NEG;

  PetscFunctionBeginUser;
  *out = id;
  if (top < 0 && TslModelElementIndex(m, id) < 0) { /* undefined: the checks say so, a side label with it */
    USER_CHECK(!side, TSL_LOC_FMT "element %" PetscInt_FMT " is not defined", TSL_LOC_ARGS(m, loc), id);
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (top < 0) {
    USER_CHECK(!side, TSL_LOC_FMT "element %" PetscInt_FMT " is not a conventional shell (S8RT, SAX2T): it has faces S1..S%d, not SPOS / SNEG",
               TSL_LOC_ARGS(m, loc), id, dim == 3 ? 6 : 4);
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  USER_CHECK(side,
             TSL_LOC_FMT "element %" PetscInt_FMT " is a conventional shell: its faces are SPOS and SNEG (FPOS / FNEG for *FILM), not %" PetscInt_FMT,
             TSL_LOC_ARGS(m, loc), id, *face);
  if (*face == TSL_FACE_POS)
    *out = top, *face = dim == 3 ? 2 : 3;
  else
    *face = 1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A face load on elements (not a surface): its faces mapped; a set target with shell sides becomes a derived
 * set of the elements carrying those faces. */
static PetscErrorCode MapLoadFace(TslModel *m, const TwinMap *tw, TslLoad *l)
{
  PetscInt face;

  PetscFunctionBeginUser;
  /* *DLOAD's P on an element set of shells (the dialect's shell pressure, pushing against the positive normal):
   * the pressure on their SPOS faces; a set that is not all shells stays a surface name (the checks judge it) */
  if (l->kind == TSL_LOAD_DLOAD && l->target_is_surface && TslModelFindSurface(m, l->target.set) < 0) {
    const PetscInt src = TslModelFindElementSet(m, l->target.set);
    PetscBool      all = src >= 0 && m->elsets[src].n > 0 ? PETSC_TRUE : PETSC_FALSE;
    for (PetscInt i = 0; all && i < m->elsets[src].n; i++)
      if (TwinOf(tw, m->elsets[src].ids[i]) < 0) all = PETSC_FALSE;
    if (all) l->target_is_surface = PETSC_FALSE, l->face = TSL_FACE_POS;
  }
  /* a body load (BF, GRAV, CENTRIF) on a shell named by its id: both of its elements (a set that holds the shell
   * holds both already) */
  if (!l->target_is_surface && l->face == 0 && !l->target.set[0] && TwinOf(tw, l->target.id) >= 0) {
    char      id[32], name[TSL_NAME_LEN];
    PetscInt  k;
    PetscBool created;
    PetscCall(PetscSNPrintf(id, sizeof(id), "%" PetscInt_FMT, l->target.id));
    PetscCall(DerivedName(name, id, "BODY", l->target.id));
    PetscCall(DerivedSet(&m->elsets, &m->nelset, name, l->loc, &k, &created));
    if (created) {
      PetscCall(SetAdd(&m->elsets[k], l->target.id));
      PetscCall(SetAdd(&m->elsets[k], TwinOf(tw, l->target.id)));
      PetscCall(PetscSortRemoveDupsInt(&m->elsets[k].n, m->elsets[k].ids));
    }
    PetscCall(PetscStrncpy(l->target.set, name, TSL_NAME_LEN));
  }
  if (l->target_is_surface || l->face <= 0) PetscFunctionReturn(PETSC_SUCCESS);
  if (!l->target.set[0]) {
    if (l->target.id >= 0) PetscCall(MapFace(m, tw, m->dim, l->target.id, &l->face, &l->target.id, l->loc));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  {
    const PetscInt src = TslModelFindElementSet(m, l->target.set);
    PetscInt       k, mapped = l->face;
    PetscBool      created;
    char           name[TSL_NAME_LEN];
    if (src < 0) PetscFunctionReturn(PETSC_SUCCESS); /* undefined: the checks say so */
    for (PetscInt i = 0; i < m->elsets[src].n; i++) {
      PetscInt id;
      face = l->face;
      PetscCall(MapFace(m, tw, m->dim, m->elsets[src].ids[i], &face, &id, l->loc));
      mapped = face;
    }
    if (l->face != TSL_FACE_POS && l->face != TSL_FACE_NEG) PetscFunctionReturn(PETSC_SUCCESS);
    PetscCall(DerivedName(name, m->elsets[src].name, l->face == TSL_FACE_POS ? "SPOS" : "SNEG", src));
    PetscCall(DerivedSet(&m->elsets, &m->nelset, name, l->loc, &k, &created));
    if (created) {
      for (PetscInt i = 0; i < m->elsets[src].n; i++) {
        const PetscInt id = m->elsets[src].ids[i];
        PetscCall(SetAdd(&m->elsets[k], l->face == TSL_FACE_POS ? TwinOf(tw, id) : id));
      }
      PetscCall(PetscSortRemoveDupsInt(&m->elsets[k].n, m->elsets[k].ids));
    }
    PetscCall(PetscStrncpy(l->target.set, name, TSL_NAME_LEN));
    l->face = mapped;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A node target (*BOUNDARY, *TEMPERATURE, initial conditions) on shell nodes: retargeted to a derived node set
 * that adds their fibres. fib[NLEV * i + lev]: node position of each fibre level, -1 where none. */
static PetscErrorCode FibreTarget(TslModel *m, const PetscInt fib[], PetscInt nfib, TslTarget *t, TslLoc loc)
{
  char      name[TSL_NAME_LEN];
  PetscInt  k, src       = -1, n, single;
  PetscBool created, any = PETSC_FALSE;

  PetscFunctionBeginUser;
  if (t->set[0]) {
    src = TslModelFindNodeSet(m, t->set);
    if (src < 0) PetscFunctionReturn(PETSC_SUCCESS);
    n = m->nsets[src].n;
  } else {
    if (t->id < 0) PetscFunctionReturn(PETSC_SUCCESS);
    n = 1;
  }
  single = t->id;
  for (PetscInt i = 0; i < n && !any; i++) {
    const PetscInt p = TslModelNodeIndex(m, src >= 0 ? m->nsets[src].ids[i] : single);
    for (PetscInt l = 0; p >= 0 && p < nfib && l < NLEV; l++)
      if (fib[NLEV * p + l] >= 0 && fib[NLEV * p + l] != p) any = PETSC_TRUE;
  }
  if (!any) PetscFunctionReturn(PETSC_SUCCESS);
  if (src >= 0)
    PetscCall(DerivedName(name, m->nsets[src].name, "FIBRE", src));
  else
    PetscCall(PetscSNPrintf(name, TSL_NAME_LEN, "~FIBRE.%" PetscInt_FMT, single));
  PetscCall(DerivedSet(&m->nsets, &m->nnset, name, loc, &k, &created));
  if (created) {
    for (PetscInt i = 0; i < n; i++) {
      const PetscInt id = src >= 0 ? m->nsets[src].ids[i] : single, p = TslModelNodeIndex(m, id);
      PetscCall(SetAdd(&m->nsets[k], id));
      for (PetscInt l = 0; p >= 0 && p < nfib && l < NLEV; l++)
        if (fib[NLEV * p + l] >= 0) PetscCall(SetAdd(&m->nsets[k], m->node_id[fib[NLEV * p + l]]));
    }
    PetscCall(PetscSortRemoveDupsInt(&m->nsets[k].n, m->nsets[k].ids));
  }
  PetscCall(PetscStrncpy(t->set, name, TSL_NAME_LEN));
  t->id = -1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Sections of shells: a *SHELL SECTION with a thickness (or NODAL THICKNESS) and OFFSET= -1/2, 0 or 1/2, holding no other
 * elements; they become solid sections of the expanded elements. sec[e]: element e's section, -1 if none. */
static PetscErrorCode ShellSections(TslModel *m, PetscInt sec[])
{
  PetscBool *conv;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(m->nsection + 1, &conv));
  for (PetscInt e = 0; e < m->nelem; e++) {
    sec[e] = -1;
    for (PetscInt s = 0; s < m->nsection && sec[e] < 0; s++) {
      const PetscInt k = TslModelFindElementSet(m, m->sections[s].elset);
      PetscInt       at;
      if (k >= 0 && !PetscFindInt(m->elem_id[e], m->elsets[k].n, m->elsets[k].ids, &at) && at >= 0) sec[e] = s;
    }
    if (!IsShell(m, e)) continue;
    {
      const TslLoc l = ElemLoc(m, e);
      USER_CHECK(sec[e] >= 0, TSL_LOC_FMT "%s element %" PetscInt_FMT " is in no *SHELL SECTION (it gives the thickness)", TSL_LOC_ARGS(m, l),
                 ShellName(m, e), m->elem_id[e]);
      const TslSection *s = &m->sections[sec[e]];
      USER_CHECK(s->shell, TSL_LOC_FMT "%s element %" PetscInt_FMT " is in a *SOLID SECTION (%s:%" PetscInt_FMT "): a shell takes a *SHELL SECTION",
                 TSL_LOC_ARGS(m, l), ShellName(m, e), m->elem_id[e], TSL_LOC_ARGS(m, s->loc));
      USER_CHECK(PetscAbsReal(s->shell_offset) < 1e-12 || PetscAbsReal(PetscAbsReal(s->shell_offset) - 0.5) < 1e-12,
                 TSL_LOC_FMT "OFFSET=%g is not supported for %s elements: 0 (the mid-surface, default), SPOS or SNEG", TSL_LOC_ARGS(m, s->loc),
                 (double)s->shell_offset, ShellName(m, e));
      conv[sec[e]] = PETSC_TRUE;
    }
  }
  for (PetscInt e = 0; e < m->nelem; e++)
    if (sec[e] >= 0 && conv[sec[e]] && !IsShell(m, e))
      USER_ERR(TSL_LOC_FMT "*SHELL SECTION of ELSET=%s holds conventional shells (S8RT, SAX2T) and element %" PetscInt_FMT
                           " (%s): give them sections of their own",
               TSL_LOC_ARGS(m, m->sections[sec[e]].loc), m->sections[sec[e]].elset, m->elem_id[e], TslElementTypeGet(m->elem_type[e])->name);
  for (PetscInt s = 0; s < m->nsection; s++)
    if (conv[s]) m->sections[s].shell = PETSC_FALSE; /* a solid section of the expanded elements */
  PetscCall(PetscFree(conv));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Each node's *NODAL THICKNESS (the last line naming it; 0: none) into nt[nnode]. */
static PetscErrorCode NodalThickness(TslModel *m, PetscReal nt[])
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < m->nnode; i++) nt[i] = 0;
  for (PetscInt k = 0; k < m->nnodal_thickness; k++) {
    const TslNodalThickness *l = &m->nodal_thickness[k];
    if (l->target.set[0]) {
      const PetscInt s = TslModelFindNodeSet(m, l->target.set);
      USER_CHECK(s >= 0, TSL_LOC_FMT "*NODAL THICKNESS: node set %s is not defined", TSL_LOC_ARGS(m, l->loc), l->target.set);
      for (PetscInt j = 0; j < m->nsets[s].n; j++) {
        const PetscInt p = TslModelNodeIndex(m, m->nsets[s].ids[j]);
        if (p >= 0) nt[p] = l->value;
      }
    } else {
      const PetscInt p = TslModelNodeIndex(m, l->target.id);
      USER_CHECK(p >= 0, TSL_LOC_FMT "*NODAL THICKNESS: node %" PetscInt_FMT " is not defined", TSL_LOC_ARGS(m, l->loc), l->target.id);
      nt[p] = l->value;
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The fibres: each shell node's normal (the average of its elements'), thickness (their average: the
 * section's, or with NODAL THICKNESS the node's own) and level
 * (0, 2 or 4 by OFFSET=, the same in every element), and its fibre's new nodes appended to the model.
 * fib[NLEV * i + l] is set for the levels node i needs, -1 elsewhere. */
static PetscErrorCode Fibres(TslModel *m, const PetscInt sec[], PetscInt fib[], PetscInt *nnew, PetscInt *first)
{
  const PetscInt nnode = m->nnode;
  PetscReal     *nrm, *thick, *nt;
  PetscInt      *lev0, *count, maxid = 0, add = 0;
  PetscBool     *corner;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc5(3 * nnode, &nrm, nnode, &thick, nnode, &lev0, nnode, &count, nnode, &corner));
  PetscCall(PetscMalloc1(nnode, &nt));
  PetscCall(NodalThickness(m, nt));
  for (PetscInt i = 0; i < NLEV * nnode; i++) fib[i] = -1;
  for (PetscInt i = 0; i < nnode; i++) maxid = PetscMax(maxid, m->node_id[i]);
  for (PetscInt e = 0; e < m->nelem; e++) {
    const PetscInt nn = m->elem_ptr[e + 1] - m->elem_ptr[e], *conn = m->elem_conn + m->elem_ptr[e];
    const TslLoc   l = ElemLoc(m, e);
    PetscInt       pos[8];
    if (!IsShell(m, e)) continue;
    const TslSection *s   = &m->sections[sec[e]];
    const PetscInt    lev = s->shell_offset < -0.25 ? 0 : s->shell_offset > 0.25 ? 4 : 2;
    for (PetscInt a = 0; a < nn; a++) {
      pos[a] = TslModelNodeIndex(m, conn[a]);
      USER_CHECK(pos[a] >= 0, TSL_LOC_FMT "element %" PetscInt_FMT " uses node %" PetscInt_FMT ", which is not defined", TSL_LOC_ARGS(m, l),
                 m->elem_id[e], conn[a]);
    }
    for (PetscInt a = 0; a < nn; a++) {
      const PetscInt i = pos[a];
      PetscReal      n[3];
      ShellNormal(m, e, pos, a, n);
      USER_CHECK(n[0] != 0 || n[1] != 0 || n[2] != 0, TSL_LOC_FMT "%s element %" PetscInt_FMT " has no normal at node %" PetscInt_FMT " (degenerate)",
                 TSL_LOC_ARGS(m, l), ShellName(m, e), m->elem_id[e], conn[a]);
      USER_CHECK(!count[i] || lev0[i] == lev,
                 TSL_LOC_FMT "node %" PetscInt_FMT " is on shells of different OFFSET= (their sections): a shared node needs one reference surface",
                 TSL_LOC_ARGS(m, l), conn[a]);
      for (PetscInt c = 0; c < 3; c++) nrm[3 * i + c] += n[c];
      USER_CHECK(s->shell_thickness > 0 || nt[i] > 0,
                 TSL_LOC_FMT "node %" PetscInt_FMT " of %s element %" PetscInt_FMT " has no *NODAL THICKNESS (its *SHELL SECTION, %s:%" PetscInt_FMT
                             ", takes NODAL THICKNESS)",
                 TSL_LOC_ARGS(m, l), conn[a], ShellName(m, e), m->elem_id[e], TSL_LOC_ARGS(m, s->loc));
      thick[i] += s->shell_thickness > 0 ? s->shell_thickness : nt[i];
      lev0[i] = lev;
      count[i]++;
      if (IsCorner(nn, a)) corner[i] = PETSC_TRUE;
    }
  }
  /* the averages, checked against each element's own normal (oppositely oriented neighbours cancel) */
  for (PetscInt i = 0; i < nnode; i++) {
    if (!count[i]) continue;
    const PetscReal len = PetscSqrtReal(nrm[3 * i] * nrm[3 * i] + nrm[3 * i + 1] * nrm[3 * i + 1] + nrm[3 * i + 2] * nrm[3 * i + 2]);
    for (PetscInt c = 0; c < 3; c++) nrm[3 * i + c] = len > 0 ? nrm[3 * i + c] / len : 0;
    thick[i] /= count[i];
  }
  for (PetscInt e = 0; e < m->nelem; e++) {
    const PetscInt nn = m->elem_ptr[e + 1] - m->elem_ptr[e], *conn = m->elem_conn + m->elem_ptr[e];
    PetscInt       pos[8];
    if (!IsShell(m, e)) continue;
    for (PetscInt a = 0; a < nn; a++) pos[a] = TslModelNodeIndex(m, conn[a]);
    for (PetscInt a = 0; a < nn; a++) {
      PetscReal      n[3];
      const PetscInt i = pos[a];
      const TslLoc   l = ElemLoc(m, e);
      ShellNormal(m, e, pos, a, n);
      USER_CHECK(n[0] * nrm[3 * i] + n[1] * nrm[3 * i + 1] + n[2] * nrm[3 * i + 2] > 0.5,
                 TSL_LOC_FMT "%s element %" PetscInt_FMT ": its normal at node %" PetscInt_FMT
                             " is more than 60 degrees from its neighbours' (the shells "
                             "around a node must be numbered the same way round, and a fold needs a node per side)",
                 TSL_LOC_ARGS(m, l), ShellName(m, e), m->elem_id[e], conn[a]);
    }
  }
  /* the new nodes, node by node and level by level */
  for (PetscInt i = 0; i < nnode; i++)
    for (PetscInt l = 0; count[i] && l < NLEV; l++)
      if (l != lev0[i] && (corner[i] || l % 2 == 0)) add++;
  USER_CHECK(maxid <= PETSC_MAX_INT - add,
             TSL_LOC_FMT "expanding the shells needs %" PetscInt_FMT " node ids above %" PetscInt_FMT ", beyond the largest id",
             TSL_LOC_ARGS(m, ElemLoc(m, 0)), add, maxid);
  *nnew  = add;
  *first = maxid + 1;
  for (PetscInt i = 0; i < nnode; i++) {
    if (!count[i]) continue;
    const PetscReal o = -0.5 + 0.25 * lev0[i]; /* the deck node's level */
    for (PetscInt l = 0; l < NLEV; l++) {
      if (l == lev0[i]) {
        fib[NLEV * i + l] = i;
        continue;
      }
      if (!corner[i] && l % 2) continue;
      PetscCall(TslDeckGrow(&m->node_id, sizeof(PetscInt), m->nnode));
      PetscCall(TslDeckGrow(&m->node_xyz, 3 * sizeof(PetscReal), m->nnode));
      for (PetscInt c = 0; c < 3; c++) m->node_xyz[3 * m->nnode + c] = m->node_xyz[3 * i + c] + thick[i] * (-0.5 + 0.25 * l - o) * nrm[3 * i + c];
      m->node_id[m->nnode] = ++maxid;
      fib[NLEV * i + l]    = m->nnode++;
    }
  }
  PetscCall(PetscFree5(nrm, thick, lev0, count, corner));
  PetscCall(PetscFree(nt));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The connectivity of layer 0 (bottom) or 1 (top) of shell e, written to out; returns its length. */
static PetscInt Layer(const TslModel *m, const PetscInt fib[], PetscInt e, PetscInt layer, PetscInt out[])
{
  const PetscInt nn = m->elem_ptr[e + 1] - m->elem_ptr[e], *c = m->elem_conn + m->elem_ptr[e], lo = 2 * layer, mid = lo + 1, hi = lo + 2;
  PetscInt       p[8];

  for (PetscInt a = 0; a < nn; a++) p[a] = TslModelNodeIndex(m, c[a]);
#define F(a, l) m->node_id[fib[NLEV * p[a] + (l)]]
  if (nn == 8) { /* C3D20RT: bottom corners, top corners, bottom midsides, top midsides, the corners' mid-thickness */
    for (PetscInt a = 0; a < 4; a++) {
      out[a]      = F(a, lo);
      out[4 + a]  = F(a, hi);
      out[8 + a]  = F(4 + a, lo);
      out[12 + a] = F(4 + a, hi);
      out[16 + a] = F(a, mid);
    }
    return 20;
  }
  /* CAX8T: the first end, the last end, up its fibre, back down the first end's; then the midsides */
  out[0] = F(0, lo), out[1] = F(2, lo), out[2] = F(2, hi), out[3] = F(0, hi);
  out[4] = F(1, lo), out[5] = F(2, mid), out[6] = F(1, hi), out[7] = F(0, mid);
  return 8;
#undef F
}

/* The shells' connectivity replaced by their bottom elements' in place, their top elements appended with new
 * ids; tw maps each shell id to its top element's. */
static PetscErrorCode Elements(TslModel *m, const PetscInt fib[], PetscInt nshell, TwinMap *tw)
{
  const PetscInt ne = m->nelem + nshell;
  PetscInt      *ptr, *conn, *id, *type, *line, k = 0, next = 0, s = 0, at = 0;

  PetscFunctionBeginUser;
  for (PetscInt e = 0; e < m->nelem; e++) next = PetscMax(next, m->elem_id[e]);
  USER_CHECK(next <= PETSC_MAX_INT - nshell, TSL_LOC_FMT "expanding the shells needs %" PetscInt_FMT " element ids above %" PetscInt_FMT,
             TSL_LOC_ARGS(m, ElemLoc(m, 0)), nshell, next);
  PetscCall(PetscMalloc1(ne + 1, &ptr));
  PetscCall(PetscMalloc1((size_t)m->elem_ptr[m->nelem] + 32 * (size_t)nshell, &conn));
  PetscCall(PetscMalloc1(ne, &id));
  PetscCall(PetscMalloc1(ne, &type));
  PetscCall(PetscMalloc1(2 * ne, &line));
  PetscCall(PetscMalloc1(nshell, &tw->id));
  PetscCall(PetscMalloc1(nshell, &tw->top));
  tw->n  = nshell;
  ptr[0] = 0;
  for (PetscInt layer = 0; layer < 2; layer++)
    for (PetscInt e = 0; e < m->nelem; e++) {
      const PetscBool shell = IsShell(m, e);
      if (layer && !shell) continue;
      type[at]         = m->elem_type[e];
      line[2 * at]     = m->elem_line[2 * e];
      line[2 * at + 1] = m->elem_line[2 * e + 1];
      id[at]           = layer ? ++next : m->elem_id[e];
      if (layer) tw->id[s] = m->elem_id[e], tw->top[s++] = id[at];
      if (shell)
        k += Layer(m, fib, e, layer, conn + k);
      else
        for (PetscInt j = m->elem_ptr[e]; j < m->elem_ptr[e + 1]; j++) conn[k++] = m->elem_conn[j];
      ptr[++at] = k;
    }
  PetscCall(PetscFree(m->elem_ptr));
  PetscCall(PetscFree(m->elem_conn));
  PetscCall(PetscFree(m->elem_id));
  PetscCall(PetscFree(m->elem_type));
  PetscCall(PetscFree(m->elem_line));
  m->elem_ptr = ptr, m->elem_conn = conn, m->elem_id = id, m->elem_type = type, m->elem_line = line, m->nelem = ne;
  PetscCall(PetscSortIntWithArray(tw->n, tw->id, tw->top));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Faces of shell sides on element surfaces and face loads; the top elements in the shells' element sets. */
static PetscErrorCode MapSetsAndFaces(TslModel *m, const TwinMap *tw)
{
  const PetscInt nelset = m->nelset; /* the sets derived for face loads below hold their faces' elements already */

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < m->nsurface; i++) {
    TslSurface *sf = &m->surfaces[i];
    if (sf->kind != TSL_SURFACE_ELEMENT) continue;
    for (PetscInt k = 0; k < sf->n; k++) PetscCall(MapFace(m, tw, m->dim, sf->elem[k], &sf->face[k], &sf->elem[k], sf->loc));
  }
  for (PetscInt s = 0; s < m->nstep; s++)
    for (PetscInt k = 0; k < m->steps[s].nload; k++) {
      TslLoad *l = &m->steps[s].loads[k];
      if (TslLoadKindOnElements(l->kind)) PetscCall(MapLoadFace(m, tw, l));
    }
  for (PetscInt i = 0; i < nelset; i++) {
    TslSet        *set = &m->elsets[i];
    const PetscInt n   = set->n;
    for (PetscInt k = 0; k < n; k++) {
      const PetscInt top = TwinOf(tw, set->ids[k]);
      if (top >= 0) PetscCall(SetAdd(set, top));
    }
    if (set->n > n) PetscCall(PetscSortRemoveDupsInt(&set->n, set->ids));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslDeckExpandShells(TslModel *m)
{
  PetscInt *sec, *fib, nshell = 0, nnew = 0, first = 0, nnode = m->nnode, top = PETSC_MAX_INT;
  TwinMap   tw = {0, NULL, NULL};

  PetscFunctionBeginUser;
  for (PetscInt e = 0; e < m->nelem; e++)
    if (IsShell(m, e)) nshell++;
  PetscCall(TslModelIndex(m));
  if (!nshell) { /* only the side labels to refuse */
    PetscCall(MapSetsAndFaces(m, &tw));
    PetscCall(PetscFree(m->nodal_thickness)); /* read by the expansion only */
    m->nnodal_thickness = 0;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscMalloc1(m->nelem, &sec));
  PetscCall(PetscMalloc1(NLEV * (size_t)m->nnode, &fib));
  PetscCall(ShellSections(m, sec));
  PetscCall(Fibres(m, sec, fib, &nnew, &first));
  PetscCall(TslModelIndex(m)); /* the new nodes */
  PetscCall(Elements(m, fib, nshell, &tw));
  PetscCall(TslModelIndex(m));
  PetscCall(MapSetsAndFaces(m, &tw));
  /* a node condition on a shell node holds its fibre */
  for (PetscInt s = 0; s < m->nstep; s++)
    for (PetscInt k = 0; k < m->steps[s].nload; k++) {
      TslLoad *l = &m->steps[s].loads[k];
      if (l->kind == TSL_LOAD_BOUNDARY) PetscCall(FibreTarget(m, fib, nnode, &l->target, l->loc));
    }
  for (PetscInt i = 0; i < m->ninit; i++) PetscCall(FibreTarget(m, fib, nnode, &m->init[i].target, m->init[i].loc));
  for (PetscInt i = 0; i < m->nvinit; i++) PetscCall(FibreTarget(m, fib, nnode, &m->vinit[i].target, m->vinit[i].loc));
  for (PetscInt i = 0; i < tw.n; i++) top = PetscMin(top, tw.top[i]);
  PetscCall(PetscPrintf(PETSC_COMM_SELF,
                        "note: %" PetscInt_FMT " shell elements expanded into %" PetscInt_FMT " (new element ids %" PetscInt_FMT " to %" PetscInt_FMT
                        "), %" PetscInt_FMT " nodes added through their thickness (ids %" PetscInt_FMT " to %" PetscInt_FMT ")\n",
                        nshell, 2 * nshell, top, top + nshell - 1, nnew, first, first + nnew - 1));
  PetscCall(PetscFree(m->nodal_thickness)); /* read by the expansion only */
  m->nnodal_thickness = 0;
  PetscCall(PetscFree(sec));
  PetscCall(PetscFree(fib));
  PetscCall(PetscFree(tw.id));
  PetscCall(PetscFree(tw.top));
  PetscFunctionReturn(PETSC_SUCCESS);
}
