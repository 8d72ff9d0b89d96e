/* Placement of model data and history data: a *BOUNDARY before the first *STEP (model data) becomes the
 * first step's first loads, so it applies from step 1 on and persists like any other (OP=MOD); an
 * OP=NEW *BOUNDARY in the first step removes it, as in Abaqus. Also *AMPLITUDE in a step and *OUTPUT
 * in the model data (the steps' default frequency), both placements the dialect allows. */
#include <thermoslide/model.h>
#include <string.h>
#include <math.h>

#ifndef TSL_DECK_DATA
#error "TSL_DECK_DATA (the tests/deck/data directory) must be defined"
#endif

#include "expect.h"

static PetscErrorCode TestModelBoundary(void)
{
  TslModel      *m;
  const TslStep *s;

  PetscFunctionBeginUser;
  PetscCall(TslDeckRead(TSL_DECK_DATA "/model_boundary.inp", &m));
  EXPECT(m->nstep == 2);
  s = &m->steps[0];
  EXPECT(s->nload == 3);
  /* the model-data lines come first, with their own deck lines, value zero, step-default amplitude */
  EXPECT(s->loads[0].kind == TSL_LOAD_BOUNDARY && !strcmp(s->loads[0].target.set, "BOTTOM") && s->loads[0].dof_first == 1 &&
         s->loads[0].dof_last == 2 && s->loads[0].value == 0 && s->loads[0].loc.line == 14 && !s->loads[0].op_new && s->loads[0].amplitude == -1);
  EXPECT(s->loads[1].kind == TSL_LOAD_BOUNDARY && !s->loads[1].target.set[0] && s->loads[1].target.id == 1 && s->loads[1].dof_first == 11 &&
         s->loads[1].value == 0 && s->loads[1].loc.line == 15);
  /* then the step's own *BOUNDARY, which modifies / adds to them (OP=MOD) */
  EXPECT(s->loads[2].kind == TSL_LOAD_BOUNDARY && !strcmp(s->loads[2].target.set, "TOP") && s->loads[2].value == 20 && !s->loads[2].op_new);
  /* *OUTPUT in the model data sets every step's default frequency */
  EXPECT(s->nout == 1 && s->out[0].frequency == 3);
  EXPECT(m->steps[1].nout == 1 && m->steps[1].out[0].frequency == 3);
  /* the second step redefines nothing: the conditions carry over in the solver (loads.c, OP=MOD) */
  EXPECT(m->steps[1].nload == 0);
  /* *AMPLITUDE inside a step is allowed (CalculiX: step or model definition) */
  EXPECT(m->namplitude == 2 && TslModelFindAmplitude(m, "LATE") == 1);
  PetscCall(TslModelDestroy(&m));

  PetscCall(TslDeckRead(TSL_DECK_DATA "/model_boundary_opnew.inp", &m));
  s = &m->steps[0];
  EXPECT(s->nload == 1 && s->loads[0].op_new && !strcmp(s->loads[0].target.set, "TOP"));
  PetscCall(TslModelDestroy(&m));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *INITIAL CONDITIONS, TYPE=VELOCITY (and TYPE=TEMPERATURE, filtered alike): the lines in deck order (node set or node, dof, value, line), whole
 * through pack/unpack, and in a subset only those that concern its nodes (a node it holds, a set with members
 * there): a rank keeps its share of a per-node list, not the whole deck's. */
static PetscErrorCode TestInitialVelocity(void)
{
  TslModel *m, *s;
  char     *buf;
  size_t    len;

  PetscFunctionBeginUser;
  PetscCall(TslDeckRead(TSL_DECK_DATA "/initial_velocity.inp", &m));
  EXPECT(m->ninit == 3 && m->nvinit == 3);
  EXPECT(!strcmp(m->vinit[0].target.set, "ALL") && m->vinit[0].dof == 1 && m->vinit[0].value == -1.5e3 && m->vinit[0].loc.line == 29);
  EXPECT(!strcmp(m->vinit[1].target.set, "LEFT") && m->vinit[1].dof == 2 && m->vinit[1].value == 250 && m->vinit[1].loc.line == 30);
  EXPECT(!m->vinit[2].target.set[0] && m->vinit[2].target.id == 6 && m->vinit[2].dof == 1 && m->vinit[2].value == 0);
  PetscCall(TslModelPack(m, &buf, &len));
  PetscCall(TslModelUnpack(buf, len, &s));
  PetscCall(PetscFree(buf));
  EXPECT(s->nvinit == 3 && !memcmp(s->vinit, m->vinit, 3 * sizeof(*m->vinit)));
  PetscCall(TslModelDestroy(&s));
  /* element 2 and its nodes 2, 5, 6, 3 (positions 1, 4, 5, 2): LEFT has no member there, node 6 is held */
  {
    const PetscInt elems[] = {1}, nodes[] = {1, 4, 5, 2};
    PetscCall(TslModelSubset(m, 1, elems, 4, nodes, &s));
    EXPECT(s->nvinit == 2 && !strcmp(s->vinit[0].target.set, "ALL") && s->vinit[1].target.id == 6);
    EXPECT(s->ninit == 2 && !strcmp(s->init[0].target.set, "ALL") && s->init[1].target.id == 6 && s->init[1].value == 30); /* temperatures alike */
    PetscCall(TslModelDestroy(&s));
  }
  /* node 1 alone: ALL and LEFT have it, node 6 is not held */
  {
    const PetscInt one[] = {0};
    PetscCall(TslModelSubset(m, 0, NULL, 1, one, &s));
    EXPECT(s->nvinit == 2 && !strcmp(s->vinit[0].target.set, "ALL") && !strcmp(s->vinit[1].target.set, "LEFT") && s->vinit[1].dof == 2);
    EXPECT(s->ninit == 2 && !strcmp(s->init[0].target.set, "ALL") && !strcmp(s->init[1].target.set, "LEFT") && s->init[1].value == 25);
    PetscCall(TslModelDestroy(&s));
  }
  PetscCall(TslModelDestroy(&m));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *AMPLITUDE, DEFINITION=PERIODIC: a = A0 + sum A_k cos(k w (t - t0)) + B_k sin(k w (t - t0)) from t0, A0 before, and its
 * integral in closed form (a velocity boundary condition integrates it); the defaults t0 = A0 = 0; DECAY, MODULATED and
 * EQUALLY SPACED alike; all through pack/unpack. */
static PetscReal SpinSeries(PetscReal t)
{
  const PetscReal w = 3.0, tau = t - 0.5;
  if (tau <= 0) return -1;
  return -1 + 2 * cos(w * tau) + 0.5 * sin(w * tau) + 0.25 * cos(2 * w * tau) - sin(2 * w * tau);
}

static PetscReal SpinPrimitive(PetscReal t) /* from t0 */
{
  const PetscReal w = 3.0, tau = t - 0.5;
  if (tau <= 0) return -tau;
  return -tau + 2 * sin(w * tau) / w + 0.5 * (1 - cos(w * tau)) / w + 0.25 * sin(2 * w * tau) / (2 * w) - (1 - cos(2 * w * tau)) / (2 * w);
}

static PetscErrorCode TestPeriodicAmplitude(void)
{
  TslModel           *m, *s;
  const TslAmplitude *spin, *plain;
  char               *buf;
  size_t              len;

  PetscFunctionBeginUser;
  PetscCall(TslDeckRead(TSL_DECK_DATA "/amplitude_forms.inp", &m));
  PetscCall(TslModelPack(m, &buf, &len));
  PetscCall(TslModelUnpack(buf, len, &s));
  PetscCall(PetscFree(buf));
  EXPECT(s->namplitude == 6);
  spin  = &s->amplitudes[TslModelFindAmplitude(s, "SPIN")];
  plain = &s->amplitudes[TslModelFindAmplitude(s, "PLAIN")];
  EXPECT(spin->form == TSL_AMP_PERIODIC && spin->nterm == 2 && spin->n == 0 && !spin->total_time);
  EXPECT(plain->form == TSL_AMP_PERIODIC && plain->nterm == 1 && plain->t0 == 0 && plain->a0 == 0 && plain->total_time);
  for (PetscReal t = 0; t <= 4.0; t += 0.37) {
    EXPECT(PetscAbsReal(TslAmplitudeEval(spin, t) - SpinSeries(t)) < 1e-13);
    EXPECT(PetscAbsReal(TslAmplitudeIntegral(spin, 0.2, t) - (SpinPrimitive(t) - SpinPrimitive(0.2))) < 1e-13);
    EXPECT(PetscAbsReal(TslAmplitudeEval(plain, t) - sin(2 * PETSC_PI * t)) < 1e-13);
  }
  EXPECT(PetscAbsReal(TslAmplitudeIntegral(plain, 0, 1)) < 1e-14); /* a whole period of a sine */
  EXPECT(PetscAbsReal(TslAmplitudeBound(spin) - 4.75) < 1e-14);
  {
    /* DECAY: 2 + 3 exp(-(t - 0.25) / 0.5); MODULATED: 0.5 + 2 sin 7 tau sin 3 tau (tau = t - 0.1), and with equal
     * frequencies sin^2 4t (its primitive t/2 - sin 8t / 16); EQUALLY SPACED: 0, 1, 4, -2 at 1, 1.5, 2, 2.5 */
    const TslAmplitude *fade = &s->amplitudes[TslModelFindAmplitude(s, "FADE")], *beat = &s->amplitudes[TslModelFindAmplitude(s, "BEAT")];
    const TslAmplitude *unison = &s->amplitudes[TslModelFindAmplitude(s, "UNISON")], *rec = &s->amplitudes[TslModelFindAmplitude(s, "RECORD")];
    EXPECT(fade->form == TSL_AMP_DECAY && beat->form == TSL_AMP_MODULATED && rec->form == TSL_AMP_POINTS && rec->n == 4);
    for (PetscReal t = 0; t <= 3.0; t += 0.23) {
      const PetscReal tf = t - 0.25, tb = t - 0.1;
      const PetscReal fade_int = (tf <= 0 ? 2 * tf : 2 * tf + 1.5 * (1 - exp(-tf / 0.5))) - 2 * (0.05 - 0.25);
      const PetscReal beat_prim = tb <= 0 ? 0.5 * tb : 0.5 * tb + (sin(4 * tb) / 4 - sin(10 * tb) / 10);
      EXPECT(PetscAbsReal(TslAmplitudeEval(fade, t) - (tf < 0 ? 2 : 2 + 3 * exp(-tf / 0.5))) < 1e-13);
      EXPECT(PetscAbsReal(TslAmplitudeIntegral(fade, 0.05, t) - fade_int) < 1e-13);
      EXPECT(PetscAbsReal(TslAmplitudeEval(beat, t) - (tb < 0 ? 0.5 : 0.5 + 2 * sin(7 * tb) * sin(3 * tb))) < 1e-13);
      EXPECT(PetscAbsReal(TslAmplitudeIntegral(beat, 0, t) - (beat_prim + 0.05)) < 1e-13);
      EXPECT(PetscAbsReal(TslAmplitudeIntegral(unison, 0, t) - (t / 2 - sin(8 * t) / 16)) < 1e-13);
    }
    EXPECT(TslAmplitudeEval(rec, 0.5) == 0 && TslAmplitudeEval(rec, 1.75) == 2.5 && TslAmplitudeEval(rec, 2.25) == 1 && TslAmplitudeEval(rec, 9) == -2);
    EXPECT(PetscAbsReal(TslAmplitudeBound(fade) - 5) < 1e-14 && PetscAbsReal(TslAmplitudeBound(rec) - 4) < 1e-14);
  }
  PetscCall(TslModelDestroy(&s));
  PetscCall(TslModelDestroy(&m));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(TestModelBoundary());
  PetscCall(TestInitialVelocity());
  PetscCall(TestPeriodicAmplitude());
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "%s: %d failed check(s)\n", nfail ? "FAILED" : "PASSED", nfail));
  PetscCall(PetscFinalize());
  return nfail ? 1 : 0;
}
