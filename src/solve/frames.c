/* The output of the step procedures, implicit (driver.c) and explicit (explicit.c) alike: the result files and
 * the history (set-up), the field requests of a step, the output times of *OUTPUT intervals, the frames, and the
 * *NODE PRINT / *EL PRINT tables. Both procedures call these; neither calls the other's. */
#include "solve_impl.h"

const char *const TslHistoryColumns[NHISTORY] = {"step",
                                             "increment",
                                             "time",
                                             "step_time",
                                             "dt",
                                             "newton_its",
                                             "heat_in",
                                             "film_heat_out",
                                             "radiation_heat_out",
                                             "reaction_heat",
                                             "stored_heat_rate",
                                             "interface_heat",
                                             "friction_dissipation_rate",
                                             "friction_dissipation_total",
                                             "friction_heat_total",
                                             "balance_residual",
                                             "strain_energy",
                                             "hourglass_energy",
                                             "plastic_heat_rate",
                                             "ALLPD",
                                             "ALLKE",
                                             "ALLIE",
                                             "ALLWK",
                                             "ALLFD",
                                             "ALLCW",
                                             "ALLMW",
                                             "ALLVD",
                                             "ETOTAL"};

/* The result files and the history of the job, and the fields written by default. */
PetscErrorCode TslFramesSetUp(Driver *d, const char *dir, const char *jobname)
{
  const TslModel *m;
  PetscInt       *xtype, *conn, *ptr;

  PetscFunctionBeginUser;
  PetscCall(TslProblemGetModel(d->prob, &m));
  PetscCall(TslOutputCreate(d->comm, dir, jobname, &d->out));
  PetscCall(TslOutputSetSyncInterval(d->out, d->sync_interval));
  PetscCall(PetscMalloc3(m->nelem, &xtype, m->elem_ptr[m->nelem], &conn, m->nelem + 1, &ptr));
  /* cells are the geometry families' nodes (an element's extra reference node is not part of its cell), in XDMF's
   * order (a wedge's differs from the dialect's: TslGeometry.xdmf_order) */
  ptr[0] = 0;
  for (PetscInt e = 0; e < m->nelem; e++) {
    const TslGeometry *g = TslElementTypeGet(m->elem_type[e])->geom;
    xtype[e]             = g->xdmf_type;
    ptr[e + 1]           = ptr[e] + g->nnode;
    for (PetscInt a = 0; a < g->nnode; a++)
      conn[ptr[e] + a] = m->node_nat[TslModelNodeIndex(m, m->elem_conn[m->elem_ptr[e] + (g->xdmf_order ? g->xdmf_order[a] : a)])];
  }
  PetscCall(TslOutputSetMesh(d->out, m->nnode_global, m->nnode_owned, m->node_nat, m->node_id, m->node_xyz, m->nelem_global, m->nelem, m->elem_nat,
                             m->elem_id, xtype, ptr, conn));
  PetscCall(PetscFree3(xtype, conn, ptr));
  PetscCall(TslHistoryCreate(d->comm, dir, jobname, NHISTORY, TslHistoryColumns, &d->hist));
  for (PetscInt s = 0; s < m->nstep; s++) /* every rank holds the steps whole */
    for (PetscInt i = 0; i < m->steps[s].nload; i++)
      if (m->steps[s].loads[i].kind == TSL_LOAD_RADIATE && (m->steps[s].loads[i].target.set[0] || m->steps[s].loads[i].target.id >= 0)) d->radiates = PETSC_TRUE;
  PetscBool plastic = PETSC_FALSE; /* every rank holds the materials whole */
  for (PetscInt k = 0; k < m->nmaterial; k++) plastic = (PetscBool)(plastic || TslMaterialIsPlastic(&m->materials[k]));
  for (PetscInt i = 0; i < TslFieldCount(); i++) {
    PetscInt deflt;
    (void)TslFieldName(i, NULL, &deflt);
    d->field_on[i] = (PetscBool)((deflt == 1 || (deflt == 2 && m->npair > 0) || (deflt == 3 && plastic)) && TslProblemFieldAvailable(d->prob, i));
  }
  d->frequency = 1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Field output requests of a step: they replace the previous step's when present. */
PetscErrorCode TslFramesSetRequests(Driver *d, const TslStep *step)
{
  PetscBool any = PETSC_FALSE;

  PetscFunctionBeginUser;
  for (PetscInt r = 0; r < step->nout; r++)
    if (!step->out[r].print) any = PETSC_TRUE;
  if (!any) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < TslFieldCount(); i++) d->field_on[i] = PETSC_FALSE;
  for (PetscInt r = 0; r < step->nout; r++) {
    const TslOutputRequest *req = &step->out[r];
    if (req->print) continue;
    d->frequency = PetscMax(1, req->frequency);
    for (PetscInt v = 0; v < req->nvar; v++) {
      PetscInt i = TslFieldFind(req->var[v]);
      if (i >= 0 && TslProblemFieldAvailable(d->prob, i))
        d->field_on[i] = PETSC_TRUE;
      else if (i >= 0)
        PetscCall(PetscPrintf(d->comm, "note: output variable %s is not written: the model has no displacement (heat transfer only)\n", req->var[v]));
      else
        PetscCall(PetscPrintf(d->comm, "warning: output variable %s is not available; ignored\n", req->var[v]));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

void TslFrameTimesSetUp(TslFrameTimes *ft, const TslStep *step, PetscInt default_number)
{
  PetscInt n = step->out_number_interval > 0 ? step->out_number_interval : default_number;

  ft->period = step->period;
  ft->eps    = 1e-12 * step->period;
  ft->dt     = step->out_time_interval > 0 ? step->out_time_interval : n > 0 ? step->period / n : 0;
  ft->next   = ft->dt > 0 ? ft->dt : step->period;
}

PetscReal TslFrameTimesBound(const TslFrameTimes *ft)
{
  return PetscMin(ft->next, ft->period);
}

PetscBool TslFrameTimesReached(TslFrameTimes *ft, PetscReal t)
{
  if (!(ft->dt > 0) || t < ft->next - ft->eps) return PETSC_FALSE;
  while (ft->next <= t + ft->eps) ft->next += ft->dt;
  return PETSC_TRUE;
}

/* Small-strain kinematics (no NLGEOM) take a rigid turn by theta for a strain of 1 - cos theta, about theta^2 / 2 (and
 * stresses of E times that): above this rotation an element's results are wrong by more than a metal's yield strain, and the step
 * says so once, at the frame that first shows it (the deck's step may be meant for finite strain: an implicit step from
 * an Abaqus or CalculiX deck is small-strain without NLGEOM, an explicit step only with NLGEOM=NO). */
#define TSL_SMALL_STRAIN_ROTATION 0.05

static PetscErrorCode SmallStrainRotation(Driver *d, PetscInt step, PetscReal time)
{
  const TslModel *m;
  PetscReal       w;
  PetscInt        id;

  PetscFunctionBeginUser;
  PetscCall(TslProblemGetModel(d->prob, &m));
  if (step < 1 || step > m->nstep || m->steps[step - 1].nlgeom || d->rotation_warned == step ||
      !TslProblemFieldAvailable(d->prob, TslFieldFind("U"))) /* heat transfer: nothing turns */
    PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(TslProblemLargestRotation(d->prob, &w, &id));
  if (!(w > TSL_SMALL_STRAIN_ROTATION)) PetscFunctionReturn(PETSC_SUCCESS);
  d->rotation_warned = step;
  PetscCall(PetscPrintf(
      d->comm,
      "warning: step %s: element %" PetscInt_FMT " has turned by %.3g rad at time %g with small-strain kinematics, which take such a "
      "turn for a strain of %.2g (1 - cos theta) and stresses of that times E; write NLGEOM on the *STEP line for finite strain "
      "(%s)\n",
      m->steps[step - 1].name, id, (double)w, (double)time, (double)(1 - PetscCosReal(w)),
      m->steps[step - 1].explicit_dynamics ? "this explicit step was given NLGEOM=NO; without it an explicit step takes finite strain"
                                           : "CalculiX's default is small strain too"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslFramesWrite(Driver *d, PetscInt step, PetscInt inc, PetscReal time)
{
  PetscFunctionBeginUser;
  d->in_output = PETSC_TRUE;
  PetscCall(TslOutputBeginFrame(d->out, step, inc, time));
  for (PetscInt i = 0; i < TslFieldCount(); i++) {
    PetscInt     nc;
    PetscReal   *v;
    TslFieldKind kind;
    const char  *name = TslFieldName(i, &kind, NULL);
    if (!d->field_on[i]) continue;
    PetscCall(TslProblemField(d->prob, i, &nc, &v));
    if (kind == TSL_FIELD_NODE)
      PetscCall(TslOutputNodeField(d->out, name, nc, v));
    else
      PetscCall(TslOutputElementField(d->out, name, nc, v));
    PetscCall(PetscFree(v));
  }
  PetscCall(TslOutputEndFrame(d->out));
  d->in_output  = PETSC_FALSE;
  d->frame_step = step;
  d->frame_inc  = inc;
  PetscCall(SmallStrainRotation(d, step, time));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *NODE PRINT / *EL PRINT tables at the end of a step: one line per node (element) of the set, printed
 * by the rank that owns it; with TOTALS= their sum. */
#define TSL_PRINT_MAX_COMPONENTS 16
typedef struct {
  const TslModel         *m;
  const TslOutputRequest *req;
  const TslSet           *set;
  const char             *var;
  PetscInt                nc;
  const PetscReal        *vals;
  PetscReal               sum[TSL_PRINT_MAX_COMPONENTS]; /* TOTALS=: this rank's part of the sum */
} PrintCtx;

/* This rank's lines of one variable of a printed table (none with TOTALS=ONLY): its owned nodes / its
 * elements of the set; their sum into c->sum. */
static PetscErrorCode PrintRows(TslPrintSink sink, void *ctx)
{
  PrintCtx *c = (PrintCtx *)ctx;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < TSL_PRINT_MAX_COMPONENTS; k++) c->sum[k] = 0;
  for (PetscInt i = 0; c->set && i < c->set->n; i++) {
    PetscInt n;
    if (c->req->node) {
      n = TslModelNodeIndex(c->m, c->set->ids[i]);
      if (n < 0 || n >= c->m->nnode_owned) continue;
    } else {
      n = TslModelElementIndex(c->m, c->set->ids[i]);
      if (n < 0) continue;
    }
    for (PetscInt k = 0; k < PetscMin(c->nc, TSL_PRINT_MAX_COMPONENTS); k++) c->sum[k] += c->vals[n * c->nc + k];
    if (!sink) continue;
    PetscCall(TslPrintLine(sink, "  %8" PetscInt_FMT " %-4s", c->set->ids[i], c->var));
    for (PetscInt k = 0; k < c->nc; k++) PetscCall(TslPrintLine(sink, " % .6e", (double)c->vals[n * c->nc + k]));
    PetscCall(TslPrintLine(sink, "\n"));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *NODE PRINT / *EL PRINT tables at the end of a step, streamed in rank order (TslPrintOrdered). */
PetscErrorCode TslFramesPrintTables(Driver *d, const TslStep *step)
{
  const TslModel *m;

  PetscFunctionBeginUser;
  PetscCall(TslProblemGetModel(d->prob, &m));
  for (PetscInt r = 0; r < step->nout; r++) {
    const TslOutputRequest *req = &step->out[r];
    PetscInt                k;
    PrintCtx                c = {m, req, NULL, NULL, 0, NULL, {0}};
    if (!req->print) continue;
    k     = req->node ? TslModelFindNodeSet(m, req->set) : TslModelFindElementSet(m, req->set);
    c.set = k < 0 ? NULL : req->node ? &m->nsets[k] : &m->elsets[k];
    PetscCall(PetscPrintf(d->comm, "%s print, step %s, set %s:\n", req->node ? "node" : "element", step->name, req->set));
    for (PetscInt v = 0; v < req->nvar; v++) {
      PetscInt     f = TslFieldFind(req->var[v]);
      PetscReal   *vals;
      TslFieldKind kind = TSL_FIELD_NODE;
      if (f >= 0) (void)TslFieldName(f, &kind, NULL);
      if (f >= 0 && !TslProblemFieldAvailable(d->prob, f)) {
        PetscCall(PetscPrintf(d->comm, "  %s: not available (the model has no displacement: heat transfer only)\n", req->var[v]));
        continue;
      }
      if (f < 0 || (kind == TSL_FIELD_NODE) != req->node) {
        PetscCall(PetscPrintf(d->comm, "  %s: not available\n", req->var[v]));
        continue;
      }
      PetscCall(TslProblemField(d->prob, f, &c.nc, &vals));
      c.var  = req->var[v];
      c.vals = vals;
      if (req->totals == 2)
        PetscCall(PrintRows(NULL, &c));
      else
        PetscCall(TslPrintOrdered(d->comm, PrintRows, &c));
      if (req->totals) {
        /* TOTALS=YES / ONLY: the sum over the set (each node once, from its owner) */
        PetscCall(MPIU_Allreduce(MPI_IN_PLACE, c.sum, TSL_PRINT_MAX_COMPONENTS, MPIU_REAL, MPIU_SUM, d->comm));
        PetscCall(PetscPrintf(d->comm, "  %8s %-4s", "total", c.var));
        for (PetscInt k = 0; k < PetscMin(c.nc, TSL_PRINT_MAX_COMPONENTS); k++) PetscCall(PetscPrintf(d->comm, " % .6e", (double)c.sum[k]));
        PetscCall(PetscPrintf(d->comm, "\n"));
      }
      PetscCall(PetscFree(vals));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
