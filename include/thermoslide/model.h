/* thermoslide model: the plain data read from an Abaqus/CalculiX keyword deck.
 *
 * A TslModel is built by the deck reader on rank 0 (the whole mesh), then split by the mesh module into
 * one local TslModel per rank (its elements, their nodes, and the sets/surfaces filtered to them; all
 * non-mesh data is copied whole). The struct knows nothing of PETSc objects or physics: it is data.
 *
 * Conventions
 *  - Deck ids (node and element numbers) are kept as written; arrays of ids are indexed by position.
 *  - Set members are stored as sorted, unique deck ids.
 *  - Degrees of freedom use the dialect's numbers: 1..3 displacement, 11 temperature.
 *  - Every item that came from a deck line remembers where (TslLoc) so later errors can name it.
 */
#pragma once
#include <thermoslide/compat.h>

/* Where something came from: index into TslModel.files[] and 1-based line number (file -1: nowhere). */
typedef struct {
  PetscInt file, line;
} TslLoc;

/* A reference to entities by set name or by a single id: if set[0] != 0 it names a set (node set,
 * element set or surface depending on context), otherwise id is a node/element id. */
typedef struct {
  char     set[TSL_NAME_LEN];
  PetscInt id;
} TslTarget;

typedef struct {
  char      name[TSL_NAME_LEN];
  PetscInt  n;
  PetscInt *ids; /* sorted unique deck ids */
  TslLoc    loc;
} TslSet;

typedef enum { TSL_SURFACE_ELEMENT = 0, TSL_SURFACE_NODE = 1 } TslSurfaceKind;

/* Face codes of a conventional shell's two sides (labels SPOS/SNEG, FPOS/FNEG): read as these, then
 * mapped to the faces of the continuum elements the shell is expanded into (shell.c) before the checks. */
#define TSL_FACE_POS 7
#define TSL_FACE_NEG 8

typedef struct {
  char           name[TSL_NAME_LEN];
  TslSurfaceKind kind;
  PetscInt       n;    /* number of facets (ELEMENT) or nodes (NODE) */
  PetscInt      *elem; /* ELEMENT: element id of each facet; NODE: node ids */
  PetscInt      *face; /* ELEMENT: face number 1..6 (S1..S6); NODE: NULL */
  TslLoc         loc;
} TslSurface;

/* Material properties, each a table in temperature: *ELASTIC (E, nu), *CONDUCTIVITY (k), *DENSITY (rho),
 * *SPECIFIC HEAT (c), *EXPANSION (alpha). A table with one row is a constant; with several rows the value
 * is linear in temperature between rows (ascending) and constant beyond the ends, as in the dialect.
 * Evaluation is in the material module (include/thermoslide/material.h). A fixed capacity keeps the model
 * a flat, packable struct. */
#define TSL_MAX_TABLE_ROWS 64
typedef enum { TSL_PROP_ELASTIC = 0, TSL_PROP_CONDUCTIVITY, TSL_PROP_DENSITY, TSL_PROP_SPECIFIC_HEAT, TSL_PROP_EXPANSION, TSL_NPROP } TslProperty;

typedef struct {
  PetscInt  n;                            /* rows; 0: the property was not given */
  PetscReal value[TSL_MAX_TABLE_ROWS][2]; /* the values of each row (E and nu for *ELASTIC) */
  PetscReal theta[TSL_MAX_TABLE_ROWS];    /* temperature of each row (ascending; unused when n == 1) */
  TslLoc    loc;                          /* the keyword line */
} TslPropertyTable;

/* *PLASTIC: Mises yield. The size of the yield surface: rows (yield stress, plastic strain, temperature) as the deck
 * gives them (HARDENING=ISOTROPIC, or *CYCLIC HARDENING's table under COMBINED): per temperature the plastic strains
 * ascend from 0, the temperatures ascend between groups (material.c, TslMaterialYield: linear in both, the end values
 * held beyond); or, with nvoce > 0 (*CYCLIC HARDENING, PARAMETERS), the exponential law sigma_0 + Q (1 - exp(-b p))
 * with rows (sigma_0, Q, b, temperature), linear between the temperatures. n = 0: elastic. Back stresses (nback of
 * them; HARDENING=KINEMATIC: one of modulus C = the slope between the deck's two points and gamma = 0, Ziegler-Prager;
 * HARDENING=COMBINED, DATA TYPE=PARAMETERS: NUMBER BACKSTRESSES of the nonlinear kinematic law (Armstrong-Frederick)
 * d alpha_k = C_k / sigma_y (sigma - alpha) d p - gamma_k alpha_k d p), their C_k, gamma_k in nkt rows, one per
 * temperature. */
