/* Private layout of TslProblem, shared by the files of src/physics/. */
#pragma once
#include <thermoslide/problem.h>
#include <thermoslide/contact.h>
#include <thermoslide/sys.h>
#include <thermoslide/output.h>
#include <thermoslide/material.h>
#include <string.h>

/* One contact pair on this rank: the law and the part of the main surface the rank holds (the faces its
 * secondary nodes can reach and their neighbours, all their nodes local: see TslContactPair in model.h;
 * active is false when it owns no secondary node of the pair). */
typedef struct {
  TslContactLaw      law;
  PetscBool          active;
  PetscInt           nmain, nper; /* main faces, nodes per face */
  TslContactFaceKind face;        /* family of the main faces */
  PetscInt          *main_lnode;  /* [nper*nmain] local nodes of each face in face order, main body on the left */
  PetscInt          *prev, *next; /* [nmain] neighbouring faces, -1 at the ends, -2 where the neighbour is not held here */
  PetscInt          *ring;        /* [nmain] 1 for a face held only as a neighbour: never paired */
  PetscReal          hull;        /* how far a face's box moves per unit of node motion (TslContactFace3HullBound) */
  PetscInt           nu;          /* unknowns per node of the contact kernels (3, or 4 with twist) */
  PetscInt           slot[TSL_CONTACT_MAX_NODE_DOF]; /* slots of u_x, u_y, theta (and phi, twist) among a node's unknowns */
  PetscReal          smooth, thickness, search_radius;
  TslKinematics      kin;
  /* 3D (dim 3): the family of each face (kind[nmain], TslContactFace3Find; faces with fewer than nper nodes
   * padded with -1 in main_lnode) and the unit nodal normals of the main surface for smoothing,
   * nnormal[3*l] for local node l, averaged over the faces around the node at the last converged state */
  PetscInt   dim;
  PetscInt  *kind;
  PetscReal *nnormal;
  /* MECHANICAL CONSTRAINT=KINEMATIC in the running explicit step (TslProblemContactSetExplicit): the pair is
   * evaluated only by the kinematic corrector (src/physics/contact_kinematic.c), each node with its own
   * penalty k_kin / A */
  PetscBool kinematic;
  /* plain *FRICTION (PENALTY friction without a stick slope): the elastic slip the automatic stick allows in implicit
   * steps (SLIP TOLERANCE x the facet size, or ELASTIC SLIP=; 0 for any other law). Explicit steps stick with the
   * normal penalty eps_n instead, as Abaqus/Explicit (TslProblemContactSetExplicit; docs/explicit.md, "Friction
   * in explicit steps"); law.elastic_slip and law.eps_t hold the running step's choice. */
  PetscReal elastic_slip_implicit;
} TslContactSurface;

/* A secondary node owned by this rank: its pairing and history (current and committed). */
typedef struct {
  PetscInt          pair, lnode;
  PetscReal         length; /* tributary length on the secondary surface */
  PetscInt          seg, seg_c;
  TslContactState hist, hist_c;
  PetscReal         cslip, cslip_c; /* accumulated slip */
  TslContactOutput  out;            /* last evaluation */
  PetscBool         fresh;          /* evaluated since the last commit (a kinematic pair commits only such nodes) */
  PetscReal         k_kin;          /* kinematic pairs: the stiffness that closes the node's gap in one increment */
  PetscBool         settled;        /* ... and, after further corrector passes, the pressure offset p_kin that gives the node */
  PetscReal         p_kin;          /*     the passes' pressure at the predicted state (friction and heat follow it) */
} TslContactNode;

/* Storage of the neighbours' nodes that a TslContactInput points to (smoothing). */
typedef struct {
  PetscReal xp[2 * TSL_CONTACT_MAX_FACE_NODES], up[TSL_CONTACT_MAX_NODE_DOF * TSL_CONTACT_MAX_FACE_NODES];
  PetscReal xn[2 * TSL_CONTACT_MAX_FACE_NODES], un[TSL_CONTACT_MAX_NODE_DOF * TSL_CONTACT_MAX_FACE_NODES];
} TslContactNeighbourData;

