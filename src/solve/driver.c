/* Step procedures: increments with cutback and DELTMX control, Newton through SNES, output. */
#include "solve_impl.h"
#include <string.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

/* Default solver choices, entered only where the user gave none, and remembered: a default that the
 * user's own choice makes irrelevant (fieldsplit options under -pc_type lu) is removed again at the end,
 * so that the unused-option warnings speak of the user's options only. */
static PetscErrorCode SetDefaultOption(Driver *d, const char *name, const char *value)
{
  PetscBool set;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasName(NULL, NULL, name, &set));
  if (set) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(d->ndefault < MAX_DEFAULTS, PETSC_COMM_SELF, PETSC_ERR_PLIB, "too many default options");
  PetscCall(PetscOptionsSetValue(NULL, name, value));
  PetscCall(PetscStrncpy(d->defaults[d->ndefault++], name, sizeof(d->defaults[0])));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The largest nodal translation of a Newton iterate, in model sizes (the reference bounding box's diagonal), that
 * is not taken for divergence: a small-strain solution moves no node by more than a few model sizes, a singular
 * step by 1e10 of them. */
#define MAX_REACH 100.0

/* Each field's round-off scale: |D x| over its rows, D the diagonal of the Jacobian of the last Newton step.
 * A residual row sums terms of about that size (K x, with the penalty and constraint rows' own entries), so
 * a few hundred ulps of it is as small as that field's residual can get, in that field's units alone. */
static PetscErrorCode RoundoffScales(Driver *d, SNES snes, PetscReal *ru, PetscReal *rt)
{
  Mat       J;
  Vec       X;
  PetscBool has;

  PetscFunctionBeginUser;
  *ru = *rt = 0;
  PetscCall(SNESGetJacobian(snes, &J, NULL, NULL, NULL));
  PetscCall(SNESGetSolution(snes, &X));
  if (!J) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MatHasOperation(J, MATOP_GET_DIAGONAL, &has));
  if (!has) PetscFunctionReturn(PETSC_SUCCESS); /* a matrix-free Jacobian (-snes_mf): no round-off path */
  if (!d->diag) PetscCall(VecDuplicate(X, &d->diag));
  PetscCall(MatGetDiagonal(J, d->diag));
  PetscCall(VecPointwiseMult(d->diag, d->diag, X));
  PetscCall(TslProblemFieldNorms(d->prob, d->diag, ru, rt));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The Newton solve of an increment ends here alone (SolveIncrement refuses any other ending), and each field
 * decides for itself in its own units: the displacement rows are forces, the temperature rows heat rates,
 * and in SI units the two differ by 1e12 or more, so no norm over both may end a solve (PETSc's tests on
 * |F|, on the step |dx| / |x| and on divergence all look at both at once: with E ~ 1e11 they saw the
 * mechanical residual fall and a step of metres against kelvins, and accepted increments whose thermal part
 * the linear solve never reached). A field is converged when
 *  (a) its residual has dropped by -tsl_rtol from the solve's reference (the residual at its start, or after
 *      its first step if that is larger: a field loaded only by the other one's step, such as the thermal
 *      stress of a body heated in its first increment), or is below -tsl_atol_rel times the largest initial
 *      residual of that field in the job; at iteration 0 only this floor counts, and not when the SNES is
 *      told to force an iteration (after an augmented-Lagrange update, SolveIncrement);
 *  (b) after a step, its residual is at the round-off of its own terms (RoundoffScales: a field never loaded,
 *      or stiff penalty contact, whose floor lies above (a)'s); or
 *  (c) after a step, that field's own update is below -snes_stol of its own solution and the linear solve
 *      that made it reached the field: the field's residual was at least 1e3 times what the linear tolerance
 *      left of the whole one, so the step is the field's own answer, not a field the solver never saw.
 * Divergence is per field too: a residual -snes_divergence_tolerance times its reference. */
/* The dialect's test (*CONTROLS, PARAMETERS=FIELD; TslFieldControls) for each field that has one, in place of
 * the per-field test below: ok[k] after a Newton step, ok0[k] at iteration 0 (no step taken yet). With r the
 * field's largest residual entry, q~ its time-averaged flux, c its largest correction (the last Newton update)
 * and du its largest change over the increment:
 *   converged if r <= R_l q~ (at any iteration), or after a step if r <= R q~ and c <= C_n du, R = R_n up to
 *   iteration I_P (*CONTROLS, PARAMETERS=TIME INCREMENTATION; 9 by default) and R_P after it;
 *   without flux (q~ <= eps max(q_0, the mean flux of the steps before)): after a step if c <= C_eps du.
 * A field whose residual is exactly zero (every dof prescribed, or none) is converged. */
static PetscErrorCode DialectFieldTest(Driver *d, SNES snes, PetscInt it, PetscBool ok[2], PetscBool ok0[2])
{
  PetscReal r[2], q[2], c[2] = {0, 0}, du[2];
  Vec       F, X, Xold, Y;
  PetscInt  ip = d->ctrl_on ? d->ctrl.ip : 9;

  PetscFunctionBeginUser;
  if (!d->fctrl[0].on && !d->fctrl[1].on) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SNESGetFunction(snes, &F, NULL, NULL));
  PetscCall(SNESGetSolution(snes, &X));
  PetscCall(TslProblemGetOldSolution(d->prob, &Xold));
  PetscCall(TslProblemFieldNormsType(d->prob, F, NORM_INFINITY, &r[0], &r[1]));
  PetscCall(TslProblemElementFlux(d->prob, q));
  if (!d->work) PetscCall(VecDuplicate(X, &d->work));
  PetscCall(VecWAXPY(d->work, -1.0, Xold, X));
  PetscCall(TslProblemFieldNormsType(d->prob, d->work, NORM_INFINITY, &du[0], &du[1]));
  if (it > 0) {
    PetscCall(SNESGetSolutionUpdate(snes, &Y));
    PetscCall(TslProblemFieldNormsType(d->prob, Y, NORM_INFINITY, &c[0], &c[1]));
  }
  for (PetscInt k = 0; k < 2; k++) {
    const TslFieldControls *fc = &d->fctrl[k];
    const PetscReal         qt = fc->qu > 0 ? fc->qu : (d->q_sum[k] + q[k]) / (d->q_n + 1);
    PetscBool               yes;

    if (!fc->on) continue;
    d->q_last[k] = q[k];
    if (fc->qu <= 0 && qt <= fc->eps * PetscMax(fc->q0, d->q_before[k])) yes = (PetscBool)(it > 0 && c[k] <= fc->ceps * du[k]);
    else yes = (PetscBool)(r[k] <= fc->rl * qt || (it > 0 && r[k] <= (it > ip ? fc->rp : fc->rn) * qt && c[k] <= fc->cn * du[k]));
    if (r[k] == 0) yes = PETSC_TRUE;
    if (it == 0) ok[k] = ok0[k] = yes;
    else ok[k] = yes;
    PetscCall(PetscInfo(snes, "it %" PetscInt_FMT " field %" PetscInt_FMT " (*CONTROLS, FIELD): largest residual %g, flux %g (mean %g), correction %g of %g: %s\n",
                        it, k, (double)r[k], (double)q[k], (double)qt, (double)c[k], (double)du[k], yes ? "converged" : "not yet"));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ConvergenceTest(SNES snes, PetscInt it, PetscReal xnorm, PetscReal snorm, PetscReal fnorm, SNESConvergedReason *reason,
                                      void *ctx)
{
  Driver   *d = (Driver *)ctx;
  Vec       F;
  PetscReal nu, nt, tol_u, tol_t, eta_prev = 0;
  PetscBool ok_u, ok_t, force;
  KSP       ksp;

  PetscFunctionBeginUser;
  d->accepted = PETSC_FALSE;
  /* asked to stop (a signal): the increment ends here, unconverged, and RunStep stops the job */
  PetscCall(TslStopRequested(d->comm, &d->stop));
  if (d->stop) {
    *reason = SNES_DIVERGED_FUNCTION_DOMAIN;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  /* PETSc's test for what is not a matter of units: a NaN, the function count */
  PetscCall(SNESConvergedDefault(snes, it, xnorm, snorm, fnorm, reason, NULL));
  if (*reason < 0) PetscFunctionReturn(PETSC_SUCCESS);
  *reason = SNES_CONVERGED_ITERATING;
  PetscCall(SNESGetForceIteration(snes, &force));
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(KSPGetTolerances(ksp, &eta_prev, NULL, NULL, NULL));
  PetscCall(SNESGetFunction(snes, &F, NULL, NULL));
  PetscCall(TslProblemFieldNorms(d->prob, F, &nu, &nt));
  if (it == 0) {
    d->r0_u        = nu;
    d->r0_theta    = nt;
    d->scale_u     = PetscMax(d->scale_u, nu);
    d->scale_theta = PetscMax(d->scale_theta, nt);
    d->fnorm_prev  = 0;
  } else if (it == 1) {
    d->r0_u     = PetscMax(d->r0_u, nu);
    d->r0_theta = PetscMax(d->r0_theta, nt);
  }
  tol_u = PetscMax(d->rtol * d->r0_u, d->atol_rel * d->scale_u);
  tol_t = PetscMax(d->rtol * d->r0_theta, d->atol_rel * d->scale_theta);
  ok_u  = (PetscBool)(nu <= tol_u || nu == 0);
  ok_t  = (PetscBool)(nt <= tol_t || nt == 0);
  if (it > 0 && d->divtol > 0 && (nu > d->divtol * PetscMax(d->r0_u, tol_u) || nt > d->divtol * PetscMax(d->r0_theta, tol_t))) {
    *reason = SNES_DIVERGED_DTOL;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (it > 0) {
    /* an iterate that moved a node by more than MAX_REACH model sizes came from a singular Jacobian (a body that
     * the iterate before left without support): diverged, whatever the residual, which such a state can make
     * look small against its own enormous terms (issue 44, item 7) */
    PetscReal reach;
    Vec       X;
    PetscCall(SNESGetSolution(snes, &X));
    PetscCall(TslProblemDisplacementReach(d->prob, X, &reach));
    if (reach > MAX_REACH) {
      d->refused = "a Newton iterate moved a node by more than 100 times the model's size (a singular Jacobian: a body the iterate before "
                   "left without support, such as a load-controlled part whose contact nodes all opened)";
      *reason    = SNES_DIVERGED_FUNCTION_DOMAIN;
      PetscFunctionReturn(PETSC_SUCCESS);
    }
  }
  if (it > 0 && (!ok_u || !ok_t)) {
    PetscReal ru, rt, yu, yt, xu, xt, stol;
    Vec       X, Y;
    PetscBool reached_u, reached_t;
    PetscCall(RoundoffScales(d, snes, &ru, &rt));
    const PetscReal ulps = 256 * PETSC_MACHINE_EPSILON;
    if (!ok_u && nu <= ulps * ru) ok_u = PETSC_TRUE;
    if (!ok_t && nt <= ulps * rt) ok_t = PETSC_TRUE;
    PetscCall(SNESGetTolerances(snes, NULL, NULL, &stol, NULL, NULL));
    PetscCall(SNESGetSolution(snes, &X));
    PetscCall(SNESGetSolutionUpdate(snes, &Y));
    PetscCall(TslProblemFieldNorms(d->prob, X, &xu, &xt));
    PetscCall(TslProblemFieldNorms(d->prob, Y, &yu, &yt));
    reached_u = (PetscBool)(d->nu_prev >= 1e3 * eta_prev * d->fnorm_prev);
    reached_t = (PetscBool)(d->nt_prev >= 1e3 * eta_prev * d->fnorm_prev);
    if (!ok_u && reached_u && yu <= stol * xu) ok_u = PETSC_TRUE;
    if (!ok_t && reached_t && yt <= stol * xt) ok_t = PETSC_TRUE;
    PetscCall(PetscInfo(snes, "it %" PetscInt_FMT ": round-off |D x| %g %g, steps %g %g of %g %g, reached by the linear solve %d %d\n", it, (double)ru,
                        (double)rt, (double)yu, (double)yt, (double)xu, (double)xt, (int)reached_u, (int)reached_t));
  }
  {
    PetscBool ok[2] = {ok_u, ok_t}, ok0[2] = {nu <= d->atol_rel * d->scale_u, nt <= d->atol_rel * d->scale_theta};
    PetscCall(DialectFieldTest(d, snes, it, ok, ok0));
    ok_u = ok[0], ok_t = ok[1];
    if (it == 0 && (force || !ok0[0] || !ok0[1])) ok_u = PETSC_FALSE;
  }
  if (ok_u && ok_t) {
    *reason     = SNES_CONVERGED_FNORM_RELATIVE;
    d->accepted = PETSC_TRUE;
  }
  if (*reason == SNES_CONVERGED_ITERATING && d->forcing_max > 0) {
    /* The linear tolerance of the next Newton step (inexact Newton): never tighter than what lands each
     * field below its Newton tolerance with a tenth to spare (so the last step is not over-solved, nor
     * the first of a solve that starts near the job's residual floor, e.g. after contact re-pairing);
     * after the first step also the Eisenstat-Walker term 0.9 (|F_k| / |F_k-1|)^2, so that far from the
     * solution the linear solve does not go beyond what the next Newton step can use; both at most
     * forcing_max and at least -ksp_rtol. The first step of an increment thus gets 1e-9 (the job's first
     * increment, whose tolerance is the 1e-8 floor) to 1e-10 (a 1e-9 reduction): a linear model converges
     * in that one step. A field far below the other in scale may get no reduction of its own from this
     * tolerance: (c) above then waits for the next step, whose residual that field dominates. */
    const PetscReal tol = PetscMin(tol_u, tol_t);
    PetscReal       eta = fnorm > 0 ? 0.1 * tol / fnorm : 0;
    if (it > 0 && fnorm > 0 && d->fnorm_prev > 0) eta = PetscMax(eta, 0.9 * PetscSqr(fnorm / d->fnorm_prev));
    eta = PetscMax(d->ksp_rtol, PetscMin(d->forcing_max, eta));
    PetscCall(KSPSetTolerances(ksp, eta, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
  }
  d->fnorm_prev = fnorm, d->nu_prev = nu, d->nt_prev = nt;
  PetscCall(PetscInfo(snes, "it %" PetscInt_FMT ": |R_u| %g (tolerance %g) |R_theta| %g (tolerance %g)%s\n", it, (double)nu, (double)tol_u, (double)nt,
                      (double)tol_t, d->accepted ? ": converged" : ""));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Before a new Jacobian pattern (the same matrix object, preallocated again; Repattern below): the
 * preconditioner lets go of everything built on the old pattern before it builds anew, so that old and new
 * blocks are never held at once (the 3D contact benchmark's peak at N = 64: the displacement block, 41 MB,
 * twice), and a factorisation starts from a new symbolic phase. PETSc's field split (-pc_type fieldsplit)
 * frees its own blocks before extracting new ones; its sub-solvers release theirs here. */
static PetscErrorCode ReleaseSubSolvers(Driver *d)
{
  KSP       ksp;
  PC        pc;
  PetscBool fs, ours;

  PetscFunctionBeginUser;
  PetscCall(SNESGetKSP(d->snes, &ksp));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(TslSplitIs(pc, &ours));
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCFIELDSPLIT, &fs));
  if (ours)
    PetscCall(TslSplitReset(pc));
  else if (fs) {
    KSP     *sub;
    PetscInt n;
    PetscCall(PCFieldSplitGetSubKSP(pc, &n, &sub));
    for (PetscInt i = 0; i < n; i++) PetscCall(KSPReset(sub[i]));
    PetscCall(PetscFree(sub));
  } else
    PetscCall(KSPReset(ksp));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The problem's new-pattern callback (TslProblemSetRepatternCallback): the preconditioner lets go of its
 * blocks and hierarchies before the new matrix is allocated, so the two are never held together. hypre's
 * hierarchy is many heap blocks, which free() keeps resident; the new matrix's large arrays come from fresh
 * mappings and could not reuse them, so the free pages go back to the system first (glibc): on the
 * surface-to-surface benchmark at N = 64 the resident set fell from 440 to 258 MB there, and the job's peak
 * from 525 to 517 MB (the second solve's working set sets it now). */
static PetscErrorCode Repattern(void *ctx)
{
  PetscFunctionBeginUser;
  PetscCall(ReleaseSubSolvers((Driver *)ctx));
#if defined(__GLIBC__)
  (void)malloc_trim(0);
#endif
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode SetUpSolver(Driver *d)
{
  KSP             ksp;
  PC              pc;
  IS              is_u, is_theta;
  const TslModel *m;
  PetscBool       pc_set;

  PetscFunctionBeginUser;
  PetscCall(TslProblemGetModel(d->prob, &m));
  d->rtol               = 1e-9;
  d->atol_rel           = 1e-8;
  d->cutback            = 0.25;
  d->growth             = 1.5;
  d->easy_its           = 5;
  d->max_contact_its    = 8;
  d->sync_interval      = 1.0;
  d->direct_max         = -1; /* by dimension, below */
  d->fallback_max       = -1;
  d->fallback_its       = 200;
  d->debug_diverge_step = 0;
  d->forcing_max        = 1e-6;
  d->ksp_rtol           = 1e-10;
  d->block_solves       = PETSC_TRUE;
  d->jacobi_scale       = 1.6;
  d->amg_cycle          = PETSC_TRUE;
  d->reuse_pc           = PETSC_TRUE;
  d->extrapolate        = PETSC_TRUE;
  d->implicit_records   = PETSC_TRUE;
  PetscOptionsBegin(d->comm, NULL, "thermoslide increment control", NULL);
  PetscCall(TslOptionsReal(PetscOptionsObject, "-tsl_linear_forcing",
                           "loosest linear tolerance of a Newton iteration after the first (inexact Newton; 0: -ksp_rtol throughout)", 0, PETSC_FALSE, 1,
                           PETSC_TRUE, &d->forcing_max));
  {
    PetscBool set;
    PetscCall(PetscOptionsHasName(NULL, NULL, "-ksp_rtol", &set));
    if (set) d->forcing_max = 0; /* the user's linear tolerance holds throughout */
  }
  PetscCall(TslOptionsBool(PetscOptionsObject, "-tsl_block_solves",
                           "a block-triangular Jacobian (no contact): each field's block solved by CG to the linear tolerance, instead of one AMG "
                           "cycle per outer iteration",
                           &d->block_solves));
  PetscCall(TslOptionsReal(PetscOptionsObject, "-tsl_amg_jacobi_scale",
                           "weighted-Jacobi smoothing of the blocks' BoomerAMG (displacement; temperature without contact): each level's weight is "
                           "this / (1.1 x its estimated largest eigenvalue of D^-1 A) (0: Chebyshev and hybrid Gauss-Seidel as before; the default "
                           "split only)",
                           0, PETSC_FALSE, 1.8, PETSC_FALSE, &d->jacobi_scale));
  PetscCall(TslOptionsBool(PetscOptionsObject, "-tsl_amg_cycle",
                           "the blocks' BoomerAMG V-cycle with Jacobi smoothing applied by thermoslide: each level's first sweep from zero "
                           "without a product with the zero iterate (the same iterates as hypre's own cycle; the default split only)",
                           &d->amg_cycle));
  PetscCall(TslOptionsBool(PetscOptionsObject, "-tsl_reuse_unchanged_jacobian",
                           "a Jacobian equal bit for bit to the last one assembled keeps the preconditioner built on it (a factorisation, or "
                           "the AMG hierarchies) instead of building the same one again",
                           &d->reuse_pc));
  PetscCall(TslOptionsBool(PetscOptionsObject, "-tsl_extrapolate",
                           "each increment's Newton solve starts from the last increment's change extrapolated linearly (the dialect's "
                           "EXTRAPOLATION=LINEAR)",
                           &d->extrapolate));
  PetscCall(TslOptionsBool(PetscOptionsObject, "-tsl_restart",
                           "continue the job from the latest valid restart point in its output directory (*RESTART, WRITE, or a stop "
                           "signal, wrote it); its results extend the earlier run's (docs/running.md, \"Restart\")",
                           &d->rs_resume));
  PetscCall(TslOptionsBool(PetscOptionsObject, "-tsl_implicit_records",
                           "implicit residuals from the element force records (geometry and conduction computed once; docs/running.md)",
                           &d->implicit_records));
  PetscCall(TslOptionsReal(PetscOptionsObject, "-tsl_rtol", "per-field Newton residual reduction", 0, PETSC_TRUE, 1, PETSC_TRUE, &d->rtol));
  PetscCall(TslOptionsReal(PetscOptionsObject, "-tsl_atol_rel", "per-field residual floor relative to the job's largest", 0, PETSC_TRUE, 1,
                           PETSC_TRUE, &d->atol_rel));
  PetscCall(
      TslOptionsReal(PetscOptionsObject, "-tsl_cutback", "increment factor after a failed increment", 0, PETSC_TRUE, 1, PETSC_TRUE, &d->cutback));
  PetscCall(
      TslOptionsReal(PetscOptionsObject, "-tsl_growth", "increment factor after an easy increment", 1, PETSC_FALSE, 100, PETSC_FALSE, &d->growth));
  PetscCall(TslOptionsInt(PetscOptionsObject, "-tsl_easy_its", "Newton iterations that count as easy", 0, 1000, &d->easy_its));
  PetscCall(TslOptionsInt(PetscOptionsObject, "-tsl_contact_max_its", "solves of one increment while contact pairing or multipliers change", 1, 1000,
                          &d->max_contact_its));
  PetscCall(TslOptionsReal(PetscOptionsObject, "-tsl_output_sync", "seconds between syncs of the .h5 and .xmf.part (0: every frame)", 0, PETSC_FALSE,
                           86400, PETSC_FALSE, &d->sync_interval));
  PetscCall(TslOptionsInt(PetscOptionsObject, "-tsl_direct_max_dofs",
                          "models up to this many unknowns get a direct solver by default (default 20000 in 2D, 2000 in 3D)", 0, PETSC_MAX_INT,
                          &d->direct_max));
  PetscCall(TslOptionsInt(PetscOptionsObject, "-tsl_fallback_max_dofs",
                          "an increment whose iterative linear solve fails is retried with MUMPS LU (for the rest of the job) up to this many unknowns "
                          "(default 400000 in 2D, 150000 in 3D; 0: never)",
                          0, PETSC_MAX_INT, &d->fallback_max));
  PetscCall(TslOptionsInt(PetscOptionsObject, "-tsl_fallback_its",
                          "an increment that needed more linear iterations per Newton iteration than this switches to MUMPS LU (up to "
                          "-tsl_fallback_max_dofs unknowns) for the rest of the job",
                          1, PETSC_MAX_INT, &d->fallback_its));
  PetscCall(TslOptionsInt(PetscOptionsObject, "-tsl_debug_diverge_step", "testing aid: treat every increment of this step (1-based) as diverged", 0,
                          PETSC_MAX_INT, &d->debug_diverge_step));
  PetscOptionsEnd();
  {
    /* full Newton steps by default; a model with *PLASTIC backtracks (bt): its points switch between elastic and
     * plastic from one iterate to the next, and full steps can cycle where the yield surface is crossed (a quadratic
     * brick unloaded from a plastic state: 45 iterations with l2, none converging with basic, 7 with bt) */
    const TslModel *m;
    PetscBool       plastic = PETSC_FALSE;
    PetscCall(TslProblemGetModel(d->prob, &m));
    for (PetscInt k = 0; k < m->nmaterial; k++) plastic = (PetscBool)(plastic || TslMaterialIsPlastic(&m->materials[k]));
    PetscCall(SetDefaultOption(d, "-snes_linesearch_type", plastic ? "bt" : "basic"));
  }
  {
    /* a small model: a sparse direct solve costs less than building and applying the AMG hierarchies,
     * whose set-up dominates the increments of a few-hundred-unknown contact deck. The factorisation
     * grows as n^1.5 in 2D but n^2 in 3D (5 500 unknowns of the 3D block: 0.7 s against 0.13 s of AMG). */
    Vec      X;
    PetscInt N;
    PetscCall(TslProblemGetSolution(d->prob, &X));
    PetscCall(VecGetSize(X, &N));
    if (d->direct_max < 0) d->direct_max = m->dim == 3 ? 2000 : 20000;
    if (d->fallback_max < 0) d->fallback_max = m->dim == 3 ? 150000 : 400000;
    if (N <= d->direct_max) {
      PetscMPIInt size;
      PetscCallMPI(MPI_Comm_size(d->comm, &size));
      /* one rank: PETSc's own sparse LU (nested dissection ordering), whose set-up costs a third of
       * MUMPS's on these sizes (the 3D conductance series: solver set-up 0.75 s against 2.6 s, 8 s -> 3.8 s
       * for the job); it does not pivot, so a zero pivot fails the linear solve and the increment is
       * repeated with MUMPS for the rest of the job (FallBackToDirect). Several ranks: MUMPS from the
       * start, with nothing to fall back to. */
      PetscCall(SetDefaultOption(d, "-pc_type", "lu"));
      PetscCall(SetDefaultOption(d, "-pc_factor_mat_solver_type", size == 1 ? "petsc" : "mumps"));
      if (size > 1) d->fell_back = PETSC_TRUE;
    }
  }
  /* whether a -pc_type (the user's, or the direct solve above) replaces thermoslide's split; -pc_type tslsplit
   * names it (TslSplitRegister makes the name known to PETSc's options) */
  PetscCall(TslSplitRegister());
  {
    char type[64] = "";
    PetscCall(PetscOptionsGetString(NULL, NULL, "-pc_type", type, sizeof(type), &pc_set));
    if (pc_set && !strcmp(type, PCTSLSPLIT)) pc_set = PETSC_FALSE;
  }
  {
    /* the default split's type, checked before any solver object exists (a type it lacks stops the job here) */
    PetscBool additive;
    if (!pc_set) PetscCall(TslSplitOptionType(NULL, &additive));
  }
  {
    /* block solves (split.c) replace the sub-solvers' preonly only where the user did not choose their type */
    PetscBool set_t, set_u;
    PetscCall(PetscOptionsHasName(NULL, NULL, "-fieldsplit_T_ksp_type", &set_t));
    PetscCall(PetscOptionsHasName(NULL, NULL, "-fieldsplit_u_ksp_type", &set_u));
    if (set_t || set_u) d->block_solves = PETSC_FALSE;
  }
  {
    /* the linear solver's defaults, one row each, entered in this order where the user gave none (a row for a
     * case comes before the general row of the same option). JACOBI: thermoslide's split with its per-level
     * Jacobi weights (-tsl_amg_jacobi_scale > 0, no -pc_type of the user's) */
    enum { ALL, CONTACT, JACOBI, JACOBI_NO_CONTACT, NOT_JACOBI };
    static const struct {
      const char *name, *value;
      int         when;
    } rows[] = {
        {"-ksp_type", "fgmres", ALL},
        {"-ksp_rtol", "1e-10", ALL},
        {"-ksp_max_it", "1000", ALL},
        {"-ksp_gmres_restart", "100", ALL},
        {"-pc_fieldsplit_type", "multiplicative", ALL},
        {"-fieldsplit_T_ksp_type", "preonly", ALL},
        {"-fieldsplit_T_pc_type", "hypre", ALL},
        {"-fieldsplit_u_ksp_type", "preonly", ALL},
        {"-fieldsplit_u_pc_type", "hypre", ALL},
        /* contact: two bodies coupled by penalty springs (a thin block held normal to the interface only
         * through it). With the lean hierarchy below the displacement block's iterations doubled with each
         * halving of the mesh (50 / 99 / 199 / 391 per Newton iteration at 289 / 1 089 / 4 225 / 16 641 contact
         * nodes); without aggressive coarsening and with strong threshold 0.8 on the displacement block they
         * take 19 / 23 / 38 / 71, and with strong threshold 0.7 on the temperature block as well (whose
         * hierarchy, with BoomerAMG's 0.25, was what still grew: with it solved exactly the count was flat)
         * 19 / 20 / 20 (docs/running.md, "Contact at scale"). Without contact, dropping the aggressive
         * coarsening costs more than it saves (the steady block: 25 instead of 29 iterations for twice the
         * set-up and a slower solve), so these are the contact models' defaults only. */
        {"-fieldsplit_u_pc_hypre_boomeramg_strong_threshold", "0.8", CONTACT},
        {"-fieldsplit_u_pc_hypre_boomeramg_agg_nl", "0", CONTACT},
        {"-fieldsplit_T_pc_hypre_boomeramg_strong_threshold", "0.7", CONTACT},
        {"-fieldsplit_u_pc_hypre_boomeramg_strong_threshold", "0.5", ALL},
        /* lean hierarchies (HMIS coarsening, ext+i interpolation, one level of aggressive coarsening): on the
         * 3D benchmark 25-35 % faster and 20 % less memory than BoomerAMG's defaults, for 24-29 instead of
         * 17-18 iterations from 5.5k to 122k dofs (docs/running.md, tests/bench/) */
        {"-fieldsplit_u_pc_hypre_boomeramg_coarsen_type", "HMIS", ALL},
        {"-fieldsplit_u_pc_hypre_boomeramg_interp_type", "ext+i", ALL},
        {"-fieldsplit_u_pc_hypre_boomeramg_agg_nl", "1", ALL},
        {"-fieldsplit_T_pc_hypre_boomeramg_coarsen_type", "HMIS", ALL},
        {"-fieldsplit_T_pc_hypre_boomeramg_interp_type", "ext+i", ALL},
        {"-fieldsplit_T_pc_hypre_boomeramg_agg_nl", "1", ALL},
        {"-fieldsplit_u_pc_hypre_boomeramg_P_max", "4", ALL},
        /* Smoothing by matrix-vector products instead of hybrid Gauss-Seidel sweeps, and interpolation
         * truncated at 0.3, on the displacement hierarchy. Thermoslide's split weights BoomerAMG's Jacobi sweeps
         * level by level from each level's spectrum (split.c, JacobiWeights): a third of a Chebyshev sweep's
         * products, the linear solve of the peer benchmark's block 22 % faster than with Chebyshev, which was
         * twice as fast as hybrid Gauss-Seidel. Without it (PETSc's -pc_type fieldsplit, -tsl_amg_jacobi_scale
         * 0) a fixed Jacobi weight can let the cycle diverge, so Chebyshev, which estimates its own spectrum,
         * stays the default there (docs/running.md, tests/bench/bench_peer.sh). */
        {"-fieldsplit_u_pc_hypre_boomeramg_relax_type_all", "Jacobi", JACOBI},
        {"-fieldsplit_u_pc_hypre_boomeramg_no_CF", "true", JACOBI},
        /* the temperature block too, without contact: 19 instead of 15 CG iterations on the peer benchmark's
         * block, each cheaper than hybrid Gauss-Seidel's, and a cheaper set-up (the job 5-8 % faster on 1 and 2
         * ranks); with contact the coupled outer iterations grew (the 3D contact benchmark at N = 32: 76 -> 94
         * displacement cycles for the same time), so hybrid Gauss-Seidel stays there */
        {"-fieldsplit_T_pc_hypre_boomeramg_relax_type_all", "Jacobi", JACOBI_NO_CONTACT},
        {"-fieldsplit_T_pc_hypre_boomeramg_no_CF", "true", JACOBI_NO_CONTACT},
        {"-fieldsplit_u_pc_hypre_boomeramg_relax_type_all", "Chebyshev", NOT_JACOBI},
        {"-fieldsplit_u_pc_hypre_boomeramg_truncfactor", "0.3", ALL},
    };
    const PetscBool contact = (PetscBool)(m->npair > 0), jacobi = (PetscBool)(!pc_set && d->jacobi_scale > 0);
    for (size_t i = 0; i < sizeof(rows) / sizeof(rows[0]); i++) {
      const int w  = rows[i].when;
      PetscBool on = (PetscBool)(w == ALL || (w == CONTACT && contact) || (w == JACOBI && jacobi) || (w == JACOBI_NO_CONTACT && jacobi && !contact) ||
                                 (w == NOT_JACOBI && !jacobi));
      if (on) PetscCall(SetDefaultOption(d, rows[i].name, rows[i].value));
    }
  }

  PetscCall(SNESCreate(d->comm, &d->snes));
  PetscCall(TslProblemSetRepatternCallback(d->prob, Repattern, d));
  PetscCall(SNESSetType(d->snes, SNESNEWTONLS));
  PetscCall(SNESSetConvergenceTest(d->snes, ConvergenceTest, d, NULL));
  {
    Vec X;
    PetscCall(TslProblemGetSolution(d->prob, &X));
    PetscCall(VecDuplicate(X, &d->F));
    PetscCall(SNESSetFunction(d->snes, d->F, TslProblemFormFunction, d->prob));
  }
  PetscCall(SNESGetKSP(d->snes, &ksp));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(TslProblemGetFieldIS(d->prob, &is_u, &is_theta));
  /* temperature first: without contact the heat equation does not depend on u, so the multiplicative
   * (block Gauss-Seidel) split is then an exact block-triangular solve up to the AMG cycles */
  PetscCall(TslSplitSetUp(pc, is_theta, is_u));
  PetscCall(TslSplitSetTriangular(pc, ksp, d->block_solves));
  PetscCall(TslSplitSetAmg(pc, d->jacobi_scale, d->amg_cycle));
  PetscCall(SNESSetFromOptions(d->snes));
  /* divergence is decided per field (ConvergenceTest): PETSc's own test compares the norm of both fields */
  PetscCall(SNESGetDivergenceTolerance(d->snes, &d->divtol));
  PetscCall(SNESSetDivergenceTolerance(d->snes, -1));
  {
    /* -pc_type fieldsplit: PETSc's own field split over the same two fields (its Schur and other types) */
    PetscBool fs;
    PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCFIELDSPLIT, &fs));
    if (fs) {
      KSP     *sub;
      PetscInt n, nu_global;
      PetscCall(ISGetSize(is_u, &nu_global));
      PetscCall(PCFieldSplitSetIS(pc, "T", is_theta));
      if (nu_global) PetscCall(PCFieldSplitSetIS(pc, "u", is_u)); /* a heat-transfer model has the temperature alone */
      PetscCall(PCFieldSplitGetSubKSP(pc, &n, &sub));
      for (PetscInt i = 0; i < n; i++) PetscCall(KSPSetFromOptions(sub[i]));
      PetscCall(PetscFree(sub));
    }
  }

  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The increment's time and its time discretisation: the kernels return heat content and capacity, and
 * the implicit procedures are backward Euler in the capacity term (rate = (Q - Q_old) / dt), or steady
 * state (no capacity term at all). */
static PetscErrorCode SetIncrement(Driver *d, const TslStep *step, PetscReal step_time, PetscReal h, PetscReal total_time)
{
  PetscFunctionBeginUser;
  PetscCall(TslProblemSetTime(d->prob, step_time, h, total_time));
  PetscCall(TslProblemSetCapacityRate(d->prob, step->steady || !(h > 0) ? 0.0 : 1.0 / h));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One increment's solve: contact pairing at its start, Newton, and again while contact pairing or
 * augmented-Lagrange multipliers change (at most -tsl_contact_max_its solves).
 * A solve after a multiplier update takes at least one Newton step. The update changes the residual only
 * by the change of the contact forces, A (lambda_new - lambda); where that is below the job's residual
 * floor the convergence test would accept the old solution as it stands, the gaps would not move, and the
 * next update would repeat the same change: the augmentations could never meet their own tolerance (1e-3
 * of the largest pressure), whose force may lie far below that floor. That stalled the CPE8T conductance
 * series with augmented Lagrange in step 5: two nodes left near the end of the main surface, pressures
 * above the conductance table's last point (k flat, so no thermal residual forced a step either), and
 * lambda growing by eps_n |g| = 1.04 in every one of the eight solves. */
/* Switches the linear solver to MUMPS LU for the rest of the job (once; up to -tsl_fallback_max_dofs
 * unknowns, whose factorisation MUMPS affords), saying why in the log. */
static PetscErrorCode FallBackToDirect(Driver *d, Vec X, PetscInt s, PetscInt inc, const char *why, PetscBool *switched)
{
  PetscInt N;

  PetscFunctionBeginUser;
  PetscCall(VecGetSize(X, &N));
  d->fell_back = PETSC_TRUE;
  *switched    = (PetscBool)(N <= d->fallback_max);
  if (*switched) {
    KSP ksp;
    PC  pc;
    PetscCall(PetscPrintf(d->comm,
                          "  step %" PetscInt_FMT " increment %" PetscInt_FMT ": %s; the direct solver MUMPS serves the rest of the job (%" PetscInt_FMT
                          " unknowns; -tsl_fallback_max_dofs %" PetscInt_FMT ")\n",
                          s + 1, inc + 1, why, N, d->fallback_max));
    PetscCall(SNESGetKSP(d->snes, &ksp));
    PetscCall(KSPGetPC(ksp, &pc));
    /* a one-rank LU that met a zero pivot has its factor set up with PETSc's package, which PCFactor will not
     * exchange while that factor exists: the PC lets go of it first */
    PetscCall(PCReset(pc));
    PetscCall(PCSetType(pc, PCLU));
    PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A digest of one rank's part of an AIJ matrix: its values word by word (FNV-1a over 64-bit words) and
 * their count. Other types give *ok false. */
static PetscErrorCode MatDigest(Mat A, uint64_t *h, PetscBool *ok)
{
  Mat       blk[2] = {NULL, NULL};
  PetscBool mpi, seq;

  PetscFunctionBeginUser;
  *h  = 0xcbf29ce484222325ULL;
  PetscCall(PetscObjectTypeCompare((PetscObject)A, MATMPIAIJ, &mpi));
  PetscCall(PetscObjectTypeCompare((PetscObject)A, MATSEQAIJ, &seq));
  *ok = (PetscBool)(mpi || seq);
  if (!*ok) PetscFunctionReturn(PETSC_SUCCESS);
  if (mpi) PetscCall(MatMPIAIJGetSeqAIJ(A, &blk[0], &blk[1], NULL));
  else blk[0] = A;
  for (int b = 0; b < 2 && blk[b]; b++) {
    const PetscInt    *ia, *ja;
    const PetscScalar *v;
    PetscInt           n;
    PetscBool          done;
    PetscCall(MatGetRowIJ(blk[b], 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
    PetscCheck(done, PETSC_COMM_SELF, PETSC_ERR_PLIB, "the Jacobian's rows could not be read");
    PetscCall(MatSeqAIJGetArrayRead(blk[b], &v));
    for (PetscInt k = 0; k < ia[n]; k++) {
      uint64_t w;
      memcpy(&w, &v[k], sizeof(w));
      *h = (*h ^ w) * 0x100000001b3ULL;
    }
    *h = (*h ^ (uint64_t)ia[n]) * 0x100000001b3ULL;
    PetscCall(MatSeqAIJRestoreArrayRead(blk[b], &v));
    PetscCall(MatRestoreRowIJ(blk[b], 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The Jacobian, and whether it is the last one assembled, bit for bit (same pattern, same digest on every
 * rank): then the preconditioner built on that one (a factorisation, or the AMG hierarchies) serves again.
 * A linear model at a constant increment assembles the same matrix in every increment (the transient
 * capacity C / dt and the stiffness do not change): CalculiX-Examples' thermal shock (5 492 unknowns,
 * C3D20R, 50 increments) factorised it 48 times, 46 of its 49 s. A digest collision (2^-64) would only
 * keep a stale preconditioner: the Newton test reads the residual, so it costs iterations, never an answer.
 * Collective. */
static PetscErrorCode FormJacobian(SNES snes, Vec X, Mat J, Mat P, void *ctx)
{
  Driver          *d = (Driver *)ctx;
  uint64_t         h;
  PetscBool        ok, same;
  PetscObjectState nz;

  PetscFunctionBeginUser;
  PetscCall(TslProblemFormJacobian(snes, X, J, P, d->prob));
  if (!d->reuse_pc) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MatDigest(P, &h, &ok));
  PetscCall(MatGetNonzeroState(P, &nz));
  same = (PetscBool)(ok && d->jac_known && h == d->jac_hash && nz == d->jac_nzstate);
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &same, 1, MPIU_BOOL, MPI_LAND, d->comm));
  d->jac_known  = ok;
  d->jac_hash   = h;
  d->jac_nzstate = nz;
  d->jac_reused = same;
  if (same) d->jac_reuses++;
  d->jac_count++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Before each linear solve (KSPSolve calls it ahead of its set-up): keep the preconditioner where
 * FormJacobian found the Jacobian unchanged. Set here, not in FormJacobian, because SNESComputeJacobian
 * sets the KSP's reuse flag itself (from its preconditioner lag) once the Jacobian callback returns. */
static PetscErrorCode KeepPreconditioner(KSP ksp, Vec b, Vec x, void *ctx)
{
  Driver *d = (Driver *)ctx;

  PetscFunctionBeginUser;
  (void)b, (void)x;
  PetscCall(KSPSetReusePreconditioner(ksp, d->jac_reused));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Hands the problem's Jacobian to the solver. A new pattern (contact pairing at an increment, or constraints
 * at a step start) has already made the preconditioner let go of what it built on the old one (Repattern). */
static PetscErrorCode HandJacobian(Driver *d)
{
  Mat J;
  KSP ksp;

  PetscFunctionBeginUser;
  PetscCall(TslProblemGetJacobian(d->prob, &J));
  PetscCall(SNESSetJacobian(d->snes, J, J, FormJacobian, d));
  PetscCall(SNESGetKSP(d->snes, &ksp));
  PetscCall(KSPSetPreSolve(ksp, KeepPreconditioner, d));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode SolveIncrement(Driver *d, Vec X, SNESConvergedReason *reason, PetscInt *its, PetscInt *lits)
{
  PetscBool again = PETSC_TRUE, repattern, augmented = PETSC_FALSE;
  PetscInt  n = 0, naug = 0; /* solves, and solves that followed a multiplier update */

  PetscFunctionBeginUser;
  *its = *lits = 0;
  PetscCall(TslPhaseBegin(TSL_PHASE_CONTACT));
  PetscCall(TslProblemContactSearch(d->prob, &repattern));
  PetscCall(TslPhaseEnd(TSL_PHASE_CONTACT));
  while (again) {
    PetscInt i, l;
    if (repattern) PetscCall(HandJacobian(d));
    naug += augmented;
    n++;
    PetscCall(SNESSetForceIteration(d->snes, augmented));
    PetscCall(TslPhaseBegin(TSL_PHASE_SOLVE));
    PetscCall(TslProblemContactChatterReset(d->prob));
    PetscCall(SNESSolve(d->snes, NULL, X));
    PetscCall(TslPhaseEnd(TSL_PHASE_SOLVE));
    PetscCall(SNESSetForceIteration(d->snes, PETSC_FALSE));
    PetscCall(SNESGetConvergedReason(d->snes, reason));
    PetscCall(SNESGetIterationNumber(d->snes, &i));
    PetscCall(SNESGetLinearSolveIterations(d->snes, &l));
    {
      /* linear iterations count the displacement block's cycles: block solves take several per outer one */
      KSP       ksp;
      PC        pc;
      PetscBool ours;
      PetscInt  extra;
      PetscCall(SNESGetKSP(d->snes, &ksp));
      PetscCall(KSPGetPC(ksp, &pc));
      PetscCall(TslSplitIs(pc, &ours));
      if (ours) {
        PetscCall(TslSplitTakeExtraCycles(pc, &extra));
        l += extra;
      }
    }
    *its += i, *lits += l;
    if (*reason > 0 && !d->accepted) {
      /* a PETSc test other than the per-field one ended the solve (a solver type or option of the user's that
       * brings its own test): nothing says each field converged, so the increment is not accepted */
      d->refused = "the Newton solve ended without each field's residual below its tolerance";
      *reason    = SNES_DIVERGED_FUNCTION_DOMAIN;
    }
    if (*reason <= 0) break;
    PetscCall(TslPhaseBegin(TSL_PHASE_CONTACT));
    PetscCall(TslProblemContactUpdate(d->prob, &again, &repattern, &augmented));
    PetscCall(TslPhaseEnd(TSL_PHASE_CONTACT));
    if (again && n >= d->max_contact_its) {
      PetscCall(PetscInfo(d->snes, "contact state still changing after %" PetscInt_FMT " solves\n", n));
      *reason = SNES_DIVERGED_MAX_IT;
      break;
    }
  }
  PetscCall(PetscInfo(d->snes, "increment: %" PetscInt_FMT " solves, %" PetscInt_FMT " of them after a multiplier update\n", n, naug));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Console and history line of an accepted increment. */
static PetscErrorCode Accept(Driver *d, PetscInt s, PetscInt inc, PetscReal t, PetscReal h, PetscReal total, PetscInt its, PetscInt lits)
{
  TslHeatBalance hb;
  PetscReal      row[NHISTORY];

  PetscFunctionBeginUser;
  PetscCall(TslProblemHeatBalance(d->prob, &hb));
  PetscCall(TslProblemContactCommit(d->prob));
  PetscCall(TslProblemCommitState(d->prob));
  d->plastic_dissipated += hb.plastic_work;
  d->dissipated += hb.dissipation * h;
  d->absorbed += hb.friction_heat * h;
  PetscCall(PetscPrintf(d->comm,
                        "  step %" PetscInt_FMT " increment %" PetscInt_FMT ": time %.6g  dt %.4g  newton %" PetscInt_FMT "  linear %" PetscInt_FMT
                        "  heat in %.6g  film out %.6g",
                        s + 1, inc, (double)total, (double)h, its, lits, (double)hb.heat_in, (double)hb.film_out));
  if (d->radiates) PetscCall(PetscPrintf(d->comm, "  radiated %.6g", (double)hb.radiation_out));
  PetscCall(PetscPrintf(d->comm, "  balance %.3g\n", (double)hb.balance));
  row[HIST_STEP]                = (PetscReal)(s + 1);
  row[HIST_INCREMENT]           = (PetscReal)inc;
  row[HIST_TIME]                = total;
  row[HIST_STEP_TIME]           = t;
  row[HIST_DT]                  = h;
  row[HIST_NEWTON_ITS]          = (PetscReal)its;
  row[HIST_HEAT_IN]             = hb.heat_in;
  row[HIST_FILM_OUT]            = hb.film_out;
  row[HIST_RADIATION_OUT]       = hb.radiation_out;
  row[HIST_REACTION_HEAT]       = hb.reaction_heat;
  row[HIST_STORED_RATE]         = hb.stored_rate;
  row[HIST_INTERFACE_HEAT]      = hb.interface_heat;
  row[HIST_DISSIPATION_RATE]    = hb.dissipation;
  row[HIST_DISSIPATION_TOTAL]   = d->dissipated;
  row[HIST_FRICTION_HEAT_TOTAL] = d->absorbed;
  row[HIST_BALANCE]             = hb.balance;
  row[HIST_STRAIN_ENERGY]       = hb.strain_energy;
  row[HIST_HOURGLASS_ENERGY]    = hb.hourglass_energy;
  row[HIST_PLASTIC_HEAT]        = hb.plastic_heat;
  row[HIST_PLASTIC_DISSIPATION] = d->plastic_dissipated;
  for (PetscInt c = HIST_ENERGY; c < NHISTORY; c++) row[c] = 0; /* the energies of explicit steps */
  PetscCall(TslHistoryAppend(d->hist, row));
  d->done_step = s + 1, d->done_inc = inc, d->done_time = total, d->done_step_time = t, d->done_dt = h;
  for (PetscInt k = 0; k < 2; k++) d->q_sum[k] += d->q_last[k];
  d->q_n++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* After a failed solve: when contacts were still switching between open and closed at every one of its last
 * residual evaluations, says so, with the likely cause (docs/contact.md, "Contact that does not settle"). */
static PetscErrorCode ReportChatter(Driver *d)
{
  PetscInt run, count, node;

  PetscFunctionBeginUser;
  PetscCall(TslProblemContactChatter(d->prob, &run, &count, &node));
  if (run < 4) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscPrintf(
      d->comm,
      "    contact did not settle: in each of the last %" PetscInt_FMT
      " residual evaluations contacts changed between open and closed (%" PetscInt_FMT " at the last, node %" PetscInt_FMT " among them)%s\n",
      run, count, node,
      d->chatter_told ? ""
                      : ". An interface law that jumps at closure, such as a *GAP CONDUCTANCE that is nonzero only while closed, with "
                        "thermal expansion across the gap, can leave no consistent state; a conductance that falls to zero over a small "
                        "clearance is continuous (docs/contact.md, \"Contact that does not settle\")"));
  d->chatter_told = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* What a job stopped in a step leaves, for its message: the last converged state at step time t, or none. */
static const char *SavedState(const Driver *d, PetscReal t, char buf[], size_t len)
{
  if (d->done_inc)
    (void)PetscSNPrintf(buf, len, "the last converged state (step time %g) is saved", (double)t);
  else
    (void)PetscSNPrintf(buf, len, "no increment has converged (step time %g): there is no state to save", (double)t);
  return buf;
}

/* Increments of one step. dt is the controller's increment; each increment h = dt cut short at the step
 * end and at the next corner of an amplitude the step follows (so a slide reversal is never straddled).
 * A failed increment is retried from the last converged state with h * cutback. */
/* The step's *CONTROLS, PARAMETERS=TIME INCREMENTATION (or RESET) replaces the controls in force; a step without
 * one keeps them (the dialect's controls hold until changed). With a surface-to-surface pair (the dialect's
 * face-to-face penalty contact) I_G and I_L left blank are raised by 12, as CalculiX does for that contact, whose
 * increments take more iterations: steady increments of up to 16 iterations grow. I_C caps each Newton solve. */
static PetscErrorCode TakeControls(Driver *d, const TslModel *m, const TslStep *step)
{
  PetscBool s2s = PETSC_FALSE;
  char      where[PETSC_MAX_PATH_LEN + 32];

  PetscFunctionBeginUser;
  if (!d->snes_max_it) PetscCall(SNESGetTolerances(d->snes, NULL, NULL, NULL, &d->snes_max_it, NULL));
  /* the field controls, and the time-averaged flux that starts anew with the step */
  for (PetscInt k = 0; k < 2; k++) {
    if (d->q_n) d->q_before[k] = d->q_sum[k] / d->q_n;
    d->q_sum[k] = d->q_last[k] = 0;
    if (step->field_controls[k].given) d->fctrl[k] = step->field_controls[k];
  }
  d->q_n = 0;
  PetscCall(TslProblemSetElementFlux(d->prob, (PetscBool)(d->fctrl[0].on || d->fctrl[1].on)));
  for (PetscInt k = 0; k < 2; k++) {
    const TslFieldControls *f = &d->fctrl[k];
    if (!step->field_controls[k].given || !f->on || (k == 1 && step->statik)) continue; /* *STATIC: temperatures held */
    PetscCall(PetscPrintf(d->comm,
                          "  convergence: *CONTROLS, PARAMETERS=FIELD (%s), %s field: largest residual at most %g (%g after %" PetscInt_FMT
                          " iterations) of %s and largest correction at most %g of its change over the increment, or residual at most %g of it\n",
                          TslLocString(m, f->loc, where, sizeof(where)), k ? "temperature" : "displacement", (double)f->rn, (double)f->rp,
                          d->ctrl_on ? d->ctrl.ip : (PetscInt)9, f->qu > 0 ? "the given flux" : "the time-averaged flux", (double)f->cn, (double)f->rl));
    if (f->qu > 0) PetscCall(PetscPrintf(d->comm, "    (the given flux q_u = %g)\n", (double)f->qu));
  }
  if (!step->controls.given) PetscFunctionReturn(PETSC_SUCCESS);
  d->ctrl    = step->controls;
  d->ctrl_on = (PetscBool)!step->controls.reset;
  for (PetscInt k = 0; k < m->npair; k++) s2s = (PetscBool)(s2s || m->pairs[k].type == TSL_CONTACT_SURFACE_TO_SURFACE);
  if (d->ctrl_on && s2s) { /* CalculiX raises both by 12 for face-to-face penalty contact, whatever the deck gives */
    d->ctrl.ig += 12;
    d->ctrl.il += 12;
  }
  PetscCall(SNESSetTolerances(d->snes, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, d->ctrl_on ? d->ctrl.ic : d->snes_max_it, PETSC_DEFAULT));
  if (d->ctrl_on)
    PetscCall(PetscPrintf(d->comm,
                          "  increment control: *CONTROLS (%s): grow x%g after two increments of at most %" PetscInt_FMT
                          " Newton iterations, x%g after one of more than %" PetscInt_FMT "; cut back x%g, at most %" PetscInt_FMT
                          " times per increment; at most %" PetscInt_FMT " iterations per solve\n",
                          TslLocString(m, d->ctrl.loc, where, sizeof(where)), (double)d->ctrl.dd, d->ctrl.ig, (double)d->ctrl.db, d->ctrl.il,
                          (double)d->ctrl.df, d->ctrl.ia, d->ctrl.ic));
  else
    PetscCall(PetscPrintf(d->comm, "  increment control: *CONTROLS, RESET (%s): thermoslide's own (-tsl_growth, -tsl_easy_its, -tsl_cutback)\n",
                          TslLocString(m, d->ctrl.loc, where, sizeof(where))));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode RunStep(Driver *d, PetscInt s, PetscReal *total_time)
{
  char            saved[128], where[PETSC_MAX_PATH_LEN + 32];
  const TslModel *m;
  const TslStep  *step;
  Vec             X, Xold;
  PetscReal       t   = 0, dt, eps;
  PetscInt        inc = 0, attempts = 0, cutbacks = 0, its_prev = PETSC_MAX_INT; /* cutbacks of this increment; its of the last accepted one */
  TslFrameTimes   frames;

  PetscFunctionBeginUser;
  PetscCall(TslProblemGetModel(d->prob, &m));
  step = &m->steps[s];
  PetscCall(PetscPrintf(d->comm, "step %" PetscInt_FMT " (%s): %s, period %g, initial increment %g\n", s + 1, step->name[0] ? step->name : "-",
                        step->statik                 ? "static (temperatures held)"
                        : step->heat && step->steady ? "heat transfer, steady state"
                        : step->heat                 ? "heat transfer, transient"
                        : step->steady               ? "steady state"
                                                     : "transient",
                        (double)step->period, (double)step->dt0));
  PetscCall(TslPhaseBegin(TSL_PHASE_SETUP));
  TslCallCollective(d->comm, TslProblemSetStep(d->prob, s));
  if (!d->records_done) {
    /* the residuals' element force records, once for the job (the geometry and the materials do not change) */
    PetscInt  nfast;
    PetscReal mb;
    d->records_done = PETSC_TRUE;
    PetscCall(TslProblemImplicitRecords(d->prob, d->implicit_records, &nfast, &mb));
    if (d->implicit_records)
      PetscCall(PetscPrintf(d->comm,
                            "  force records: %" PetscInt_FMT " of %" PetscInt_FMT " elements (%.1f MB on the largest rank) for the residuals; the "
                            "others and every tangent take the generic kernels\n",
                            nfast, m->nelem_global, (double)mb));
  }
  PetscCall(TslPhaseEnd(TSL_PHASE_SETUP));
  PetscCall(HandJacobian(d));
  PetscCall(TslFramesSetRequests(d, step));
  PetscCall(TslProblemGetSolution(d->prob, &X));
  PetscCall(TslProblemGetOldSolution(d->prob, &Xold));

  PetscCall(TakeControls(d, m, step));
  d->h_prev = 0; /* no extrapolation into a step's first increment */

  dt  = PetscMin(step->dt0, step->period);
  eps = 1e-12 * step->period;
  TslFrameTimesSetUp(&frames, step, 0);
  if (d->rs_resume && s == d->rs_loop.step) {
    /* a continuation (-tsl_restart): the loop goes on from the point's state */
    TslRestartLoop L;
    PetscCall(TslRestartLoad(d, &L));
    t = L.t, dt = L.dt, inc = L.inc, its_prev = L.its_prev, cutbacks = L.cutbacks, *total_time = L.total;
    d->h_prev   = L.h_prev;
    frames.next = L.frames_next;
    /* the problem's time as the point's increment left it (its start plus its length, not the loop's time snapped to
     * the period: the next step holds its ramped values as they were reached) */
    if (d->done_step == s + 1) PetscCall(TslProblemSetTime(d->prob, d->rs_ptime, d->done_dt, d->done_time));
    if (d->rs_fell_back && !d->fell_back) {
      PetscBool switched;
      PetscCall(FallBackToDirect(d, X, s, inc, "the run before the restart point had switched to the direct solver", &switched));
    }
    PetscCall(TslRestartEndStep(d, s, &t, step->period));
  }
  while (t < step->period - eps) {
    SNESConvergedReason reason;
    PetscInt            its, lits;
    PetscReal           dtheta = 0, h, t_end, t_corner;
    PetscBool           accept, last, frame, steady;
    const char         *why;
    char                why_rs[64];

    /* the increment ends at the next output time too (*OUTPUT, NUMBER INTERVAL= / TIME INTERVAL=), as Abaqus/Standard cuts it */
    PetscCall(TslProblemNextAmplitudeCorner(d->prob, t, step->period, &t_corner));
    t_end = PetscMin(t_corner, TslFrameTimesBound(&frames));
    h     = PetscMin(dt, t_end - t);
    last = (PetscBool)(t + h >= step->period - eps);
    PetscCheck(inc < step->max_inc, d->comm, PETSC_ERR_NOT_CONVERGED,
               "step %" PetscInt_FMT ": the maximum number of increments (INC=%" PetscInt_FMT ") was reached at step time %g", s + 1, step->max_inc,
               (double)t);
    attempts++;
    PetscCall(VecCopy(X, Xold));
    d->trial = PETSC_TRUE;
    PetscCall(SetIncrement(d, step, t + h, h, *total_time + h));
    /* the start of the Newton solve: the last increment's change scaled to this one (the dialect's EXTRAPOLATION=LINEAR),
     * X + (h / h_prev)(X - Xprev), then the prescribed values; not in a step's first increment, nor after an
     * increment cut short at an amplitude's corner (the rate may change there) or to less than a tenth of its size */
    if (d->extrapolate && !step->no_extrapolation && d->h_prev > 0) PetscCall(VecAXPBY(X, -h / d->h_prev, 1.0 + h / d->h_prev, d->Xprev));
    PetscCall(TslProblemApplyPrescribed(d->prob, X));
    PetscCall(SolveIncrement(d, X, &reason, &its, &lits));
    if (d->stop) {
      /* told to stop: a restart point of the last converged state, the loop's state before this attempt */
      const TslRestartLoop L = {s, inc, its_prev, cutbacks, t, dt, *total_time, d->h_prev, frames.next};
      PetscCall(VecCopy(Xold, X));
      PetscCall(TslProblemContactRollback(d->prob));
      d->trial = PETSC_FALSE;
      PetscCall(TslRestartWrite(d, &L, TslStopName(d->stop), NULL));
    }
    PetscCheck(!d->stop, d->comm, PETSC_ERR_SIG, "step %" PetscInt_FMT ": %s received at step time %g, in increment %" PetscInt_FMT "; %s", s + 1,
               TslStopName(d->stop), (double)(t + h), inc + 1, SavedState(d, t, saved, sizeof(saved)));
    if (s + 1 == d->debug_diverge_step) reason = SNES_DIVERGED_FUNCTION_DOMAIN;
    accept = (PetscBool)(reason > 0);
    if (accept && !step->steady && (step->deltmx > 0 || step->end_ss_rate > 0)) {
      PetscCall(TslProblemMaxTemperatureChange(d->prob, &dtheta));
      if (step->deltmx > 0 && dtheta > step->deltmx * 1.0001 && !step->direct) accept = PETSC_FALSE;
    }
    if (!accept && reason == SNES_DIVERGED_LINEAR_SOLVE && !d->fell_back) {
      /* the preconditioner, not the increment, failed (quadratic tetrahedra pressed into contact defeat the
       * AMG split; or the one-rank LU of a small model met a zero pivot): the same increment again with
       * MUMPS, which pivots and affords up to -tsl_fallback_max_dofs, for the rest of the job */
      PetscBool switched;
      PetscCall(FallBackToDirect(d, X, s, inc, "the linear solve failed (DIVERGED_LINEAR_SOLVE: the iterative solver, or a zero pivot of the one-rank LU); the increment is repeated", &switched));
      if (switched) {
        PetscCall(VecCopy(Xold, X));
        PetscCall(TslProblemContactRollback(d->prob));
        d->trial = PETSC_FALSE;
        continue;
      }
    }
    if (!accept) {
      const PetscReal cut = d->ctrl_on ? d->ctrl.df : d->cutback, da = d->ctrl_on ? d->ctrl.da : 0.85;
      PetscReal       f = reason > 0 ? PetscMax(cut, da * step->deltmx / dtheta) : cut;
      PetscCall(VecCopy(Xold, X));
      PetscCall(TslProblemContactRollback(d->prob));
      d->trial = PETSC_FALSE;
      PetscCall(TslProblemGetFailureMessage(d->prob, &why));
      if (d->refused) why = d->refused;
      d->refused = NULL;
      if (reason > 0)
        why = "temperature change exceeds DELTMX";
      else if (reason != SNES_DIVERGED_FUNCTION_DOMAIN && reason != SNES_DIVERGED_JACOBIAN_DOMAIN)
        why = SNESConvergedReasons[reason];
      else if (!why[0])
        why = "diverged";
      PetscCall(PetscPrintf(d->comm, "  step %" PetscInt_FMT " increment %" PetscInt_FMT ": %s; cutback dt %g -> %g\n", s + 1, inc + 1, why,
                            (double)h, (double)(h * f)));
      if (reason < 0) PetscCall(ReportChatter(d));
      PetscCheck(!step->direct, d->comm, PETSC_ERR_NOT_CONVERGED,
                 "step %" PetscInt_FMT ": increment %" PetscInt_FMT " did not converge (%s) and DIRECT forbids a cutback", s + 1, inc + 1, why);
      dt = h * f;
      cutbacks++;
      PetscCheck(!d->ctrl_on || cutbacks <= d->ctrl.ia, d->comm, PETSC_ERR_NOT_CONVERGED,
                 "step %" PetscInt_FMT ": increment %" PetscInt_FMT " was cut back %" PetscInt_FMT " times, more than I_A = %" PetscInt_FMT
                 " of *CONTROLS (%s) allows, at step time %g; %s",
                 s + 1, inc + 1, cutbacks, d->ctrl.ia, TslLocString(m, d->ctrl.loc, where, sizeof(where)), (double)t,
                 SavedState(d, t, saved, sizeof(saved)));
      PetscCheck(dt >= step->dtmin * (1 - 1e-12), d->comm, PETSC_ERR_NOT_CONVERGED,
                 "step %" PetscInt_FMT ": the increment fell below the minimum %g at step time %g; %s", s + 1, (double)step->dtmin, (double)t,
                 SavedState(d, t, saved, sizeof(saved)));
      continue;
    }
    t = last ? step->period : t + h;
    *total_time += h;
    inc++;
    if (d->extrapolate) {
      if (!d->Xprev) PetscCall(VecDuplicate(X, &d->Xprev));
      PetscCall(VecCopy(Xold, d->Xprev));
      /* an output time (*OUTPUT, NUMBER INTERVAL= / TIME INTERVAL=) is no corner of the loading: the rate goes on, and
       * without the extrapolation the increment after each frame would start from the last state with only the
       * prescribed values moved (a disc turned by its hub, a pad on it: the first solve's nodes slide past their
       * faces on the faces' tangents, the re-pairing finds them all open and the pad unsupported: a cutback at
       * every frame; tests/nlgeom spin_disc_implicit) */
      const PetscBool corner = (PetscBool)(h < dt * (1 - 1e-12) && t_corner <= t_end + eps);
      d->h_prev              = corner || h < 0.1 * dt ? 0 : h;
    }
    d->trial = PETSC_FALSE;
    PetscCall(TslPhaseBegin(TSL_PHASE_OUTPUT));
    PetscCall(Accept(d, s, inc, t, h, *total_time, its, lits));
    if (!d->fell_back && its > 0 && lits > d->fallback_its * its) {
      /* converged, but the preconditioner barely helps: a direct solve is cheaper from here on */
      PetscBool switched;
      char      why[128];
      PetscCall(PetscSNPrintf(why, sizeof(why), "%" PetscInt_FMT " linear iterations per Newton iteration (-tsl_fallback_its %" PetscInt_FMT ")",
                              lits / its, d->fallback_its));
      PetscCall(FallBackToDirect(d, X, s, inc - 1, why, &switched));
    }
    frame = frames.dt > 0 ? TslFrameTimesReached(&frames, t) : (PetscBool)(inc % d->frequency == 0); /* intervals replace FREQUENCY= */
    /* END=SS: the steady state is reached when no free temperature changed faster than the deck's rate over the
     * increment; the step ends there, its last frame written */
    steady = (PetscBool)(!last && step->end_ss_rate > 0 && dtheta < step->end_ss_rate * h);
    if (last || frame || steady) PetscCall(TslFramesWrite(d, s + 1, inc, *total_time));
    PetscCall(TslPhaseEnd(TSL_PHASE_OUTPUT));
    if (!step->direct) {
      /* the controller grows from the increment it asked for, not from one cut short at a corner. The deck's
       * *CONTROLS: D_D after two consecutive increments of at most I_G iterations, D_B after one of more than I_L
       * (the dialect's rule); else thermoslide's: -tsl_growth after one of at most -tsl_easy_its */
      PetscReal f;
      if (d->ctrl_on)
        f = its > d->ctrl.il ? d->ctrl.db : its <= d->ctrl.ig && its_prev <= d->ctrl.ig ? d->ctrl.dd : 1.0;
      else
        f = its <= d->easy_its ? d->growth : 1.0;
      if (!step->steady && step->deltmx > 0 && dtheta > 0) f = PetscMin(f, (d->ctrl_on ? d->ctrl.da : 0.85) * step->deltmx / dtheta);
      dt = PetscMin(step->dtmax, dt * PetscMax(f, d->ctrl_on ? PetscMin(d->ctrl.df, d->ctrl.db) : d->cutback));
    }
    its_prev = its;
    cutbacks = 0;
    if (TslRestartDue(step, inc, t - h, t, (PetscBool)(last || steady), why_rs, sizeof(why_rs))) {
      /* *RESTART, WRITE (END=SS: the loop's time set to the period, so that the continuation ends the step there too) */
      const TslRestartLoop L = {s, inc, its_prev, 0, steady ? step->period : t, dt, *total_time, d->h_prev, frames.next};
      PetscCall(TslRestartWrite(d, &L, why_rs, NULL));
    }
    if (steady) {
      PetscCall(PetscPrintf(d->comm,
                            "  step %" PetscInt_FMT ": steady state at step time %g (largest temperature rate %g below END=SS's %g); the step ends\n",
                            s + 1, (double)t, (double)(dtheta / h), (double)step->end_ss_rate));
      break;
    }
  }
  PetscCall(TslPhaseBegin(TSL_PHASE_OUTPUT));
  PetscCall(TslFramesPrintTables(d, step));
  PetscCall(TslPhaseEnd(TSL_PHASE_OUTPUT));
  PetscCall(PetscInfo(NULL, "step %" PetscInt_FMT ": %" PetscInt_FMT " increments in %" PetscInt_FMT " attempts\n", s + 1, inc, attempts));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* After a failure (the same on all ranks): back to the last converged state, and its frame written if the
 * output frequency skipped it. */
static PetscErrorCode SaveLastConverged(Driver *d)
{
  TslHeatBalance hb;
  Vec            X, Xold;

  PetscFunctionBeginUser;
  if (d->in_explicit) PetscFunctionReturn(PETSC_SUCCESS); /* X is past the last history row's state: the frames written stay */
  if (d->trial) {
    PetscCall(TslProblemGetSolution(d->prob, &X));
    PetscCall(TslProblemGetOldSolution(d->prob, &Xold));
    PetscCall(VecCopy(Xold, X));
    PetscCall(TslProblemContactRollback(d->prob));
    d->trial = PETSC_FALSE;
  }
  if (d->done_inc > 0 && (d->frame_step != d->done_step || d->frame_inc != d->done_inc)) {
    const TslModel *m;
    PetscCall(TslProblemGetModel(d->prob, &m));
    PetscCall(SetIncrement(d, &m->steps[d->done_step - 1], d->done_step_time, d->done_dt, d->done_time));
    PetscCall(TslProblemHeatBalance(d->prob, &hb)); /* contact outputs at that state */
    PetscCall(TslFramesWrite(d, d->done_step, d->done_inc, d->done_time));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Where the results of a run go. A complete run replaces earlier results. A run that stopped keeps what
 * it converged: under the usual names if there were no earlier results, else beside them as
 * <job>.failed.{h5,xmf,csv} so that a good earlier result is never lost. A run that converged nothing
 * leaves everything as it was. */
static PetscErrorCode Finish(Driver *d, PetscErrorCode ierr, const char *dir, const char *jobname)
{
  PetscBool earlier = PETSC_FALSE;
  char      path[PETSC_MAX_PATH_LEN];

  PetscFunctionBeginUser;
  if (!ierr) {
    PetscCall(TslOutputFinalize(d->out, NULL));
    PetscCall(TslHistoryFinalize(d->hist, NULL));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s.h5", dir, jobname));
  PetscCall(PetscTestFile(path, 'r', &earlier));
  PetscCallMPI(MPI_Bcast(&earlier, 1, MPIU_BOOL, 0, d->comm));
  if (d->frame_inc == 0) {
    PetscCall(PetscPrintf(d->comm, "no increment converged: nothing was written%s%s\n", earlier ? "; the earlier results stay in " : "",
                          earlier ? path : ""));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(TslOutputFinalize(d->out, earlier ? "failed" : NULL));
  PetscCall(TslHistoryFinalize(d->hist, earlier ? "failed" : NULL));
  PetscCall(PetscPrintf(d->comm, "results up to step %" PetscInt_FMT " increment %" PetscInt_FMT " are saved in %s/%s%s.h5%s%s\n", d->frame_step,
                        d->frame_inc, dir, jobname, earlier ? ".failed" : "", earlier ? "; the earlier results stay in " : "", earlier ? path : ""));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The procedures, one row each: its options and solvers (read for every job, so that the unused-option check sees
 * them all), one step of it, and whether its steps assemble no matrix. A step takes the row of its procedure. */
typedef struct {
  PetscErrorCode (*setup)(Driver *);
  PetscErrorCode (*run_step)(Driver *, PetscInt, PetscReal *);
  PetscBool matrix_free;
} Procedure;

static const Procedure Procedures[] = {
    {SetUpSolver, RunStep, PETSC_FALSE},                         /* implicit: *STATIC, *COUPLED TEMPERATURE-DISPLACEMENT */
    {TslExplicitSetFromOptions, TslExplicitRunStep, PETSC_TRUE}, /* *DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT */
};

static const Procedure *StepProcedure(const TslStep *step)
{
  return &Procedures[step->explicit_dynamics ? 1 : 0];
}

PetscErrorCode TslAnalysisRun(TslProblem prob, const char *dir, const char *jobname)
{
  Driver          d;
  const TslModel *m;
  PetscReal       total = 0;
  PetscErrorCode  ierr  = PETSC_SUCCESS;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(&d, sizeof(d)));
  d.prob          = prob;
  d.explicit_last = -1;
  PetscCall(TslProblemGetModel(prob, &m));
  {
    Vec X;
    PetscCall(TslProblemGetSolution(prob, &X));
    PetscCall(PetscObjectGetComm((PetscObject)X, &d.comm));
  }
  for (size_t k = 0; k < sizeof(Procedures) / sizeof(Procedures[0]); k++) PetscCall(Procedures[k].setup(&d));
  PetscCall(TslOptionsCheckUnused(d.comm, PETSC_TRUE)); /* every -tsl_ option has been read by now */
  PetscCall(TslProblemTemperatureFilesCheck(prob)); /* *TEMPERATURE, FILE=: the files against the model, before any result is written */
  PetscCall(TslRestartSetUp(&d, dir, jobname)); /* -tsl_restart: the point to continue from */
  PetscCall(TslFramesSetUp(&d, dir, jobname));
  ierr = TslRestartCopyOutput(&d); /* ... and the frames and history rows of the run that wrote it */
  /* every failure inside a step is decided by all ranks together (sys.h), so all ranks stop here alike */
  if (m->post_output) ierr = TslRestartPostOutput(&d); /* a POST OUTPUT deck: frames from the old job's points, no step run */
  for (PetscInt s = 0; s < m->nstep && !ierr && !m->post_output; s++) {
    const Procedure *pr = StepProcedure(&m->steps[s]);
    PetscCall(TslProblemSetMatrixFree(prob, pr->matrix_free));
    ierr = TslRestartStepStart(&d, s, &total);
    if (!ierr && d.rs_resume && s < d.rs_loop.step) {
      /* a continuation replays the steps before the point's only as far as their loads and boundary conditions */
      ierr = TslProblemSetStep(prob, s);
      continue;
    }
    if (!ierr) ierr = pr->run_step(&d, s, &total);
    if (!ierr) PetscCall(TslProblemPlasticTemperatureCheck(prob, s));
  }
  if (d.jac_reuses)
    PetscCall(PetscPrintf(d.comm, "thermoslide: %" PetscInt_FMT " of %" PetscInt_FMT " Jacobians equal to the one before them: the preconditioner built on that one was kept\n",
                          d.jac_reuses, d.jac_count));
  if (ierr && !d.in_output) {
    PetscErrorCode e = SaveLastConverged(&d);
    if (e) d.in_output = PETSC_TRUE; /* could not even write the last state: keep nothing of this run */
  }
  if (!d.in_output) {
    PetscCall(TslPhaseBegin(TSL_PHASE_OUTPUT));
    PetscCall(Finish(&d, ierr, dir, jobname));
    PetscCall(TslPhaseEnd(TSL_PHASE_OUTPUT));
  }
  PetscCall(TslRestartFinish(&d, (PetscBool)!ierr));
  PetscCall(TslOutputDestroy(&d.out));
  PetscCall(TslHistoryDestroy(&d.hist));
  PetscCall(SNESDestroy(&d.snes));
  PetscCall(VecDestroy(&d.velocity));
  PetscCall(VecDestroy(&d.mass));
  PetscCall(VecDestroy(&d.F));
  PetscCall(VecDestroy(&d.diag));
  PetscCall(VecDestroy(&d.work));
  PetscCall(VecDestroy(&d.Xprev));
  for (PetscInt i = 0; i < d.ndefault; i++) PetscCall(PetscOptionsClearValue(NULL, d.defaults[i]));
  PetscFunctionReturn(ierr);
}