#define TSL_MAX_BACKSTRESS 10
typedef struct {
  PetscInt  n;
  PetscReal row[TSL_MAX_TABLE_ROWS][3];
  PetscInt  nvoce;
  PetscReal voce[TSL_MAX_TABLE_ROWS][4];
  PetscInt  nback;
  PetscBool combined;  /* HARDENING=COMBINED (a *CYCLIC HARDENING may follow) */
  /* the back stresses' C_k, gamma_k: one row (nkt = 1), or nkt > 1 rows of ascending kt_theta, linear between them and
   * the end rows held beyond (TslMaterialBackStress); the point's state then keeps the temperature of its last commit */
  PetscInt  nkt;
  PetscReal kt_theta[TSL_MAX_TABLE_ROWS], kt_C[TSL_MAX_TABLE_ROWS][TSL_MAX_BACKSTRESS], kt_gamma[TSL_MAX_TABLE_ROWS][TSL_MAX_BACKSTRESS];
  PetscInt  rate_law;  /* *RATE DEPENDENT: 0 none, 1 TYPE=POWER LAW (rate = D (sigma / sigma_static - 1)^n), 2 JOHNSON COOK
                          (sigma = sigma_static (1 + C ln(rate / rate_0)) above rate_0) */
  PetscReal rate[2];   /* D, n or C, rate_0 */
  TslLoc    rate_loc;
  TslLoc    loc;
  TslLoc    cyclic_loc; /* *CYCLIC HARDENING's keyword line (line 0: none) */
} TslPlasticTable;

typedef struct {
  char             name[TSL_NAME_LEN];
  TslPropertyTable prop[TSL_NPROP];
  PetscReal        alpha_zero; /* *EXPANSION, ZERO= (reference temperature of alpha; default 0) */
  TslPlasticTable  plastic;
  PetscReal        heat_fraction; /* *INELASTIC HEAT FRACTION (0: none given: no plastic heating) */
  TslLoc           heat_fraction_loc;
  /* *DAMPING, ALPHA=, BETA= (Rayleigh damping; explicit steps only, docs/explicit.md "Damping"): nodal forces alpha m v
   * on the material's lumped masses and the damping stress beta D^el : eps_dot in its elements (0, 0: none) */
  PetscReal        damp_alpha, damp_beta;
  TslLoc           damping_loc;
  TslLoc           loc;
} TslMaterial;

typedef struct {
  char      elset[TSL_NAME_LEN];
  char      material[TSL_NAME_LEN];
  PetscInt  material_index; /* resolved by TslModelCheck, index into materials[] */
  PetscReal thickness;      /* data line; plane elements' out-of-plane thickness (default 1) */
  TslTarget ref_node;       /* REF NODE= (generalized plane strain): a node id or a node set of one node; id -1 and no set: none */
  PetscBool shell;          /* *SHELL SECTION (continuum shells) rather than *SOLID SECTION */
  PetscInt  shell_points;   /* *SHELL SECTION: Simpson points through the thickness (data line; default 5) */
  PetscReal thickness_modulus; /* *SHELL SECTION, THICKNESS MODULUS= (0: the default, 2 G) */
  PetscInt  shell_stack;       /* *SHELL SECTION, STACK DIRECTION= 1..3 (default 3) */
  PetscReal shell_thickness;   /* *SHELL SECTION data line: a conventional shell's (S8RT, SAX2T) thickness (default 1) */
  PetscReal shell_offset;      /* *SHELL SECTION, OFFSET= (SPOS 0.5, SNEG -0.5; default 0, the mid-surface) */
  TslLoc    loc;
} TslSection;

/* *INITIAL CONDITIONS, TYPE=TEMPERATURE (target first: model.c filters both kinds of line by it, so after
 * distribution each rank keeps the lines of the nodes it holds, as for the velocities below). */
typedef struct {
  TslTarget target; /* node or node set */
  PetscReal value;
  TslLoc    loc;
} TslInitialTemperature;

/* *NODAL THICKNESS: the thickness at a node or node set, for the conventional shells whose *SHELL SECTION
 * has NODAL THICKNESS. Used when the shells are expanded (shell.c) and dropped there: never distributed. */
typedef struct {
  TslTarget target; /* node or node set */
  PetscReal value;
  TslLoc    loc;
} TslNodalThickness;

/* *INITIAL CONDITIONS, TYPE=VELOCITY: the velocity of displacement dof (1..3) of a node or node set at the
 * start of the first explicit step (implicit steps are static and ignore it; a prescribed dof keeps its
 * boundary condition). After distribution each rank keeps the lines whose node it holds or whose set has
 * members there (TslModelSubset), so no rank holds a list the size of a per-node deck. */
typedef struct {
  TslTarget target; /* node or node set */
  PetscInt  dof;
  PetscReal value;
  TslLoc    loc;
} TslInitialVelocity;

/* *AMPLITUDE, DEFINITION=: points (TABULAR, EQUALLY SPACED, SMOOTH STEP) or a closed form */
typedef enum { TSL_AMP_POINTS = 0, TSL_AMP_PERIODIC, TSL_AMP_DECAY, TSL_AMP_MODULATED } TslAmplitudeForm;