/* Surface-to-surface contact (src/physics/contact_s2s.c): the secondary faces held here and their points. */
typedef struct _n_TslContactS2S *TslContactS2S;

/* Amplitude codes besides an index into model->amplitudes[]. */
#define TSL_AMP_DEFAULT (-1) /* the step's default: RAMP or STEP */
#define TSL_AMP_HOLD    (-2) /* carried over from an earlier step: constant */

/* A load value (prescribed value, load magnitude) that follows the step's loading history: v(t) = amplitude or ramp from v0 to v1.
 * A velocity boundary condition (velocity): v(t) is the dof's velocity and the value is u0 + its integral from total time t0. */
typedef struct {
  PetscBool active;
  PetscReal v0, v1;
  PetscInt  amp;
  PetscBool velocity;
  PetscReal u0, t0;
  PetscBool held; /* a *STATIC step's hold of a temperature at its start value (ends with the step) */
  PetscBool file; /* follows the step's *TEMPERATURE, FILE= frames in time (tfile.c; a later definition in the step ends it) */
} TslLoadValue;

/* A distributed (face or body) load on one local element. */
typedef struct {
  PetscInt        elem, face; /* local element, face 1..6 (0: body) */
  TslFaceLoadKind kind;
  TslLoadValue    value;    /* pressure, flux, film coefficient, or radiation coefficient sigma eps */
  TslLoadValue    sink;     /* film sink or radiation ambient temperature */
  PetscInt        film_amp; /* amplitude scaling the film or radiation coefficient (FILM / RADIATION AMPLITUDE), or -1 */
  PetscInt        seq;      /* order of definition (later replaces earlier) */
  PetscReal       axis[6];  /* body forces (GRAV, CENTRIF): the load's direction, point and axis (TslLoad.axis) */
} TslFaceRecord;

struct _p_TslProblem {
  MPI_Comm  comm;
  TslModel *m;
  PetscInt  dim, nn, nown; /* local nodes, owned nodes */
  /* dof layout, from the element rows: ndof unknowns per node, the dialect's number of each
   * (node_dof[], theta last; 0 for a slot the kinematics does not use), nu of them displacements; an
   * extra node of the rows (the generalized plane strain reference node) has extra_dof[] instead.
   * Unused slots are pinned at zero (pinned[], a constraint row of their own). */
  PetscInt ndof, nu, node_dof[TSL_MAX_NODE_DOF], extra_dof[TSL_MAX_NODE_DOF];
  char    *extra;  /* [nn] 1 for an extra (reference) node */
  char    *pinned; /* [nn*ndof] */
  PetscInt rstart; /* first owned global dof */

  Vec                    X, Xold, Xl, Fl; /* Xl, Fl: ghosted work vectors */
  Vec                    Rraw;            /* unconstrained residual of the last post-processed state */
  Mat                    J;
  ISLocalToGlobalMapping l2g, l2g_node; /* dof blocks (bs = ndof) and nodes (bs = 1) */
  IS                     is_u, is_theta;

  PetscInt          *elem_lnode;   /* local node of each element node (model elem_ptr layout) */
  TslElementSection *esec;         /* [nelem] material and thickness of each element */
  PetscReal         *theta_init;   /* [nn] */
  PetscReal          row_scale[3]; /* constraint-row scale for translations, temperature, twist (assemble.c, RowGroup) */

  /* *TEMPERATURE, FILE= of the current step (tfile.c): the file, its window of frames (positions in the file's frame
   * list, in time order), the file's total time at step time 0, the temperatures at the step's start Ts [nn], the two
   * frames whose values are in Ta, Tb [nn] (each local node's row node_nat), and T [nn] the values last asked for */
  struct {
    TslResults       r;
    const TslResultsFrame *frames;
    PetscInt         nwin, *win, a, b;
    PetscReal        t0, *Ts, *Ta, *Tb, *T;
  } tfile;

