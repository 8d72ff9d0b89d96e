/* Is every body supported? A user error is better than a singular matrix.
 *
 * For each step (boundary conditions carried over as the dialect says), each connected body (elements
 * sharing nodes, or tied by *EQUATION) must have its rigid-body modes removed by prescribed
 * displacements: the Gram matrix of the modes restricted to the prescribed dofs must have full rank
 * (3 modes in plane models, 1 (axial translation) in axisymmetric ones, 6 in 3D). In steady-state steps
 * each body also needs a prescribed temperature, a film or radiation, or its temperature is undetermined.
 * Bodies joined by a contact pair count as one: contact is assumed to hold the secondary body.
 */
#include <thermoslide/problem.h>

static PetscInt Find(PetscInt *parent, PetscInt i)
{
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

static void Union(PetscInt *parent, PetscInt a, PetscInt b)
{
  a = Find(parent, a), b = Find(parent, b);
  if (a != b) parent[PetscMax(a, b)] = PetscMin(a, b);
}

/* Rank of a small symmetric positive semi-definite matrix by pivoted elimination. */
static PetscInt GramRank(PetscInt n, PetscReal G[6][6])
{
  PetscReal tol     = 0;
  PetscInt  rank    = 0;
  PetscBool used[6] = {PETSC_FALSE};

  for (PetscInt i = 0; i < n; i++) tol = PetscMax(tol, G[i][i]);
  tol *= 1e-10;
  for (PetscInt k = 0; k < n; k++) {
    PetscInt  p    = -1;
    PetscReal best = tol;
    for (PetscInt i = 0; i < n; i++)
      if (!used[i] && G[i][i] > best) best = G[i][i], p = i;
    if (p < 0) break;
    used[p] = PETSC_TRUE;
    rank++;
    for (PetscInt i = 0; i < n; i++)
      for (PetscInt j = 0; j < n; j++)
        if (i != p && j != p) G[i][j] -= G[i][p] * G[p][j] / G[p][p];
    for (PetscInt i = 0; i < n; i++) G[i][p] = G[p][i] = 0;
  }
  return rank;
}

/* Nodes (positions) of a node target. */
/* Marks the prescribed slots of a node target; slots are those of the model's nodal unknowns (the rows'
 * node_dof: displacement-like unknowns first, the temperature last). */
static void MarkTarget(const TslModel *g, const TslTarget *t, PetscInt dof_first, PetscInt dof_last, const char *extra, char *fixed)
{
  const TslElementType *t0 = TslElementTypeGet(g->elem_type[0]);
  PetscInt n = 1, k = t->set[0] ? TslModelFindNodeSet(g, t->set) : -1;
  if (k >= 0) n = g->nsets[k].n;
  for (PetscInt i = 0; i < n; i++) {
    PetscInt p = TslModelNodeIndex(g, k >= 0 ? g->nsets[k].ids[i] : t->id);
    if (p < 0 || extra[p]) continue; /* a reference node's dofs are not in-plane displacements */
    for (PetscInt d = dof_first; d <= dof_last; d++)
      for (PetscInt c = 0; c < t0->ndof; c++)
        if (t0->node_dof[c] == d) fixed[TSL_MAX_NODE_DOF * p + c] = 1;
  }
}

/* Elements of a face-load target get the mark bit (the exchanges that fix a steady temperature: film, radiation). */
static void MarkExchange(const TslModel *g, const TslLoad *ld, char bit, char *film)
{
  PetscInt k, n;
  if (ld->target_is_surface) {
    k = TslModelFindSurface(g, ld->target.set);
    for (PetscInt i = 0; k >= 0 && i < g->surfaces[k].n; i++) {
      PetscInt e = TslModelElementIndex(g, g->surfaces[k].elem[i]);
      if (e >= 0) film[e] |= bit;
    }
    return;
  }
  k = ld->target.set[0] ? TslModelFindElementSet(g, ld->target.set) : -1;
  n = k >= 0 ? g->elsets[k].n : 1;
  for (PetscInt i = 0; i < n; i++) {
    PetscInt e = TslModelElementIndex(g, k >= 0 ? g->elsets[k].ids[i] : ld->target.id);
    if (e >= 0) film[e] |= bit;
  }
}

PetscErrorCode TslModelCheckSupports(TslModel *g)
{
  PetscInt  *parent, *first_elem, nn = g->nnode;
  char      *fixed, *film, *thermal, *extra;
  PetscReal *gram;
  PetscInt  *body, nbody = 0, th;
  PetscReal *centre, *size;

  PetscFunctionBeginUser;
  if (g->nelem == 0) PetscFunctionReturn(PETSC_SUCCESS);
  th = TslElementTypeGet(g->elem_type[0])->ndof - 1; /* the temperature's slot; the others are displacements */
  PetscCall(TslModelIndex(g));
  PetscCall(PetscMalloc4(nn, &parent, nn, &first_elem, 4 * nn, &centre, nn, &size));
  PetscCall(PetscCalloc2(TSL_MAX_NODE_DOF * nn, &fixed, g->nelem, &film));
  PetscCall(PetscCalloc1(nn, &extra));
  for (PetscInt e = 0; e < g->nelem; e++) {
    const TslElementType *t = TslElementTypeGet(g->elem_type[e]);
    for (PetscInt k = g->elem_ptr[e + 1] - t->nextra; k < g->elem_ptr[e + 1]; k++) extra[TslModelNodeIndex(g, g->elem_conn[k])] = 1;
  }
  for (PetscInt i = 0; i < nn; i++) parent[i] = i, first_elem[i] = -1;
  for (PetscInt e = 0; e < g->nelem; e++)
    for (PetscInt k = g->elem_ptr[e] + 1; k < g->elem_ptr[e + 1]; k++)
      Union(parent, TslModelNodeIndex(g, g->elem_conn[g->elem_ptr[e]]), TslModelNodeIndex(g, g->elem_conn[k]));
  for (PetscInt q = 0; q < g->nequation; q++)
    for (PetscInt t = 1; t < g->equations[q].n; t++)
      Union(parent, TslModelNodeIndex(g, g->equations[q].node[0]), TslModelNodeIndex(g, g->equations[q].node[t]));
  /* a contact pair supports the secondary body on the main one (assumed closed), a tie (not yet equations:
   * TslMeshTies makes them at partitioning) likewise */
  for (PetscInt k = 0; k < g->npair + g->ntie; k++) {
    PetscInt    nd[2] = {-1, -1};
    const char *sname = k < g->npair ? g->pairs[k].secondary : g->ties[k - g->npair].secondary;
    const char *mname = k < g->npair ? g->pairs[k].main : g->ties[k - g->npair].main;
    for (PetscInt side = 0; side < 2; side++) {
      PetscInt j = TslModelFindSurface(g, side ? mname : sname);
      if (j < 0 || g->surfaces[j].n == 0) continue;
      if (g->surfaces[j].kind == TSL_SURFACE_NODE)
        nd[side] = TslModelNodeIndex(g, g->surfaces[j].elem[0]);
      else {
        PetscInt e = TslModelElementIndex(g, g->surfaces[j].elem[0]);
        if (e >= 0) nd[side] = TslModelNodeIndex(g, g->elem_conn[g->elem_ptr[e]]);
      }
    }
    if (nd[0] >= 0 && nd[1] >= 0) Union(parent, nd[0], nd[1]);
  }
  /* body centre and size (for well-scaled rotation modes); a body's kinematics from one of its elements */
  PetscCall(PetscArrayzero(centre, 4 * nn));
  for (PetscInt e = 0; e < g->nelem; e++) first_elem[Find(parent, TslModelNodeIndex(g, g->elem_conn[g->elem_ptr[e]]))] = e;
  for (PetscInt i = 0; i < nn; i++) {
    PetscInt r = Find(parent, i);
    for (PetscInt c = 0; c < 3; c++) centre[4 * r + c] += g->node_xyz[3 * i + c];
    centre[4 * r + 3] += 1;
  }
  for (PetscInt i = 0; i < nn; i++) size[i] = 0;
  for (PetscInt i = 0; i < nn; i++) {
    PetscInt r = Find(parent, i);
    for (PetscInt c = 0; c < 3; c++) size[r] = PetscMax(size[r], PetscAbsReal(g->node_xyz[3 * i + c] - centre[4 * r + c] / centre[4 * r + 3]));
  }

  /* bodies numbered 0..nbody-1 through their root nodes; Gram matrices per body */
  PetscCall(PetscMalloc1(nn, &body));
  for (PetscInt i = 0; i < nn; i++) body[i] = (Find(parent, i) == i && first_elem[i] >= 0) ? nbody++ : -1;
  PetscCall(PetscMalloc2(36 * nbody, &gram, nbody, &thermal));
  for (PetscInt s = 0; s < g->nstep; s++) {
    const TslStep *step     = &g->steps[s];
    /* film[e]: bit 1 a film, bit 2 radiation, each removed by its own keyword's OP=NEW */
    PetscBool clear_bc   = PETSC_FALSE;
    char      clear_film = 0, loc[PETSC_MAX_PATH_LEN + 32];
    for (PetscInt i = 0; i < step->nload; i++) {
      if (step->loads[i].kind == TSL_LOAD_BOUNDARY && step->loads[i].op_new) clear_bc = PETSC_TRUE;
      if (step->loads[i].kind == TSL_LOAD_FILM && step->loads[i].op_new) clear_film |= 1;
      if (step->loads[i].kind == TSL_LOAD_RADIATE && step->loads[i].op_new) clear_film |= 2;
    }
    if (clear_bc) PetscCall(PetscArrayzero(fixed, TSL_MAX_NODE_DOF * nn));
    for (PetscInt e = 0; clear_film && e < g->nelem; e++) film[e] &= (char)~clear_film;
    for (PetscInt i = 0; i < step->nload; i++) {
      const TslLoad *ld = &step->loads[i];
      if (ld->kind == TSL_LOAD_BOUNDARY) MarkTarget(g, &ld->target, ld->dof_first, ld->dof_last, extra, fixed);
      if (ld->kind == TSL_LOAD_FILM) MarkExchange(g, ld, 1, film);
      if (ld->kind == TSL_LOAD_RADIATE) MarkExchange(g, ld, 2, film);
    }
    /* one pass over the nodes and elements: Gram matrix and thermal support of every body */
    PetscCall(PetscArrayzero(gram, 36 * nbody));
    PetscCall(PetscArrayzero(thermal, nbody));
    for (PetscInt i = 0; i < nn; i++) {
      PetscInt  r = Find(parent, i), nm;
      PetscReal modes[6][3], x[3], *G;
      if (first_elem[r] < 0) continue;
      G = &gram[36 * body[r]];
      if (fixed[TSL_MAX_NODE_DOF * i + th] || step->statik) thermal[body[r]] = 1; /* *STATIC holds every temperature */
      for (PetscInt c = 0; c < 3; c++) x[c] = (g->node_xyz[3 * i + c] - centre[4 * r + c] / centre[4 * r + 3]) / (size[r] > 0 ? size[r] : 1);
      nm = TslElementTypeRigidModes(TslElementTypeGet(g->elem_type[first_elem[r]]), x, modes);
      for (PetscInt d = 0; d < th; d++) {
        if (!fixed[TSL_MAX_NODE_DOF * i + d]) continue;
        for (PetscInt a = 0; a < nm; a++)
          for (PetscInt b = 0; b < nm; b++) G[6 * a + b] += modes[a][d] * modes[b][d];
      }
    }
    for (PetscInt e = 0; e < g->nelem; e++)
      if (film[e]) thermal[body[Find(parent, TslModelNodeIndex(g, g->elem_conn[g->elem_ptr[e]]))]] = 1;
    for (PetscInt r = 0; r < nn; r++) {
      PetscReal modes[6][3], x[3] = {0, 0, 0}, G[6][6];
      PetscInt  nm;
      if (body[r] < 0) continue;
      nm = TslElementTypeRigidModes(TslElementTypeGet(g->elem_type[first_elem[r]]), x, modes);
      for (PetscInt a = 0; a < 6; a++)
        for (PetscInt b = 0; b < 6; b++) G[a][b] = gram[36 * body[r] + 6 * a + b];
      /* an explicit step integrates the rigid-body motion like any other (no stiffness matrix to invert) */
      PetscCheck(step->explicit_dynamics || GramRank(nm, G) == nm, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
                 "%s: step %" PetscInt_FMT ": the body containing node %" PetscInt_FMT
                 " is not fully supported (it can move as a rigid body, so the stiffness matrix is singular); add *BOUNDARY conditions",
                 TslLocString(g, step->loc, loc, sizeof(loc)), s + 1, g->node_id[r]);
      PetscCheck(thermal[body[r]] || !step->steady, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
                 "%s: step %" PetscInt_FMT ": in this steady-state step the temperature of the body containing node %" PetscInt_FMT
                 " is undetermined; prescribe a temperature (*BOUNDARY dof 11) or add a *FILM",
                 TslLocString(g, step->loc, loc, sizeof(loc)), s + 1, g->node_id[r]);
    }
  }
  PetscCall(PetscFree4(parent, first_elem, centre, size));
  PetscCall(PetscFree2(gram, thermal));
  PetscCall(PetscFree(body));
  PetscCall(PetscFree2(fixed, film));
  PetscCall(PetscFree(extra));
  PetscFunctionReturn(PETSC_SUCCESS);
}
