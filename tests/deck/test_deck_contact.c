/* Reads tests/deck/data/contact.inp (two surface interactions with every interface law, two *CONTACT PAIR
 * keywords, three pairs) and checks every stored value; then that a Pack/Unpack round trip and
 * TslModelSubset keep the interactions and pairs whole. Exits non-zero when a check fails. */
#include <thermoslide/model.h>
#include <string.h>

#ifndef TSL_DECK_DATA
#error "TSL_DECK_DATA (the tests/deck/data directory) must be defined"
#endif

#include "expect.h"

static PetscErrorCode TestInteractions(const TslModel *m)
{
  const TslInteraction *c, *r;

  PetscFunctionBeginUser;
  EXPECT(m->ninteraction == 2);
  EXPECT(TslModelFindInteraction(m, "CONDUCT") == 0 && TslModelFindInteraction(m, "radiate") == 1);
  EXPECT(TslModelFindInteraction(m, "NOPE") == -1);
  c = &m->interactions[0];
  EXPECT(!strcmp(c->name, "Conduct") && c->loc.file == 0 && c->loc.line == 39 && NEAR(c->thickness, 1));
  EXPECT(c->behavior.given && c->behavior.enforcement == TSL_CONTACT_AUGMENTED_LAGRANGE && NEAR(c->behavior.penalty_stiffness, 1e7) &&
         c->behavior.loc.line == 40);
  EXPECT(c->friction.given && NEAR(c->friction.mu, 0.1) && c->friction.lagrange && !c->friction.rough);
  EXPECT(NEAR(c->friction.slip_tolerance, 0.005) && NEAR(c->friction.stick_slope, 0) && c->friction.loc.line == 42);
  /* given as (5, 200), (20, 100): stored sorted by pressure */
  EXPECT(c->conductance.given && c->conductance.by_pressure && c->conductance.n == 2 && c->conductance.loc.line == 44);
  EXPECT(NEAR(c->conductance.abscissa[0], 100) && NEAR(c->conductance.value[0], 20));
  EXPECT(NEAR(c->conductance.abscissa[1], 200) && NEAR(c->conductance.value[1], 5));
  EXPECT(!c->radiation.given && c->radiation.n == 0 && !c->radiation.view_factor && !c->radiation.clearance);
  EXPECT(c->heat_generation.given && NEAR(c->heat_generation.fraction, 0.5) && NEAR(c->heat_generation.weight_secondary, 0.25) &&
         c->heat_generation.loc.line == 47);

  r = &m->interactions[1];
  EXPECT(!strcmp(r->name, "RADIATE") && r->loc.line == 49 && NEAR(r->thickness, 2));
  EXPECT(r->behavior.given && r->behavior.enforcement == TSL_CONTACT_HARD_PENALTY && NEAR(r->behavior.penalty_stiffness, 0));
  EXPECT(r->friction.given && NEAR(r->friction.mu, 0.2) && !r->friction.lagrange && NEAR(r->friction.slip_tolerance, 0.01));
  EXPECT(NEAR(r->friction.stick_slope, 1e5));
  EXPECT(!r->conductance.given && r->conductance.n == 0 && !r->conductance.value);
  EXPECT(r->radiation.given && NEAR(r->radiation.emissivity_main, 0.8) && NEAR(r->radiation.emissivity_secondary, 0.6));
  EXPECT(r->radiation.n == 3 && r->radiation.loc.line == 54);
  EXPECT(NEAR(r->radiation.clearance[0], 0) && NEAR(r->radiation.clearance[1], 0.1) && NEAR(r->radiation.clearance[2], 0.2));
  EXPECT(NEAR(r->radiation.view_factor[0], 1) && NEAR(r->radiation.view_factor[1], 0.5) && NEAR(r->radiation.view_factor[2], 0.25));
  /* no *GAP HEAT GENERATION: the dialect's defaults */
  EXPECT(!r->heat_generation.given && NEAR(r->heat_generation.fraction, 1) && NEAR(r->heat_generation.weight_secondary, 0.5));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestPairs(const TslModel *m)
{
  const TslContactPair *p;

  PetscFunctionBeginUser;
  EXPECT(m->npair == 3);
  p = &m->pairs[0];
  EXPECT(!strcmp(p->interaction, "conduct") && p->interaction_index == 0 && p->loc.line == 61);
  EXPECT(!strcmp(p->secondary, "SLIDER_NODES") && !strcmp(p->main, "BASE_TOP"));
  EXPECT(p->type == TSL_CONTACT_NODE_TO_SURFACE && p->small_sliding && NEAR(p->smooth, 0.05) && !p->adjust_given);
  p = &m->pairs[1]; /* keyword line continued: ADJUST on the next line */
  EXPECT(!strcmp(p->interaction, "RADIATE") && p->interaction_index == 1 && p->loc.line == 64);
  EXPECT(!strcmp(p->secondary, "SLIDER_BOTTOM") && !strcmp(p->main, "BASE_TOP"));
  EXPECT(p->type == TSL_CONTACT_SURFACE_TO_SURFACE && !p->small_sliding && NEAR(p->smooth, 0.2));
  EXPECT(p->adjust_given && NEAR(p->adjust, 0.01) && !p->adjust_set[0]);
  p = &m->pairs[2]; /* second data line of the same keyword: same parameters */
  EXPECT(p->interaction_index == 1 && p->loc.line == 65 && p->type == TSL_CONTACT_SURFACE_TO_SURFACE);
  EXPECT(!strcmp(p->secondary, "slider_bottom") && !strcmp(p->main, "Base_side") && p->adjust_given);
  /* the step's *CONTACT OUTPUT is skipped */
  EXPECT(m->nstep == 1 && m->steps[0].nload == 1 && m->steps[0].nout == 0);
  PetscFunctionReturn(PETSC_SUCCESS);
}

#define SAME(a, b, n) ((n) == 0 || (!(a) && !(b)) || ((a) && (b) && !memcmp((a), (b), (size_t)(n) * sizeof(*(a)))))
/* Interactions and pairs equal in content (pointers differ). */
static PetscBool ContactEqual(const TslModel *x, const TslModel *y)
{
  if (x->ninteraction != y->ninteraction || x->npair != y->npair) return PETSC_FALSE;
  if (!SAME(x->pairs, y->pairs, x->npair)) return PETSC_FALSE;
  for (PetscInt i = 0; i < x->ninteraction; i++) {
    TslInteraction a = x->interactions[i], b = y->interactions[i];
    if (a.conductance.n != b.conductance.n || a.radiation.n != b.radiation.n) return PETSC_FALSE;
    if (!SAME(a.conductance.value, b.conductance.value, a.conductance.n) || !SAME(a.conductance.abscissa, b.conductance.abscissa, a.conductance.n) ||
        !SAME(a.radiation.view_factor, b.radiation.view_factor, a.radiation.n) || !SAME(a.radiation.clearance, b.radiation.clearance, a.radiation.n))
      return PETSC_FALSE;
    /* the rest of the struct byte for byte, with the table pointers blanked */
    a.conductance.value = a.conductance.abscissa = a.radiation.view_factor = a.radiation.clearance = NULL;
    b.conductance.value = b.conductance.abscissa = b.radiation.view_factor = b.radiation.clearance = NULL;
    if (memcmp(&a, &b, sizeof(a))) return PETSC_FALSE;
  }
  return PETSC_TRUE;
}

static PetscErrorCode TestPackAndSubset(const TslModel *m)
{
  char          *buf;
  size_t         len;
  TslModel      *u, *s;
  const PetscInt elems[] = {1}, nodes[] = {4, 5, 6, 7}; /* the slider only */

  PetscFunctionBeginUser;
  PetscCall(TslModelPack(m, &buf, &len));
  PetscCall(TslModelUnpack(buf, len, &u));
  PetscCall(PetscFree(buf));
  EXPECT(ContactEqual(m, u));
  EXPECT(u->interactions[0].conductance.value != m->interactions[0].conductance.value); /* a deep copy */
  PetscCall(TestInteractions(u));
  PetscCall(TestPairs(u));
  PetscCall(TslModelDestroy(&u));

  PetscCall(TslModelSubset(m, 1, elems, 4, nodes, &s));
  EXPECT(s->nelem == 1 && s->nnode == 4);
  EXPECT(ContactEqual(m, s)); /* non-mesh data: whole, although BASE_TOP is empty on this subset */
  EXPECT(s->surfaces[TslModelFindSurface(s, "BASE_TOP")].n == 0);
  PetscCall(TestInteractions(s));
  PetscCall(TestPairs(s));
  PetscCall(TslModelDestroy(&s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  TslModel *m;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(TslDeckRead(TSL_DECK_DATA "/contact.inp", &m));
  PetscCall(TestInteractions(m));
  PetscCall(TestPairs(m));
  PetscCall(TestPackAndSubset(m));
  PetscCall(TslModelDestroy(&m));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "%s: %d failed check(s)\n", nfail ? "FAILED" : "PASSED", nfail));
  PetscCall(PetscFinalize());
  return nfail ? 1 : 0;
}