  /* Mises plasticity (kernels.c, MechanicsPlastic): the committed state of the plastic elements' points (TslMaterialPlasticState
   * reals a point; pstate_off[e] the element's first, -1 for an elastic element; NULL arrays: no plastic element here),
   * pstate_new the state the heat balance's pass reaches at the converged solution (pstate_write), made the committed
   * one by TslProblemCommitState */
  PetscReal *pstate, *pstate_new;
  PetscInt  *pstate_off, npstate; /* npstate: the reals of each block */
  PetscBool  pstate_write;

  /* step state */
  PetscInt      step;
  PetscBool     steady;
  TslAmpDefault amp_default;
  PetscReal     period, t, dt, ttot;
  PetscBool     matrix_free;     /* explicit steps: no Jacobian, so no pattern is built (TslProblemSetMatrixFree) */
  PetscReal     shift;           /* capacity rate factor chosen by the solver: 1/dt (backward Euler) or 0 (steady) */
  PetscBool     nlgeom;          /* finite strain in the current step (*STEP, NLGEOM; implicit steps: TslProblemSetStep) */
  PetscReal     inelastic_rate;  /* the plastic work's heat rate per work: shift in implicit steps, 1 / (the move's increment) in explicit ones */
  PetscReal     step_start_ttot; /* total time at the start of the step */
  PetscBool    *amp_active;      /* [namplitude] followed by some load of the step (any rank) */
  PetscBool    *plastic_warned;  /* [nmaterial] TslProblemPlasticTemperatureCheck has warned of the material */

  TslLoadValue  *bc;    /* [nn*ndof] prescribed values (owned and ghost dofs) */
  TslLoadValue  *nload; /* [nn*ndof] nodal loads (CLOAD, CFLUX), owned dofs only */
  PetscInt      *bc_own, nbc_own;       /* the owned dofs with bc[] active, ascending (TslProblemSetStep) */
  PetscInt      *nload_own, nnload_own; /* the owned dofs with nload[] active, ascending */
  PetscInt       nface, face_seq;
  TslFaceRecord *face;       /* sorted by element */
  PetscInt      *face_start; /* [nelem+1] CSR over face[] */

  /* contact */
  PetscInt           ncsurf, ncnode;
  TslContactSurface *csurf;
  TslContactNode    *cnode;
  PetscReal          augment_tol;
  PetscBool          pattern_stale;    /* a rollback changed the pairing: the matrix pattern is the failed attempt's */
  PetscInt           search_moved;     /* the last search's re-paired nodes and re-cut faces, over all ranks (0: it changed nothing) */
  PetscErrorCode (*repattern)(void *); /* called before a new pattern replaces the old one (TslProblemSetRepatternCallback) */
  void              *repattern_ctx;
  PetscReal          margin_rerun;  /* > 0: a node left its rank's held region; the job restarts with this -tsl_contact_margin */
  PetscBool          select_kinematic; /* TslProblemContactAssemble evaluates the kinematic pairs (true) or the others */
  TslContactS2S      s2s;           /* surface-to-surface pairs (NULL without) */
  PetscBool          s2s_reported;  /* the first search's points per surface-to-surface pair are in the log */
  char              *pattern_rows;  /* [nn*ndof] kind of each row (free, prescribed, pinned, eliminated) when J's pattern was built */
  struct {                          /* the pattern pass's node pairs of owned rows (TslProblemPreallocate, MatAdd) */
    PetscInt *rec;                  /* records {nr, nc, rows[nr], cols[nc]} in local node numbers; NULL outside the pass */
    PetscInt  n, cap;               /* used and allocated length of rec */
  } pattern_pairs;
  /* Direct insertion (TslProblemPreallocate): for an element whose nodes are all owned and none of whose
   * rows is eliminated by an equation, blk[blk_ptr[e] + a*nb + b] is the place of node b's block among
   * node a's blocks in the local diagonal CSR matrix (whole ndof x ndof blocks, sorted; unset for a node
   * without a free row); blk_ptr[e] = blk_ptr[e+1] otherwise. Rows of prescribed or pinned dofs are skipped
   * when inserting. During a Jacobian assembly jac_val / jac_row / jac_col point at that matrix's values, row
   * starts and column indices (the other blocks, contact's, find their places by search: InsertDirect). */
  PetscInt          *blk_ptr;
  unsigned short    *blk;
  PetscScalar       *jac_val;
  const PetscInt    *jac_row, *jac_col;