typedef struct {
  char       name[TSL_NAME_LEN];
  PetscInt   n;
  PetscReal *t, *a;      /* tabular (time, value) pairs, t ascending (EQUALLY SPACED: BEGIN + k FIXED INTERVAL) */
  PetscBool  total_time; /* TIME=TOTAL TIME (default STEP TIME) */
  PetscBool  smooth;     /* DEFINITION=SMOOTH STEP: a + (b - a) xi^3 (10 - 15 xi + 6 xi^2) between points */
  /* The closed forms (n = 0, no points), each a0 before t0 and, with tau = t - t0 >= 0 (Abaqus's definitions):
   * PERIODIC   a0 + sum_k cosc[k] cos((k+1) omega tau) + sinc[k] sin((k+1) omega tau) (the Fourier series)
   * DECAY      a0 + A exp(-tau / td)
   * MODULATED  a0 + A sin(omega tau) sin(omega2 tau) */
  TslAmplitudeForm form;
  PetscInt         nterm;
  PetscReal        omega, omega2, t0, a0, A, td;
  PetscReal       *cosc, *sinc;
  TslLoc     loc;
} TslAmplitude;

/* *EQUATION: sum_k coef[k] * u(node[k], dof[k]) = 0. The first term's dof is the dependent one
 * (eliminated), as in the dialect. gdof[] is filled by the mesh module (global PETSc dof numbers). */
typedef struct {
  PetscInt   n;
  PetscInt  *node, *dof;
  PetscReal *coef;
  PetscInt  *gdof; /* NULL until distributed */
  PetscBool  tie;  /* generated from a *TIE (src/mesh/tie.c): allowed in explicit steps, where it moves mass and force */
  TslLoc     loc;
} TslEquation;

/* *TIE, or a *CONTACT PAIR that is TIED or whose interaction has PRESSURE-OVERCLOSURE=TIED: every node of the
 * secondary surface follows the main surface, u_s = sum_k c_sk u_k for each displacement dof and the
 * temperature (docs/keywords.md "*TIE", docs/design.md "Ties"). The mesh module turns each tie into
 * equations on rank 0 before partitioning (TslMeshTies); after that a tie is only a record. */
typedef struct {
  char      name[TSL_NAME_LEN];
  char      secondary[TSL_NAME_LEN], main[TSL_NAME_LEN];
  PetscReal tolerance; /* POSITION TOLERANCE=; 0: the default, 2.5 % of the mean main face size */
  PetscBool adjust;    /* ADJUST=YES (the default): secondary nodes moved onto the main surface */
  PetscBool from_pair; /* a tied *CONTACT PAIR (for messages) */
  TslLoc    loc;       /* the *TIE line, or a tied pair's data line */
} TslTie;

typedef enum {
  TSL_LOAD_BOUNDARY = 0, /* *BOUNDARY: prescribed dofs dof_first..dof_last = value */
  TSL_LOAD_CLOAD,        /* *CLOAD: nodal force on dof_first */
  TSL_LOAD_CFLUX,        /* *CFLUX: nodal heat flux (dof 11) */
  TSL_LOAD_DLOAD,        /* *DLOAD: pressure on face (face 1..6 = P1..P6), or a body force (GRAV, CENTRIF: face 0, body) */
  TSL_LOAD_DFLUX,        /* *DFLUX (face 1..6 = S1..S6, face 0 = BF body flux) and *DSFLUX (surface) */
  TSL_LOAD_FILM,         /* *FILM / *SFILM: face 1..6 = F1..F6 or surface; value = h, sink */
  TSL_LOAD_RADIATE,      /* *RADIATE / *SRADIATE: face 1..6 = R1..R6 or surface; value = emissivity, sink = ambient temperature */
  TSL_LOAD_NKINDS
} TslLoadKind;

/* Does the kind act on element faces or bodies (DLOAD, DFLUX, FILM, RADIATE) rather than on nodes? */
static inline PetscBool TslLoadKindOnElements(TslLoadKind kind)
{
  return kind > TSL_LOAD_CFLUX && kind < TSL_LOAD_NKINDS ? PETSC_TRUE : PETSC_FALSE;
}

/* *DLOAD's body forces (face 0): none (a pressure: TSL_DLOAD_FACE), GRAV (value g, axis[0..2] the unit direction) or CENTRIF
 * (value omega^2, axis[0..2] a point of the axis, axis[3..5] its unit direction). */
typedef enum { TSL_DLOAD_FACE = 0, TSL_DLOAD_GRAV, TSL_DLOAD_CENTRIF } TslDload;

/* A load whose target is empty (set[0] == 0, id < 0) comes from a keyword line with OP=NEW and no data
 * lines: it only removes the earlier loads of its kind. */
typedef struct {
  TslLoadKind kind;
  TslTarget   target;            /* node/nset (BOUNDARY, CLOAD, CFLUX), element/elset or surface (faces) */
  PetscBool   target_is_surface; /* target.set names a *SURFACE (DSFLUX, surface film or radiation, surface dload) */
  PetscInt    dof_first, dof_last;
  PetscInt    face;           /* 1..6 for face loads; 0 = body (BF, GRAV, CENTRIF) */
  TslDload    dload;          /* *DLOAD GRAV / CENTRIF (TSL_DLOAD_FACE otherwise) */
  PetscReal   axis[6];        /* GRAV: unit direction; CENTRIF: point, unit axis direction */
  PetscReal   value;          /* magnitude, prescribed value, flux, film coefficient, or emissivity */
  PetscReal   sink;           /* FILM sink temperature, RADIATE ambient temperature */
  PetscInt    amplitude;      /* index into amplitudes[], -1 = step default (FILM, RADIATE: scales the sink) */
  PetscInt    film_amplitude; /* FILM AMPLITUDE= (scales h) or RADIATION AMPLITUDE= (scales the emissivity), -1 = none */
  PetscBool   op_new;         /* OP=NEW on this keyword: previous loads of this kind are removed */
  PetscBool   fixed;          /* *BOUNDARY, FIXED: hold the dofs at their values at the start of the step */
  PetscBool   velocity;       /* *BOUNDARY, TYPE=VELOCITY: value is a velocity, the dof follows its time integral */
  PetscBool   temperature;    /* from *TEMPERATURE (a *STATIC step's prescribed temperature, kind BOUNDARY on dof 11) */
  TslLoc      loc;
} TslLoad;

