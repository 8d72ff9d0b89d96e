/* tsl_deck_check DECK: reads a deck with TslDeckRead and prints a summary, or the error.
 *
 * Errors: PETSc's default handler would print a traceback around the message. Here the return
 * handler is pushed instead and the message SETERRQ formatted ("file:line: ...") is fetched with
 * PetscErrorMessage() and printed alone as "error: file:line: ...", so the bad-input tests can match
 * the exact text. The exit code is 1 on any error. */
#include <thermoslide/model.h>

static PetscErrorCode Summary(const TslModel *m)
{
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "deck: %s (%" PetscInt_FMT " file(s))\n", m->files[0], m->nfile));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "heading: %s\n", m->heading));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "dim %" PetscInt_FMT ", nodes %" PetscInt_FMT ", elements %" PetscInt_FMT "\n", m->dim, m->nnode, m->nelem));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "node sets %" PetscInt_FMT ", element sets %" PetscInt_FMT ", surfaces %" PetscInt_FMT "\n", m->nnset,
                        m->nelset, m->nsurface));
  PetscCall(PetscPrintf(PETSC_COMM_SELF,
                        "materials %" PetscInt_FMT ", sections %" PetscInt_FMT ", initial conditions %" PetscInt_FMT ", amplitudes %" PetscInt_FMT
                        ", equations %" PetscInt_FMT "\n",
                        m->nmaterial, m->nsection, m->ninit, m->namplitude, m->nequation));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "surface interactions %" PetscInt_FMT ", contact pairs %" PetscInt_FMT "\n", m->ninteraction, m->npair));
  for (PetscInt i = 0; i < m->nstep; i++) {
    const TslStep *s = &m->steps[i];
    PetscCall(PetscPrintf(
        PETSC_COMM_SELF, "step %s: %s%s, dt0 %g, period %g, dtmin %g, dtmax %g, %" PetscInt_FMT " loads, %" PetscInt_FMT " output requests%s\n", s->name,
        s->explicit_dynamics ? "explicit, " : "", s->steady ? "steady" : "transient", (double)s->dt0, (double)s->period, (double)s->dtmin, (double)s->dtmax,
        s->nload, s->nout, s->nlgeom ? (s->nlgeom_default ? ", finite strain (the explicit default)" : ", finite strain") : ", small strain"));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  TslModel      *model = NULL;
  PetscErrorCode ierr;
  int            status = 0;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  if (argc < 2) {
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "usage: %s deck.inp\n", argv[0]));
    PetscCall(PetscFinalize());
    return 2;
  }
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = TslDeckRead(argv[1], &model);
  PetscCall(PetscPopErrorHandler());
  if (ierr) {
    const char *text;
    char       *specific = NULL;
    PetscCall(PetscErrorMessage(ierr, &text, &specific));
    PetscCall(PetscFPrintf(PETSC_COMM_SELF, stderr, "error: %s\n", specific && specific[0] ? specific : text));
    status = 1;
  } else {
    PetscCall(Summary(model));
    PetscCall(TslModelDestroy(&model));
  }
  PetscCall(PetscFinalize());
  return status;
}
