/* TslProblem: unknowns, materials and initial state of a distributed mesh. */
#include "problem_impl.h"
#include <string.h>

static PetscErrorCode SetUpSections(TslProblem p)
{
  TslModel *m = p->m;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(m->nelem, &p->esec));
  for (PetscInt s = 0; s < m->nsection; s++) {
    const TslSection *sec = &m->sections[s];
    PetscInt          k   = TslModelFindElementSet(m, sec->elset);

    if (k < 0) continue; /* the set has no element on this rank */
    for (PetscInt i = 0; i < m->elsets[k].n; i++) {
      PetscInt e = TslModelElementIndex(m, m->elsets[k].ids[i]);
      if (e >= 0)
        p->esec[e] = (TslElementSection){&m->materials[sec->material_index], sec->thickness > 0 ? sec->thickness : 1.0, sec->shell_points,
                                         sec->thickness_modulus, sec->shell_stack};
    }
  }
  for (PetscInt e = 0; e < m->nelem; e++)
    PetscCheck(p->esec[e].mat, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "element %" PetscInt_FMT " has no section (*SOLID SECTION or *SHELL SECTION)",
               m->elem_id[e]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The dof layout from the element rows: every row of the model must have the same nodal unknowns (the
 * deck check rejects a mix), so the first element of any rank gives it; ranks without elements take it
 * from the others. */
static PetscErrorCode SetUpLayout(TslProblem p)
{
  PetscInt mine[1 + 2 * TSL_MAX_NODE_DOF] = {0}, all[1 + 2 * TSL_MAX_NODE_DOF];

  PetscFunctionBeginUser;
  if (p->m->nelem > 0) {
    const TslElementType *t = TslElementTypeGet(p->m->elem_type[0]);
    mine[0]                 = t->ndof;
    for (PetscInt i = 0; i < t->ndof; i++) mine[1 + i] = t->node_dof[i], mine[1 + TSL_MAX_NODE_DOF + i] = t->extra_dof[i];
  }
  PetscCall(MPIU_Allreduce(mine, all, 1 + 2 * TSL_MAX_NODE_DOF, MPIU_INT, MPI_MAX, p->comm));
  PetscCheck(all[0] > 0, p->comm, PETSC_ERR_USER_INPUT, "the model has no elements");
  p->ndof = all[0];
  p->nu   = p->ndof - 1;
  for (PetscInt i = 0; i < p->ndof; i++) p->node_dof[i] = all[1 + i], p->extra_dof[i] = all[1 + TSL_MAX_NODE_DOF + i];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Extra nodes (the last nextra nodes of each element whose row has them) and the pinned slots. */
static PetscErrorCode SetUpExtraNodes(TslProblem p)
{
  PetscFunctionBeginUser;
  PetscCall(PetscCalloc2(p->nn, &p->extra, p->nn * p->ndof, &p->pinned));
  for (PetscInt e = 0; e < p->m->nelem; e++) {
    const TslElementType *t = TslElementTypeGet(p->m->elem_type[e]);
    for (PetscInt k = p->m->elem_ptr[e + 1] - t->nextra; k < p->m->elem_ptr[e + 1]; k++) p->extra[p->elem_lnode[k]] = 1;
  }
  for (PetscInt l = 0; l < p->nn; l++)
    for (PetscInt i = 0; i < p->ndof; i++) p->pinned[l * p->ndof + i] = (char)((p->extra[l] ? p->extra_dof[i] : p->node_dof[i]) == 0);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscInt TslProblemDofSlot(TslProblem p, PetscInt dof)
{
  for (PetscInt i = 0; i < p->ndof; i++)
    if (p->node_dof[i] == dof) return i;
  return -1;
}

PetscInt TslProblemNodeDofSlot(TslProblem p, PetscInt l, PetscInt dof)
{
  const PetscInt *list = p->extra[l] ? p->extra_dof : p->node_dof;
  if (dof <= 0) return -1;
  for (PetscInt i = 0; i < p->ndof; i++)
    if (list[i] == dof) return i;
  return -1;
}

static PetscErrorCode SetUpInitialTemperature(TslProblem p)
{
  TslModel *m = p->m;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(p->nn, &p->theta_init));
  for (PetscInt i = 0; i < m->ninit; i++) {
    const TslInitialTemperature *ic = &m->init[i];
    if (ic->target.set[0]) {
      PetscInt k = TslModelFindNodeSet(m, ic->target.set);
      if (k < 0) continue;
      for (PetscInt j = 0; j < m->nsets[k].n; j++) {
        PetscInt n = TslModelNodeIndex(m, m->nsets[k].ids[j]);
        if (n >= 0) p->theta_init[n] = ic->value;
      }
    } else {
      PetscInt n = TslModelNodeIndex(m, ic->target.id);
      if (n >= 0) p->theta_init[n] = ic->value;
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Abaqus/Explicit starts the central differences from the given velocities (Theory Guide, "Explicit dynamic
 * analysis": v_{+1/2} = v_0 + dt/2 a_0); a prescribed dof moves as its boundary condition says, so the
 * condition wins there. Lines are applied in deck order (a later one for the same dof wins); only owned
 * nodes are written, so each dof is set and counted once. */
PetscErrorCode TslProblemInitialVelocity(TslProblem p, Vec V, PetscInt *held)
{
  const TslModel *m = p->m;
  PetscScalar    *v;
  PetscInt        loc = 0;

  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(V));
  PetscCall(VecGetArray(V, &v));
  for (PetscInt i = 0; i < m->nvinit; i++) {
    const TslInitialVelocity *iv  = &m->vinit[i];
    const PetscInt            set = iv->target.set[0] ? TslModelFindNodeSet(m, iv->target.set) : -1;
    const PetscInt            n   = iv->target.set[0] ? (set >= 0 ? m->nsets[set].n : 0) : 1;
    for (PetscInt j = 0; j < n; j++) {
      PetscInt l = TslModelNodeIndex(m, set >= 0 ? m->nsets[set].ids[j] : iv->target.id), slot;
      if (l < 0 || l >= p->nown) continue;
      slot = TslProblemNodeDofSlot(p, l, iv->dof);
      if (slot >= 0 && slot < p->nu) v[l * p->ndof + slot] = iv->value;
    }
  }
  for (PetscInt d = 0; d < p->nown * p->ndof; d++)
    if ((p->pinned[d] || p->bc[d].active) && v[d] != 0) v[d] = 0, loc++;
  PetscCall(VecRestoreArray(V, &v));
  PetscCall(MPIU_Allreduce(&loc, held, 1, MPIU_INT, MPI_SUM, p->comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The near-null space of the displacement block for algebraic multigrid: the rigid-body modes that the
 * element rows admit (translations and rotations), evaluated at the owned nodes relative to the model's
 * centre (coordinates far from the origin must not swamp the rotations), orthonormalised, and attached to
 * the displacement index set, where PCFIELDSPLIT hands it to the u block's preconditioner (GAMG builds
 * its coarse spaces from it, BoomerAMG its interpolation vectors). Kinematics with fewer rigid modes than
 * displacement components (axisymmetric: only the axial translation) get none: AMG's default of one
 * constant per component serves them better than an incomplete set. Slots a node does not use and
 * reference nodes stay zero. Collective. */
static PetscErrorCode SetUpNearNullSpace(TslProblem p)
{
  const TslModel *m = p->m;
  PetscInt        nm = 0, nmg;
  PetscReal       c[4] = {0, 0, 0, 0}, cg[4];
  PetscScalar    *a[6];
  PetscBool      *done;
  Vec             v[6];
  MatNullSpace    sp;

  PetscFunctionBeginUser;
  /* the same kinematics throughout the model (deck check): its mode count from any local element */
  if (m->nelem > 0) {
    PetscReal modes[6][3] = {{0}}, x[3] = {0, 0, 0};
    nm = TslElementTypeRigidModes(TslElementTypeGet(m->elem_type[0]), x, modes);
  }
  PetscCall(MPIU_Allreduce(&nm, &nmg, 1, MPIU_INT, MPI_MAX, p->comm)); /* a rank without elements has 0 */
  nm = nmg;
  if (nm < p->nu || p->nu == 0) PetscFunctionReturn(PETSC_SUCCESS); /* none, or no displacement block (heat transfer) */
  for (PetscInt n = 0; n < p->nown; n++) {
    for (PetscInt d = 0; d < 3; d++) c[d] += m->node_xyz[3 * n + d];
    c[3] += 1;
  }
  PetscCall(MPIU_Allreduce(c, cg, 4, MPIU_REAL, MPIU_SUM, p->comm));
  for (PetscInt d = 0; d < 3; d++) cg[d] /= PetscMax(cg[3], 1);
  for (PetscInt k = 0; k < nm; k++) {
    PetscCall(VecCreateMPI(p->comm, p->nown * p->nu, PETSC_DETERMINE, &v[k]));
    PetscCall(VecSetBlockSize(v[k], p->nu));
    PetscCall(VecSet(v[k], 0));
    PetscCall(VecGetArray(v[k], &a[k]));
  }
  PetscCall(PetscCalloc1(p->nown, &done));
  for (PetscInt e = 0; e < m->nelem; e++) {
    const TslElementType *t = TslElementTypeGet(m->elem_type[e]);
    for (PetscInt j = 0; j < t->geom->nnode; j++) {
      PetscInt  l           = p->elem_lnode[m->elem_ptr[e] + j];
      PetscReal modes[6][3] = {{0}}, x[3];
      if (l >= p->nown || done[l]) continue;
      done[l] = PETSC_TRUE;
      for (PetscInt d = 0; d < 3; d++) x[d] = m->node_xyz[3 * l + d] - cg[d];
      (void)TslElementTypeRigidModes(t, x, modes);
      for (PetscInt k = 0; k < nm; k++)
        for (PetscInt i = 0; i < p->nu; i++)
          if (!p->pinned[l * p->ndof + i]) a[k][l * p->nu + i] = modes[k][i];
    }
  }
  PetscCall(PetscFree(done));
  for (PetscInt k = 0; k < nm; k++) PetscCall(VecRestoreArray(v[k], &a[k]));
  /* modified Gram-Schmidt (MatNullSpaceCreate wants orthonormal vectors) */
  for (PetscInt k = 0; k < nm; k++) {
    PetscReal nrm;
    for (PetscInt j = 0; j < k; j++) {
      PetscScalar dot;
      PetscCall(VecDot(v[k], v[j], &dot));
      PetscCall(VecAXPY(v[k], -dot, v[j]));
    }
    PetscCall(VecNormalize(v[k], &nrm));
    PetscCheck(nrm > 0, p->comm, PETSC_ERR_PLIB, "rigid-body mode %" PetscInt_FMT " vanishes", k);
  }
  PetscCall(MatNullSpaceCreate(p->comm, PETSC_FALSE, nm, v, &sp));
  PetscCall(PetscObjectCompose((PetscObject)p->is_u, "nearnullspace", (PetscObject)sp));
  PetscCall(MatNullSpaceDestroy(&sp));
  for (PetscInt k = 0; k < nm; k++) PetscCall(VecDestroy(&v[k]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode SetUpVectors(TslProblem p)
{
  TslModel    *m = p->m;
  PetscInt    *ghost, *idx;
  PetscScalar *x;
  Vec          xl;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(p->nn - p->nown, &ghost));
  for (PetscInt i = p->nown; i < p->nn; i++) ghost[i - p->nown] = m->node_gnum[i];
  PetscCall(VecCreateGhostBlock(p->comm, p->ndof, p->ndof * p->nown, PETSC_DECIDE, p->nn - p->nown, ghost, &p->X));
  PetscCall(PetscFree(ghost));
  PetscCall(PetscObjectSetName((PetscObject)p->X, "solution"));
  PetscCall(VecDuplicate(p->X, &p->Xold));
  PetscCall(VecDuplicate(p->X, &p->Xl));
  PetscCall(VecDuplicate(p->X, &p->Rraw));
  PetscCall(VecDuplicate(p->X, &p->Fl));
  PetscCall(VecGetOwnershipRange(p->X, &p->rstart, NULL));
  PetscCheck(p->nown == 0 || p->rstart == m->node_gnum[0] * p->ndof, PETSC_COMM_SELF, PETSC_ERR_PLIB, "node numbering is not contiguous per rank");
  PetscCall(ISLocalToGlobalMappingCreate(p->comm, p->ndof, p->nn, m->node_gnum, PETSC_COPY_VALUES, &p->l2g));
  PetscCall(ISLocalToGlobalMappingCreate(p->comm, 1, p->nn, m->node_gnum, PETSC_COPY_VALUES, &p->l2g_node));

  /* initial state: u = 0, theta = initial temperature */
  PetscCall(VecGhostGetLocalForm(p->X, &xl));
  PetscCall(VecGetArray(xl, &x));
  for (PetscInt n = 0; n < p->nn; n++) {
    for (PetscInt c = 0; c < p->ndof - 1; c++) x[n * p->ndof + c] = 0;
    x[n * p->ndof + p->ndof - 1] = p->pinned[n * p->ndof + p->ndof - 1] ? 0 : p->theta_init[n];
  }
  PetscCall(VecRestoreArray(xl, &x));
  PetscCall(VecGhostRestoreLocalForm(p->X, &xl));
  PetscCall(VecCopy(p->X, p->Xold));

  /* field index sets over owned dofs */
  PetscCall(PetscMalloc1(p->nown * p->nu, &idx));
  for (PetscInt n = 0; n < p->nown; n++)
    for (PetscInt c = 0; c < p->nu; c++) idx[n * p->nu + c] = p->rstart + n * p->ndof + c;
  PetscCall(ISCreateGeneral(p->comm, p->nown * p->nu, idx, PETSC_OWN_POINTER, &p->is_u));
  if (p->nu) PetscCall(ISSetBlockSize(p->is_u, p->nu)); /* a heat-transfer model's is_u is empty */
  PetscCall(ISCreateStride(p->comm, p->nown, p->rstart + p->ndof - 1, p->ndof, &p->is_theta));
  PetscCall(SetUpNearNullSpace(p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Local node of a global node number: owned nodes are contiguous, ghosts are sorted by number. */
PetscErrorCode TslProblemLocalNode(TslProblem p, PetscInt gnum, PetscInt *lnode)
{
  PetscInt first = p->nown > 0 ? p->m->node_gnum[0] : -1, loc;

  PetscFunctionBeginUser;
  *lnode = -1;
  if (p->nown > 0 && gnum >= first && gnum < first + p->nown) {
    *lnode = gnum - first;
  } else {
    PetscCall(PetscFindInt(gnum, p->nn - p->nown, p->m->node_gnum + p->nown, &loc));
    if (loc >= 0) *lnode = p->nown + loc;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Local dofs of every equation term and the map from an eliminated dof to its equation. Chained
 * equations (an eliminated dof appearing in another equation) are rejected. */
static PetscErrorCode SetUpEquations(TslProblem p)
{
  TslModel *m = p->m;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(p->nn * p->ndof, &p->dep));
  for (PetscInt d = 0; d < p->nn * p->ndof; d++) p->dep[d] = -1;
  PetscCall(PetscCalloc1(m->nequation, &p->eq_ldof));
  for (PetscInt q = 0; q < m->nequation; q++) {
    TslEquation *eq = &m->equations[q];
    char         loc[PETSC_MAX_PATH_LEN + 32];
    PetscCheck(eq->gdof, PETSC_COMM_SELF, PETSC_ERR_PLIB, "equation without global dofs");
    PetscCheck(eq->coef[0] != 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: the first coefficient of an *EQUATION must not be zero",
               TslLocString(m, eq->loc, loc, sizeof(loc)));
    PetscBool complete = PETSC_TRUE;
    PetscCall(PetscMalloc1(eq->n, &p->eq_ldof[q]));
    for (PetscInt t = 0; t < eq->n; t++) {
      PetscInt n;
      PetscCall(TslProblemLocalNode(p, eq->gdof[t] / p->ndof, &n));
      if (n < 0) complete = PETSC_FALSE;
      p->eq_ldof[q][t] = n * p->ndof + eq->gdof[t] % p->ndof;
    }
    /* the distribution brings every term of an equation whose eliminated dof is used here; an
     * equation seen only through such a brought-in node is not needed on this rank */
    if (!complete) {
      PetscCall(PetscFree(p->eq_ldof[q]));
      continue;
    }
    PetscCheck(p->dep[p->eq_ldof[q][0]] < 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
               "%s: node %" PetscInt_FMT " dof %" PetscInt_FMT " is already eliminated by another *EQUATION",
               TslLocString(m, eq->loc, loc, sizeof(loc)), eq->node[0], eq->dof[0]);
    p->dep[p->eq_ldof[q][0]] = q;
  }
  for (PetscInt q = 0; q < m->nequation; q++)
    for (PetscInt t = 1; p->eq_ldof[q] && t < m->equations[q].n; t++) {
      char loc[PETSC_MAX_PATH_LEN + 32];
      PetscCheck(p->dep[p->eq_ldof[q][t]] < 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
                 "%s: node %" PetscInt_FMT " dof %" PetscInt_FMT " is eliminated by another *EQUATION; chained equations are not supported",
                 TslLocString(m, m->equations[q].loc, loc, sizeof(loc)), m->equations[q].node[t], m->equations[q].dof[t]);
    }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The part of the set-up that involves this rank only. */
static PetscErrorCode SetUpLocal(TslProblem p)
{
  const TslModel *local = p->m;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < local->elem_ptr[local->nelem]; k++) {
    p->elem_lnode[k] = TslModelNodeIndex(local, local->elem_conn[k]);
    PetscCheck(p->elem_lnode[k] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "element node %" PetscInt_FMT " missing on this rank", local->elem_conn[k]);
  }
  PetscCall(SetUpExtraNodes(p));
  PetscCall(SetUpSections(p));
  PetscCall(SetUpInitialTemperature(p));
  PetscCall(SetUpEquations(p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The plastic elements' state (TslMaterialPlasticState reals at each mechanical point), zero: no plastic strain yet. */
static PetscErrorCode SetUpPlasticState(TslProblem p)
{
  PetscInt n = 0;

  PetscFunctionBeginUser;
  for (PetscInt e = 0; e < p->m->nelem; e++)
    if (TslMaterialIsPlastic(p->esec[e].mat) && TslElementTypeGet(p->m->elem_type[e])->ndof > 1) n++;
  if (!n) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscMalloc1(p->m->nelem, &p->pstate_off));
  n = 0;
  for (PetscInt e = 0; e < p->m->nelem; e++) {
    const TslElementType *t = TslElementTypeGet(p->m->elem_type[e]);
    p->pstate_off[e]        = TslMaterialIsPlastic(p->esec[e].mat) && t->ndof > 1 ? n : -1; /* a heat-transfer type has no mechanics */
    if (p->pstate_off[e] >= 0) n += TslMaterialPlasticState(p->esec[e].mat) * TslElementTypeMechanicalPoints(t, &p->esec[e]);
  }
  p->npstate = n;
  PetscCall(PetscCalloc1(n, &p->pstate)); /* two blocks, not one: TslProblemCommitState swaps them */
  PetscCall(PetscCalloc1(n, &p->pstate_new));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The temperatures a material's plastic data cover, [lo, hi] (every table's range: the narrowest), FALSE if they do
 * not depend on temperature. */
static PetscBool PlasticCover(const TslPlasticTable *t, PetscReal *lo, PetscReal *hi)
{
  PetscBool dep = PETSC_FALSE;

  *lo = PETSC_MIN_REAL, *hi = PETSC_MAX_REAL;
  if (t->n > 1 && t->row[t->n - 1][2] != t->row[0][2]) *lo = PetscMax(*lo, t->row[0][2]), *hi = PetscMin(*hi, t->row[t->n - 1][2]), dep = PETSC_TRUE;
  if (t->nvoce > 1) *lo = PetscMax(*lo, t->voce[0][3]), *hi = PetscMin(*hi, t->voce[t->nvoce - 1][3]), dep = PETSC_TRUE;
  if (t->nkt > 1) *lo = PetscMax(*lo, t->kt_theta[0]), *hi = PetscMin(*hi, t->kt_theta[t->nkt - 1]), dep = PETSC_TRUE;
  return dep;
}

PetscErrorCode TslProblemPlasticTemperatureCheck(TslProblem p, PetscInt s)
{
  TslModel          *m = p->m;
  const PetscInt     nm = m->nmaterial;
  PetscReal         *ext, *g;
  Vec                xl;
  const PetscScalar *xa;

  PetscFunctionBeginUser;
  { /* collective: whether any material is plastic, the same on every rank (a rank may hold no plastic element) */
    PetscBool any = PETSC_FALSE;
    for (PetscInt k = 0; k < nm; k++) any = (PetscBool)(any || TslMaterialIsPlastic(&m->materials[k]));
    if (!any) PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (!p->plastic_warned) PetscCall(PetscCalloc1(nm, &p->plastic_warned));
  PetscCall(PetscMalloc2(2 * nm, &ext, 2 * nm, &g));
  for (PetscInt k = 0; k < nm; k++) ext[2 * k] = PETSC_MAX_REAL, ext[2 * k + 1] = PETSC_MAX_REAL; /* min theta, min -theta */
  PetscCall(TslProblemGetLocalSolution(p, &xl, &xa));
  for (PetscInt e = 0; e < m->nelem; e++) {
    const TslMaterial *mat = p->esec[e].mat;
    const PetscInt     k   = (PetscInt)(mat - m->materials);
    if (!p->pstate_off || p->pstate_off[e] < 0 || k < 0 || k >= nm) continue;
    for (PetscInt j = m->elem_ptr[e]; j < m->elem_ptr[e + 1]; j++) {
      const PetscInt  l = p->elem_lnode[j], c = TslProblemNodeDofSlot(p, l, 11);
      const PetscReal T = c >= 0 ? PetscRealPart(xa[l * p->ndof + c]) : 0;
      if (c < 0) continue;
      ext[2 * k] = PetscMin(ext[2 * k], T), ext[2 * k + 1] = PetscMin(ext[2 * k + 1], -T);
    }
  }
  PetscCall(TslProblemRestoreLocalSolution(p, &xl, &xa));
  PetscCall(MPIU_Allreduce(ext, g, 2 * nm, MPIU_REAL, MPIU_MIN, p->comm));
  for (PetscInt k = 0; k < nm; k++) {
    PetscReal lo, hi, tmin = g[2 * k], tmax = -g[2 * k + 1];
    char      where[256];
    if (p->plastic_warned[k] || tmin > tmax || !PlasticCover(&m->materials[k].plastic, &lo, &hi)) continue;
    if (tmin >= lo - 1e-9 * (hi - lo) && tmax <= hi + 1e-9 * (hi - lo)) continue;
    p->plastic_warned[k] = PETSC_TRUE;
    (void)TslLocString(m, m->materials[k].plastic.loc, where, sizeof(where));
    {
      char reach[64];
      if (tmin == tmax) (void)PetscSNPrintf(reach, sizeof(reach), "%g", (double)tmin);
      else (void)PetscSNPrintf(reach, sizeof(reach), "%g to %g", (double)tmin, (double)tmax);
      PetscCall(PetscPrintf(p->comm, "warning: %s: material %s: its plastic data cover temperatures %g to %g, and step %" PetscInt_FMT " reached %s: the end values hold outside, as in the dialect\n",
                            where, m->materials[k].name, (double)lo, (double)hi, s + 1, reach));
    }
  }
  PetscCall(PetscFree2(ext, g));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemCommitState(TslProblem p)
{
  PetscReal *s = p->pstate;

  PetscFunctionBeginUser;
  p->pstate     = p->pstate_new;
  p->pstate_new = s;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemCreate(MPI_Comm comm, TslModel *local, TslProblem *prob)
{
  TslProblem p;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&p));
  p->comm = comm;
  p->m    = local;
  p->dim  = local->dim;
  p->nn   = local->nnode;
  p->nown = local->nnode_owned;
  p->step = -1;
  PetscCall(PetscMalloc1(local->elem_ptr[local->nelem], &p->elem_lnode));
  PetscCall(TslInjectSetFromOptions(comm, &p->inject));
  PetscCall(SetUpLayout(p));
  {
    /* checks that can fail on one rank come before the first collective call, and all ranks agree on
     * their outcome */
    PetscErrorCode e;
    TslFailure     fail;
    PetscCall(TslCaptureBegin());
    e = SetUpLocal(p);
    PetscCall(TslCaptureEnd());
    PetscCall(TslAgree(comm, e, &fail, NULL));
    PetscCheck(!fail, comm, PETSC_ERR_PLIB, "problem set-up failed");
  }
  PetscCall(SetUpVectors(p));
  PetscCall(PetscCalloc2(p->nn * p->ndof, &p->bc, p->nn * p->ndof, &p->nload));
  PetscCall(PetscCalloc1(local->nelem + 1, &p->face_start));
  PetscCall(TslProblemCheckElements(p));
  PetscCall(SetUpPlasticState(p));
  PetscCall(TslProblemContactSetUp(p));
  *prob = p;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemDestroy(TslProblem *prob)
{
  TslProblem p = *prob;

  PetscFunctionBeginUser;
  if (!p) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(VecDestroy(&p->X));
  PetscCall(VecDestroy(&p->Xold));
  PetscCall(VecDestroy(&p->Xl));
  PetscCall(VecDestroy(&p->Rraw));
  PetscCall(VecDestroy(&p->Fl));
  PetscCall(MatDestroy(&p->J));
  PetscCall(ISLocalToGlobalMappingDestroy(&p->l2g));
  PetscCall(ISLocalToGlobalMappingDestroy(&p->l2g_node));
  PetscCall(ISDestroy(&p->is_u));
  PetscCall(ISDestroy(&p->is_theta));
  PetscCall(PetscFree(p->elem_lnode));
  PetscCall(PetscFree(p->amp_active));
  PetscCall(TslProblemTemperatureFileEnd(p));
  PetscCall(PetscFree(p->esec));
  PetscCall(PetscFree(p->pstate_off));
  PetscCall(PetscFree(p->pstate));
  PetscCall(PetscFree(p->pstate_new));
  PetscCall(PetscFree(p->plastic_warned));
  PetscCall(PetscFree2(p->extra, p->pinned));
  PetscCall(PetscFree(p->theta_init));
  PetscCall(PetscFree2(p->bc, p->nload));
  PetscCall(PetscFree2(p->bc_own, p->nload_own));
  PetscCall(PetscFree(p->face));
  PetscCall(PetscFree(p->face_start));
  if (p->eq_ldof)
    for (PetscInt q = 0; q < p->m->nequation; q++) PetscCall(PetscFree(p->eq_ldof[q]));
  PetscCall(PetscFree(p->eq_ldof));
  PetscCall(PetscFree(p->dep));
  PetscCall(PetscFree(p->pattern_rows));
  PetscCall(PetscFree(p->pattern_pairs.rec)); /* left by a pattern pass that failed */
  PetscCall(PetscFree(p->blk_ptr));
  PetscCall(PetscFree(p->blk));
  PetscCall(TslProblemFastDestroy(p));
  PetscCall(TslProblemContactDestroy(p));
  PetscCall(TslModelDestroy(&p->m));
  PetscCall(PetscFree(p));
  *prob = NULL;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemSetCapacityRate(TslProblem p, PetscReal shift)
{
  PetscFunctionBeginUser;
  p->shift = p->inelastic_rate = shift;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemGetFailureMessage(TslProblem p, const char **msg)
{
  PetscFunctionBeginUser;
  *msg = p->fail_msg;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemGetModel(TslProblem p, const TslModel **model)
{
  PetscFunctionBeginUser;
  *model = p->m;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemGetSolution(TslProblem p, Vec *X)
{
  PetscFunctionBeginUser;
  *X = p->X;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemGetOldSolution(TslProblem p, Vec *Xold)
{
  PetscFunctionBeginUser;
  *Xold = p->Xold;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemGetJacobian(TslProblem p, Mat *J)
{
  PetscFunctionBeginUser;
  *J = p->J;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemSetRepatternCallback(TslProblem p, PetscErrorCode (*fn)(void *), void *ctx)
{
  PetscFunctionBeginUser;
  p->repattern     = fn;
  p->repattern_ctx = ctx;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemGetFieldIS(TslProblem p, IS *is_u, IS *is_theta)
{
  PetscFunctionBeginUser;
  *is_u     = p->is_u;
  *is_theta = p->is_theta;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemMaxTemperatureChange(TslProblem p, PetscReal *dtheta)
{
  const PetscScalar *x, *xo;
  PetscReal          d  = 0;
  const PetscInt     th = p->ndof - 1;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(p->X, &x));
  PetscCall(VecGetArrayRead(p->Xold, &xo));
  /* prescribed temperatures are excluded: their jumps are the user's, not the increment's */
  for (PetscInt n = 0; n < p->nown; n++)
    if (!p->bc[n * p->ndof + th].active) d = PetscMax(d, PetscAbsScalar(x[n * p->ndof + th] - xo[n * p->ndof + th]));
  PetscCall(VecRestoreArrayRead(p->X, &x));
  PetscCall(VecRestoreArrayRead(p->Xold, &xo));
  PetscCall(MPIU_Allreduce(&d, dtheta, 1, MPIU_REAL, MPIU_MAX, p->comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemDisplacementReach(TslProblem p, Vec X, PetscReal *reach)
{
  const PetscScalar *x;
  PetscInt           slot[3];
  PetscReal          loc[7] = {0, PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_MAX_REAL, -PETSC_MAX_REAL, -PETSC_MAX_REAL, -PETSC_MAX_REAL}, g[7];

  PetscFunctionBeginUser;
  for (PetscInt d = 0; d < p->dim; d++) slot[d] = TslProblemDofSlot(p, d + 1);
  PetscCall(VecGetArrayRead(X, &x));
  for (PetscInt n = 0; n < p->nown; n++) {
    if (p->extra[n]) continue; /* a reference node: its dofs are no translations */
    for (PetscInt d = 0; d < p->dim; d++) {
      const PetscReal c = p->m->node_xyz[3 * n + d];
      if (slot[d] >= 0) loc[0] = PetscMax(loc[0], PetscAbsReal(PetscRealPart(x[n * p->ndof + slot[d]])));
      loc[1 + d] = PetscMin(loc[1 + d], c), loc[4 + d] = PetscMax(loc[4 + d], c);
    }
  }
  PetscCall(VecRestoreArrayRead(X, &x));
  for (PetscInt d = 0; d < 3; d++) loc[1 + d] = -loc[1 + d]; /* one MAX reduction for all */
  PetscCall(MPIU_Allreduce(loc, g, 7, MPIU_REAL, MPIU_MAX, p->comm));
  {
    PetscReal diag = 0;
    for (PetscInt d = 0; d < p->dim; d++) diag += PetscSqr(g[4 + d] + g[1 + d]);
    diag   = PetscSqrtReal(diag);
    *reach = diag > 0 ? g[0] / diag : 0; /* a model of one point has no size to compare with */
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemFieldNormsType(TslProblem p, Vec F, NormType type, PetscReal *norm_u, PetscReal *norm_theta)
{
  const PetscScalar *f;
  PetscReal          s[2] = {0, 0}, g[2];
  const PetscBool    inf  = (PetscBool)(type == NORM_INFINITY);

  PetscFunctionBeginUser;
  PetscCheck(type == NORM_2 || inf, p->comm, PETSC_ERR_SUP, "field norms: NORM_2 or NORM_INFINITY");
  PetscCall(VecGetArrayRead(F, &f));
  for (PetscInt n = 0; n < p->nown; n++) {
    for (PetscInt c = 0; c < p->ndof; c++) {
      const PetscReal v = PetscRealPart(f[n * p->ndof + c]);
      const PetscInt  k = c == p->ndof - 1;
      s[k]              = inf ? PetscMax(s[k], PetscAbsReal(v)) : s[k] + v * v;
    }
  }
  PetscCall(VecRestoreArrayRead(F, &f));
  PetscCall(MPIU_Allreduce(s, g, 2, MPIU_REAL, inf ? MPIU_MAX : MPIU_SUM, p->comm));
  *norm_u     = inf ? g[0] : PetscSqrtReal(g[0]);
  *norm_theta = inf ? g[1] : PetscSqrtReal(g[1]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemFieldNorms(TslProblem p, Vec F, PetscReal *norm_u, PetscReal *norm_theta)
{
  PetscFunctionBeginUser;
  PetscCall(TslProblemFieldNormsType(p, F, NORM_2, norm_u, norm_theta));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemSetElementFlux(TslProblem p, PetscBool on)
{
  PetscFunctionBeginUser;
  p->flux_on = on;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemElementFlux(TslProblem p, PetscReal q[2])
{
  PetscReal s[4] = {p->flux_abs[0], p->flux_abs[1], p->flux_n[0], p->flux_n[1]}, g[4];

  PetscFunctionBeginUser;
  PetscCall(MPIU_Allreduce(s, g, 4, MPIU_REAL, MPIU_SUM, p->comm));
  for (PetscInt k = 0; k < 2; k++) q[k] = g[2 + k] > 0 ? g[k] / g[2 + k] : 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}