typedef enum { TSL_AMP_RAMP = 0, TSL_AMP_STEP = 1 } TslAmpDefault;

/* An output request: *NODE OUTPUT / *ELEMENT OUTPUT / *NODE PRINT / *EL PRINT. */
typedef struct {
  PetscBool node;              /* node (TRUE) or element (FALSE) variables */
  PetscBool print;             /* *NODE PRINT (table in the job log) rather than field output */
  char      set[TSL_NAME_LEN]; /* NSET=/ELSET= or empty */
  PetscInt  nvar;
  char      var[16][8]; /* U, NT, RF, RFL, S, E, HFL, ... (upper case) */
  PetscInt  frequency;  /* FREQUENCY= (default 1) */
  PetscInt  totals;     /* *NODE PRINT / *EL PRINT, TOTALS=: 0 NO (default), 1 YES (the rows and their sum), 2 ONLY (the sum) */
  TslLoc    loc;
} TslOutputRequest;

/* ---- contact (model data; read, checked and distributed, not yet used by the solver) ----------
 * A *SURFACE INTERACTION is a named set of interface laws; a *CONTACT PAIR puts one between a secondary
 * and a main surface. Each law remembers whether its keyword was given (given) and where (loc). */

/* Normal contact (*SURFACE BEHAVIOR): hard pressure-overclosure enforced by a penalty (default) or by
 * augmented Lagrange. penalty_stiffness 0 means "the solver's default". */
typedef enum { TSL_CONTACT_HARD_PENALTY = 0, TSL_CONTACT_AUGMENTED_LAGRANGE = 1 } TslContactEnforcement;

typedef struct {
  PetscBool             given;
  TslContactEnforcement enforcement;
  PetscReal             penalty_stiffness;
  PetscBool             tied; /* PRESSURE-OVERCLOSURE=TIED: its pairs become ties (TslTie); the slope is read and not used */
  TslLoc                loc;
} TslSurfaceBehavior;

/* Coulomb friction (*FRICTION). Without the keyword the interface is frictionless. */
typedef struct {
  PetscBool given;
  PetscReal mu;             /* friction coefficient */
  PetscBool lagrange;       /* LAGRANGE: exact stick (Lagrange multiplier) instead of penalty elastic slip */
  PetscBool rough;          /* ROUGH: no slip at all (mu unused) */
  PetscReal slip_tolerance; /* SLIP TOLERANCE= (default 0.005): allowed elastic slip / facet size */
  PetscReal elastic_slip;   /* ELASTIC SLIP= (absolute allowed elastic slip; 0: SLIP TOLERANCE decides) */
  PetscReal stick_slope;    /* CalculiX second value: stick stiffness; 0 = solver default */
  TslLoc    loc;
} TslFriction;

/* *GAP CONDUCTANCE: q = k (theta_main - theta_secondary), k(abscissa) with abscissa the contact pressure
 * (PRESSURE) or the clearance, ascending. k is linear in the table and keeps its end values beyond it,
 * except beyond the last clearance, where the dialect makes it zero. */
typedef struct {
  PetscBool  given;
  PetscBool  by_pressure;
  PetscInt   n;
  PetscReal *value;    /* conductance k */
  PetscReal *abscissa; /* clearance d or pressure p */
  TslLoc     loc;
} TslGapConductance;

/* *GAP RADIATION: q = C [(theta_A - theta_Z)^4 - (theta_B - theta_Z)^4] with
 * C = F sigma / (1/eps_A + 1/eps_B - 1) (Abaqus Theory Guide, "Thermal contact properties"), A the main
 * and B the secondary surface, sigma and theta_Z from *PHYSICAL CONSTANTS. F(clearance) is linear in
 * the table and zero beyond its last clearance. */
typedef struct {
  PetscBool  given;
  PetscReal  emissivity_main, emissivity_secondary; /* eps_A, eps_B: first data line */
  PetscInt   n;
  PetscReal *view_factor; /* effective view factor F */
  PetscReal *clearance;   /* ascending */
  TslLoc     loc;
} TslGapRadiation;

/* *GAP HEAT GENERATION: eta * (frictional dissipation) becomes heat; the secondary surface receives
 * the fraction weight_secondary (f), the main one 1 - f. Defaults eta = 1, f = 0.5 also when absent. */
typedef struct {
  PetscBool given;
  PetscReal fraction;         /* eta */
  PetscReal weight_secondary; /* f */
  TslLoc    loc;
} TslGapHeatGeneration;