  /* explicit force records (element.h, fast.c; TslProblemExplicitRecords), in batches of TSL_FAST_LANES
   * elements of one type: fast_batch[W b + j] the local element in lane j of batch b (-1: an empty lane,
   * holding a copy of lane 0's record), fast_boff[b] the offset of its interleaved records in fast_rec;
   * fast_off[e] = W b + j for an element with a record, -1 for the generic kernels; fast_shape[] one per
   * catalogue type */
  PetscBool            fast_built;
  /* the explicit procedure's per-element stable increments and lumped masses, once per distinct element
   * (dynamics.c, "Each distinct element once"; NULL until an explicit step asks) */
  struct TslElemCache *elem_cache;
  /* finite-strain explicit steps: [TSL_STABLE_SHAPE nelem] each element's centre C = F^T F (Voigt) at its last stable-increment
   * evaluation, then its dt_mech and dt_heat there (dynamics.c, StableElement); NULL until first asked */
  PetscReal *stable_shape;
  PetscBool            fast_implicit;                       /* implicit residuals take the records too (TslProblemImplicitRecords) */
  PetscInt             fast_count, fast_total, fast_nbatch; /* elements with a record, reals in fast_rec, batches */
  PetscInt            *fast_off, *fast_batch, *fast_boff;
  PetscReal           *fast_rec;
  PetscReal           *fast_ev;  /* [W fast_nbatch] each lane's volumetric strain at its last explicit evaluation (bulk viscosity's rate) */
  PetscBool            fast_all; /* every element on every rank has a record (then no rank reads the velocities for the bulk viscosity) */
  PetscBool            fast_ti_uniform; /* one initial temperature at every local node: fast_ti holds it in every lane and node */
  PetscReal            fast_ti[TSL_FAST_MAX_NODES * TSL_FAST_LANES];
  TslElementFastShape *fast_shape;
  /* explicit face loads of elements with a record (dynamics.c, FaceCache): every load is linear in its value
   * and sink on the reference faces, so each face record's integrals are formed once: fcache_off[i] the
   * offset in fcache of face record i's (pressure: int N_a n dA per face node; flux: int N_a dA and the area;
   * film: those and int N_a N_b dA; body forces: -int N_a rho b dV per node at unit magnitude), -1 for a kind
   * without (body flux: that element takes the generic path);
   * rebuilt when face_gen (the face list's edits) moves past fcache_gen */
  PetscInt   face_gen, fcache_gen;
  PetscInt  *fcache_off;
  PetscReal *fcache;

  /* contact that does not settle (TslProblemContactChatter): the residual evaluations in a row, up to the last,
   * in which some secondary node or surface-to-surface point changed between open and closed; at the last one
   * how many did (this rank), and the global id of the first of them */
  PetscInt chatter_run, chatter_count, chatter_node;

  /* the last residual evaluation's element forces (TslProblemElementFlux): sums of |R_i| over the displacement and
   * the temperature components of every element's vector on this rank, and their counts */
  PetscReal flux_abs[2], flux_n[2];
  PetscBool flux_on; /* ... gathered at all (TslProblemSetElementFlux: only for the dialect's field test) */

  /* failures decided by all ranks (sys.h) */
  TslInject inject;
  char      fail_msg[TSL_FAIL_MSG_LEN]; /* the last convergence-type failure */

  /* equations: dep[d] = index into m->equations if local dof d is eliminated, else -1 */
  PetscInt  *dep;
  PetscInt **eq_ldof; /* [nequation][n] local dof of each term */
};

/* Element data gathered from the local (ghosted) arrays; xa / xoa may be NULL (the initial state:
 * zero displacement, initial temperature). in: the current state, in_old: the state at the start of the
 * increment (same element, other unknowns). */
