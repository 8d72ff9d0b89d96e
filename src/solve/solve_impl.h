/* Private to src/solve/: the step driver's state, shared by the implicit procedures (driver.c), the explicit one
 * (explicit.c) and the output both write, the same frames and the same history (frames.c). driver.c calls
 * explicit.c and frames.c; explicit.c calls frames.c alone. */
#pragma once
#include <thermoslide/solve.h>
#include <thermoslide/output.h>
#include <thermoslide/sys.h>
#include <thermoslide/material.h>
#include <petscsnes.h>
#include <stdint.h>

/* History columns: the implicit increment's figures, then the energies of explicit steps (zero in implicit
 * steps; docs/explicit.md): kinetic ALLKE, internal ALLIE (work of the element forces), external work ALLWK
 * (loads and reactions at prescribed dofs), frictional dissipation ALLFD, energy absorbed by contact ALLCW
 * (ALLFD and the penalty's elastic energy), mass-scaling work ALLMW and the balance
 * ETOTAL = ALLKE + ALLIE + ALLVD + ALLCW - ALLWK - ALLMW. */
#define MAX_DEFAULTS 32
#define MAX_FIELDS   32

extern const char *const TslHistoryColumns[];
#define NHISTORY 28
/* The place of each column in a row (TslHistoryColumns names them in this order). */
enum {
  HIST_STEP = 0,
  HIST_INCREMENT,
  HIST_TIME,
  HIST_STEP_TIME,
  HIST_DT,
  HIST_NEWTON_ITS,
  HIST_HEAT_IN,
  HIST_FILM_OUT,
  HIST_RADIATION_OUT,
  HIST_REACTION_HEAT,
  HIST_STORED_RATE,
  HIST_INTERFACE_HEAT,
  HIST_DISSIPATION_RATE,
  HIST_DISSIPATION_TOTAL,
  HIST_FRICTION_HEAT_TOTAL,
  HIST_BALANCE,
  HIST_STRAIN_ENERGY,
  HIST_HOURGLASS_ENERGY,
  HIST_PLASTIC_HEAT,        /* *INELASTIC HEAT FRACTION x the plastic work rate */
  HIST_PLASTIC_DISSIPATION, /* ALLPD: the plastic work so far */
  HIST_ENERGY /* the first energy column of explicit steps: ALLKE, ALLIE, ALLWK, ALLFD, ALLCW, ALLMW, ALLVD, ETOTAL */
};

/* The increment loop's state at a restart point (RunStep's variables at the top of its loop; restart.c). */
typedef struct {
  PetscInt  step, inc, its_prev, cutbacks; /* step 0-based; increments done in it */
  PetscReal t, dt, total, h_prev, frames_next;
} TslRestartLoop;