typedef struct {
  char                 name[TSL_NAME_LEN];
  PetscReal            thickness; /* optional data line: out-of-plane thickness (2D), default 1 */
  TslSurfaceBehavior   behavior;
  TslFriction          friction;
  TslGapConductance    conductance;
  TslGapRadiation      radiation;
  TslGapHeatGeneration heat_generation;
  TslLoc               loc;
} TslInteraction;

typedef enum { TSL_CONTACT_NODE_TO_SURFACE = 0, TSL_CONTACT_SURFACE_TO_SURFACE = 1 } TslContactType;

/* *CONTACT PAIR: one per data line "secondary surface, main surface". */
typedef struct {
  char           interaction[TSL_NAME_LEN];
  PetscInt       interaction_index; /* resolved by TslModelCheck, index into interactions[] */
  char           secondary[TSL_NAME_LEN], main[TSL_NAME_LEN];
  TslContactType type;          /* TYPE= (default NODE TO SURFACE) */
  PetscBool      small_sliding; /* SMALL SLIDING */
  PetscBool      kinematic;     /* MECHANICAL CONSTRAINT=KINEMATIC (explicit steps; PENALTY, the default here, otherwise) */
  PetscReal      smooth;        /* SMOOTH= (default 0.2) */
  PetscBool      adjust_given;  /* ADJUST= given: a distance (adjust) or a node set (adjust_set) */
  PetscReal      adjust;
  char           adjust_set[TSL_NAME_LEN];
  TslLoc         loc; /* the data line */

  /* Derived by the mesh module on rank 0 (NULL / 0 before): the main surface as faces (2D: line2 or
   * line3 segments), the secondary nodes with their tributary lengths; after distribution each rank keeps
   * the secondary nodes it owns and the whole main surface (whose nodes it holds as ghosts). */
  PetscInt  nmain;
  PetscInt  nper;                   /* 2D: nodes per main face, 2 (line2) or 3 (line3), the same for all faces of the pair;
                                       3D: the most nodes of any main face (the stride of main_node) */
  PetscInt  main_face;              /* 2D: face family of the main faces, a TslContactFaceKind (include/thermoslide/contact.h);
                                       3D: the first face's TslContactFace3Find family */
  PetscInt *main_kind;              /* [nmain] family of each face (3D surfaces may mix tri3 and quad4: wedges) */
  PetscInt *main_node;              /* [nper*nmain] node ids of each face in face order (ends, then midside), main body on the
                                       left of the first end -> the second end (2D) or on the side opposite the right-hand
                                       normal (3D); a face with fewer than nper nodes is padded with -1 */
  PetscInt  *main_prev, *main_next; /* [nmain] neighbouring face (sharing the first / the second end), -1 at an end */
  PetscInt   main_element;          /* id of the element of the first main face (its material gives the default penalty) */
  PetscInt   nsec;
  PetscInt  *sec_node;    /* [nsec] node ids (corner and midside nodes alike) */
  PetscReal *sec_length;  /* [nsec] tributary length (2D) or area (3D) on the secondary surface (reference): sum of int N_a ds
                             (dA) over the node's faces */
  PetscReal  thickness;   /* out-of-plane thickness of the secondary elements (plane models) */
  PetscInt   kin;         /* TslKinematics of the secondary elements */
  PetscReal  mean_length; /* mean main face length (reference, along the face; 3D: the square root of the mean face area) */
  /* TYPE=SURFACE TO SURFACE (nsec = 0 then): the secondary faces, snper nodes each in face order, family
   * sface_kind (a TslContactFaceKind); after distribution each rank keeps the faces with a node it owns (it
   * holds all their nodes), sface_asm[i] = 1 on the one rank that assembles face i (the owner of its first
   * node) */
  PetscInt  nsface, snper, sface_kind;
  PetscInt *sface_node; /* [snper*nsface] node ids */
  PetscInt *sface_asm;  /* [nsface] */
  /* The part of the main surface a rank holds (src/mesh/distribute.c, docs/contact.md "Parallel
   * exchange"): the main faces whose reference box meets the held region, the reference box of the
   * rank's secondary nodes (and secondary faces) inflated by margin, plus one ring of neighbours (2D: the
   * previous and next face; 3D: the faces sharing a node), which only complete the smoothing data and are
   * never paired (main_ring = 1). main_prev/main_next are local face numbers, -1 at an end of the surface,
   * -2 for a neighbour this rank does not hold. main_own lists the main-surface nodes this rank owns (their
   * displacement bounds how far unheld faces can have come). */
  PetscInt  nmain_global; /* faces of the whole main surface */
  PetscReal margin;       /* inflation of the held region (-tsl_contact_margin or the deck's default) */
  PetscInt  margin_default; /* 1 if margin is the deck's default */
  PetscReal margin_disp;  /* largest prescribed displacement of the deck (for the default and the log) */
  PetscReal margin_radius; /* the search radius (for the default and the log) */
  PetscInt  held;         /* 1 if this rank has a held region (it owns secondary nodes or faces) */
  PetscReal held_box[6];  /* held region: lower corner [0..2], upper corner [3..5] (reference) */
  PetscInt *main_ring;    /* [nmain] */
  PetscInt  nmain_own;
  PetscInt *main_own; /* [nmain_own] node ids */
} TslContactPair;