typedef struct {
  PetscInt        n, nd;
  PetscInt        ld[TSL_MAX_ELEM_DOF];
  PetscReal       x[TSL_MAX_ELEM_NODES * 3], u[TSL_MAX_ELEM_DOF], uo[TSL_MAX_ELEM_DOF], ti[TSL_MAX_ELEM_NODES];
  TslElementInput in, in_old;
} TslElemData;

void TslProblemGather(TslProblem p, PetscInt e, const PetscScalar *xa, const PetscScalar *xoa, TslElemData *d);
/* Frees the explicit force records (dynamics.c). */
PetscErrorCode TslProblemFastDestroy(TslProblem p);
/* Strain and hourglass energies of the elements of force-record batch b (dynamics.c), summed over its lanes. */
void           TslProblemFastBatchEnergy(TslProblem p, PetscInt b, const PetscScalar *xa, PetscReal *strain, PetscReal *hourglass);
/* A per-element computation: set *stop to end the loop early. */
typedef PetscErrorCode (*TslElementVisitor)(TslProblem p, PetscInt e, TslElemData *d, void *ctx, PetscBool *stop);
PetscErrorCode TslProblemElementLoop(TslProblem p, const PetscScalar *xa, const PetscScalar *xoa, TslElementVisitor visit, void *ctx);
typedef enum { ASM_RESIDUAL, ASM_JACOBIAN, ASM_PATTERN, ASM_RAW } AsmMode;

/* Notes, during a residual evaluation, whether a contact (node or point) went from open to closed or back
 * (was: its status before, now: after) for TslProblemContactChatter. */
static inline void TslProblemContactChatterNote(TslProblem p, TslContactStatus was, TslContactStatus now, PetscInt lnode)
{
  if ((was == TSL_CONTACT_OPEN) == (now == TSL_CONTACT_OPEN)) return;
  if (!p->chatter_count++) p->chatter_node = p->m->node_id[lnode];
}

/* Heat totals gathered during an assembly (this rank's share, per unit time). */
typedef struct {
  PetscReal flux_in;       /* heat added by fluxes (faces, body, nodes) */
  PetscReal film;          /* heat added by films (negative when heat leaves) */
  PetscReal radiation;     /* heat added by radiation to the ambient (negative when heat leaves) */
  PetscReal interface;     /* heat conducted and radiated across contact interfaces (main -> secondary) */
  PetscReal dissipation;   /* frictional dissipation rate */
  PetscReal friction_heat; /* part of it converted to heat (eta) */
  PetscReal stored;        /* sum of the lumped heat contents' change over the increment (Q - Q_old) */
  PetscReal energy[2];     /* the elements' strain and hourglass energies (TslElementInternalEnergy) */
  PetscReal plastic_work;  /* plastic work of the increment, int sigma : d eps_p dV */
  PetscReal plastic_heat;  /* the heat it gives per unit time (eta / dt) */
} AsmHeat;

/* Books the heat h that a face record of this kind added (TslElementFaceLoad's *heat) in its total; mechanical
 * kinds add none. */
static inline void TslAsmHeatAdd(AsmHeat *heat, TslFaceLoadKind kind, PetscReal h)
{
  switch (kind) {
  case TSL_FACE_FLUX:
  case TSL_BODY_FLUX:
    heat->flux_in += h;
    break;
  case TSL_FACE_FILM:
    heat->film += h;
    break;
  case TSL_FACE_RADIATION:
    heat->radiation += h;
    break;
  default:
    break;
  }
}

/* Local form (owned + ghosts) of the current solution, ghosts updated; restore when done. */
PetscErrorCode TslProblemGetLocalSolution(TslProblem p, Vec *xl, const PetscScalar **xa);
PetscErrorCode TslProblemRestoreLocalSolution(TslProblem p, Vec *xl, const PetscScalar **xa);
/* Inserts an element's rows: ld[n] local dofs, R[n], K[n*n] (row-major; either may be NULL as the mode allows). A
 * negative ld is a slot the model does not have (a contact kernel's displacement in a heat-transfer model): its row
 * and column are left out. */
