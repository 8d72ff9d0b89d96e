/* *TEMPERATURE, FILE= (sequential coupling; docs/keywords.md, *TEMPERATURE): the nodal temperatures of an earlier
 * job's results prescribed at every node of a *STATIC or coupled step.
 *
 * The file must hold the same nodes (ids and coordinates, in its natural order: row = node_nat). Every rank opens it
 * for itself and reads the rows of its own nodes (owned and ghost), two frames at a time: nothing of global size.
 * The window: frames (BSTEP, BINC) .. (ESTEP, EINC), BINC defaulting to BSTEP's first frame, EINC to ESTEP's last.
 * Step time t is the file's total time t0 + t, t0 the time of the last frame before BSTEP (0 when BSTEP is the
 * first step: the end of the step before it, where the file's steps join); between two frames the values are
 * interpolated linearly, from t0 to the window's first frame from the temperatures at the start of the step (the
 * file has no frame at a step's start: they are its state there when the step continues the file's sequence, the
 * initial conditions or the end of the window before), after the last frame they are its values. */
#include "problem_impl.h"

static const char *Where(TslProblem p, const TslTemperatureFile *tf, char *buf, size_t len) { return TslLocString(p->m, tf->loc, buf, len); }

/* Positions of the window's frames in the file's list (*win allocated), or an error naming the missing end. */
static PetscErrorCode Window(const TslTemperatureFile *tf, PetscInt nframe, const TslResultsFrame *f, PetscInt *nwin, PetscInt **win)
{
  PetscInt first = -1, last = -1;

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < nframe; k++) {
    PetscBool after_begin = f[k].step > tf->bstep || (f[k].step == tf->bstep && f[k].increment >= tf->binc);
    PetscBool before_end  = f[k].step < tf->estep || (f[k].step == tf->estep && (!tf->einc || f[k].increment <= tf->einc));
    if (after_begin && before_end) {
      if (first < 0) first = k;
      last = k;
    }
  }
  if (first < 0) {
    char from[64], to[64];
    PetscCall(PetscSNPrintf(from, sizeof(from), tf->binc ? "step %" PetscInt_FMT " increment %" PetscInt_FMT : "the start of step %" PetscInt_FMT, tf->bstep, tf->binc));
    PetscCall(PetscSNPrintf(to, sizeof(to), tf->einc ? "step %" PetscInt_FMT " increment %" PetscInt_FMT : "the end of step %" PetscInt_FMT, tf->estep, tf->einc));
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "the file has no frame from %s to %s", from, to);
  }
  if (tf->binc) {
    PetscCheck(f[first].step == tf->bstep && f[first].increment == tf->binc, PETSC_COMM_SELF, PETSC_ERR_FILE_READ,
               "BSTEP=%" PetscInt_FMT ", BINC=%" PetscInt_FMT ": the file has no such frame (step %" PetscInt_FMT " increment %" PetscInt_FMT " is the first after it)",
               tf->bstep, tf->binc, f[first].step, f[first].increment);
  } else
    PetscCheck(f[first].step == tf->bstep, PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "BSTEP=%" PetscInt_FMT ": the file has no frame of that step", tf->bstep);
  if (tf->einc)
    PetscCheck(f[last].step == tf->estep && f[last].increment == tf->einc, PETSC_COMM_SELF, PETSC_ERR_FILE_READ,
               "ESTEP=%" PetscInt_FMT ", EINC=%" PetscInt_FMT ": the file has no such frame", tf->estep, tf->einc);
  else
    PetscCheck(f[last].step == tf->estep, PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "ESTEP=%" PetscInt_FMT ": the file has no frame of that step", tf->estep);
  *nwin = last - first + 1;
  PetscCall(PetscMalloc1(*nwin, win));
  for (PetscInt k = 0; k < *nwin; k++) (*win)[k] = first + k;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The local part of the check of one step's file: the same nodes here (ids, coordinates within tol) and NT in every
 * frame of the window (its rows read for the first frame, the dataset's shape for the others). */
static PetscErrorCode CheckLocal(TslProblem p, const TslTemperatureFile *tf, PetscInt nglobal, PetscReal tol)
{
  TslModel              *m = p->m;
  TslResults             r = NULL;
  PetscInt               nnode, nframe, nwin = 0, *win = NULL, *ids;
  const TslResultsFrame *f;
  PetscReal             *xyz;

  PetscFunctionBeginUser;
  PetscCall(TslResultsOpen(tf->path, &r));
  PetscCall(TslResultsInfo(r, &nnode, &nframe, &f));
  PetscCheck(nnode == nglobal, PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "%s has %" PetscInt_FMT " nodes, the model %" PetscInt_FMT ": the earlier job must have the same mesh",
             tf->path, nnode, nglobal);
  PetscCall(PetscMalloc2(m->nnode, &ids, 3 * m->nnode, &xyz));
  PetscCall(TslResultsReadNodeIds(r, m->nnode, m->node_nat, ids));
  PetscCall(TslResultsReadRows(r, "/mesh/coordinates", m->nnode, m->node_nat, 3, xyz));
  for (PetscInt l = 0; l < m->nnode; l++) {
    PetscCheck(ids[l] == m->node_id[l], PETSC_COMM_SELF, PETSC_ERR_FILE_READ,
               "%s: its node %" PetscInt_FMT " stands where the model has node %" PetscInt_FMT ": the earlier job must have the same mesh", tf->path, ids[l],
               m->node_id[l]);
    for (PetscInt c = 0; c < 3; c++)
      PetscCheck(PetscAbsReal(xyz[3 * l + c] - m->node_xyz[3 * l + c]) <= tol, PETSC_COMM_SELF, PETSC_ERR_FILE_READ,
                 "%s: node %" PetscInt_FMT " is at (%g, %g, %g) there, (%g, %g, %g) in the model: the earlier job must have the same mesh", tf->path,
                 m->node_id[l], (double)xyz[3 * l], (double)xyz[3 * l + 1], (double)xyz[3 * l + 2], (double)m->node_xyz[3 * l],
                 (double)m->node_xyz[3 * l + 1], (double)m->node_xyz[3 * l + 2]);
  }
  PetscCall(PetscFree2(ids, xyz));
  PetscCall(Window(tf, nframe, f, &nwin, &win));
  for (PetscInt k = 0; k < nwin; k++) {
    char name[32];
    PetscCall(PetscSNPrintf(name, sizeof(name), "/frames/%06d/NT", (int)(win[k] + 1)));
    PetscCall(TslResultsReadRows(r, name, 0, NULL, 1, NULL));
  }
  PetscCall(PetscFree(win));
  PetscCall(TslResultsClose(&r));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemTemperatureFilesCheck(TslProblem p)
{
  TslModel *m = p->m;
  PetscInt  nglobal;
  PetscReal box[6] = {PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_MAX_REAL}, g[6], size = 0;

  PetscFunctionBeginUser;
  {
    PetscBool any = PETSC_FALSE;
    for (PetscInt s = 0; s < m->nstep; s++) any = any || m->steps[s].tfile.given;
    if (!any) PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(MPIU_Allreduce(&p->nown, &nglobal, 1, MPIU_INT, MPI_SUM, p->comm));
  /* coordinates compared within 1e-9 of the model's extent: a file of the same deck has them exactly */
  for (PetscInt l = 0; l < m->nnode; l++)
    for (PetscInt c = 0; c < 3; c++) box[c] = PetscMin(box[c], m->node_xyz[3 * l + c]), box[3 + c] = PetscMin(box[3 + c], -m->node_xyz[3 * l + c]);
  PetscCall(MPIU_Allreduce(box, g, 6, MPIU_REAL, MPIU_MIN, p->comm));
  for (PetscInt c = 0; c < 3; c++) size = PetscMax(size, -g[3 + c] - g[c]);
  for (PetscInt s = 0; s < m->nstep; s++) {
    const TslTemperatureFile *tf = &m->steps[s].tfile;
    PetscErrorCode            ierr;
    TslFailure                kind;
    char                      msg[TSL_FAIL_MSG_LEN], where[PETSC_MAX_PATH_LEN + 32];
    if (!tf->given) continue;
    PetscCall(TslCaptureBegin());
    ierr = CheckLocal(p, tf, nglobal, 1e-9 * PetscMax(size, PETSC_SMALL));
    PetscCall(TslCaptureEnd());
    PetscCall(TslCaptureBegin());
    PetscErrorCode agreed = TslAgree(p->comm, ierr, &kind, msg);
    PetscCall(TslCaptureEnd());
    if (agreed) {
      const char *generic;
      char       *specific = NULL;
      PetscCall(PetscErrorMessage(agreed, &generic, &specific));
      SETERRQ(p->comm, PETSC_ERR_USER_INPUT, "%s: *TEMPERATURE, FILE=: %s", Where(p, tf, where, sizeof(where)), specific ? specific : "cannot read the file");
    }
    PetscCheck(kind == TSL_FAIL_NONE, p->comm, PETSC_ERR_USER_INPUT, "%s: *TEMPERATURE, FILE=: %s", Where(p, tf, where, sizeof(where)), msg);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemTemperatureFileEnd(TslProblem p)
{
  PetscFunctionBeginUser;
  PetscCall(TslResultsClose(&p->tfile.r));
  PetscCall(PetscFree(p->tfile.win));
  PetscCall(PetscFree4(p->tfile.Ts, p->tfile.Ta, p->tfile.Tb, p->tfile.T));
  PetscCall(PetscMemzero(&p->tfile, sizeof(p->tfile)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* reads frame window position k into T (local failures agreed on all ranks) */
static PetscErrorCode ReadFrame(TslProblem p, PetscInt k, PetscReal T[])
{
  char           name[32];
  PetscErrorCode ierr;
  TslFailure     kind;

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(name, sizeof(name), "/frames/%06d/NT", (int)(p->tfile.win[k] + 1)));
  PetscCall(TslCaptureBegin());
  ierr = TslResultsReadRows(p->tfile.r, name, p->m->nnode, p->m->node_nat, 1, T);
  PetscCall(TslCaptureEnd());
  PetscCall(TslAgree(p->comm, ierr, &kind, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* window frame k into buffer V (its frame index *kv), copied from the other buffer W when that holds it */
static PetscErrorCode Load(TslProblem p, PetscInt k, PetscInt *kv, PetscReal V[], const PetscInt *kw, const PetscReal W[])
{
  PetscFunctionBeginUser;
  if (*kv == k) PetscFunctionReturn(PETSC_SUCCESS);
  if (*kw == k) PetscCall(PetscArraycpy(V, W, p->nn));
  else PetscCall(ReadFrame(p, k, V));
  *kv = k;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemTemperatureFileBegin(TslProblem p, PetscInt s, const PetscScalar x[])
{
  const TslTemperatureFile *tf = &p->m->steps[s].tfile;
  PetscInt                  nframe;
  PetscErrorCode            ierr;
  TslFailure                kind;

  PetscFunctionBeginUser;
  PetscCall(TslProblemTemperatureFileEnd(p));
  if (!tf->given) PetscFunctionReturn(PETSC_SUCCESS);
  /* checked before the run (TslProblemTemperatureFilesCheck): a failure now is the file changing under the job */
  PetscCall(TslCaptureBegin());
  ierr = TslResultsOpen(tf->path, &p->tfile.r);
  if (!ierr) ierr = TslResultsInfo(p->tfile.r, NULL, &nframe, &p->tfile.frames);
  if (!ierr) ierr = Window(tf, nframe, p->tfile.frames, &p->tfile.nwin, &p->tfile.win);
  PetscCall(TslCaptureEnd());
  PetscCall(TslAgree(p->comm, ierr, &kind, NULL));
  p->tfile.t0 = 0;
  for (PetscInt k = 0; k < p->tfile.win[0]; k++)
    if (p->tfile.frames[k].step < tf->bstep) p->tfile.t0 = p->tfile.frames[k].time;
  PetscCall(PetscMalloc4(p->nn, &p->tfile.Ts, p->nn, &p->tfile.Ta, p->nn, &p->tfile.Tb, p->nn, &p->tfile.T));
  for (PetscInt l = 0; l < p->nn; l++) {
    const PetscInt c = TslProblemNodeDofSlot(p, l, 11);
    p->tfile.Ts[l]   = c < 0 ? 0 : PetscRealPart(x[l * p->ndof + c]);
  }
  p->tfile.a = p->tfile.b = -1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemTemperatureFileAt(TslProblem p, PetscReal t, const PetscReal **T)
{
  const PetscInt nwin = p->tfile.nwin;
  PetscReal      tf = p->tfile.t0 + t, t1 = p->tfile.frames[p->tfile.win[0]].time, ta, tb, w;
  PetscInt       a  = 0;
  const PetscReal *A, *B;

  PetscFunctionBeginUser;
  /* the bracketing frames a, a + 1 (the later of equal times), the step's start and the first frame, or the last */
  while (a + 1 < nwin && p->tfile.frames[p->tfile.win[a + 1]].time <= tf) a++;
  if (tf < t1) { /* between the step's start (t0) and the first frame */
    PetscCall(Load(p, 0, &p->tfile.a, p->tfile.Ta, &p->tfile.b, p->tfile.Tb));
    A = p->tfile.Ts, B = p->tfile.Ta, ta = p->tfile.t0, tb = t1;
  } else if (a + 1 == nwin) { /* at or after the last frame */
    PetscCall(Load(p, a, &p->tfile.a, p->tfile.Ta, &p->tfile.b, p->tfile.Tb));
    A = B = p->tfile.Ta, ta = tb = tf;
  } else {
    PetscCall(Load(p, a, &p->tfile.a, p->tfile.Ta, &p->tfile.b, p->tfile.Tb));
    PetscCall(Load(p, a + 1, &p->tfile.b, p->tfile.Tb, &p->tfile.a, p->tfile.Ta));
    A = p->tfile.Ta, B = p->tfile.Tb, ta = p->tfile.frames[p->tfile.win[a]].time, tb = p->tfile.frames[p->tfile.win[a + 1]].time;
  }
  w = tb > ta ? (tf - ta) / (tb - ta) : 0;
  w = PetscMax(0, PetscMin(1, w));
  for (PetscInt l = 0; l < p->nn; l++) p->tfile.T[l] = w == 0 ? A[l] : w == 1 ? B[l] : (1 - w) * A[l] + w * B[l];
  *T = p->tfile.T;
  PetscFunctionReturn(PETSC_SUCCESS);
}