/* *FIXED MASS SCALING / *VARIABLE MASS SCALING in an explicit step: the element masses of the set (all
 * elements when elset is empty) scaled by factor, then further where an element's stable increment is
 * below dt (TYPE=BELOW MIN: just enough to reach dt). Variable scaling is re-evaluated every frequency
 * increments. */
#define TSL_MAX_MASS_SCALING 8
typedef struct {
  char      elset[TSL_NAME_LEN];
  PetscReal factor;    /* FACTOR= (1 when absent) */
  PetscReal dt;        /* DT= target element stable increment (0: none) */
  PetscBool variable;  /* *VARIABLE MASS SCALING */
  PetscInt  frequency; /* FREQUENCY= (variable scaling: increments between re-evaluations, default 1) */
  TslLoc    loc;
} TslMassScaling;

/* *CONTROLS, PARAMETERS=TIME INCREMENTATION: the dialect's increment controller, CalculiX's names (docs/keywords.md).
 * given: the step has such a *CONTROLS (or RESET); it holds for this and the later steps until the next one.
 * reset: *CONTROLS, RESET: back to thermoslide's own controller (-tsl_growth, -tsl_easy_its, -tsl_cutback).
 * A blank field keeps the dialect's default; unused ones (I_0, I_R, I_P, I_S, I_J, I_T, D_C, D_S, D_H, W_G)
 * are read and checked only. contact_defaults: the surface-to-surface (face-to-face penalty) raise of I_G and
 * I_L applies to the fields left blank. */
typedef struct {
  PetscBool given, reset;
  TslLoc    loc;
  PetscInt  i0, ir, ip, ic, il, ig, is, ia, ij, it;
  PetscReal df, dc, db, da, ds, dh, dd, wg;
} TslIncrementControls;

/* *CONTROLS, PARAMETERS=FIELD (FIELD=GLOBAL, DISPLACEMENT or TEMPERATURE): the dialect's Newton convergence test
 * for a field (docs/keywords.md, *CONTROLS): the largest residual at most R_n q~ (R_P after I_P iterations) and
 * the largest correction at most C_n times the largest change of the field over the increment; or the residual
 * at most R_l q~ alone; a field without flux (q~ at most eps q_0) converges on its correction alone (C_eps).
 * q~: q_u when given (> 0), else the mean over the step's converged increments and the current iterate of the
 * instantaneous flux (TslProblemElementFlux). given: this step has such a *CONTROLS (or RESET, which clears it:
 * on = FALSE); it holds for the later steps until the next. */
typedef struct {
  PetscBool given, on;
  TslLoc    loc;
  PetscReal rn, cn, q0, qu, rp, eps, ceps, rl;
} TslFieldControls;

/* *TEMPERATURE, FILE= (sequential coupling): the nodal temperatures of an earlier job's results (<path>, its .h5)
 * prescribed at every node, from the frames (bstep, binc) .. (estep, einc) of that file (0: the default, see
 * docs/keywords.md: binc the first frame of bstep, estep = bstep, einc the last frame of estep). One frame: its
 * values are the step's target, reached as any *TEMPERATURE value (the step's amplitude); several: followed in time,
 * step time t read at the file's total time t0 + t (t0 the end of the step before bstep in the file). */
typedef struct {
  PetscBool given;
  TslLoc    loc;
  char      path[PETSC_MAX_PATH_LEN]; /* the file found when the deck was read */
  PetscInt  bstep, binc, estep, einc;
  PetscInt  amplitude; /* AMPLITUDE= (one frame), -1: the step's default */
} TslTemperatureFile;