PetscErrorCode TslProblemInsert(TslProblem p, AsmMode mode, Mat A, PetscScalar *f, PetscInt n, const PetscInt ld[], const PetscReal R[],
                                const PetscReal K[]);
/* The value of a node's unknown in slot `slot` of the local vector xa, 0 where the model has no such unknown
 * (slot < 0: the displacements of a heat-transfer model, which contact takes at the deck's geometry); and its local
 * dof, -1 there. */
static inline PetscReal TslProblemSlotValue(TslProblem p, const PetscScalar *xa, PetscInt l, PetscInt slot)
{
  return xa && slot >= 0 ? PetscRealPart(xa[l * p->ndof + slot]) : 0;
}
static inline PetscInt TslProblemSlotDof(TslProblem p, PetscInt l, PetscInt slot)
{
  return slot >= 0 ? l * p->ndof + slot : -1;
}
PetscErrorCode TslProblemContactAssemble(TslProblem p, AsmMode mode, const PetscScalar *xa, PetscScalar *f, Mat A, AsmHeat *heat);
PetscErrorCode TslProblemContactSetUp(TslProblem p);
/* The contact area A of a secondary node: tributary length x thickness (or x 2 pi r), or the 3D tributary area
 * (reference configuration; the kernels' out.area). */
PetscReal TslProblemContactNodeArea(TslProblem p, const TslContactNode *cn);
/* A kinematic node's normal penalty k_s / A_s: the pressure per penetration that closes its gap in one increment. */
static inline PetscReal TslProblemContactKinematicPenalty(TslProblem p, const TslContactNode *cn)
{
  return cn->k_kin / TslProblemContactNodeArea(p, cn);
}
/* 3D node-to-surface (contact3.c): the kernel input of a paired node (its local nodes in kernel order, *n of
 * them), the pairing of the pair's owned secondary nodes (*changed counts new pairings), whether a converged
 * projection left its face, and the nodal normals at the state xa (at set-up and after each accepted
 * increment). */
PetscErrorCode TslProblemContact3Input(TslProblem p, const TslContactNode *cn, const PetscScalar *xa, TslContactInput3 *in, PetscInt nodes[], PetscInt *n);
PetscErrorCode TslProblemContact3Search(TslProblem p, PetscInt pair, const PetscScalar *xa, PetscInt *changed);
PetscBool      TslProblemContact3Departed(TslProblem p, const TslContactNode *cn, PetscReal tol);
PetscErrorCode TslProblemContact3Normals(TslProblem p, TslContactSurface *cs, const PetscScalar *xa);
/* A face record's load value and sink at the current time (amplitudes, film or radiation amplitude), and the
 * model's absolute zero. */
PetscErrorCode TslProblemFaceLoadValue(TslProblem p, const TslFaceRecord *r, TslFaceLoadValue *v);
/* A distributed load of the element of in at the current time through its kernel (TslElementFaceLoad, or
 * TslElementBodyForce for a body force), added to R and K (NULL: not wanted); *heat as TslElementFaceLoad's. */
PetscErrorCode TslProblemRecordLoad(TslProblem p, const TslFaceRecord *r, const TslElementInput *in, PetscReal R[], PetscReal K[], PetscReal *heat);
/* Collective: bad >= 0 (a local element) on any rank is the user error "element is inverted" on all. */
PetscErrorCode TslProblemCheckBadElement(TslProblem p, PetscInt bad);
PetscErrorCode TslProblemContactDestroy(TslProblem p);
/* The contact node fields (fields.c's rows CPRESS, CSLIP, CSTATUS, HFLA, in this order: a row's index is its kind) */
typedef enum { TSL_CONTACT_FIELD_PRESSURE, TSL_CONTACT_FIELD_SLIP, TSL_CONTACT_FIELD_STATUS, TSL_CONTACT_FIELD_HEAT_FLUX } TslContactField;
PetscErrorCode TslProblemContactNodeField(TslProblem p, TslContactField kind, PetscReal vals[]);
/* What surface-to-surface contact takes from node-to-surface (src/physics/contact.c): the kernel input of
 * node cn on its segment (nodes[] in kernel order, *n of them; in points into nb) and a node's reference
 * coordinates and contact unknowns; a main face's metric. */
