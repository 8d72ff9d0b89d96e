/* The dialect's line syntax (docs/keywords.md, "General syntax"): a keyword line ending in a comma continues
 * only onto parameters (data/continuation.inp: "*node file," then "U" is a request for U); *STEP's optional
 * title line (data/step_title.inp); *PARAMETER and its <name> substitution in data lines and keyword-line
 * values (data/parameter.inp). */
#include <thermoslide/model.h>
#include <string.h>

#ifndef TSL_DECK_DATA
#error "TSL_DECK_DATA (the tests/deck/data directory) must be defined"
#endif

#include "expect.h"

static PetscErrorCode TestContinuation(void)
{
  TslModel      *m;
  const TslStep *s;

  PetscFunctionBeginUser;
  PetscCall(TslDeckRead(TSL_DECK_DATA "/continuation.inp", &m));
  EXPECT(TslModelFindNodeSet(m, "TOP") >= 0 && m->nsets[TslModelFindNodeSet(m, "TOP")].n == 2); /* *NSET, then NSET=TOP */
  EXPECT(TslModelFindElementSet(m, "EALL") >= 0 && m->nelem == 1);                              /* TYPE=CPE4T, then ELSET=EALL, */
  EXPECT(m->nsection == 1 && !strcmp(m->sections[0].material, "STEEL"));                         /* then MATERIAL = STEEL */
  EXPECT(m->nstep == 1);
  s = &m->steps[0];
  EXPECT(!strcmp(s->name, "S1") && s->max_inc == 20); /* NAME=S1, then INC=20 */
  EXPECT(s->steady);                                  /* a line of a parameter name alone: steady state */
  EXPECT(s->nout == 3);
  EXPECT(s->out[0].node && !s->out[0].print && s->out[0].nvar == 1 && !strcmp(s->out[0].var[0], "U")); /* "*node file," then "U" */
  EXPECT(!s->out[1].node && s->out[1].nvar == 2 && !strcmp(s->out[1].var[0], "S") && !strcmp(s->out[1].var[1], "E"));
  EXPECT(s->out[2].print && !strcmp(s->out[2].set, "TOP") && s->out[2].totals == 1 && s->out[2].nvar == 1 && !strcmp(s->out[2].var[0], "RF"));
  PetscCall(TslModelDestroy(&m));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestStepTitle(void)
{
  TslModel *m;

  PetscFunctionBeginUser;
  PetscCall(TslDeckRead(TSL_DECK_DATA "/step_title.inp", &m));
  EXPECT(m->nstep == 2 && !strcmp(m->steps[0].name, "PRESS") && m->steps[0].steady && m->steps[0].nload == 3);
  EXPECT(!strcmp(m->steps[1].name, "Step-2") && m->steps[1].steady);
  PetscCall(TslModelDestroy(&m));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestParameter(void)
{
  TslModel      *m;
  const TslStep *s;

  PetscFunctionBeginUser;
  PetscCall(TslDeckRead(TSL_DECK_DATA "/parameter.inp", &m));
  EXPECT(!strcmp(m->heading, "Parameters: <w> stays as written in the title"));
  /* w = 2, then w = w + 1 = 3; h = w / 4 = 0.5 (with the w of then); h2 = <h> * 2 = 1 */
  EXPECT(m->nnode == 4 && m->node_xyz[3 * 1] == 3.0 && m->node_xyz[3 * 2] == 3.0 && m->node_xyz[3 * 2 + 1] == 1.0 && m->node_xyz[3 * 3 + 1] == 1.0);
  EXPECT(m->materials[0].prop[TSL_PROP_ELASTIC].value[0][0] == 2.1e5); /* E = 2.1D5 */
  s = &m->steps[0];
  EXPECT(!strcmp(s->name, "S2") && s->max_inc == 20); /* n = 2**3 - (1 + 1) * 3 = 2: NAME=S<n>, INC=<n>0 */
  EXPECT(s->deltmx == 0.5 && s->dt0 == 0.25);         /* DELTMX=<h>; dt = 1 / n * 0.5 */
  EXPECT(s->nload == 3 && s->loads[2].value == -4.0); /* k = -2**2: ** binds tighter than the sign, as in Python */
  PetscCall(TslModelDestroy(&m));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(TestContinuation());
  PetscCall(TestStepTitle());
  PetscCall(TestParameter());
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "%s: %d failed check(s)\n", nfail ? "FAILED" : "PASSED", nfail));
  PetscCall(PetscFinalize());
  return nfail ? 1 : 0;
}