typedef struct {
  char              name[TSL_NAME_LEN];
  TslLoc            loc;
  PetscBool         coupled;                   /* a procedure seen (*COUPLED, *STATIC, *HEAT TRANSFER or *DYNAMIC TEMPERATURE-DISPLACEMENT) */
  PetscBool         explicit_dynamics;         /* *DYNAMIC TEMPERATURE-DISPLACEMENT, EXPLICIT (src/solve/explicit.c) */
  PetscReal         dt_user;                   /* explicit, DIRECT USER CONTROL: the fixed increment (0: the stable increment) */
  PetscReal         dt_scale;                  /* explicit, SCALE FACTOR= on the stable increment (default 1) */
  PetscReal         bv_linear, bv_quadratic;   /* explicit, *BULK VISCOSITY b1, b2 (defaults 0.06, 1.2) */
  PetscBool         bv_given;                  /* *BULK VISCOSITY seen in the step */
  TslLoc            bv_loc;
  PetscInt          nmass;                     /* explicit: mass scaling definitions of the step */
  TslMassScaling    mass[TSL_MAX_MASS_SCALING];
  PetscInt          out_number_interval;       /* *OUTPUT, NUMBER INTERVAL= (0: not given): frames at n equal intervals (TslFrameTimes) */
  PetscReal         out_time_interval;         /* *OUTPUT, TIME INTERVAL= (0: not given): frames every dt of step time */
  PetscBool         steady;                    /* STEADY STATE (and *STATIC) */
  PetscBool         statik;                    /* *STATIC: mechanical equilibrium with every temperature held at its value (no heat transfer) */
  PetscBool         heat;                      /* *HEAT TRANSFER: the temperature alone (a model of such steps only: docs/design.md) */
  TslLoc            heat_loc;                  /* the *HEAT TRANSFER line */
  PetscReal         end_ss_rate;               /* *HEAT TRANSFER, END=SS: the step ends once no temperature changes faster (0: END=PERIOD) */
  PetscBool         direct;                    /* DIRECT: fixed increments */
  PetscBool         nlgeom;                    /* finite strain (NLGEOM; on in every step after one that has it, check.c) */
  PetscBool         nlgeom_given;              /* NLGEOM= written on the *STEP line */
  PetscBool         nlgeom_default;            /* on by the explicit procedure's default (Abaqus/Explicit's; NLGEOM not written
                                                  and not inherited): not carried into later implicit steps (check.c) */
  PetscBool         no_extrapolation;          /* EXTRAPOLATION=NO: each increment starts from the last converged state */
  PetscReal         dt0, period, dtmin, dtmax; /* data line; defaults dt0=period=1, dtmin=1e-5*period, dtmax=period */
  PetscReal         deltmx;                    /* DELTMX (0 = none) */
  PetscInt          max_inc;                   /* INC= (default 100) */
  TslAmpDefault     amp_default;               /* *STEP, AMPLITUDE=RAMP|STEP; default RAMP for steady, STEP for transient */
  PetscBool         amp_given;                 /* AMPLITUDE= was given explicitly */
  PetscInt          nload;
  TslLoad          *loads;
  PetscInt          nout;
  TslOutputRequest *out;
  TslIncrementControls controls; /* *CONTROLS, PARAMETERS=TIME INCREMENTATION or RESET (given = FALSE: none in this step) */
  TslFieldControls     field_controls[2]; /* *CONTROLS, PARAMETERS=FIELD for the displacement and the temperature field */
  TslTemperatureFile   tfile;             /* *TEMPERATURE, FILE= (given = FALSE: none in this step) */
  /* *RESTART, WRITE in force in this step (the last one given, in this step or before, or in the model data):
   * a restart point every restart_frequency increments, at restart_interval times evenly spaced over the step
   * (NUMBER INTERVAL), and at the step's end (both 0: none; restart_frequency -1: neither given, the dialect's
   * default: every increment in implicit steps, NUMBER INTERVAL=1 in explicit ones; TslRestartDue, docs/running.md
   * "Restart"); restart_overlay: OVERLAY, only the latest point kept */
  PetscInt  restart_frequency, restart_interval;
  PetscBool restart_overlay;
  TslLoc    restart_loc; /* the *RESTART line in force (its place in messages) */
} TslStep;

typedef struct {
  /* files read (deck and *INCLUDEs), for TslLoc */
  PetscInt nfile;
  char   **files;

  char heading[256];

  /* mesh */
  PetscInt   dim; /* 2 or 3, from the element types */
  PetscInt   nnode;
  PetscInt  *node_id;  /* [nnode] */
  PetscReal *node_xyz; /* [3*nnode]; z = 0 in 2D */
  PetscInt   nelem;
  PetscInt  *elem_id;   /* [nelem] */
  PetscInt  *elem_type; /* [nelem] index into the element catalogue */
  PetscInt  *elem_ptr;  /* [nelem+1] offsets into elem_conn */
  PetscInt  *elem_conn; /* deck node ids */
  PetscInt  *elem_line; /* [2*nelem] (file, line) of each element's data line */

  PetscInt    nnset, nelset, nsurface;
  TslSet     *nsets, *elsets;
  TslSurface *surfaces;

  PetscInt               nmaterial, nsection, ninit, namplitude, nequation;
  TslMaterial           *materials;
  TslSection            *sections;
  TslInitialTemperature *init;
  PetscInt               nvinit;
  TslInitialVelocity    *vinit; /* in deck order: a later line for the same dof wins */
  PetscInt               nnodal_thickness;
  TslNodalThickness     *nodal_thickness; /* in deck order (a later line for a node wins); empty after the shells' expansion */
  TslAmplitude          *amplitudes;
  TslEquation           *equations;

  PetscInt        ninteraction, npair, ntie;
  TslInteraction *interactions;
  TslContactPair *pairs;
  TslTie         *ties;

  PetscBool has_absolute_zero, has_stefan_boltzmann;
  PetscReal absolute_zero, stefan_boltzmann; /* *PHYSICAL CONSTANTS */

  PetscInt nstep;
  TslStep *steps;

  /* *RESTART, READ (a restart deck run with -oldjob DIR/JOB: docs/running.md "Restart"): the old job's model and
   * steps 1..restart_read_step come from its deck copy, then this deck's steps; the job continues from the old job's
   * point of that step's increment restart_read_inc (0: no *RESTART, READ), ending the step there with END STEP */
  PetscInt  restart_read_step, restart_read_inc;
  PetscBool restart_read_end_step;
  char      restart_read_job[PETSC_MAX_PATH_LEN]; /* DIR/JOB as -oldjob gave it (also *POST OUTPUT's) */
  TslLoc    restart_read_loc;                      /* the *RESTART, READ (or *POST OUTPUT) line */
  /* *POST OUTPUT (with -oldjob): 0 none; 1 a frame of each of the npost points post[2k] (step), post[2k+1] (increment);
   * 2 (ALL) of every point the old job wrote */
  PetscInt  post_output, npost;
  PetscInt *post;
  /* the POST OUTPUT deck's own field output requests after *POST OUTPUT (npost_out 0: the old steps' requests) */
  TslOutputRequest *post_out;
  PetscInt          npost_out;

  /* Filled by the mesh module on distribution (NULL / 0 in the model read by rank 0):
   * local nodes are ordered owned first, then ghosts. */
  PetscInt  nnode_global, nelem_global;
  PetscInt  nnode_owned;
  PetscInt *node_gnum; /* [nnode] global PETSc node number (contiguous per rank) */
  PetscInt *node_nat;  /* [nnode] natural index = rank of the id among all node ids (output order) */
  PetscInt *elem_nat;  /* [nelem] natural index of the element (output order) */

  /* Id lookups built by TslModelIndex(): ids sorted ascending and their positions. Derived data, so
   * not packed (TslModelUnpack and TslModelSubset rebuild them); the lookups fall back to a linear
   * search when they are missing or stale (built for another nnode/nelem). */
  PetscInt  index_nnode, index_nelem;
  PetscInt *index_node_id, *index_node_pos, *index_elem_id, *index_elem_pos;
} TslModel;