void TslProblemContactElementInput(TslProblem p, const TslContactNode *cn, const PetscScalar *xa, TslContactInput *in, PetscInt nodes[], PetscInt *n,
                                   TslContactNeighbourData *nb);
void TslProblemContactNodeData(TslProblem p, const TslContactSurface *cs, const PetscScalar *xa, PetscInt l, PetscReal x[2], PetscReal u[]);
/* The metric |dx/dxi| of main face seg at xi (current configuration). */
PetscErrorCode TslProblemContactFaceMetric(TslProblem p, const TslContactSurface *cs, const PetscScalar *xa, PetscInt seg, PetscReal xi, PetscReal *L);
/* Surface-to-surface contact, called at the end of the node-to-surface functions of the same role. */
PetscErrorCode TslProblemContactS2SSetUp(TslProblem p);
PetscErrorCode TslProblemContactS2SDestroy(TslProblem p);
PetscErrorCode TslProblemContactS2SAssemble(TslProblem p, AsmMode mode, const PetscScalar *xa, PetscScalar *f, Mat A, AsmHeat *heat);
/* *changed: faces whose main faces (the matrix pattern) changed; *recut: faces cut differently (points or weights moved) */
PetscErrorCode TslProblemContactS2SSearch(TslProblem p, const PetscScalar *xa, PetscInt *changed, PetscInt *recut);
/* The secondary faces this rank inserts and their points in contact reach, per pair: counts[2 k], counts[2 k + 1]
 * (zeros without surface-to-surface pairs). */
void TslProblemContactS2SCount(TslProblem p, PetscInt counts[]);
PetscErrorCode TslProblemContactS2SReach(TslProblem p, PetscInt k, const PetscScalar *xa, const PetscReal lo[], const PetscReal hi[], PetscReal *excess,
                                         PetscInt *node);
PetscErrorCode TslProblemContactS2SUpdate(TslProblem p, PetscInt *depart, PetscReal *change, PetscReal *scale);
PetscErrorCode TslProblemContactS2SAugment(TslProblem p);
PetscErrorCode TslProblemContactS2SCommit(TslProblem p);
PetscErrorCode TslProblemContactS2SRollback(TslProblem p);
PetscErrorCode TslProblemContactS2SNodeField(TslProblem p, TslContactField kind, PetscReal vals[]);
PetscReal      TslProblemEvalLoadValue(TslProblem p, const TslLoadValue *h);
/* The slot of dialect dof number dof (1..6, 11) among an ordinary node's unknowns (TslProblemDofSlot) or
 * among local node l's (TslProblemNodeDofSlot: reference nodes have their own), -1 when it has no such dof. */
PetscInt       TslProblemDofSlot(TslProblem p, PetscInt dof);
PetscInt       TslProblemNodeDofSlot(TslProblem p, PetscInt l, PetscInt dof);
/* *TEMPERATURE, FILE= (tfile.c): opens step s's window (closing the one before; nothing when the step has none; x the
 * local solution at the step's start); the
 * values at step time t for every local node (collective: a failed read stops all ranks); closes it */
PetscErrorCode TslProblemTemperatureFileBegin(TslProblem p, PetscInt s, const PetscScalar x[]);
PetscErrorCode TslProblemTemperatureFileAt(TslProblem p, PetscReal t, const PetscReal **T);
PetscErrorCode TslProblemTemperatureFileEnd(TslProblem p);
PetscErrorCode TslProblemLocalNode(TslProblem p, PetscInt gnum, PetscInt *lnode);
PetscErrorCode TslProblemPreallocate(TslProblem p);
PetscErrorCode TslProblemPreallocateIfChanged(TslProblem p); /* TslProblemPreallocate unless every row kind is as it was */
PetscErrorCode TslProblemCheckElements(TslProblem p);