typedef struct {
  TslProblem prob;
  MPI_Comm   comm;
  SNES       snes;
  Vec        F;
  TslOutput  out;
  TslHistory hist;
  PetscReal  rtol, atol_rel, cutback, growth;
  PetscInt   easy_its;
  PetscInt   debug_diverge_step;   /* test hook: every increment of this step is declared diverged */
  int        stop;                 /* the signal the job was asked to stop by (src/sys/stop.c), agreed; 0: none */
  PetscReal  scale_u, scale_theta; /* largest initial residuals seen in the job */
  PetscReal  r0_u, r0_theta;       /* initial residuals of the current solve */
  PetscReal  forcing_max;          /* -tsl_linear_forcing: loosest linear tolerance of a Newton iteration after the first (0: -ksp_rtol always) */
  PetscReal  ksp_rtol;             /* the linear tolerance of the first Newton iteration (-ksp_rtol) */
  PetscBool  block_solves;         /* -tsl_block_solves: a block-triangular operator's blocks solved by CG (split.c) */
  PetscReal  jacobi_scale;         /* -tsl_amg_jacobi_scale: per-level weights of BoomerAMG's Jacobi smoothing (split.c) */
  PetscBool  amg_cycle;            /* -tsl_amg_cycle: BoomerAMG's V-cycle applied by thermoslide (amg.c) */
  PetscBool  chatter_told;         /* the cause of contact that does not settle was explained (ReportChatter) */
  PetscBool  implicit_records;     /* -tsl_implicit_records: residuals from the element force records */
  PetscBool  records_done;         /* ... built (or declined) at the first implicit step */
  PetscReal  fnorm_prev;           /* residual norm at the previous Newton iteration of the current solve */
  PetscReal  nu_prev, nt_prev;     /* ... and each field's */
  PetscReal  divtol;               /* -snes_divergence_tolerance, applied to each field (ConvergenceTest) */
  PetscBool  accepted;             /* the per-field test ended the last Newton solve (no other test may) */
  const char *refused;             /* why the last solve's convergence was refused, for the cutback line */
  Vec        diag;                 /* the Jacobian's diagonal: each field's round-off scale (ConvergenceTest) */
  PetscBool  field_on[MAX_FIELDS]; /* rows of the problem's field table written in frames */
  PetscInt   frequency;
  PetscInt   frame_step, frame_inc; /* last frame written */
  PetscInt   rotation_warned;       /* the step (1-based) whose large small-strain rotation was reported (frames.c) */
  PetscInt   done_step, done_inc;   /* last converged increment */
  PetscReal  dissipated, absorbed;  /* frictional dissipation and the heat made of it, since the start */
  PetscReal  plastic_dissipated;    /* the plastic work since the start (ALLPD) */
  PetscBool  radiates;              /* some step has *RADIATE / *SRADIATE: the increment lines show the heat radiated */
  PetscInt   max_contact_its;
  PetscReal  sync_interval; /* -tsl_output_sync: seconds between syncs of the result files */
  PetscInt   direct_max;    /* -tsl_direct_max_dofs: direct solver by default up to this size */
  PetscInt   fallback_max;  /* -tsl_fallback_max_dofs: a failed iterative solve switches to MUMPS up to this size */
  PetscInt   fallback_its;  /* -tsl_fallback_its: ... or an increment needs more linear iterations per Newton iteration */
  PetscBool  fell_back;     /* the switch happened (once per job) */
  PetscBool  reuse_pc;      /* -tsl_reuse_unchanged_jacobian: a Jacobian equal to the last one keeps its preconditioner */
  PetscBool  jac_known;     /* jac_hash / jac_nzstate describe the last Jacobian assembled (FormJacobian) */
  PetscBool  jac_reused;    /* the last Jacobian was the one before it (the preconditioner was kept) */
  PetscInt   jac_reuses, jac_count; /* ... how many times in the job, of how many Jacobians */
  uint64_t   jac_hash;
  PetscObjectState jac_nzstate;
  PetscReal  done_time, done_step_time, done_dt;
  PetscBool  trial;     /* X holds an unconverged trial state (Xold the last converged one) */
  PetscBool  in_output; /* inside a frame: a failure there leaves the output unusable */
  PetscBool  in_explicit; /* inside an explicit step's loop: the state has moved past its last history row, so a failure
                           keeps the frames written (SaveLastConverged writes none) */
  PetscInt   ndefault;  /* solver options entered as defaults (SetDefaultOption) */
  char       defaults[MAX_DEFAULTS][64];
  /* explicit steps: the velocity and the energies carry over from one explicit step to the next (an
   * implicit step between them is static: the velocity restarts at zero) */
  Vec       velocity;
  Vec       mass;          /* the lumped mass the last explicit step ended with (ALLMW of the next one's scaling) */
  PetscInt  explicit_last; /* last explicit step run (0-based), -1 none */
  PetscReal energy[7];     /* ALLKE ALLIE ALLWK ALLFD ALLCW ALLMW ALLVD since the start of the job */
  PetscReal explicit_safety;   /* -tsl_explicit_safety */
  PetscInt  explicit_progress; /* -tsl_explicit_progress */
  PetscInt  explicit_history;  /* -tsl_explicit_history */
  PetscInt  explicit_search;   /* -tsl_explicit_contact_search */
  PetscInt  explicit_kin_passes; /* -tsl_explicit_kinematic_passes */
  PetscReal explicit_kin_tol;    /* -tsl_explicit_kinematic_tol */
  PetscReal explicit_kin_gap;    /* -tsl_explicit_kinematic_gap_tol (0: the pressure criterion alone) */
  PetscBool explicit_records;    /* -tsl_explicit_records */
  /* the deck's *CONTROLS, PARAMETERS=TIME INCREMENTATION in force (ctrl_on), with the surface-to-surface raise of
   * I_G and I_L applied; snes_max_it: the SNES's own limit, restored when the controls are reset */
  TslIncrementControls ctrl;
  PetscBool            ctrl_on;
  PetscInt             snes_max_it;
  /* the deck's *CONTROLS, PARAMETERS=FIELD in force per field (displacement, temperature; DialectFieldTest), the
   * instantaneous flux of the last residual evaluation, its sum over the step's converged increments and their
   * count, and the mean of the steps before */
  TslFieldControls fctrl[2];
  PetscReal        q_last[2], q_sum[2], q_before[2];
  PetscInt         q_n;
  Vec              work; /* X - Xold: each field's change over the increment */
  PetscBool        extrapolate; /* -tsl_extrapolate */
  Vec              Xprev;       /* the converged state before Xold */
  PetscReal        h_prev;      /* the last accepted increment of the step (0: none yet) */
  /* restart points (restart.c): where they go, each implicit step's solution at its start and its total time and
   * the step time the step before ended at (what TslProblemSetStep reads), the points written and their cost;
   * a continuation (-tsl_restart): the point, its loop state, and the earlier run's output files */
  char           rs_dir[PETSC_MAX_PATH_LEN], rs_job[256];
  Vec           *rs_xstart;
  PetscReal     *rs_tstart;
  PetscInt       rs_count;
  double         rs_seconds, rs_bytes;
  char           rs_last[PETSC_MAX_PATH_LEN]; /* the last point written (OVERLAY removes it when the next is in place) */
  PetscBool      rs_resume;
  PetscBool      rs_oldjob, rs_end_step; /* continuing an old job's point (*RESTART, READ); END STEP: its step ends there */
  char           rs_point[PETSC_MAX_PATH_LEN], rs_src_h5[PETSC_MAX_PATH_LEN], rs_src_csv[PETSC_MAX_PATH_LEN];
  TslRestartLoop rs_loop;
  PetscReal      rs_ptime;     /* the problem's step time at the point (TslProblemGetStepTime) */
  PetscReal      rs_sums[24];  /* the driver's sums at the point (restart.c, RestoreSums) */
  PetscInt       rs_nframe, rs_nrow, rs_fell_back, rs_nextra; /* the point's counts */
  /* a point written on another rank count (rs_nranks) is read in natural terms: its state's records (rs_nblob), its
   * vectors through rs_map, from their file split (rs_fvec's layout) to this run's (restart.c, NaturalMap) */
  PetscBool      rs_portable;
  PetscInt       rs_nblob, rs_nranks, rs_xelem;
  VecScatter     rs_map;
  Vec            rs_fvec;
  uint64_t       rs_run_id;
} Driver;

