/* Step loading history: which boundary conditions and loads are active, and their values in time.
 *
 * Dialect semantics (see docs/keywords.md, "Loads across steps"):
 *  - a load or boundary condition stays active in later steps; one that followed a step-time amplitude
 *    (or the step's ramp) is held at the value it reached at the end of its step; total-time amplitudes
 *    keep being followed;
 *  - OP=NEW on any line of a kind removes all earlier loads of that kind at the start of the step;
 *  - a value defined without amplitude ramps from its previous value (or, for a newly prescribed dof,
 *    from the current solution) under AMPLITUDE=RAMP, and applies at once under AMPLITUDE=STEP;
 *  - film coefficients, emissivities and sink (ambient) temperatures apply at once, scaled by their
 *    amplitudes if given;
 *  - *BOUNDARY, FIXED holds the dofs at the values they have at the start of the step.
 */
#include "problem_impl.h"

/* A velocity boundary condition's displacement: u0 + the integral of its velocity since t0 (total time). Its
 * velocity follows the same history as any value (an amplitude, the step's ramp from v0 to v1, or constant). */
static PetscReal EvalVelocityDisplacement(TslProblem p, const TslLoadValue *h)
{
  if (h->amp >= 0) {
    const TslAmplitude *a = &p->m->amplitudes[h->amp];
    return h->u0 + h->v1 * (a->total_time ? TslAmplitudeIntegral(a, h->t0, p->ttot) : TslAmplitudeIntegral(a, 0, p->t));
  }
  if (h->amp == TSL_AMP_HOLD || p->amp_default == TSL_AMP_STEP) return h->u0 + h->v1 * (p->ttot - h->t0);
  return h->u0 + h->v0 * p->t + (h->v1 - h->v0) * (p->period > 0 ? 0.5 * p->t * p->t / p->period : p->t);
}

/* The value's own history (a velocity boundary condition's velocity) at step time t, total time ttot. */
static PetscReal EvalAt(TslProblem p, const TslLoadValue *h, PetscReal t, PetscReal ttot)
{
  if (h->amp >= 0) {
    const TslAmplitude *a = &p->m->amplitudes[h->amp];
    return h->v1 * TslAmplitudeEval(a, a->total_time ? ttot : t);
  }
  if (h->amp == TSL_AMP_HOLD || p->amp_default == TSL_AMP_STEP) return h->v1;
  return h->v0 + (h->v1 - h->v0) * (p->period > 0 ? t / p->period : 1.0);
}

PetscReal TslProblemEvalLoadValue(TslProblem p, const TslLoadValue *h)
{
  if (!h->active) return 0;
  return h->velocity ? EvalVelocityDisplacement(p, h) : EvalAt(p, h, p->t, p->ttot);
}

/* At a step change: the value reached becomes a constant, unless it follows a total-time amplitude. */
static void Freeze(TslProblem p, TslLoadValue *h)
{
  PetscReal v;

  if (!h->active) return;
  if (h->amp >= 0 && p->m->amplitudes[h->amp].total_time) return;
  if (h->velocity) { /* the velocity reached is held, and the displacement goes on from where it is */
    h->u0 = EvalVelocityDisplacement(p, h);
    h->t0 = p->ttot;
    /* the velocity at the step's end exactly (the last increment's time may fall short of it by a rounding):
     * an amplitude that jumps there, as one that stops the motion at the end, gives its later value */
    h->v0 = h->v1 = EvalAt(p, h, p->period > 0 ? p->period : p->t, p->ttot);
    h->amp        = TSL_AMP_HOLD;
    return;
  }
  v     = TslProblemEvalLoadValue(p, h);
  h->v0 = h->v1 = v;
  h->amp        = TSL_AMP_HOLD;
}

/* Starts a new value from the current one. */
static void Redefine(TslLoadValue *h, PetscReal start, PetscReal value, PetscInt amp)
{
  h->v0       = h->active && !h->velocity ? h->v1 : start;
  h->v1       = value;
  h->amp      = amp;
  h->active   = PETSC_TRUE;
  h->velocity = PETSC_FALSE;
  h->held     = PETSC_FALSE; /* a *STATIC step's own *BOUNDARY on a temperature: prescribed, not held */
  h->file     = PETSC_FALSE; /* and no longer read from a *TEMPERATURE, FILE= */
}

/* Starts a velocity from the current one (0 for a dof that was not moving by a velocity), the displacement
 * from the dof's current value u at total time t0. */
