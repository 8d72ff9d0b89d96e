/* Output fields of the current state, one table row per field: nodal (owned nodes) and element values. */
#include "problem_impl.h"
#include <string.h>

/* U: displacements (3 comps, zero-padded in 2D); NT: temperature. */
static PetscErrorCode NodeSolution(TslProblem p, PetscInt which, PetscInt ncomp, PetscReal vals[])
{
  const PetscScalar *x;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(p->X, &x));
  for (PetscInt n = 0; n < p->nown; n++) {
    const PetscScalar *xn = x + n * p->ndof;
    if (which == 0)
      for (PetscInt c = 0; c < p->nu; c++) vals[ncomp * n + c] = PetscRealPart(xn[c]);
    else
      vals[n] = PetscRealPart(xn[p->ndof - 1]);
  }
  PetscCall(VecRestoreArrayRead(p->X, &x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* RF / RFL: the unconstrained residual at prescribed dofs, as computed by the last
 * TslProblemHeatBalance; zero elsewhere (with twist, RF3 is the torque about the axis). */
static PetscErrorCode NodeReaction(TslProblem p, PetscInt which, PetscInt ncomp, PetscReal vals[])
{
  const PetscScalar *r;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(p->Rraw, &r));
  for (PetscInt n = 0; n < p->nown; n++) {
    const PetscInt d = n * p->ndof;
    if (which == 0) {
      const PetscInt *dof = p->extra[n] ? p->extra_dof : p->node_dof;
      for (PetscInt c = 0; c < p->nu; c++) {
        /* forces on dofs 1..3; with twist, RF3 is the torque about the axis; a reference node's moments are not RF */
        const PetscInt comp = dof[c] >= 1 && dof[c] <= 3 ? dof[c] - 1 : (dof[c] == 5 && !p->extra[n] ? 2 : -1);
        if (p->bc[d + c].active && comp >= 0) vals[ncomp * n + comp] = PetscRealPart(r[d + c]);
      }
    }
    else
      vals[n] = p->bc[d + p->ndof - 1].active ? PetscRealPart(r[d + p->ndof - 1]) : 0;
  }
  PetscCall(VecRestoreArrayRead(p->Rraw, &r));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode NodeContact(TslProblem p, PetscInt which, PetscInt ncomp, PetscReal vals[])
{
  PetscFunctionBeginUser;
  (void)ncomp;
  PetscCall(TslProblemContactNodeField(p, (TslContactField)which, vals));
  PetscFunctionReturn(PETSC_SUCCESS);
}

typedef struct {
  PetscReal *vals;
  PetscInt   which, ncomp;
} ElementFieldCtx;

static PetscErrorCode ElementResult(TslProblem p, PetscInt e, TslElemData *d, void *ctx, PetscBool *stop)
{
  ElementFieldCtx *c = (ElementFieldCtx *)ctx;
  TslElementResult res;
  const PetscReal *src;

  PetscFunctionBeginUser;
  (void)p, (void)stop;
  PetscCall(TslElementOutput(&d->in, &res));
  src = c->which == 0   ? res.S
        : c->which == 1 ? res.E
        : c->which == 2 ? res.HFL
        : c->which == 3 ? &res.strain_energy
        : c->which == 4 ? &res.hourglass_energy
        : c->which == 5 ? res.PE
                        : &res.PEEQ;
  for (PetscInt k = 0; k < c->ncomp; k++) c->vals[e * c->ncomp + k] = src[k];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* testing aid (-tsl_debug_fail_kind element): an element pass that fails on one rank, inside the pass's capture */
static PetscErrorCode InjectedElement(TslProblem p)
{
  PetscFunctionBeginUser;
  PetscCheck(!TslInjectNow(&p->inject, TSL_INJECT_ELEMENT, p->step + 1), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG,
             "injected element output failure (-tsl_debug_fail_kind)");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The outcome of a rank's element pass (its error code, captured: TslCaptureBegin) agreed on all ranks (collective): an
 * element whose output fails on one rank (a plastic return that does not converge) stops every rank with its message,
 * where the others would wait in the next collective call. */
static PetscErrorCode AgreeElementPass(TslProblem p, PetscErrorCode ierr, const char *what)
{
  TslFailure fail;
  char       msg[TSL_FAIL_MSG_LEN];

  PetscFunctionBeginUser;
  PetscCall(TslAgree(p->comm, ierr, &fail, msg));
  PetscCheck(!fail, p->comm, PETSC_ERR_NOT_CONVERGED, "%s: %s", what, msg);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* S and E (Voigt 11 22 33 12 13 23), HFL (3): integration-point averages; ELSE, ELASE: the element's
 * strain energy and the energy of its hourglass control. */
static PetscErrorCode ElementValues(TslProblem p, PetscInt which, PetscInt ncomp, PetscReal vals[])
{
  Vec                xl;
  const PetscScalar *xa;
  ElementFieldCtx    ctx = {vals, which, ncomp};
  PetscErrorCode     ierr;

  PetscFunctionBeginUser;
  PetscCall(TslProblemGetLocalSolution(p, &xl, &xa));
  PetscCall(TslCaptureBegin());
  ierr = TslProblemElementLoop(p, xa, xa, ElementResult, &ctx);
  if (!ierr) ierr = InjectedElement(p);
  PetscCall(TslCaptureEnd());
  PetscCall(TslProblemRestoreLocalSolution(p, &xl, &xa));
  PetscCall(AgreeElementPass(p, ierr, "element output"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

typedef struct {
  const char  *name;
  TslFieldKind kind;
  PetscInt     deflt; /* written without an *OUTPUT request: 0 no, 1 yes, 2 when the model has contact, 3 when it has plasticity */
  PetscBool    mech;  /* a field of the displacement: none in a heat-transfer model (TslProblemFieldAvailable) */
  PetscInt     ncomp, which;
  PetscErrorCode (*eval)(TslProblem, PetscInt which, PetscInt ncomp, PetscReal vals[]);
} FieldRow;

static const FieldRow Fields[] = {
    {"U", TSL_FIELD_NODE, 1, PETSC_TRUE, 3, 0, NodeSolution},
    {"NT", TSL_FIELD_NODE, 1, PETSC_FALSE, 1, 1, NodeSolution},
    {"RF", TSL_FIELD_NODE, 1, PETSC_TRUE, 3, 0, NodeReaction},
    {"RFL", TSL_FIELD_NODE, 1, PETSC_FALSE, 1, 1, NodeReaction},
    {"CPRESS", TSL_FIELD_NODE, 2, PETSC_TRUE, 1, TSL_CONTACT_FIELD_PRESSURE, NodeContact},
    {"CSLIP", TSL_FIELD_NODE, 2, PETSC_TRUE, 1, TSL_CONTACT_FIELD_SLIP, NodeContact},
    {"CSTATUS", TSL_FIELD_NODE, 2, PETSC_TRUE, 1, TSL_CONTACT_FIELD_STATUS, NodeContact},
    {"HFLA", TSL_FIELD_NODE, 2, PETSC_FALSE, 1, TSL_CONTACT_FIELD_HEAT_FLUX, NodeContact},
    {"S", TSL_FIELD_ELEMENT, 1, PETSC_TRUE, 6, 0, ElementValues},
    {"E", TSL_FIELD_ELEMENT, 1, PETSC_TRUE, 6, 1, ElementValues},
    {"LE", TSL_FIELD_ELEMENT, 0, PETSC_TRUE, 6, 1, ElementValues}, /* on request: E's values (the logarithmic strain under NLGEOM) */
    {"HFL", TSL_FIELD_ELEMENT, 1, PETSC_FALSE, 3, 2, ElementValues},
    {"ELSE", TSL_FIELD_ELEMENT, 0, PETSC_TRUE, 1, 3, ElementValues},
    {"ELASE", TSL_FIELD_ELEMENT, 0, PETSC_TRUE, 1, 4, ElementValues},
    {"PE", TSL_FIELD_ELEMENT, 3, PETSC_TRUE, 6, 5, ElementValues},
    {"PEEQ", TSL_FIELD_ELEMENT, 3, PETSC_TRUE, 1, 6, ElementValues},
};

PetscInt TslFieldCount(void)
{
  return (PetscInt)(sizeof(Fields) / sizeof(Fields[0]));
}

PetscInt TslFieldFind(const char *name)
{
  for (PetscInt i = 0; i < TslFieldCount(); i++)
    if (!strcmp(Fields[i].name, name)) return i;
  return -1;
}

const char *TslFieldName(PetscInt i, TslFieldKind *kind, PetscInt *deflt)
{
  if (kind) *kind = Fields[i].kind;
  if (deflt) *deflt = Fields[i].deflt;
  return Fields[i].name;
}

PetscBool TslProblemFieldAvailable(TslProblem p, PetscInt i)
{
  return (PetscBool)(i >= 0 && i < TslFieldCount() && (!Fields[i].mech || p->nu > 0));
}

PetscErrorCode TslProblemField(TslProblem p, PetscInt i, PetscInt *ncomp, PetscReal **vals)
{
  const FieldRow *f = &Fields[i];

  PetscFunctionBeginUser;
  *ncomp = f->ncomp;
  PetscCall(PetscCalloc1((f->kind == TSL_FIELD_NODE ? p->nown : p->m->nelem) * f->ncomp, vals));
  PetscCall(f->eval(p, f->which, f->ncomp, *vals));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode EnergyVisit(TslProblem p, PetscInt e, TslElemData *d, void *ctx, PetscBool *stop)
{
  PetscReal       *sum = (PetscReal *)ctx;
  TslElementResult res;

  PetscFunctionBeginUser;
  (void)p, (void)e, (void)stop;
  PetscCall(TslElementOutput(&d->in, &res));
  sum[0] += res.strain_energy;
  sum[1] += res.hourglass_energy;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Elements with an explicit force record take their energies from it (TslElementFastEnergy: the same
 * formulas, no geometry), the others the generic output; an explicit step writes a history row every few
 * increments, so this pass costs what a force evaluation does. */
PetscErrorCode TslProblemEnergies(TslProblem p, PetscReal *strain, PetscReal *hourglass)
{
  Vec                xl;
  const PetscScalar *xa;
  PetscReal          loc[2] = {0, 0}, g[2];
  TslElemData        d;
  PetscErrorCode     ierr = PETSC_SUCCESS;

  PetscFunctionBeginUser;
  PetscCall(TslProblemGetLocalSolution(p, &xl, &xa));
  for (PetscInt b = 0; p->fast_built && b < p->fast_nbatch; b++) {
    PetscReal se, hg;
    TslProblemFastBatchEnergy(p, b, xa, &se, &hg);
    loc[0] += se, loc[1] += hg;
  }
  PetscCall(TslCaptureBegin());
  for (PetscInt e = 0; e < p->m->nelem && !ierr; e++) {
    PetscBool stop = PETSC_FALSE;
    if (p->fast_built && p->fast_off[e] >= 0) continue;
    TslProblemGather(p, e, xa, xa, &d);
    ierr = EnergyVisit(p, e, &d, loc, &stop);
  }
  if (!ierr) ierr = InjectedElement(p);
  PetscCall(TslCaptureEnd());
  PetscCall(TslProblemRestoreLocalSolution(p, &xl, &xa));
  PetscCall(AgreeElementPass(p, ierr, "element energies"));
  PetscCall(MPIU_Allreduce(loc, g, 2, MPIU_REAL, MPIU_SUM, p->comm));
  *strain    = g[0];
  *hourglass = g[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemLargestRotation(TslProblem p, PetscReal *omega, PetscInt *elem_id)
{
  Vec                xl;
  const PetscScalar *xa;
  PetscReal          w = 0;
  PetscInt           id = -1;
  TslElemData        d;

  PetscFunctionBeginUser;
  PetscCall(TslProblemGetLocalSolution(p, &xl, &xa));
  for (PetscInt e = 0; e < p->m->nelem; e++) {
    PetscReal we;
    TslProblemGather(p, e, xa, xa, &d);
    if (TslElementCentreRotation(&d.in, &we) && we > w) w = we, id = p->m->elem_id[e];
  }
  PetscCall(TslProblemRestoreLocalSolution(p, &xl, &xa));
  PetscCall(MPIU_Allreduce(&w, omega, 1, MPIU_REAL, MPIU_MAX, p->comm));
  if (w != *omega) id = -1;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &id, 1, MPIU_INT, MPI_MAX, p->comm));
  *elem_id = id;
  PetscFunctionReturn(PETSC_SUCCESS);
}