/* Lifetime. TslModelDestroy frees everything and nulls the pointer. */
PetscErrorCode TslModelCreate(TslModel **model);
PetscErrorCode TslModelDestroy(TslModel **model);

/* Formats "file:line" for error messages into buf. */
const char *TslLocString(const TslModel *model, TslLoc loc, char *buf, size_t len);

/* Lookups by name (case-insensitive); return -1 when absent. */
PetscInt TslModelFindNodeSet(const TslModel *model, const char *name);
PetscInt TslModelFindElementSet(const TslModel *model, const char *name);
PetscInt TslModelFindSurface(const TslModel *model, const char *name);
PetscInt TslModelFindMaterial(const TslModel *model, const char *name);
PetscInt TslModelFindAmplitude(const TslModel *model, const char *name);
PetscInt TslModelFindInteraction(const TslModel *model, const char *name);

/* Position of a node / element id in the model's arrays, or -1. Needs TslModelIndex() first. */
PetscErrorCode TslModelIndex(TslModel *model); /* builds the id lookups (call after the mesh changes) */
PetscInt       TslModelNodeIndex(const TslModel *model, PetscInt id);
PetscInt       TslModelElementIndex(const TslModel *model, PetscInt id);

/* Amplitude value at time t (linear interpolation, or the smooth step between points with SMOOTH STEP;
 * constant beyond the ends; the Fourier series with PERIODIC). TslAmplitudeIntegral: its integral over [ta, tb],
 * exact for every definition; TslAmplitudeBound: the largest |value| it can take. */
PetscReal TslAmplitudeEval(const TslAmplitude *amp, PetscReal t);
PetscReal TslAmplitudeIntegral(const TslAmplitude *amp, PetscReal ta, PetscReal tb);
PetscReal TslAmplitudeBound(const TslAmplitude *amp);

/* Serialisation used to broadcast / scatter models. TslModelPack writes the whole model into a
 * newly allocated buffer (caller frees with PetscFree); TslModelUnpack builds a model from it. */
PetscErrorCode TslModelPack(const TslModel *model, char **buf, size_t *len);
PetscErrorCode TslModelUnpack(const char *buf, size_t len, TslModel **model);

/* A copy of the model restricted to the given elements (positions, not ids) and nodes (positions,
 * in the order wanted for the copy). Sets and NODE surfaces keep only members among those nodes,
 * element sets and ELEMENT surfaces only members among those elements; equations keep those with a
 * term on one of those nodes. All non-mesh data is copied whole. */
PetscErrorCode TslModelSubset(const TslModel *model, PetscInt ne, const PetscInt elems[], PetscInt nn, const PetscInt nodes[], TslModel **sub);

/* The deck reader (rank 0 only). Reads path and its *INCLUDEs, fills a model and checks it
 * (TslModelCheck). User errors are PETSC_ERR_USER_INPUT with "file:line: message". */
PetscErrorCode TslDeckRead(const char *path, TslModel **model);
/* The same, with the deck as it was read (*INCLUDEs in place, comments and blank lines left out, a *RESTART, READ
 * replaced by the old job's deck up to its step) in *flat, to free with PetscFree: the deck copy a job with restart
 * points keeps beside them (<job>.restart.inp), from which a restart deck takes the model. */
PetscErrorCode TslDeckReadFlat(const char *path, TslModel **model, char **flat);

/* Consistency checks that need the whole model: undefined sets/surfaces/materials/amplitudes,
 * elements without a section, missing material properties, wrong node counts, duplicate ids,
 * element references to undefined nodes, steps without a procedure; contact pairs (interaction and
 * surfaces defined, main surface element-based, secondary != main) and the interface laws' values;
 * initial velocities (a node or set defined, a displacement dof the elements carry, a node given alone
 * belonging to an element). Prints a warning (once) when initial velocities are given but no step is
 * explicit. */
PetscErrorCode TslModelCheck(TslModel *model);