static void RedefineVelocity(TslLoadValue *h, PetscReal u, PetscReal t0, PetscReal value, PetscInt amp)
{
  h->v0       = h->active && h->velocity ? h->v1 : 0;
  h->v1       = value;
  h->amp      = amp;
  h->active   = PETSC_TRUE;
  h->velocity = PETSC_TRUE;
  h->held     = PETSC_FALSE;
  h->file     = PETSC_FALSE;
  h->u0       = u;
  h->t0       = t0;
}

/* Local nodes of a node target (set members present here, or one id). Returns a list to free. */
static PetscErrorCode TargetNodes(TslProblem p, const TslTarget *t, PetscInt *n, PetscInt **nodes)
{
  TslModel *m = p->m;

  PetscFunctionBeginUser;
  *n = 0;
  if (t->set[0]) {
    PetscInt k = TslModelFindNodeSet(m, t->set);
    PetscCall(PetscMalloc1(k >= 0 ? m->nsets[k].n : 0, nodes));
    if (k >= 0)
      for (PetscInt i = 0; i < m->nsets[k].n; i++) {
        PetscInt l = TslModelNodeIndex(m, m->nsets[k].ids[i]);
        if (l >= 0) (*nodes)[(*n)++] = l;
      }
  } else {
    PetscInt l = TslModelNodeIndex(m, t->id);
    PetscCall(PetscMalloc1(1, nodes));
    if (l >= 0) (*nodes)[(*n)++] = l;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Local (element, face) pairs of a face-load target. */
static PetscErrorCode TargetFaces(TslProblem p, const TslLoad *ld, PetscInt *n, PetscInt **elem, PetscInt **face)
{
  TslModel *m = p->m;
  PetscInt  k, cap;

  PetscFunctionBeginUser;
  *n = 0;
  if (ld->target_is_surface) {
    k   = TslModelFindSurface(m, ld->target.set);
    cap = k >= 0 ? m->surfaces[k].n : 0;
    PetscCall(PetscMalloc2(cap, elem, cap, face));
    for (PetscInt i = 0; i < cap; i++) {
      PetscInt e = TslModelElementIndex(m, m->surfaces[k].elem[i]);
      if (e >= 0) (*elem)[*n] = e, (*face)[(*n)++] = m->surfaces[k].face[i];
    }
  } else if (ld->target.set[0]) {
    k   = TslModelFindElementSet(m, ld->target.set);
    cap = k >= 0 ? m->elsets[k].n : 0;
    PetscCall(PetscMalloc2(cap, elem, cap, face));
    for (PetscInt i = 0; i < cap; i++) {
      PetscInt e = TslModelElementIndex(m, m->elsets[k].ids[i]);
      if (e >= 0) (*elem)[*n] = e, (*face)[(*n)++] = ld->face;
    }
  } else {
    PetscInt e = TslModelElementIndex(m, ld->target.id);
    PetscCall(PetscMalloc2(1, elem, 1, face));
    if (e >= 0) (*elem)[*n] = e, (*face)[(*n)++] = ld->face;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static int CompareFace(const void *a, const void *b)
{
  const TslFaceRecord *x = a, *y = b;
  if (x->elem != y->elem) return x->elem < y->elem ? -1 : 1;
  if (x->face != y->face) return x->face < y->face ? -1 : 1;
  if (x->kind != y->kind) return x->kind < y->kind ? -1 : 1;
  return x->seq < y->seq ? -1 : (x->seq > y->seq);
}

/* The owned dofs with a prescribed value and those with a nodal load, as lists: the loops of every
 * increment (TslProblemApplyPrescribed, the nodal loads of the residual and of the explicit forces) visit
 * these alone instead of reading every dof's record (32 bytes a dof: 17 MB per pass at a million unknowns). */
static PetscErrorCode ActiveDofs(TslProblem p)
{
  const PetscInt n = p->nown * p->ndof;

  PetscFunctionBeginUser;
  PetscCall(PetscFree2(p->bc_own, p->nload_own));
  p->nbc_own = p->nnload_own = 0;
  for (PetscInt d = 0; d < n; d++) p->nbc_own += p->bc[d].active ? 1 : 0, p->nnload_own += p->nload[d].active ? 1 : 0;
  PetscCall(PetscMalloc2(p->nbc_own, &p->bc_own, p->nnload_own, &p->nload_own));
  p->nbc_own = p->nnload_own = 0;
  for (PetscInt d = 0; d < n; d++) {
    if (p->bc[d].active) p->bc_own[p->nbc_own++] = d;
    if (p->nload[d].active) p->nload_own[p->nnload_own++] = d;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Sorts face records by element, keeps the latest definition of each (element, face, kind), and
 * builds the per-element index. A redefined load starts from the value the earlier one had. */
static PetscErrorCode CompactFaces(TslProblem p)
{
  PetscInt n = 0;

  PetscFunctionBeginUser;
  if (p->nface) qsort(p->face, (size_t)p->nface, sizeof(TslFaceRecord), CompareFace);
  for (PetscInt i = 0; i < p->nface; i++) {
    TslFaceRecord *r = &p->face[i];
    if (n > 0 && p->face[n - 1].elem == r->elem && p->face[n - 1].face == r->face && p->face[n - 1].kind == r->kind) {
      TslFaceRecord *prev = &p->face[n - 1];
      if (r->value.amp == TSL_AMP_DEFAULT) r->value.v0 = prev->value.v1;
      *prev = *r;
    } else
      p->face[n++] = *r;
  }
  p->nface = n;
  p->face_gen++;
  for (PetscInt e = 0; e <= p->m->nelem; e++) p->face_start[e] = 0;
  for (PetscInt i = 0; i < n; i++) p->face_start[p->face[i].elem + 1]++;
  for (PetscInt e = 0; e < p->m->nelem; e++) p->face_start[e + 1] += p->face_start[e];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The keyword of each distributed load kind: its OP=NEW removes them. */
static const TslLoadKind face_keyword[] = {
    [TSL_FACE_PRESSURE] = TSL_LOAD_DLOAD, [TSL_FACE_FLUX] = TSL_LOAD_DFLUX, [TSL_FACE_FILM] = TSL_LOAD_FILM,
    [TSL_BODY_FLUX] = TSL_LOAD_DFLUX,     [TSL_BODY_GRAV] = TSL_LOAD_DLOAD, [TSL_BODY_CENTRIF] = TSL_LOAD_DLOAD,
    [TSL_FACE_RADIATION] = TSL_LOAD_RADIATE};

/* The kind of each *DLOAD: a pressure or one of the body forces. */
static const TslFaceLoadKind dload_kind[] = {
    [TSL_DLOAD_FACE] = TSL_FACE_PRESSURE, [TSL_DLOAD_GRAV] = TSL_BODY_GRAV, [TSL_DLOAD_CENTRIF] = TSL_BODY_CENTRIF};

static PetscErrorCode AddFaceLoads(TslProblem p, const TslLoad *ld)
{
  TslModel       *m = p->m;
  PetscInt        n, *elem, *face;
  TslFaceLoadKind kind = ld->kind == TSL_LOAD_DLOAD                ? dload_kind[ld->dload]
                         : ld->kind == TSL_LOAD_FILM               ? TSL_FACE_FILM
                         : ld->kind == TSL_LOAD_RADIATE            ? TSL_FACE_RADIATION
                         : ld->face == 0 && !ld->target_is_surface ? TSL_BODY_FLUX /* BF; *DSFLUX's S (face 0 too) is on the surface's faces */
                                                                   : TSL_FACE_FLUX;
  char            loc[PETSC_MAX_PATH_LEN + 32];

  PetscFunctionBeginUser;
  PetscCall(TargetFaces(p, ld, &n, &elem, &face));
  PetscCall(PetscRealloc(sizeof(TslFaceRecord) * (size_t)(p->nface + n), &p->face));
  for (PetscInt i = 0; i < n; i++) {
    const TslElementType *type = TslElementTypeGet(m->elem_type[elem[i]]);
    TslFaceRecord        *r    = &p->face[p->nface++];

    PetscCheck(kind == TSL_BODY_FLUX || TslFaceLoadKindIsBodyForce(kind) || (face[i] >= 1 && face[i] <= type->geom->nface), PETSC_COMM_SELF,
               PETSC_ERR_USER_INPUT, "%s: element %" PetscInt_FMT " (%s) has no face %" PetscInt_FMT, TslLocString(m, ld->loc, loc, sizeof(loc)),
               m->elem_id[elem[i]], type->name, face[i]);
    PetscCall(PetscMemzero(r, sizeof(*r)));
    r->elem = elem[i];
    r->face = face[i];
    r->kind = kind;
    r->seq  = p->face_seq++;
    if (kind == TSL_FACE_FILM || kind == TSL_FACE_RADIATION) {
      /* the film coefficient h, or the radiation coefficient sigma eps (the kernels' value) */
      const PetscReal c = kind == TSL_FACE_RADIATION ? m->stefan_boltzmann * ld->value : ld->value;
      r->value          = (TslLoadValue){PETSC_TRUE, c, c, TSL_AMP_HOLD, PETSC_FALSE, 0, 0, PETSC_FALSE, PETSC_FALSE};
      r->sink     = (TslLoadValue){PETSC_TRUE, ld->sink, ld->sink, ld->amplitude >= 0 ? ld->amplitude : TSL_AMP_HOLD, PETSC_FALSE, 0, 0, PETSC_FALSE, PETSC_FALSE};
      r->film_amp = ld->film_amplitude;
    } else {
      r->value    = (TslLoadValue){PETSC_TRUE, 0, ld->value, ld->amplitude >= 0 ? ld->amplitude : TSL_AMP_DEFAULT, PETSC_FALSE, 0, 0, PETSC_FALSE, PETSC_FALSE};
      r->film_amp = -1;
    }
    PetscCall(PetscArraycpy(r->axis, ld->axis, 6));
  }
  PetscCall(PetscFree2(elem, face));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The amplitudes that some load or boundary condition follows in this step, on any rank: increments end
 * on their corners (TslProblemNextAmplitudeCorner). */
static PetscErrorCode MarkActiveAmplitudes(TslProblem p)
{
  PetscInt   na = p->m->namplitude;
  PetscBool *loc;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(na, &loc));
  for (PetscInt d = 0; d < p->nn * p->ndof; d++) {
    if (p->bc[d].active && p->bc[d].amp >= 0) loc[p->bc[d].amp] = PETSC_TRUE;
    if (p->nload[d].active && p->nload[d].amp >= 0) loc[p->nload[d].amp] = PETSC_TRUE;
  }
  for (PetscInt i = 0; i < p->nface; i++) {
    const TslFaceRecord *r = &p->face[i];
    if (r->value.active && r->value.amp >= 0) loc[r->value.amp] = PETSC_TRUE;
    if (r->sink.active && r->sink.amp >= 0) loc[r->sink.amp] = PETSC_TRUE;
    if (r->film_amp >= 0) loc[r->film_amp] = PETSC_TRUE;
  }
  PetscCall(PetscFree(p->amp_active));
  PetscCall(PetscMalloc1(na, &p->amp_active));
  if (na) PetscCall(MPIU_Allreduce(loc, p->amp_active, (PetscMPIInt)na, MPIU_BOOL, MPI_LOR, p->comm));
  PetscCall(PetscFree(loc));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemSetStep(TslProblem p, PetscInt s)
{
  TslModel          *m                      = p->m;
  const TslStep     *step                   = &m->steps[s];
  PetscBool          clear[TSL_LOAD_NKINDS] = {PETSC_FALSE};
  Vec                xl;
  const PetscScalar *x;
  PetscInt           nd = p->nn * p->ndof;

  PetscFunctionBeginUser;
  /* finite strain (the force records and the generic kernels alike: TslElementInput.nlgeom) */
  p->nlgeom = step->nlgeom;
  /* values reached at the end of the previous step */
  for (PetscInt d = 0; d < nd; d++) Freeze(p, &p->bc[d]), Freeze(p, &p->nload[d]), p->bc[d].file = PETSC_FALSE;
  for (PetscInt i = 0; i < p->nface; i++) {
    TslFaceRecord *r = &p->face[i];
    if (r->film_amp >= 0 && !m->amplitudes[r->film_amp].total_time) {
      const TslAmplitude *a = &m->amplitudes[r->film_amp];
      r->value.v0 = r->value.v1 = r->value.v1 * TslAmplitudeEval(a, p->t);
      r->film_amp               = -1;
    }
    Freeze(p, &r->value);
    Freeze(p, &r->sink);
  }

  p->step        = s;
  p->steady      = step->steady;
  p->amp_default = step->amp_default;
  p->period      = step->period;
  p->t           = 0;

  for (PetscInt i = 0; i < step->nload; i++)
    if (step->loads[i].op_new) clear[step->loads[i].kind] = PETSC_TRUE;
  for (PetscInt d = 0; d < nd; d++) {
    PetscBool theta = (d % p->ndof) == p->ndof - 1;
    if (clear[TSL_LOAD_BOUNDARY]) p->bc[d].active = PETSC_FALSE;
    if ((clear[TSL_LOAD_CLOAD] && !theta) || (clear[TSL_LOAD_CFLUX] && theta)) p->nload[d].active = PETSC_FALSE;
  }
  if (clear[TSL_LOAD_DLOAD] || clear[TSL_LOAD_DFLUX] || clear[TSL_LOAD_FILM] || clear[TSL_LOAD_RADIATE]) {
    PetscInt n = 0;
    for (PetscInt i = 0; i < p->nface; i++) {
      if (!clear[face_keyword[p->face[i].kind]]) p->face[n++] = p->face[i];
    }
    p->nface = n;
    p->face_gen++;
  }

  PetscCall(TslGhostUpdate(p->X, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGhostGetLocalForm(p->X, &xl));
  PetscCall(VecGetArrayRead(xl, &x));
  /* *STATIC: every temperature not prescribed otherwise is held at its value now (the step's own *BOUNDARY on
   * dof 11, below, redefines it); a hold ends with its step, the temperature dofs then free again */
  for (PetscInt l = 0; l < p->nn; l++) {
    const PetscInt c = TslProblemNodeDofSlot(p, l, 11), d = l * p->ndof + c;
    if (c < 0) continue;
    if (p->bc[d].held) p->bc[d].active = p->bc[d].held = PETSC_FALSE;
    if (step->statik && !p->bc[d].active && p->dep[d] < 0)
      p->bc[d] = (TslLoadValue){PETSC_TRUE, PetscRealPart(x[d]), PetscRealPart(x[d]), TSL_AMP_HOLD, PETSC_FALSE, 0, 0, PETSC_TRUE, PETSC_FALSE};
  }
  /* *TEMPERATURE, FILE=: every temperature from the file (tfile.c), part of the step's hold as *TEMPERATURE is; one
   * frame is the step's target (ramped or stepped as the step's amplitude says), several are followed in time
   * (TslProblemSetTime); the step's own *BOUNDARY or *TEMPERATURE lines on a node, below, replace it there */
  PetscCall(TslProblemTemperatureFileBegin(p, s, x));
  if (step->tfile.given) {
    const PetscReal *T;
    const PetscBool  one = p->tfile.nwin == 1 ? PETSC_TRUE : PETSC_FALSE;
    PetscCall(TslProblemTemperatureFileAt(p, one ? PETSC_MAX_REAL : 0, &T)); /* one frame: that frame; several: the start */
    for (PetscInt l = 0; l < p->nn; l++) {
      const PetscInt c = TslProblemNodeDofSlot(p, l, 11), d = l * p->ndof + c;
      if (c < 0 || p->dep[d] >= 0) continue;
      if (one) Redefine(&p->bc[d], PetscRealPart(x[d]), T[l], step->tfile.amplitude >= 0 ? step->tfile.amplitude : TSL_AMP_DEFAULT);
      else p->bc[d] = (TslLoadValue){PETSC_TRUE, T[l], T[l], TSL_AMP_HOLD, PETSC_FALSE, 0, 0, PETSC_FALSE, PETSC_TRUE};
      p->bc[d].held = PETSC_TRUE;
    }
  }
  for (PetscInt i = 0; i < step->nload; i++) {
    const TslLoad *ld  = &step->loads[i];
    PetscInt       amp = ld->amplitude >= 0 ? ld->amplitude : TSL_AMP_DEFAULT;

    switch (ld->kind) {
    case TSL_LOAD_BOUNDARY:
    case TSL_LOAD_CLOAD:
    case TSL_LOAD_CFLUX: {
      PetscInt n, *nodes;
      PetscCall(TargetNodes(p, &ld->target, &n, &nodes));
      for (PetscInt j = 0; j < n; j++)
        for (PetscInt dof = ld->dof_first; dof <= ld->dof_last; dof++) {
          PetscInt c = TslProblemNodeDofSlot(p, nodes[j], dof), d = nodes[j] * p->ndof + c;
          if (c < 0) continue; /* a dof the model's elements do not have (e.g. 3 in 2D): ignored as in the dialect */
          if (ld->kind == TSL_LOAD_BOUNDARY && ld->fixed)
            p->bc[d] = (TslLoadValue){PETSC_TRUE, PetscRealPart(x[d]), PetscRealPart(x[d]), TSL_AMP_HOLD, PETSC_FALSE, 0, 0, PETSC_FALSE, PETSC_FALSE};
          else if (ld->kind == TSL_LOAD_BOUNDARY && ld->velocity)
            RedefineVelocity(&p->bc[d], PetscRealPart(x[d]), p->ttot, ld->value, amp);
          else if (ld->kind == TSL_LOAD_BOUNDARY) {
            Redefine(&p->bc[d], PetscRealPart(x[d]), ld->value, amp);
            p->bc[d].held = ld->temperature; /* *TEMPERATURE is part of its *STATIC step's hold: it ends with the step */
          } else if (nodes[j] < p->nown)
            Redefine(&p->nload[d], 0, ld->value, amp);
        }
      PetscCall(PetscFree(nodes));
    } break;
    default:
      PetscCall(AddFaceLoads(p, ld));
    }
  }
  PetscCall(VecRestoreArrayRead(xl, &x));
  PetscCall(VecGhostRestoreLocalForm(p->X, &xl));
  for (PetscInt d = 0; d < nd; d++) {
    char loc[PETSC_MAX_PATH_LEN + 32];
    /* a tie's secondary dof under a *BOUNDARY: the boundary condition wins (docs/keywords.md, *TIE) */
    PetscCheck(!(p->bc[d].active && p->dep[d] >= 0 && !m->equations[p->dep[d]].tie), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
               "%s: node %" PetscInt_FMT " has a *BOUNDARY on a dof that an *EQUATION eliminates", TslLocString(m, step->loc, loc, sizeof(loc)),
               m->node_id[d / p->ndof]);
  }
  PetscCall(CompactFaces(p));
  PetscCall(ActiveDofs(p));
  PetscCall(MarkActiveAmplitudes(p));
  p->step_start_ttot = p->ttot;
  if (!p->matrix_free) PetscCall(TslProblemPreallocateIfChanged(p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemNextAmplitudeCorner(TslProblem p, PetscReal t, PetscReal t_end, PetscReal *tb)
{
  PetscReal eps = 1e-12 * PetscMax(p->period, PETSC_SMALL);

  PetscFunctionBeginUser;
  *tb = t_end;
  for (PetscInt k = 0; k < p->m->namplitude; k++) {
    const TslAmplitude *a = &p->m->amplitudes[k];
    PetscReal           shift;
    if (!p->amp_active[k]) continue;
    shift = a->total_time ? p->step_start_ttot : 0; /* amplitude time - step time */
    for (PetscInt i = 0; i < a->n; i++) {
      PetscReal ts = a->t[i] - shift;
      if (ts > t + eps && ts < *tb) *tb = ts;
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemSetTime(TslProblem p, PetscReal step_time, PetscReal dt, PetscReal total_time)
{
  PetscFunctionBeginUser;
  p->t    = step_time;
  p->dt   = dt;
  p->ttot = total_time;
  if (p->tfile.nwin > 1) { /* *TEMPERATURE, FILE= followed in time */
    const PetscReal *T;
    PetscCall(TslProblemTemperatureFileAt(p, step_time, &T));
    for (PetscInt l = 0; l < p->nn; l++) {
      const PetscInt c = TslProblemNodeDofSlot(p, l, 11), d = l * p->ndof + c;
      if (c >= 0 && p->bc[d].file) p->bc[d].v0 = p->bc[d].v1 = T[l];
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscReal TslProblemGetStepTime(TslProblem p)
{
  return p->t;
}

PetscErrorCode TslProblemApplyPrescribed(TslProblem p, Vec X)
{
  PetscScalar *x;

  PetscFunctionBeginUser;
  PetscCall(VecGetArray(X, &x));
  for (PetscInt i = 0; i < p->nbc_own; i++) {
    const PetscInt d = p->bc_own[i];
    x[d]             = TslProblemEvalLoadValue(p, &p->bc[d]);
  }
  PetscCall(VecRestoreArray(X, &x));
  PetscCall(TslGhostUpdate(X, INSERT_VALUES, SCATTER_FORWARD));
  if (p->m->ntie) { /* tie-secondary dofs from their main dofs (ghosts current now), then their own ghosts */
    Vec xl;
    PetscCall(VecGhostGetLocalForm(X, &xl));
    PetscCall(VecGetArray(xl, &x));
    for (PetscInt d = 0; d < p->nown * p->ndof; d++) {
      const PetscInt q = p->dep[d];
      if (q < 0 || p->bc[d].active || p->pinned[d]) continue;
      x[d] = 0;
      for (PetscInt t = 1; t < p->m->equations[q].n; t++) x[d] -= p->m->equations[q].coef[t] / p->m->equations[q].coef[0] * x[p->eq_ldof[q][t]];
    }
    PetscCall(VecRestoreArray(xl, &x));
    PetscCall(VecGhostRestoreLocalForm(X, &xl));
    PetscCall(TslGhostUpdate(X, INSERT_VALUES, SCATTER_FORWARD));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
