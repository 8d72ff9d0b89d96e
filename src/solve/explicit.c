/* The explicit procedure: *DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT (docs/explicit.md).
 *
 * Central differences for the displacements with the lumped mass M, forward Euler for the temperatures
 * with the lumped capacity C (Abaqus Theory Guide, "Fully coupled thermal-stress analysis" in
 * Abaqus/Explicit), both from the nodal vectors of one force evaluation at the state of time n:
 *   M a_n = Fe_n - Fi_n - Fc_n                       (displacement rows; Fi internal, Fe applied, Fc contact)
 *   v_{n+1/2} = v_{n-1/2} + (dt_{n+1} + dt_n)/2 a_n,  u_{n+1} = u_n + dt_{n+1} v_{n+1/2}
 *   theta_{n+1} = theta_n + dt_{n+1} (-Fi_n - Fc_n) / C   (temperature rows, residual form)
 * Prescribed dofs take their value at t_{n+1}; their velocity is the difference quotient. No matrix: a
 * step costs one element loop per increment, and memory is the vectors of Explicit below.
 *
 * Energies (history, docs/explicit.md): every force F_n works over w_n = dt_avg (v_{n-1/2} + v_{n+1/2}) / 2,
 * the displacement that the central-difference kinetic energy change 1/2 M (v_{n+1/2}^2 - v_{n-1/2}^2)
 * equals M a_n . w_n for; so ALLKE (at the half step) + ALLIE + ALLCW - ALLWK - ALLMW stays at round-off
 * when the forces and the update are consistent, and ALLIE is checked against the elements' strain
 * energy (a state function) in the tests. */
#include "solve_impl.h"
#include <thermoslide/contact.h>

/* Finite strain: the stable increment is recomputed from the deformed elements every this many increments (a
 * deforming element's size changes by a fraction of its strain rate times the interval: 0.1 % for a strain rate of
 * 1e-4 per increment) */
#define TSL_NLGEOM_STABLE_EVERY 10

#define MASS_WARN_FACTOR 100.0 /* a mass scaled by more than this is worth a warning */

typedef struct {
  Driver         *d;
  TslProblem      p;
  const TslModel *m;
  const TslStep  *step;
  MPI_Comm        comm;
  PetscInt        ndof, nown;
  Vec             X, Xold;         /* the problem's solution and the state at the start of the increment */
  Vec             V, M, Mask;      /* half-step velocity, lumped mass / capacity, prescribed dofs */
  PetscInt         npresc, *presc;  /* the owned dofs the mask holds (prescribed or pinned), in increasing order */
  Vec             Fi, Fe, Fc;      /* force vectors of the current state (Fi with the bulk viscosity's forces; Fc NULL without contact) */
  Vec             Qp;              /* *PLASTIC: the plastic heat sources, a rate over dt_forces, deposited as dt_forces Qp (NULL: no plastic material) */
  PetscReal      *qv, vd_h;        /* bulk viscosity: q = p V per element (NULL: none); h_avg of the last increment, whose
                                      viscous work's second half the next force evaluation books */
  /* *DAMPING (docs/explicit.md "Damping"): per element alpha and beta of its material; AM the lumped alpha m per dof
   * (NULL: no mass-proportional damping); damped: some beta > 0 (its forces are in Fi, its power in the rates' viscous) */
  PetscReal      *alpha, *beta;
  Vec             AM;
  PetscBool       damped;
  Vec             Fk;              /* kinematic contact: the corrector's forces at the predicted state (NULL without) */
  Vec             W;               /* contact: a work vector (the corrector's, the interface's row sums for the stable increment; NULL without) */
  PetscInt        kin_passes, kin_total; /* -tsl_explicit_kinematic_passes (most corrector passes per increment); passes made in the step */
  PetscReal       kin_tol;         /* -tsl_explicit_kinematic_tol: passes stop when the pressure change is below this fraction of the largest */
  PetscReal        kin_gap;         /* -tsl_explicit_kinematic_gap_tol: ... and no gap left above this (over the search radius) still shrinks */
  PetscReal       *dt_mech, *dt_heat, *scale, *eta, *eta2; /* [nelem] element stable increments, mass scale factors, b1 L_e / c_d, (b2 L_e / c_d)^2 */
  PetscReal       dt_stable, dt;   /* stable increment (with safety) and the increment used */
  PetscReal       lim_mech, lim_heat;   /* limits of the elements: mechanical, thermal */
  PetscReal       lim_cmech, lim_cheat; /* limits of the interface: normal penalty, heat exchange (PETSC_MAX_REAL: none) */
  PetscReal       safety;          /* -tsl_explicit_safety */
  PetscInt        progress;        /* -tsl_explicit_progress: increments between progress lines */
  PetscInt        history_rows;    /* -tsl_explicit_history: history rows per step besides the frames */
  PetscInt        search_every;    /* -tsl_explicit_contact_search: increments between pairing searches */
  PetscInt        nrepair;         /* contact nodes re-paired because their projection left the face */
  PetscReal       dt_forces;       /* the increment the last force evaluation measured slip over */
  PetscBool       capacity_varies; /* temperature-dependent c or rho: capacity re-lumped every increment */
  PetscReal       rates_reaction_heat, stored_rate;
  PetscReal       balance; /* the last increment's heat balance: the rates it was advanced with (state n) against its stored heat */
  int              stop; /* the signal a rank was stopped by (src/sys/stop.c), agreed in Advance's reduction; 0: none */
  TslExplicitRates rates;
  TslExplicitRates krates;         /* the kinematic corrector's heat rates (its slip measured over the increment it corrects) */
} Explicit;

/* the energies since the start of the job (Driver.energy) */
typedef struct {
  PetscReal ke, ie, wk, fd, cw, mw, vd;
} Energies;

/* A restart point's share of the explicit state (TslRestartExtra; docs/running.md "Restart"), what the next
 * increment reads beyond the solution and the contact state: the vectors V, M, Fi, Fe (Fc with contact: the forces
 * of the state, evaluated at the end of its increment) and as reals the loop's scalars (XR_*), the last evaluation's
 * heat rates, the element increments, scale factors and viscosity coefficients (the mass scaling's, as last set),
 * the bulk viscosity's q per element and the records' carried strains. One walk serves both ways (Carry). */
enum { XR_H_PREV, XR_T_HIST, XR_DT, XR_DT_STABLE, XR_LIM_MECH, XR_LIM_HEAT, XR_LIM_CMECH, XR_LIM_CHEAT, XR_VD_H, XR_DT_FORCES,
       XR_KIN_TOTAL, XR_NREPAIR, XR_REACTION, XR_STORED, XR_BALANCE, XR_N };
#define NRATES ((PetscInt)(sizeof(TslExplicitRates) / sizeof(PetscReal)))

static void CarryReals(PetscReal **at, PetscReal *var, PetscInt n, PetscBool out)
{
  if (out) memcpy(*at, var, sizeof(PetscReal) * (size_t)n);
  else memcpy(var, *at, sizeof(PetscReal) * (size_t)n);
  *at += n;
}

/* out: the state into e->real (allocated here, e->vec set); else the reals back into the state. h_prev and t_hist
 * are the loop's. */