/* Restart (restart.c; docs/running.md "Restart"). SetUp: the -tsl_restart option, and the point to continue from
 * (before TslFramesSetUp, which copies its run's frames and history rows: TslRestartCopyOutput). StepStart: at the
 * start of implicit step s, X is kept (a run that writes points) or set from the point (a continuation, s up to
 * the point's step). Write: a point of the loop state (the problem's committed state, X, Xprev); why names it in
 * the log. Load: the point's X, Xprev and problem state, the driver's sums; *loop the loop's variables. */
PetscErrorCode TslRestartSetUp(Driver *d, const char *dir, const char *jobname);
PetscErrorCode TslRestartCopyOutput(Driver *d);
PetscErrorCode TslRestartStepStart(Driver *d, PetscInt s, PetscReal *total_time);
/* Step s's start from the point d->rs_point: its solution into X, the problem's time at the step's start. */
PetscErrorCode TslRestartStepStartLoad(Driver *d, PetscInt s, Vec X);
/* *POST OUTPUT: a frame of each point the deck names (or every point of the old job), recovered from its state with
 * its step's output requests, in place of the steps. */
PetscErrorCode TslRestartPostOutput(Driver *d);
/* A procedure's own state in a point beyond the loop's (explicit steps: velocities, masses, forces, the element
 * increments; explicit.c): vectors of X's layout, and reals of each rank's own (NULL, 0 when none) */
#define TSL_RESTART_MAXVEC 8
typedef struct {
  PetscInt   nvec;
  Vec        vec[TSL_RESTART_MAXVEC];
  PetscInt   nreal;
  PetscReal *real;
  /* the reals' parts, for a point read on another rank count (restart.c, ExtraBlobs): real[0..nglobal) the same on
   * every rank, then nearr arrays of one real per local element, then from carried_off the elements' carried reals,
   * element e's at carried_off + lane[e] (lane NULL or lane[e] < 0: none) */
  PetscInt        nglobal, nearr, carried_off;
  const PetscInt *lane;
} TslRestartExtra;
/* Whether a point is due after increment inc (from step time t_old to t_new; last: the step's last) under the step's
 * *RESTART, WRITE, with the reason for the log in why. */