static PetscErrorCode Carry(Explicit *x, TslRestartExtra *e, PetscReal *h_prev, PetscReal *t_hist, PetscBool out)
{
  PetscReal *ev, *at, sc[XR_N], *shape;
  PetscInt   nev, ne = x->m->nelem, nsh;
  const PetscInt *lane;

  PetscFunctionBeginUser;
  PetscCall(TslProblemExplicitCarried(x->p, &ev, &nev, &lane));
  PetscCall(TslProblemStableShapes(x->p, &shape)); /* finite strain: the stable increments' memory of the shapes */
  nsh = shape ? TSL_STABLE_SHAPE : 0;
  if (!e->real) {
    e->nvec   = 0;
    e->vec[e->nvec++] = x->V, e->vec[e->nvec++] = x->M, e->vec[e->nvec++] = x->Fi, e->vec[e->nvec++] = x->Fe;
    if (x->Fc) e->vec[e->nvec++] = x->Fc;
    if (x->Qp) e->vec[e->nvec++] = x->Qp;
    e->nreal = XR_N + 2 * NRATES + (5 + nsh) * ne + (x->qv ? ne : 0) + nev;
    PetscCall(PetscMalloc1(e->nreal, &e->real));
    /* the loop's scalars and the heat rates are the same on every rank (summed), nrepair aside (a count of rank 0's
     * for the log) */
    e->nglobal     = XR_N + 2 * NRATES;
    e->nearr       = 5 + (x->qv ? 1 : 0) + nsh;
    e->carried_off = e->nglobal + e->nearr * ne;
    e->lane        = nev ? lane : NULL;
  }
  if (out) {
    sc[XR_H_PREV] = *h_prev, sc[XR_T_HIST] = *t_hist, sc[XR_DT] = x->dt, sc[XR_DT_STABLE] = x->dt_stable;
    sc[XR_LIM_MECH] = x->lim_mech, sc[XR_LIM_HEAT] = x->lim_heat, sc[XR_LIM_CMECH] = x->lim_cmech, sc[XR_LIM_CHEAT] = x->lim_cheat;
    sc[XR_VD_H] = x->vd_h, sc[XR_DT_FORCES] = x->dt_forces, sc[XR_KIN_TOTAL] = (PetscReal)x->kin_total, sc[XR_NREPAIR] = (PetscReal)x->nrepair;
    sc[XR_REACTION] = x->rates_reaction_heat, sc[XR_STORED] = x->stored_rate, sc[XR_BALANCE] = x->balance;
  }
  at = e->real;
  CarryReals(&at, sc, XR_N, out);
  CarryReals(&at, (PetscReal *)&x->rates, NRATES, out);
  CarryReals(&at, (PetscReal *)&x->krates, NRATES, out);
  CarryReals(&at, x->dt_mech, ne, out);
  CarryReals(&at, x->dt_heat, ne, out);
  CarryReals(&at, x->scale, ne, out);
  CarryReals(&at, x->eta, ne, out);
  CarryReals(&at, x->eta2, ne, out);
  if (x->qv) CarryReals(&at, x->qv, ne, out);
  for (PetscInt k = 0; k < nsh; k++, at += ne) /* one array per part, as the others (the elements' arrays of xelem) */
    for (PetscInt el = 0; el < ne; el++) {
      if (out) at[el] = shape[nsh * el + k];
      else shape[nsh * el + k] = at[el];
    }
  if (nev) CarryReals(&at, ev, nev, out);
  if (!out) {
    *h_prev = sc[XR_H_PREV], *t_hist = sc[XR_T_HIST], x->dt = sc[XR_DT], x->dt_stable = sc[XR_DT_STABLE];
    x->lim_mech = sc[XR_LIM_MECH], x->lim_heat = sc[XR_LIM_HEAT], x->lim_cmech = sc[XR_LIM_CMECH], x->lim_cheat = sc[XR_LIM_CHEAT];
    x->vd_h = sc[XR_VD_H], x->dt_forces = sc[XR_DT_FORCES], x->kin_total = (PetscInt)sc[XR_KIN_TOTAL], x->nrepair = (PetscInt)sc[XR_NREPAIR];
    x->rates_reaction_heat = sc[XR_REACTION], x->stored_rate = sc[XR_STORED], x->balance = sc[XR_BALANCE];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A restart point at the end of increment inc (its forces evaluated, its frame and history row written). */
static PetscErrorCode WritePoint(Explicit *x, const TslRestartLoop *L, PetscReal h_prev, PetscReal t_hist, const char *why)
{
  TslRestartExtra e = {0};

  PetscFunctionBeginUser;
  PetscCall(Carry(x, &e, &h_prev, &t_hist, PETSC_TRUE));
  PetscCall(TslRestartWrite(x->d, L, why, &e));
  PetscCall(PetscFree(e.real));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode AlphaMasses(Explicit *x);

/* The continuation (-tsl_restart) in the point's step: after the step's set-up (from the state the step started
 * with, so that what the set-up computes once is the original run's), the point's state replaces the set-up's. */
static PetscErrorCode Resume(Explicit *x, TslRestartLoop *L, PetscReal *h_prev, PetscReal *t_hist)
{
  TslRestartExtra e = {0};

  PetscFunctionBeginUser;
  PetscCall(Carry(x, &e, h_prev, t_hist, PETSC_TRUE)); /* the layout */
  PetscCall(TslRestartLoadExtra(x->d, &e));
  PetscCall(TslRestartLoad(x->d, L));
  PetscCall(Carry(x, &e, h_prev, t_hist, PETSC_FALSE));
  PetscCall(PetscFree(e.real));
  PetscCall(AlphaMasses(x)); /* from the point's scale factors */
  PetscCall(TslGhostUpdate(x->M, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(TslGhostUpdate(x->V, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(TslProblemSetTime(x->p, L->t, *h_prev, L->total));
  PetscFunctionReturn(PETSC_SUCCESS);
}
PetscErrorCode TslExplicitSetFromOptions(Driver *d)
{
  PetscFunctionBeginUser;
  d->explicit_safety   = 0.9;
  d->explicit_progress = 5000;
  d->explicit_history  = 200;
  d->explicit_search   = 10;
  d->explicit_kin_passes = 20;
  d->explicit_kin_tol    = 1e-3;
  d->explicit_kin_gap    = 1e-12; /* closure to round-off (docs/explicit.md, "Kinematic contact") */
  d->explicit_records    = PETSC_TRUE;
  PetscOptionsBegin(d->comm, NULL, "thermoslide explicit dynamics", NULL);
  PetscCall(TslOptionsReal(PetscOptionsObject, "-tsl_explicit_safety", "explicit: factor on the element-by-element stable increment", 0, PETSC_TRUE, 1,
                           PETSC_FALSE, &d->explicit_safety));
  PetscCall(TslOptionsInt(PetscOptionsObject, "-tsl_explicit_progress", "explicit: increments between progress lines (0: none)", 0, PETSC_MAX_INT,
                          &d->explicit_progress));
  PetscCall(TslOptionsInt(PetscOptionsObject, "-tsl_explicit_history", "explicit: history rows per step besides those of the frames", 0,
                          PETSC_MAX_INT, &d->explicit_history));
  PetscCall(TslOptionsInt(PetscOptionsObject, "-tsl_explicit_contact_search", "explicit: increments between contact pairing searches (besides a node leaving its face)", 1,
                          PETSC_MAX_INT, &d->explicit_search));
  PetscCall(TslOptionsInt(PetscOptionsObject, "-tsl_explicit_kinematic_passes", "explicit: most passes of the kinematic contact corrector per increment", 1, 1000,
                          &d->explicit_kin_passes));
  PetscCall(TslOptionsReal(PetscOptionsObject, "-tsl_explicit_kinematic_tol", "explicit: kinematic corrector passes stop at this pressure change (fraction of the largest pressure)",
                           0, PETSC_FALSE, 1, PETSC_FALSE, &d->explicit_kin_tol));
  PetscCall(TslOptionsReal(PetscOptionsObject, "-tsl_explicit_kinematic_gap_tol",
                           "explicit: kinematic corrector passes also go on while a gap left (over the search radius) exceeds this and still shrinks "
                           "(0: the pressure criterion alone)",
                           0, PETSC_FALSE, 1, PETSC_FALSE, &d->explicit_kin_gap));
  PetscCall(TslOptionsBool(PetscOptionsObject, "-tsl_explicit_records", "explicit: element force records (geometry and conduction computed once; docs/explicit.md)",
                           &d->explicit_records));
  PetscOptionsEnd();
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Is local element e in the set named (all elements for an empty name)? Set members are sorted ids. */
static PetscBool InSet(const TslModel *m, const char *name, PetscInt e)
{
  PetscInt k, loc;
  if (!name[0]) return PETSC_TRUE;
  k = TslModelFindElementSet(m, name);
  if (k < 0) return PETSC_FALSE;
  if (PetscFindInt(m->elem_id[e], m->elsets[k].n, m->elsets[k].ids, &loc)) return PETSC_FALSE;
  return loc >= 0 ? PETSC_TRUE : PETSC_FALSE;
}

/* Mass scale factors of the step's definitions, in their order: FACTOR, then (TYPE=BELOW MIN) just
 * enough for the element's stable increment to reach DT; the mass grows as the square of the increment. */
static void MassScaleFactors(Explicit *x, PetscBool variable_only)
{
  for (PetscInt e = 0; e < x->m->nelem; e++) {
    if (!variable_only) x->scale[e] = 1;
    for (PetscInt k = 0; k < x->step->nmass; k++) {
      const TslMassScaling *ms = &x->step->mass[k];
      if ((variable_only && !ms->variable) || !InSet(x->m, ms->elset, e)) continue;
      if (!variable_only) x->scale[e] *= ms->factor;
      if (ms->dt > 0 && x->dt_mech[e] * PetscSqrtReal(x->scale[e]) < ms->dt) x->scale[e] = PetscSqr(ms->dt / x->dt_mech[e]);
    }
  }
}

/* The interface's limits (src/physics/contact_bound.c: Gershgorin bounds of the normal penalty on the lumped
 * masses and of the heat exchange on the lumped capacities, every point on every node it touches). They
 * change with the pairing, the pressure and the temperatures: recomputed at every pairing search. */
static PetscErrorCode ContactIncrements(Explicit *x, PetscInt *node_mech, PetscInt *node_heat)
{
  PetscFunctionBeginUser;
  PetscCall(TslProblemContactIncrements(x->p, x->M, x->W, &x->lim_cmech, node_mech, &x->lim_cheat, node_heat));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The mechanical limit of the elements and the interface: a node is both in its elements and on the contact
 * springs, their eigenvalues add at most (omega^2 <= omega_e^2 + omega_c^2), so 1/dt^2 = 1/dt_e^2 + 1/dt_c^2
 * bounds the combined limit. */
static PetscReal MechanicalLimit(const Explicit *x)
{
  return x->lim_cmech < PETSC_MAX_REAL ? 1.0 / PetscSqrtReal(1.0 / PetscSqr(x->lim_mech) + 1.0 / PetscSqr(x->lim_cmech)) : x->lim_mech;
}

/* The thermal one (first-order: 1/dt = 1/dt_e + 1/dt_c). */
static PetscReal ThermalLimit(const Explicit *x)
{
  return x->lim_cheat < PETSC_MAX_REAL ? 1.0 / (1.0 / x->lim_heat + 1.0 / x->lim_cheat) : x->lim_heat;
}

/* The increment from the limits, times the safety factor and the step's SCALE FACTOR. */
static void CombineLimits(Explicit *x)
{
  x->dt_stable = x->safety * x->step->dt_scale * PetscMin(MechanicalLimit(x), ThermalLimit(x));
}

/* The damping fraction xi of the highest element mode (Abaqus documentation, "Bulk viscosity":
 * xi = b1 - b2^2 (L_e / c_d) min(0, eps_vol_dot)) shortens its stable increment to (2 / omega)(sqrt(1 + xi^2) - xi).
 * Only the linear term's b1 enters here: the quadratic term's share b2^2 dt_e |eps_vol_dot| follows the strain
 * rate of the current increment, so it would change the increment from one increment to the next (which
 * excites the parametric instability described at the frame loop) and cost a reduction per increment. It is
 * small where the small-strain kinematics holds: it eats the safety margin (0.9) only when an element's
 * volume changes by 7 % per transit time of a wave (a shock of particle velocity 0.07 c_d); docs/explicit.md. */
static PetscReal BulkViscosityFactor(PetscReal xi)
{
  return PetscSqrtReal(1 + xi * xi) - xi;
}

/* The stable increment: min over the elements of the mechanical 2/omega (with the mass scaled) and the
 * thermal 2/lambda, by one reduction (MINLOC over both, so the log names the controlling element of each),
 * with the interface's limits; times the safety factor and the step's SCALE FACTOR. */
static PetscErrorCode StableIncrement(Explicit *x, PetscBool print)
{
  struct {
    double v;
    int    id;
  } loc[2] = {{PETSC_MAX_REAL, -1}, {PETSC_MAX_REAL, -1}}, g[2];
  PetscInt node_mech = -1, node_heat = -1;

  PetscFunctionBeginUser;
  for (PetscInt e = 0; e < x->m->nelem; e++) {
    PetscReal dm = x->dt_mech[e] * PetscSqrtReal(x->scale[e]);
    /* bulk viscosity: L_e / c_d is the element's own (mass-scaled) increment, so rho c_d L_e = (lambda + 2 mu) dt_e
     * and rho (b2 L_e)^2 = (lambda + 2 mu) (b2 dt_e)^2 (the scaled density, as Abaqus's mass scaling scales rho) */
    x->eta[e]  = x->step->bv_linear * (dm < PETSC_MAX_REAL ? dm : 0);
    x->eta2[e] = dm < PETSC_MAX_REAL ? PetscSqr(x->step->bv_quadratic * dm) : 0;
    /* *DAMPING adds its fraction of critical at the element's highest mode omega = 2 / dm: beta omega / 2 and
     * alpha / (2 omega) */
    if (dm < PETSC_MAX_REAL) dm *= BulkViscosityFactor(x->step->bv_linear + x->beta[e] / dm + 0.25 * x->alpha[e] * dm);
    /* ties (copies of one element share their increments bit for bit: dynamics.c) go to the smallest id, as
     * MINLOC's across the ranks, so the log names the same element on any number of ranks */
    const int id = (int)x->m->elem_id[e];
    if (dm < loc[0].v || (dm == loc[0].v && id < loc[0].id)) loc[0].v = dm, loc[0].id = id;
    if (x->dt_heat[e] < loc[1].v || (x->dt_heat[e] == loc[1].v && id < loc[1].id)) loc[1].v = x->dt_heat[e], loc[1].id = id;
  }
  PetscCallMPI(MPI_Allreduce(loc, g, 2, MPI_DOUBLE_INT, MPI_MINLOC, x->comm));
  x->lim_mech  = g[0].v;
  x->lim_heat  = g[1].v;
  x->lim_cmech = x->lim_cheat = PETSC_MAX_REAL;
  if (x->m->npair) PetscCall(ContactIncrements(x, &node_mech, &node_heat));
  CombineLimits(x);
  if (print) {
    const PetscReal mech = MechanicalLimit(x);
    PetscCall(PetscPrintf(x->comm, "  stable increment %.4e (safety %g x scale factor %g): mechanical %.4e at element %d%s, thermal %.4e at element %d; %s controls\n",
                          (double)x->dt_stable, (double)x->safety, (double)x->step->dt_scale, g[0].v, g[0].id,
                          x->step->bv_linear > 0 ? (x->damped || x->AM ? " (with the damping of the linear bulk viscosity and *DAMPING)" : " (with the linear bulk viscosity's damping)")
                                                 : (x->damped || x->AM ? " (with *DAMPING's damping)" : ""),
                          g[1].v, g[1].id,
                          mech * x->safety * x->step->dt_scale <= x->dt_stable * (1 + 1e-12) ? "the mechanical limit" : "the thermal (diffusion) limit"));
    if (node_mech >= 0)
      PetscCall(PetscPrintf(x->comm, "  contact penalty (eps_n A on the lumped masses, nodal bound) %.4e at node %" PetscInt_FMT "; with the elements' %.4e: mechanical %.4e\n",
                            (double)x->lim_cmech, node_mech, (double)x->lim_mech, (double)mech));
    if (node_heat >= 0)
      PetscCall(PetscPrintf(x->comm, "  contact heat exchange (k A on the lumped capacities, nodal bound) %.4e at node %" PetscInt_FMT "; with the elements' %.4e: thermal %.4e\n",
                            (double)x->lim_cheat, node_heat, (double)x->lim_heat, (double)ThermalLimit(x)));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Lumped mass with the current scale factors; the work of adding mass to moving nodes, 1/2 dM v^2, goes to
 * ALLMW; the added mass is reported. */
/* *DAMPING, ALPHA: AM = the lumped masses of the elements' alpha m with their scale factors (the mass the update uses:
 * mass scaling scales the damping force with it, as it scales the density), a tie's secondary share moved as the mass's */
static PetscErrorCode AlphaMasses(Explicit *x)
{
  PetscReal *as;

  PetscFunctionBeginUser;
  if (!x->AM) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscMalloc1(x->m->nelem, &as));
  for (PetscInt e = 0; e < x->m->nelem; e++) as[e] = x->alpha[e] * x->scale[e];
  PetscCall(TslProblemLumpedMass(x->p, as, x->AM));
  PetscCall(TslProblemTieMove(x->p, x->AM));
  PetscCall(PetscFree(as));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Masses(Explicit *x, Energies *en, PetscBool report)
{
  Vec                M0;
  const PetscScalar *m0, *m, *v;
  PetscReal          loc[3] = {0, 0, 0}, g[3], smax = 1, gmax;
  PetscInt           th = x->ndof - 1;

  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(x->M, &M0));
  PetscCall(VecCopy(x->M, M0)); /* the mass before (zero at the start) */
  PetscCall(TslProblemLumpedMass(x->p, x->scale, x->M));
  PetscCall(TslProblemTieMove(x->p, x->M)); /* a tie's secondary mass and capacity to its main nodes */
  PetscCall(VecGetArrayRead(M0, &m0));
  PetscCall(VecGetArrayRead(x->M, &m));
  PetscCall(VecGetArrayRead(x->V, &v));
  for (PetscInt i = 0; i < x->nown * x->ndof; i++)
    if (i % x->ndof != th) loc[0] += 0.5 * (m[i] - m0[i]) * v[i] * v[i];
  PetscCall(VecRestoreArrayRead(x->V, &v));
  PetscCall(VecRestoreArrayRead(x->M, &m));
  PetscCall(VecRestoreArrayRead(M0, &m0));
  PetscCall(VecDestroy(&M0));
  PetscCall(TslGhostUpdate(x->M, INSERT_VALUES, SCATTER_FORWARD)); /* once per change: the corrector reads main nodes' masses */
  PetscCall(AlphaMasses(x));
  if (report) {
    Vec                Mu;
    const PetscScalar *mu;
    PetscCall(VecDuplicate(x->M, &Mu));
    PetscCall(TslProblemLumpedMass(x->p, NULL, Mu));
    PetscCall(TslProblemTieMove(x->p, Mu));
    PetscCall(VecGetArrayRead(Mu, &mu));
    PetscCall(VecGetArrayRead(x->M, &m));
    for (PetscInt i = 0; i < x->nown; i++) loc[1] += mu[i * x->ndof], loc[2] += m[i * x->ndof] - mu[i * x->ndof];
    PetscCall(VecRestoreArrayRead(x->M, &m));
    PetscCall(VecRestoreArrayRead(Mu, &mu));
    PetscCall(VecDestroy(&Mu));
  }
  for (PetscInt e = 0; e < x->m->nelem; e++) smax = PetscMax(smax, x->scale[e]);
  PetscCall(MPIU_Allreduce(loc, g, 3, MPIU_REAL, MPIU_SUM, x->comm));
  PetscCall(MPIU_Allreduce(&smax, &gmax, 1, MPIU_REAL, MPIU_MAX, x->comm));
  en->mw += g[0];
  if (report && x->step->nmass) {
    PetscCall(PetscPrintf(x->comm, "  mass scaling: total mass %.6g, added %.6g (%.3g %%), largest element factor %.4g\n", (double)g[1], (double)g[2],
                          (double)(g[1] > 0 ? 100 * g[2] / g[1] : 0), (double)gmax));
    if (gmax > MASS_WARN_FACTOR)
      PetscCall(PetscPrintf(x->comm, "  warning: mass scaling multiplies the mass of some element by %.4g (more than %g): inertia is no longer physical there\n",
                            (double)gmax, MASS_WARN_FACTOR));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Element stable increments at the current state, mass scale factors, lumped mass and the increment. */
static PetscErrorCode SetUpIncrement(Explicit *x, Energies *en, PetscBool first)
{
  PetscFunctionBeginUser;
  PetscCall(TslProblemStableIncrements(x->p, x->dt_mech, x->dt_heat));
  MassScaleFactors(x, PETSC_FALSE);
  PetscCall(Masses(x, en, first));
  PetscCall(StableIncrement(x, first));
  x->dt = x->step->dt_user > 0 ? x->step->dt_user : x->dt_stable;
  if (first && x->step->dt_user > x->dt_stable)
    PetscCall(PetscPrintf(x->comm, "  warning: DIRECT USER CONTROL increment %g exceeds the stable increment %g: the solution may blow up\n",
                          (double)x->step->dt_user, (double)x->dt_stable));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Forces at the current state; with contact, its state (slip since the last increment, anchors) is
 * committed as the history of the next increment, and pairing searched every search_every increments or
 * when a node left its face. */
static PetscErrorCode Forces(Explicit *x, PetscReal dt, PetscInt inc)
{
  PetscInt nrepair;

  PetscFunctionBeginUser;
  PetscCall(TslPhaseBegin(TSL_PHASE_ASSEMBLY));
  /* bulk viscosity of the velocity v_{n-1/2} (the latest one: central differences have no v_n), in the
   * same element pass, its forces in Fi. The viscous work over the last increment, q (eps_n + eps_{n+1}) / 2
   * h_avg per element, is booked in two halves: q_n eps_n by Advance, q_n eps_{n+1} here, at the next
   * evaluation (ALLVD; ALLIE is the internal forces' work less it) */
  PetscCall(TslProblemExplicitForces(x->p, x->Fi, x->Fe, x->Fc, x->Qp, x->V, x->eta, x->eta2, x->qv, dt, &x->rates));
  x->d->plastic_dissipated += x->rates.plastic_work; /* ALLPD: the move's plastic work, committed by this evaluation */
  PetscCall(TslProblemTieMove(x->p, x->Fi)); /* a tie's secondary forces and heat to its main nodes */
  PetscCall(TslProblemTieMove(x->p, x->Fe));
  if (x->Qp) PetscCall(TslProblemTieMove(x->p, x->Qp));
  if (x->qv || x->damped) {
    Energies       *en = (Energies *)x->d->energy;
    const PetscReal w  = 0.5 * x->vd_h * x->rates.viscous_prev;
    en->vd += w, en->ie -= w;
  }
  x->dt_forces = dt;
  if (x->m->npair) {
    PetscCall(TslProblemContactExplicitIncrement(x->p, (PetscBool)(inc % x->search_every == 0), &nrepair));
    x->nrepair += nrepair;
  }
  if (x->Fc) PetscCall(TslProblemTieMove(x->p, x->Fc));
  PetscCall(TslPhaseEnd(TSL_PHASE_ASSEMBLY));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Kinematic contact (src/physics/contact_kinematic.c): the predictor moves the free displacement dofs to
 *   u* = u_n + h (v_{n-1/2} + h_avg a*),   M a* = Fe - Fi - Fc   (without the kinematic pairs),
 * prescribed dofs to t_{n+1}, temperatures kept at theta_n; the kinematic pairs are evaluated there into Fk
 * (each node with the stiffness that closes its gap in this increment), and X is restored: Advance's update
 * then includes Fk like any other force (a_n = a* - M^-1 Fk), so the corrected gaps close and the energy
 * columns account for it (ALLCW). The temperatures see the contact heat at (u*, theta_n): forward Euler. */
static PetscErrorCode KinematicCorrector(Explicit *x, PetscReal h, PetscReal h_avg, PetscReal t_new, PetscReal total_new)
{
  PetscInt           passes;
  PetscScalar       *u;
  const PetscScalar *v, *m, *mask, *fi, *fe, *fc = NULL, *am = NULL;
  const PetscInt     n = x->nown * x->ndof, th = x->ndof - 1;

  PetscFunctionBeginUser;
  PetscCall(TslProblemContactKinematicStiffness(x->p, x->M, x->Mask, x->W, h * h_avg));
  if (x->AM) PetscCall(VecGetArrayRead(x->AM, &am));
  PetscCall(VecGetArray(x->X, &u));
  PetscCall(VecGetArrayRead(x->V, &v));
  PetscCall(VecGetArrayRead(x->M, &m));
  PetscCall(VecGetArrayRead(x->Mask, &mask));
  PetscCall(VecGetArrayRead(x->Fi, &fi));
  PetscCall(VecGetArrayRead(x->Fe, &fe));
  if (x->Fc) PetscCall(VecGetArrayRead(x->Fc, &fc));
  for (PetscInt i0 = 0; i0 < n; i0 += x->ndof) /* node by node: no division to tell a temperature dof */
    for (PetscInt i = i0; i < i0 + th; i++)
      if (mask[i] == 0) u[i] += h * (v[i] + h_avg * (fe[i] - fi[i] - (fc ? fc[i] : 0) - (am ? am[i] * v[i] : 0)) / m[i]);
  if (x->AM) PetscCall(VecRestoreArrayRead(x->AM, &am));
  if (x->Fc) PetscCall(VecRestoreArrayRead(x->Fc, &fc));
  PetscCall(VecRestoreArrayRead(x->Fe, &fe));
  PetscCall(VecRestoreArrayRead(x->Fi, &fi));
  PetscCall(VecRestoreArrayRead(x->Mask, &mask));
  PetscCall(VecRestoreArrayRead(x->M, &m));
  PetscCall(VecRestoreArrayRead(x->V, &v));
  PetscCall(VecRestoreArray(x->X, &u));
  PetscCall(TslProblemSetTime(x->p, t_new, h, total_new));
  PetscCall(TslProblemApplyPrescribed(x->p, x->X));
  PetscCall(TslPhaseBegin(TSL_PHASE_ASSEMBLY));
  PetscCall(TslProblemExplicitKinematicForces(x->p, x->Fk, &x->krates));
  x->kin_total++;
  passes = 1;
  PetscReal residual = PETSC_MAX_REAL;
  for (PetscInt pass = 1; pass < x->kin_passes; pass++) {
    /* what the lumped compliance left of a rough penetration (or the pressure of a node it opened) is
     * corrected again from the linearised gaps, normal forces only, unless no pressure would change by
     * more than the tolerance (the quasi-static case: one pass) */
    PetscReal change[3];
    PetscBool applied;
    PetscCall(TslProblemContactKinematicPass(x->p, x->Fk, x->M, x->Mask, x->W, h * h_avg, x->kin_tol, x->kin_gap, &residual, change, &applied));
    if (!applied) break;
    PetscCall(VecAXPY(x->Fk, 1.0, x->W));
    x->kin_total++;
    passes++;
  }
  if (passes > 1) {
    /* the passes' pressures, with the friction (Coulomb limit mu p) and heat (conductance at p) that go
     * with them: the kernels once more at the predicted state, each node's normal penalty the one that gives
     * it its pressure at its predicted gap */
    PetscCall(TslProblemContactKinematicSettle(x->p));
    PetscCall(TslProblemExplicitKinematicForces(x->p, x->Fk, &x->krates));
  }
  PetscCall(TslPhaseEnd(TSL_PHASE_ASSEMBLY));
  PetscCall(VecCopy(x->Xold, x->X));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One increment from the state X = x_n (forces evaluated there) to x_{n+1} at step time t + h. */
static PetscErrorCode Advance(Explicit *x, Energies *en, PetscReal h, PetscReal h_prev, PetscReal t_new, PetscReal total_new)
{
  PetscScalar       *u, *v;
  const PetscScalar *uo, *xr, *m, *mask, *fi, *fe, *fc = NULL, *fk = NULL, *am = NULL, *qp = NULL;
  const PetscInt     n = x->nown * x->ndof, th = x->ndof - 1;
  const PetscReal    h_avg = h_prev > 0 ? 0.5 * (h + h_prev) : 0.5 * h; /* from rest at the start: v_{1/2} = dt/2 a_0 */
  /* the plastic heat is the move's (a rate over dt_forces): deposited whole over this increment, whatever its length */
  const PetscReal    qh = x->dt_forces / h;
  /* the loops' sums in locals whose address is never taken: in loc[] the compiler must keep them in memory, as
   * the stores to u and v might alias them (a store and a reload per dof on each sum's chain) */
  PetscReal w_int = 0, w_ext = 0, w_con = 0, w_damp = 0, q_pres = 0, q_stored = 0;
  PetscReal loc[8], g[8];

  PetscFunctionBeginUser;
  PetscCall(VecCopy(x->X, x->Xold));
  if (x->Fk) PetscCall(KinematicCorrector(x, h, h_avg, t_new, total_new));
  PetscCall(VecGetArray(x->X, &u));
  PetscCall(VecGetArray(x->V, &v));
  PetscCall(VecGetArrayRead(x->M, &m));
  PetscCall(VecGetArrayRead(x->Mask, &mask));
  PetscCall(VecGetArrayRead(x->Fi, &fi));
  PetscCall(VecGetArrayRead(x->Fe, &fe));
  if (x->Fc) PetscCall(VecGetArrayRead(x->Fc, &fc));
  if (x->Fk) PetscCall(VecGetArrayRead(x->Fk, &fk));
  if (x->AM) PetscCall(VecGetArrayRead(x->AM, &am));
  if (x->Qp) PetscCall(VecGetArrayRead(x->Qp, &qp));
  /* free dofs, node by node (no slot arithmetic per dof): the update and the forces' work; a temperature's
   * stored heat per unit time, m (theta_{n+1} - theta_n) / h, here too (the prescribed values set below do not
   * touch a free dof) */
  for (PetscInt i0 = 0; i0 < n; i0 += x->ndof) {
    const PetscInt it = i0 + th;
    for (PetscInt i = i0; i < it; i++) {
      PetscReal fcon, f, vo, w, fd;
      if (mask[i] != 0) continue;
      /* *DAMPING, ALPHA: the force alpha m v of the latest velocity v_{n-1/2}, as the bulk viscosity's */
      fcon = (fc ? fc[i] : 0) + (fk ? fk[i] : 0), vo = v[i], fd = am ? am[i] * vo : 0, f = fe[i] - fi[i] - fcon - fd;
      v[i] += h_avg * f / m[i];
      u[i] += h * v[i];
      w = h_avg * 0.5 * (vo + v[i]);
      w_int += fi[i] * w;
      w_ext += fe[i] * w;
      w_con += fcon * w;
      w_damp += fd * w;
    }
    if (mask[it] == 0) {
      const PetscReal to = u[it];
      u[it] += h * (fe[it] - fi[it] - ((fc ? fc[it] : 0) + (fk ? fk[it] : 0)) + (qp ? qh * qp[it] : 0)) / m[it];
      q_stored += m[it] * (u[it] - to) / h;
    }
  }
  PetscCall(VecRestoreArray(x->X, &u));
  /* prescribed values at t_{n+1} */
  PetscCall(TslProblemSetTime(x->p, t_new, h, total_new));
  PetscCall(TslProblemApplyPrescribed(x->p, x->X)); /* its ghost update is the state's for the next evaluation */
  PetscCall(VecGetArrayRead(x->X, &xr));
  PetscCall(VecGetArrayRead(x->Xold, &uo));
  for (PetscInt k = 0; k < x->npresc; k++) { /* prescribed dofs: velocity, reaction and work; stored and brought-in heat */
    const PetscInt  i    = x->presc[k];
    const PetscReal fcon = (fc ? fc[i] : 0) + (fk ? fk[i] : 0), vo = v[i], fd = am && i % x->ndof != th ? am[i] * vo : 0, f = fe[i] - fi[i] - fcon - fd;
    PetscReal       w, s;
    if (i % x->ndof == th) {
      const PetscReal rate = m[i] * (xr[i] - uo[i]) / h; /* heat stored at the node per unit time */
      q_stored += rate;
      q_pres += rate - f - (qp ? qh * qp[i] : 0); /* heat the prescribed temperature brings in */
      continue;
    }
    v[i] = (xr[i] - uo[i]) / h;
    s    = m[i] * (v[i] - vo) / h_avg - f; /* the support's force at time n */
    w    = h_avg * 0.5 * (vo + v[i]);
    w_int += fi[i] * w;
    w_ext += (fe[i] + s) * w;
    w_con += fcon * w;
    w_damp += fd * w;
  }
  PetscCall(VecRestoreArrayRead(x->Xold, &uo));
  PetscCall(VecRestoreArrayRead(x->X, &xr));
  if (x->Fc) PetscCall(VecRestoreArrayRead(x->Fc, &fc));
  if (x->Fk) PetscCall(VecRestoreArrayRead(x->Fk, &fk));
  if (x->AM) PetscCall(VecRestoreArrayRead(x->AM, &am));
  if (x->Qp) PetscCall(VecRestoreArrayRead(x->Qp, &qp));
  PetscCall(VecRestoreArrayRead(x->Fe, &fe));
  PetscCall(VecRestoreArrayRead(x->Fi, &fi));
  PetscCall(VecRestoreArrayRead(x->Mask, &mask));
  PetscCall(VecRestoreArrayRead(x->M, &m));
  PetscCall(VecRestoreArray(x->V, &v));
  loc[0] = w_int, loc[1] = w_ext, loc[2] = w_con, loc[3] = w_damp, loc[4] = 0, loc[5] = q_pres, loc[6] = q_stored;
  loc[7] = TslStopLocal(); /* asked to stop: noticed in the reduction every increment makes anyway */
  PetscCall(MPIU_Allreduce(loc, g, 8, MPIU_REAL, MPIU_SUM, x->comm));
  if (g[7] != 0) PetscCall(TslStopRequested(x->comm, &x->stop)); /* which signal (every rank saw the sum) */
  /* a run that has left the stable range (a DIRECT USER CONTROL increment above the stable one, a contact
   * spring or quadratic viscosity the estimate did not see) grows until it overflows: every rank sees the same
   * sums, so all stop here together, before a frame of the state is written; the frames so far are kept */
  for (PetscInt k = 0; k < 7; k++)
    PetscCheck(!PetscIsInfOrNanReal(g[k]), x->comm, PETSC_ERR_NOT_CONVERGED,
               "explicit step %s: the solution is no longer finite at step time %g (increment %g against the stable %g): the increment exceeds what the "
               "model can take; lower -tsl_explicit_safety or the step's SCALE FACTOR, or the DIRECT USER CONTROL increment. The frames written before "
               "are kept",
               x->step->name, (double)t_new, (double)h, (double)x->dt_stable);
  /* g[0] is the work of Fi, the bulk viscosity's forces included: the first half of their work over this
   * increment, q_n eps_n h_avg / 2 per element, is ALLVD's now, the second half at the next evaluation (Forces) */
  x->vd_h = h_avg;
  en->ie += g[0] - 0.5 * h_avg * x->rates.viscous;
  en->vd += 0.5 * h_avg * x->rates.viscous;
  en->wk += g[1];
  en->cw += g[2];
  en->vd += g[3]; /* *DAMPING, ALPHA's work (BETA's is in the viscous rates, its forces in Fi) */
  /* the forces of state n measured the slip over the increment that ended there (dt_forces): its
   * dissipation; the heat they generate enters the temperatures over h (forward Euler) */
  en->fd += x->rates.dissipation * x->dt_forces;
  x->d->dissipated += x->rates.dissipation * x->dt_forces;
  x->d->absorbed += x->rates.friction_heat * h;
  /* the kinematic corrector measured its slip over this increment */
  en->fd += x->krates.dissipation * h;
  x->d->dissipated += x->krates.dissipation * h;
  x->d->absorbed += x->krates.friction_heat * h;
  x->rates_reaction_heat = g[5];
  x->stored_rate         = g[6];
  /* the heat balance of this increment: the rates of state n that advanced the temperatures (forward Euler)
   * against the heat stored over it; round-off. The history row is written after the next force evaluation,
   * whose rates (state n+1) its heat columns show: their balance with this stored heat would be off by the
   * rates' change over one increment (up to 0.6 of a heat input of 200 where the flux is ramped down) */
  x->balance = x->rates.heat_in + g[5] + x->rates.friction_heat + x->krates.friction_heat + x->rates.plastic_heat * qh - x->rates.film_out -
               x->rates.radiation_out - g[6];
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KineticEnergy(Explicit *x, PetscReal *ke)
{
  const PetscScalar *m, *v;
  PetscReal          loc = 0;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(x->M, &m));
  PetscCall(VecGetArrayRead(x->V, &v));
  for (PetscInt i = 0; i < x->nown * x->ndof; i++)
    if (i % x->ndof != x->ndof - 1) loc += 0.5 * m[i] * v[i] * v[i];
  PetscCall(VecRestoreArrayRead(x->V, &v));
  PetscCall(VecRestoreArrayRead(x->M, &m));
  PetscCall(MPIU_Allreduce(&loc, ke, 1, MPIU_REAL, MPIU_SUM, x->comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The first explicit step starts from the deck's initial velocities (v_0; the first update is
 * v_{1/2} = v_0 + dt/2 a_0, h_prev = 0 in Advance), set after the lumped mass so that ALLMW does not book them
 * as the work of adding mass. Their kinetic energy 1/2 v_0 M v_0 was put into the body before the step, so it
 * is booked as work done (ALLWK) and ETOTAL starts at zero, as with the strain energy of earlier static steps.
 * Collective (the local model may hold no lines on some ranks: the sums decide). */
static PetscErrorCode InitialVelocity(Explicit *x, Energies *en)
{
  PetscInt  held, lines = x->m->nvinit, glines;
  PetscReal ke;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(&lines, &glines, 1, MPIU_INT, MPI_SUM, x->comm));
  if (!glines) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(TslProblemInitialVelocity(x->p, x->V, &held));
  PetscCall(KineticEnergy(x, &ke));
  en->ke = ke;
  en->wk += ke;
  PetscCall(PetscPrintf(x->comm, "  initial velocities (*INITIAL CONDITIONS, TYPE=VELOCITY): kinetic energy %.6g", (double)ke));
  if (held) PetscCall(PetscPrintf(x->comm, "; %" PetscInt_FMT " prescribed dofs keep their boundary condition instead", held));
  PetscCall(PetscPrintf(x->comm, "\n"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A history row: the heat rates of the state, the energies since the start of the job. */
static PetscErrorCode HistoryRow(Explicit *x, Energies *en, PetscInt s, PetscInt inc, PetscReal t, PetscReal h, PetscReal total)
{
  PetscReal row[NHISTORY];
  Driver   *d = x->d;

  PetscFunctionBeginUser;
  PetscCall(KineticEnergy(x, &en->ke));
  row[HIST_STEP]                = (PetscReal)(s + 1);
  row[HIST_INCREMENT]           = (PetscReal)inc;
  row[HIST_TIME]                = total;
  row[HIST_STEP_TIME]           = t;
  row[HIST_DT]                  = h;
  row[HIST_NEWTON_ITS]          = 0;
  row[HIST_HEAT_IN]             = x->rates.heat_in;
  row[HIST_FILM_OUT]            = x->rates.film_out;
  row[HIST_RADIATION_OUT]       = x->rates.radiation_out;
  row[HIST_REACTION_HEAT]       = x->rates_reaction_heat;
  row[HIST_STORED_RATE]         = x->stored_rate;
  row[HIST_INTERFACE_HEAT]      = x->rates.interface_heat + x->krates.interface_heat;
  row[HIST_DISSIPATION_RATE]    = x->rates.dissipation + x->krates.dissipation;
  row[HIST_DISSIPATION_TOTAL]   = en->fd;
  row[HIST_FRICTION_HEAT_TOTAL] = d->absorbed;
  row[HIST_BALANCE]             = x->balance;
  row[HIST_PLASTIC_HEAT]        = x->rates.plastic_heat;
  row[HIST_PLASTIC_DISSIPATION] = x->d->plastic_dissipated;
  PetscCall(TslProblemEnergies(x->p, &row[HIST_STRAIN_ENERGY], &row[HIST_HOURGLASS_ENERGY]));
  row[HIST_ENERGY + 0] = en->ke;
  row[HIST_ENERGY + 1] = en->ie;
  row[HIST_ENERGY + 2] = en->wk;
  row[HIST_ENERGY + 3] = en->fd;
  row[HIST_ENERGY + 4] = en->cw;
  row[HIST_ENERGY + 5] = en->mw;
  row[HIST_ENERGY + 6] = en->vd;
  row[HIST_ENERGY + 7] = en->ke + en->ie + en->vd + en->cw - en->wk - en->mw;
  PetscCall(TslHistoryAppend(d->hist, row));
  d->done_step = s + 1, d->done_inc = inc, d->done_time = total, d->done_step_time = t, d->done_dt = h;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Destroy(Explicit *x)
{
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&x->M));
  PetscCall(VecDestroy(&x->Mask));
  PetscCall(PetscFree(x->presc));
  PetscCall(VecDestroy(&x->Fi));
  PetscCall(VecDestroy(&x->Fe));
  PetscCall(VecDestroy(&x->Fc));
  PetscCall(VecDestroy(&x->Qp));
  PetscCall(PetscFree(x->qv));
  PetscCall(PetscFree2(x->alpha, x->beta));
  PetscCall(VecDestroy(&x->AM));
  PetscCall(VecDestroy(&x->Fk));
  PetscCall(VecDestroy(&x->W));
  PetscCall(PetscFree5(x->dt_mech, x->dt_heat, x->scale, x->eta, x->eta2));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslExplicitRunStep(Driver *d, PetscInt s, PetscReal *total_time)
{
  Explicit        x;
  PetscReal       t = 0, h_prev = 0, eps, t_hist, dt_hist, wall0, now;
  TslFrameTimes   frames;
  PetscInt  inc = 0;
  Energies *en = (Energies *)d->energy;

  PetscFunctionBeginUser;
  PetscCheck(sizeof(Energies) == sizeof(d->energy), PETSC_COMM_SELF, PETSC_ERR_PLIB, "energy layout");
  PetscCall(PetscMemzero(&x, sizeof(x)));
  x.d    = d;
  x.p    = d->prob;
  x.comm = d->comm;
  PetscCall(TslProblemGetModel(x.p, &x.m));
  x.step = &x.m->steps[s];
  x.safety       = d->explicit_safety;
  x.progress     = d->explicit_progress;
  x.history_rows = d->explicit_history;
  x.search_every = d->explicit_search;
  x.kin_passes   = d->explicit_kin_passes;
  x.kin_tol      = d->explicit_kin_tol;
  x.kin_gap      = d->explicit_kin_gap;
  PetscCall(PetscPrintf(d->comm, "step %" PetscInt_FMT " (%s): explicit dynamics, period %g%s\n", s + 1, x.step->name[0] ? x.step->name : "-",
                        (double)x.step->period, x.step->dt_user > 0 ? ", fixed increment (DIRECT USER CONTROL)" : ""));
  PetscCall(TslPhaseBegin(TSL_PHASE_SETUP));
  TslCallCollective(d->comm, TslProblemSetStep(x.p, s));
  PetscCall(TslProblemSetCapacityRate(x.p, 0));
  PetscCall(TslFramesSetRequests(d, x.step));
  PetscCall(TslProblemGetSolution(x.p, &x.X));
  PetscCall(TslProblemGetOldSolution(x.p, &x.Xold));
  PetscCall(VecGetBlockSize(x.X, &x.ndof));
  PetscCall(VecGetLocalSize(x.X, &x.nown));
  x.nown /= x.ndof;
  if (!d->velocity || d->explicit_last != s - 1) {
    PetscCall(VecDestroy(&d->velocity));
    PetscCall(VecDuplicate(x.X, &d->velocity));
    PetscCall(VecZeroEntries(d->velocity));
  }
  x.V = d->velocity;
  if (d->explicit_last != s - 1) {
    /* entering explicit from rest (a static implicit step or the initial state): the stored strain energy
     * is the work done on the body so far, so the balance starts at zero */
    PetscReal se, hg;
    PetscCall(TslProblemEnergies(x.p, &se, &hg));
    en->ke = 0, en->ie = se + hg;
    en->wk = en->ie + en->vd + en->cw - en->mw;
  }
  PetscCall(VecDuplicate(x.X, &x.M));
  /* the mass before this step's scaling: the last step's when the velocity carries over (only a change of
   * mass does work on moving nodes, ALLMW), zero from rest */
  if (d->mass && d->explicit_last == s - 1) PetscCall(VecCopy(d->mass, x.M));
  else PetscCall(VecZeroEntries(x.M));
  PetscCall(VecDuplicate(x.X, &x.Mask));
  PetscCall(VecDuplicate(x.X, &x.Fi));
  PetscCall(VecDuplicate(x.X, &x.Fe));
  for (PetscInt k = 0; k < x.m->nmaterial; k++) /* the same on every rank: the model's materials */
    if (TslMaterialIsPlastic(&x.m->materials[k]) && !x.Qp) PetscCall(VecDuplicate(x.X, &x.Qp));
  if (x.m->npair) {
    PetscBool kinematic;
    PetscCall(VecDuplicate(x.X, &x.Fc));
    PetscCall(VecDuplicate(x.X, &x.W));
    PetscCall(TslProblemContactSetExplicit(x.p, PETSC_TRUE, &kinematic));
    if (kinematic) {
      PetscCall(VecDuplicate(x.X, &x.Fk));
      PetscCall(VecZeroEntries(x.Fk));
    }
  }
  if (x.step->bv_linear > 0 || x.step->bv_quadratic > 0) PetscCall(PetscCalloc1(x.m->nelem, &x.qv)); /* q of no earlier evaluation: 0 */
  PetscCall(PetscMalloc5(x.m->nelem, &x.dt_mech, x.m->nelem, &x.dt_heat, x.m->nelem, &x.scale, x.m->nelem, &x.eta, x.m->nelem, &x.eta2));
  {
    PetscBool any_alpha = PETSC_FALSE; /* the same on every rank: the model's materials */
    PetscCall(PetscMalloc2(x.m->nelem, &x.alpha, x.m->nelem, &x.beta));
    PetscCall(TslProblemElementDamping(x.p, x.alpha, x.beta));
    for (PetscInt i = 0; i < x.m->nmaterial; i++) {
      if (x.m->materials[i].damp_alpha > 0) any_alpha = PETSC_TRUE;
      if (x.m->materials[i].damp_beta > 0) x.damped = PETSC_TRUE;
    }
    if (any_alpha) PetscCall(VecDuplicate(x.X, &x.AM));
  }
  for (PetscInt i = 0; i < x.m->nmaterial; i++)
    if (TslMaterialIsTemperatureDependent(&x.m->materials[i])) x.capacity_varies = PETSC_TRUE;
  PetscCall(TslProblemConstrainedMask(x.p, x.Mask));
  PetscCall(VecGhostUpdateBegin(x.Mask, INSERT_VALUES, SCATTER_FORWARD)); /* the kinematic corrector reads main nodes' masks */
  PetscCall(VecGhostUpdateEnd(x.Mask, INSERT_VALUES, SCATTER_FORWARD));
  {
    const PetscScalar *mask;
    PetscCall(VecGetArrayRead(x.Mask, &mask));
    x.npresc = 0;
    for (PetscInt i = 0; i < x.nown * x.ndof; i++) x.npresc += mask[i] != 0;
    PetscCall(PetscMalloc1(x.npresc, &x.presc));
    x.npresc = 0;
    for (PetscInt i = 0; i < x.nown * x.ndof; i++)
      if (mask[i] != 0) x.presc[x.npresc++] = i;
    PetscCall(VecRestoreArrayRead(x.Mask, &mask));
  }
  {
    PetscInt  nfast;
    PetscReal mb;
    /* the records hold the reference geometry: they give the small-strain forces, or in an NLGEOM step the finite-strain
     * (total Lagrangian) ones */
    PetscCall(TslProblemExplicitRecords(x.p, d->explicit_records, &nfast, &mb));
    if (d->explicit_records)
      PetscCall(PetscPrintf(d->comm, "  force records: %" PetscInt_FMT " of %" PetscInt_FMT " elements (%.1f MB on the largest rank%s); the others take the generic kernels\n",
                            nfast, x.m->nelem_global, (double)mb, x.step->nlgeom ? ", finite strain" : ""));
    if (x.step->nlgeom)
      PetscCall(PetscPrintf(d->comm, "  finite strain (NLGEOM%s): the stable increment follows the deformed elements (every %d increments)\n",
                            x.step->nlgeom_default ? ", the explicit default: NLGEOM=NO on the *STEP line keeps small strain" : "",
                            (int)TSL_NLGEOM_STABLE_EVERY));
  }
  PetscCall(TslProblemSetTime(x.p, 0, 0, *total_time));
  PetscCall(TslProblemApplyPrescribed(x.p, x.X));
  if (x.m->npair) {
    PetscBool repattern;
    PetscCall(TslProblemContactSearch(x.p, &repattern));
  }
  PetscCall(SetUpIncrement(&x, en, PETSC_TRUE));
  if (d->explicit_last < 0) PetscCall(InitialVelocity(&x, en)); /* the job's first explicit step */
  PetscCall(Forces(&x, 0, 0));
  PetscCall(TslPhaseEnd(TSL_PHASE_SETUP));

  /* output times: NUMBER INTERVAL= (default 20, as in the dialect) or TIME INTERVAL= */
  TslFrameTimesSetUp(&frames, x.step, 20);
  dt_hist = x.history_rows > 0 ? x.step->period / x.history_rows : PETSC_MAX_REAL;
  t_hist  = dt_hist;
  eps     = 1e-12 * x.step->period;
  if (d->rs_resume && s == d->rs_loop.step) {
    TslRestartLoop L;
    PetscCall(Resume(&x, &L, &h_prev, &t_hist));
    t = L.t, inc = L.inc, *total_time = L.total, frames.next = L.frames_next;
    PetscCall(TslRestartEndStep(d, s, &t, x.step->period));
  }
  wall0          = MPI_Wtime();
  d->in_explicit = PETSC_TRUE; /* a failure from here on keeps the frames written (driver.c, SaveLastConverged) */
  PetscCall(PetscPrintf(d->comm, "  about %.0f increments; frames every %g\n", (double)PetscCeilReal((x.step->period - t) / x.dt), (double)frames.dt));
  while (t < x.step->period - eps) {
    PetscReal h, t_new, to_frame = TslFrameTimesBound(&frames) - t;
    PetscBool frame, last, row;
    /* increments end on the frame times: the time to the next frame is cut into equal increments of at
     * most dt, so that a constant dt gives constant increments. Changing the increment from one to the next
     * (a remainder before each frame) excites the highest mode parametrically: the released bar of
     * tests/explicit blew up with the pattern 0.9, 0.55, 0.55 of the stable increment. */
    h = to_frame / PetscCeilReal(to_frame / x.dt * (1 - 1e-10));
    h     = PetscMin(h, x.step->period - t);
    last  = (PetscBool)(t + h >= x.step->period - eps);
    t_new = last ? x.step->period : t + h;
    PetscCall(TslPhaseBegin(TSL_PHASE_SOLVE));
    PetscCall(Advance(&x, en, h, h_prev, t_new, *total_time + h));
    PetscCall(TslPhaseEnd(TSL_PHASE_SOLVE));
    *total_time += h;
    t = t_new;
    h_prev = h;
    inc++;
    /* the element set-up repeated in the loop counts as set-up in the job's wall-time split */
    PetscCall(TslPhaseBegin(TSL_PHASE_SETUP));
    if (x.capacity_varies) PetscCall(Masses(&x, en, PETSC_FALSE)); /* capacity (and rho) at the new temperatures */
    for (PetscInt k = 0; k < x.step->nmass; k++)
      if (x.step->mass[k].variable && inc % x.step->mass[k].frequency == 0) {
        PetscCall(TslProblemStableIncrements(x.p, x.dt_mech, x.dt_heat));
        MassScaleFactors(&x, PETSC_FALSE);
        PetscCall(Masses(&x, en, PETSC_FALSE));
        PetscCall(StableIncrement(&x, PETSC_FALSE));
        if (x.step->dt_user <= 0) x.dt = x.dt_stable;
        break;
      }
    if (x.step->nlgeom && inc % TSL_NLGEOM_STABLE_EVERY == 0) { /* the elements' current size and shape (the masses stay) */
      PetscCall(TslProblemStableIncrements(x.p, x.dt_mech, x.dt_heat));
      PetscCall(StableIncrement(&x, PETSC_FALSE));
      if (x.step->dt_user <= 0) x.dt = x.dt_stable;
    }
    PetscCall(TslPhaseEnd(TSL_PHASE_SETUP));
    PetscCall(Forces(&x, h, inc));
    if (x.m->npair && inc % x.search_every == 0) { /* the pairing, and the conductance following pressure and temperature */
      PetscInt node_mech, node_heat;
      PetscCall(ContactIncrements(&x, &node_mech, &node_heat));
      CombineLimits(&x);
      if (x.step->dt_user <= 0) x.dt = x.dt_stable;
    }
    frame = TslFrameTimesReached(&frames, t);
    frame = (PetscBool)(frame || last);
    PetscCall(TslPhaseBegin(TSL_PHASE_OUTPUT));
    row = (PetscBool)(frame || t >= t_hist - eps);
    if (row) {
      PetscCall(HistoryRow(&x, en, s, inc, t, h, *total_time));
      while (t_hist <= t + eps) t_hist += dt_hist;
    }
    if (frame) PetscCall(TslFramesWrite(d, s + 1, inc, *total_time));
    {
      /* a restart point counts the frames and rows the run writes anyway, not the one a stop adds (below): the
       * continuation's output is the uninterrupted run's */
      char why[64];
      if (x.stop || TslRestartDue(x.step, inc, t - h, t, last, why, sizeof(why))) {
        const TslRestartLoop L = {s, inc, 0, 0, t, x.dt, *total_time, 0, frames.next};
        PetscCall(WritePoint(&x, &L, h_prev, t_hist, x.stop ? TslStopName(x.stop) : why));
      }
    }
    if (x.stop && !frame) { /* asked to stop: this increment's state is the one saved */
      if (!row) PetscCall(HistoryRow(&x, en, s, inc, t, h, *total_time));
      PetscCall(TslFramesWrite(d, s + 1, inc, *total_time));
    }
    PetscCall(TslPhaseEnd(TSL_PHASE_OUTPUT));
    PetscCheck(!x.stop || last, d->comm, PETSC_ERR_SIG, /* at the step's end: its results are whole; a next step stops at once */
               "explicit step %s: %s received at step time %g, in increment %" PetscInt_FMT "; this state is saved", x.step->name,
               TslStopName(x.stop), (double)t, inc);
    if (x.progress > 0 && inc % x.progress == 0) {
      /* ALLKE is otherwise computed at history rows only: the line showed the last row's, and an ETOTAL off
       * by the kinetic energy gained since (up to 14 of 120 in a fast slide) */
      PetscCall(KineticEnergy(&x, &en->ke));
      now = MPI_Wtime();
      PetscCall(PetscPrintf(d->comm, "  step %" PetscInt_FMT " increment %" PetscInt_FMT ": step time %.6g (%.1f %%)  dt %.4g  ALLKE %.4g  ETOTAL %.3g  wall %.1f s, about %.1f s left\n",
                            s + 1, inc, (double)t, (double)(100 * t / x.step->period), (double)h, (double)en->ke,
                            (double)(en->ke + en->ie + en->vd + en->cw - en->wk - en->mw), now - wall0, (now - wall0) * (x.step->period - t) / t));
    }
  }
  d->in_explicit = PETSC_FALSE;
  now            = MPI_Wtime();
  PetscCall(KineticEnergy(&x, &en->ke));
  PetscCall(PetscPrintf(d->comm,
                        "  step %" PetscInt_FMT ": %" PetscInt_FMT " increments in %.2f s (%.3g s per increment); ALLKE %.6g ALLIE %.6g ALLWK %.6g ALLFD %.6g ALLCW %.6g ALLMW %.6g ALLVD %.6g ETOTAL %.3g\n",
                        s + 1, inc, now - wall0, inc ? (now - wall0) / inc : 0.0, (double)en->ke, (double)en->ie, (double)en->wk, (double)en->fd, (double)en->cw,
                        (double)en->mw, (double)en->vd, (double)(en->ke + en->ie + en->vd + en->cw - en->wk - en->mw)));
  if (x.m->npair)
    PetscCall(PetscPrintf(d->comm, "  contact: pairing searched every %" PetscInt_FMT " increments; %" PetscInt_FMT " re-pairings of nodes that left their face\n",
                          x.search_every, x.nrepair));
  if (x.Fk && inc)
    PetscCall(PetscPrintf(d->comm, "  kinematic contact: %.3g corrector passes per increment (at most %" PetscInt_FMT ", -tsl_explicit_kinematic_passes)\n",
                          (double)x.kin_total / (double)inc, x.kin_passes));
  PetscCall(TslFramesPrintTables(d, x.step));
  d->explicit_last = s;
  if (x.m->npair) {
    PetscBool any;
    PetscCall(TslProblemContactSetExplicit(x.p, PETSC_FALSE, &any)); /* implicit steps: no kinematic pairs, the automatic stick */
  }
  PetscCall(VecDestroy(&d->mass));
  d->mass = x.M;
  x.M     = NULL;
  PetscCall(Destroy(&x));
  PetscFunctionReturn(PETSC_SUCCESS);
}