PetscBool      TslRestartDue(const TslStep *step, PetscInt inc, PetscReal t_old, PetscReal t_new, PetscBool last, char why[], size_t len);
PetscErrorCode TslRestartWrite(Driver *d, const TslRestartLoop *loop, const char *why, const TslRestartExtra *extra);
PetscErrorCode TslRestartLoad(Driver *d, TslRestartLoop *loop);
/* The extra state of the point being continued from into extra's vectors and reals (their sizes this run's: an error
 * naming the point if its differ). */
PetscErrorCode TslRestartLoadExtra(Driver *d, TslRestartExtra *extra);
/* After the point's state is loaded into step s at step time *t: *RESTART, READ, END STEP ends the step there (*t set
 * to the period; the loads of the next step start from their values at the point). */
PetscErrorCode TslRestartEndStep(Driver *d, PetscInt s, PetscReal *t, PetscReal period);
PetscErrorCode TslRestartFinish(Driver *d, PetscBool completed);


/* The output times of a step given by *OUTPUT, NUMBER INTERVAL=n (every period/n) or TIME INTERVAL=dt (every dt,
 * and the step's end): increments end on them and frames are written there, in implicit and explicit steps
 * alike. The times are accumulated (t += dt), as the explicit procedure always did, so its increments keep their
 * bits. dt = 0: the step has no output times (an implicit step without intervals: frames follow FREQUENCY=). */
typedef struct {
  PetscReal dt, next, period, eps;
} TslFrameTimes;
/* default_number: the intervals when the step gives neither (explicit: 20, as in the dialect; implicit: 0) */
void TslFrameTimesSetUp(TslFrameTimes *ft, const TslStep *step, PetscInt default_number);
/* The next output time, or the step's end (the bound that TslProblemNextAmplitudeCorner cuts further). */
PetscReal TslFrameTimesBound(const TslFrameTimes *ft);
/* Whether step time t reached an output time, moving on to the next one after t when it did. */
PetscBool TslFrameTimesReached(TslFrameTimes *ft, PetscReal t);

/* The procedures' output (frames.c), used by the implicit (driver.c) and the explicit (explicit.c) procedure:
 * the result files and the history of the job, a step's field requests (they replace the previous step's when
 * present), a frame of the fields requested, and the step's *NODE PRINT / *EL PRINT tables. */
PetscErrorCode TslFramesSetUp(Driver *d, const char *dir, const char *jobname);
PetscErrorCode TslFramesSetRequests(Driver *d, const TslStep *step);
PetscErrorCode TslFramesWrite(Driver *d, PetscInt step, PetscInt inc, PetscReal time);
PetscErrorCode TslFramesPrintTables(Driver *d, const TslStep *step);
/* The explicit procedure's run-time options (read with the others, before the unused-option check). */
PetscErrorCode TslExplicitSetFromOptions(Driver *d);
/* One explicit step (explicit.c); *total_time advances by the step period. */
PetscErrorCode TslExplicitRunStep(Driver *d, PetscInt s, PetscReal *total_time);

/* thermoslide's default preconditioner (split.c): the temperature-displacement block Gauss-Seidel with the
 * displacement block held once, a PC type of its own (PCTSLSPLIT, registered by TslSplitRegister: -pc_type
 * tslsplit selects it, -ksp_view names it, -pc_fieldsplit_type multiplicative|additive is its option) */
#define PCTSLSPLIT "tslsplit"
PetscErrorCode TslSplitRegister(void);
/* pc becomes a PCTSLSPLIT over the temperature and displacement index sets (referenced) */
PetscErrorCode TslSplitSetUp(PC pc, IS is_theta, IS is_u);
PetscErrorCode TslSplitOptionType(const char *prefix, PetscBool *additive);
PetscErrorCode TslSplitSetAmg(PC pc, PetscReal jacobi_scale, PetscBool cycle);
/* BoomerAMG's plain V-cycle applied by thermoslide (amg.c), set after pc's set-up; *used: whether it applies */
PetscErrorCode TslAmgCycleSet(PC pc, PetscBool on, PetscBool *used);
PetscErrorCode TslSplitReset(PC pc);
PetscErrorCode TslSplitIs(PC pc, PetscBool *is);
PetscErrorCode TslSplitSetTriangular(PC pc, KSP outer, PetscBool allowed);
PetscErrorCode TslSplitTakeExtraCycles(PC pc, PetscInt *extra);
