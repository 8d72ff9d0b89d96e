/* thermoslide contact kernels: 2D node-to-segment contact for coupled temperature-displacement
 * analysis (plane strain, plane stress, axisymmetric).
 *
 * Everything here works on plain arrays: no MPI, no PETSc objects. The assembly calls
 * TslContactElement() once per active contact element (one secondary node against one main segment)
 * each Newton iteration, and keeps the per-secondary-node history (TslContactHistory) itself.
 * docs/contact.md describes the algorithm, formulas, units and signs in full.
 *
 * Conventions (as include/thermoslide/element.h):
 *   - nodal unknowns interleaved per node, (u_x, u_y, theta); residual = internal - external;
 *     K = dR/du, row-major;
 *   - axisymmetric: x = r, y = z, forces and heat are totals around the circumference (2 pi r);
 *   - plane: forces and heat are per the given thickness.
 *   - A main segment (m1, m2) is given in the order of its element face, i.e. with the main body on the
 *     left of m1 -> m2 (counter-clockwise elements). Its unit tangent is tau = (x2 - x1)/|x2 - x1| and
 *     the outward normal of the main body is n = (tau_y, -tau_x) (pointing towards the secondary side).
 *   - Gap g = (x_s - x_m(xi)) . n: positive = open clearance, negative = penetration.
 *   - Slip increment ds = L (xi - xi_old) > 0 when the secondary node moves towards m2 relative to the
 *     main surface (L = current segment length). The shear stress tT has the sign of the slip it resists:
 *     the force on the secondary node is A (pN n - tT tau), the opposite force acts on the main nodes.
 *   - Heat flux q (per area) > 0 flows from the main surface into the secondary node.
 * Units are whatever the deck uses (force, length, time, temperature, energy consistent).
 */
#pragma once
#include <thermoslide/compat.h>
#include <thermoslide/element.h>

#define TSL_CONTACT_MAX_NODES 5 /* secondary, m1, m2, previous-segment node, next-segment node */
#define TSL_CONTACT_MAX_DOF   (TSL_CONTACT_MAX_NODES * 3)

/* ---------------------------------------------------------------------------------------------------
 * Tables
 * ------------------------------------------------------------------------------------------------- */

/* Piecewise-linear table y(x) through n points (x[] strictly increasing; n >= 1), constant beyond the
 * ends (dydx = 0 there). At an interior breakpoint the slope of the interval to the right is returned.
 * Outputs: *y, *dydx (may be NULL). Errors (PETSC_ERR_ARG_OUTOFRANGE / WRONG) for n < 1 or unsorted x. */
PetscErrorCode TslTableEvaluate(PetscInt n, const PetscReal x[], const PetscReal y[], PetscReal arg, PetscReal *value, PetscReal *dvalue);

/* ---------------------------------------------------------------------------------------------------
 * Interaction law (one *SURFACE INTERACTION)
 * ------------------------------------------------------------------------------------------------- */
typedef enum {
  TSL_CONTACT_NORMAL_PENALTY = 0, /* pN = eps_n <-g> */
  TSL_CONTACT_NORMAL_AUGMENTED    /* pN = <lambda + eps_n (-g)>, lambda updated between augmentations */
} TslContactNormalMethod;

typedef enum {
  TSL_CONTACT_FRICTION_NONE = 0, /* frictionless */
  TSL_CONTACT_FRICTION_PENALTY,  /* Coulomb with elastic slip (stiffness eps_t), return mapping */
  TSL_CONTACT_FRICTION_LAGRANGE  /* stick-free Coulomb: tT = mu pN sign(ds), sign regularised for |ds| < slip_tol:
                                    all relative motion beyond slip_tol dissipates (Abaqus "Lagrange friction") */
} TslContactFrictionMethod;

typedef enum {
  TSL_CONTACT_CONDUCTANCE_NONE = 0,
  TSL_CONTACT_CONDUCTANCE_PRESSURE, /* k(pN), heat conducted only while closed (touching: k(0)) */
  TSL_CONTACT_CONDUCTANCE_CLEARANCE /* k(d), d = <g>; k = 0 for d beyond the last table clearance (Abaqus rule) */
} TslContactConductanceKind;

typedef struct {
  TslContactNormalMethod normal;
  PetscReal              eps_n; /* normal penalty stiffness (force/length^3: pressure per penetration) */

  TslContactFrictionMethod friction;
  PetscReal                mu;           /* Coulomb coefficient */
  PetscReal                eps_t;        /* tangential penalty stiffness (pressure per slip length), PENALTY mode */
  PetscReal                elastic_slip; /* PENALTY mode: > 0 replaces eps_t by mu pN / elastic_slip, so that a node
                                            sticks while its elastic slip is at most elastic_slip (a length; the
                                            dialect's SLIP TOLERANCE times the facet size) */
  PetscReal slip_tol;                    /* LAGRANGE mode: |ds| below which sign(ds) is regularised (length) */

  /* gap conductance table: k_value[i] at k_arg[i] (pressure or clearance, increasing) */
  TslContactConductanceKind conductance;
  PetscInt                  k_n;
  const PetscReal          *k_arg, *k_value; /* k: power/(area temperature) */

  /* gap radiation: effective view factor table F(d) (d clearance; first value below the table, zero beyond its last clearance), emissivities
   * of the main (A) and secondary (B) surfaces, Stefan-Boltzmann constant, absolute zero. F_n = 0: none. */
  PetscInt         F_n;
  const PetscReal *F_clearance, *F_value;
  PetscReal        eps_main, eps_secondary, sigma, theta_zero;

  /* gap heat generation: eta = fraction of frictional dissipation converted to heat; f = fraction of that heat
   * into the SECONDARY surface, (1 - f) into the main surface (Abaqus *GAP HEAT GENERATION convention). */
  PetscReal eta, f;
} TslContactLaw;

/* Fills a law with defaults: penalty normal (eps_n = 0: caller must set it), no friction, no thermal
 * interaction, slip_tol = 1e-12, eta = 1, f = 0.5, sigma = 0, theta_zero = 0, eps_* = 1. */
PetscErrorCode TslContactLawSetDefaults(TslContactLaw *law);

/* Gap radiation constant (Abaqus Theory Guide, "Thermal contact properties"):
 *   C = F sigma / (1/eps_A + 1/eps_B - 1)
 * sigma Stefan-Boltzmann constant, F effective view factor (0..1), eps_A/eps_B emissivities (0..1].
 * Units of C: power / (area temperature^4). dC_dF may be NULL. */
PetscErrorCode TslGapRadiationCoefficient(PetscReal sigma, PetscReal F, PetscReal eps_A, PetscReal eps_B, PetscReal *C, PetscReal *dC_dF);

/* Augmented-Lagrange multiplier update between augmentations (caller-owned, per secondary node):
 *   lambda_new = <lambda + eps_n (-g)>   (the converged contact pressure of this augmentation).
 * *change returns |lambda_new - lambda| for the caller's augmentation convergence test (may be NULL). */
PetscErrorCode TslContactAugmentedUpdate(PetscReal eps_n, PetscReal g, PetscReal *lambda, PetscReal *change);

/* ---------------------------------------------------------------------------------------------------
 * Geometry of one contact element
 * ------------------------------------------------------------------------------------------------- */

/* History the caller keeps per secondary node, from the converged end of the previous increment. */
typedef struct {
  PetscReal xi_old;    /* projection parameter on the current segment at the start of the increment */
  PetscReal xi_anchor; /* sticking anchor (PENALTY friction): tT = eps_t L (xi - xi_anchor) while sticking */
  PetscReal lambda;    /* augmented-Lagrange multiplier (pressure), AUGMENTED normal only */
} TslContactHistory;

typedef enum { TSL_CONTACT_OPEN = 0, TSL_CONTACT_STICK, TSL_CONTACT_SLIP } TslContactStatus;

/* Input of one contact element. Node order: 0 = secondary s, 1 = m1, 2 = m2, then the optional
 * neighbour nodes used for smoothing: m0 (start of the previous segment m0 -> m1) if x_prev is given,
 * then m3 (end of the next segment m2 -> m3) if x_next is given. */
typedef struct {
  TslKinematics     kin;             /* TSL_KIN_PLANE_STRAIN, TSL_KIN_PLANE_STRESS or TSL_KIN_AXISYMMETRIC */
  PetscReal         thickness;       /* plane models (length); ignored for axisymmetry */
  PetscReal         length;          /* tributary length of the secondary node on its own surface (reference) */
  PetscReal         x[3][2];         /* reference coordinates of s, m1, m2 */
  PetscReal         u[3][3];         /* current unknowns (u_x, u_y, theta) of s, m1, m2 */
  const PetscReal  *x_prev, *u_prev; /* m0: reference coords [2], unknowns [3]; NULL at a surface end */
  const PetscReal  *x_next, *u_next; /* m3: idem */
  PetscReal         smoothing;       /* fraction s of the segment length rounded at each end, 0 <= s < 0.5 */
  PetscReal         dt;              /* increment (time) for the dissipation rate; > 0 when friction heats */
  TslContactHistory hist;
} TslContactInput;

/* Closest-point (normal) projection of the current secondary position onto the current, smoothed
 * segment: solves (x_s - x_m(xi)) . tau(xi) = 0 for xi by Newton, where tau, n are the smoothed unit
 * tangent and normal. Outputs: *xi unclamped (outside [0,1] when the node is beyond a segment end), *g gap
 * at that projection (on the extended segment), n[2] normal there (any output may be NULL). Thermal
 * unknowns are ignored. */
PetscErrorCode TslContactProject(const TslContactInput *in, PetscReal *xi, PetscReal *g, PetscReal n[]);

/* Which side of the segment an (unclamped) projection lies: -1 before m1 (xi < -tol), +1 beyond m2
 * (xi > 1 + tol), 0 on the segment. The caller re-pairs the node with the neighbouring segment on that side,
 * or, at a surface end, declares it out of contact (no force, no heat). */
PetscInt TslContactProjectionSide(PetscReal xi, PetscReal tol);

/* Re-expresses history parameters when the node moves to the neighbouring segment on `side` (+1 next,
 * -1 previous): xi' = (xi - 1) L_from / L_to for side +1, 1 + xi L_from / L_to for side -1, applied to
 * xi_old and xi_anchor so slip and sticking stress carry over. */
PetscErrorCode TslContactHistoryTransfer(PetscInt side, PetscReal L_from, PetscReal L_to, TslContactHistory *h);

/* Smoothed unit outward normal at parameter xi of segment x1 -> x2 (current coordinates, 2 each), blending
 * with the neighbouring segments' normals over the fraction s at each end (x0 = start of the previous
 * segment, x3 = end of the next segment, NULL at surface ends). The weight of the neighbour's normal is
 * w = h(1 - xi/s)/2 near m1 (h(t) = 3t^2 - 2t^3, clamped to [0,1]), so at the node both segments give the
 * normalised average normal with zero derivative: the normal field is C1 along the surface. */
PetscErrorCode TslContactSmoothedNormal(const PetscReal x0[], const PetscReal x1[], const PetscReal x2[], const PetscReal x3[], PetscReal s,
                                        PetscReal xi, PetscReal n[]);

/* ---------------------------------------------------------------------------------------------------
 * The contact element kernel
 * ------------------------------------------------------------------------------------------------- */
typedef struct {
  PetscInt         nnode;            /* 3 + (x_prev != NULL) + (x_next != NULL); R and K have 3*nnode rows */
  PetscReal        xi;               /* projection used (= xi_raw unless beyond [-1, 2]) */
  PetscReal        xi_raw;           /* unclamped projection (see TslContactProjectionSide) */
  PetscInt         side;             /* TslContactProjectionSide(xi_raw, 0) */
  PetscReal        normal[2];        /* unit normal used (outward from main) */
  PetscReal        gap;              /* g (length), negative = penetration */
  PetscReal        area;             /* A = length * thickness, or length * 2 pi r_s (reference r of s) */
  PetscReal        pressure;         /* CPRESS = pN >= 0 */
  PetscReal        slip;             /* slip increment ds = L (xi - xi_old) (length), CSLIP increment */
  PetscReal        shear;            /* CSHEAR = tT (signed like the slip it resists) */
  PetscReal        slip_dissipative; /* part of ds that dissipates (ds in LAGRANGE mode, plastic slip in PENALTY) */
  PetscReal        conductance;      /* k used */
  PetscReal        radiation_C;      /* C used */
  PetscReal        heat_flux;        /* q = q_cond + q_rad per area, main -> secondary (HFLA) */
  PetscReal        dissipation_rate; /* tT * slip_dissipative / dt per area (power/area) */
  PetscReal        heat_generation;  /* eta * dissipation_rate per area */
  TslContactStatus status;
  PetscReal        xi_anchor; /* updated sticking anchor: store with TslContactHistoryUpdate after convergence */
} TslContactOutput;

/* Residual R[3*nnode] (internal - external: the contact force on a node enters with a minus sign, heat
 * flowing into a node with a minus sign) and consistent (unsymmetric) tangent K = dR/du (row-major,
 * 3*nnode x 3*nnode, may be NULL) of one node-to-segment contact element, plus diagnostics (out, may be
 * NULL). Node order as TslContactInput. With no neighbours (or s = 0 and no neighbours) this is the
 * 9-entry / 9x9 element of s, m1, m2.
 *   R_s  = -A (pN n - tT tau),             R_a  = +A N_a (pN n - tT tau),        a = m1, m2
 *   Rth_s = -A (q + f eta D),              Rth_a = +A N_a (q - (1 - f) eta D)
 * with N_1 = 1 - xi, N_2 = xi, q = k (theta_m - theta_s) + C [(theta_m - theta_Z)^4 - (theta_s - theta_Z)^4],
 * theta_m = N_a theta_a, D the dissipation rate per area. Beyond a segment end the element works on the
 * extended segment (xi outside [0,1], frozen only beyond [-1,2]); when out->side != 0 the caller must
 * re-pair or drop the node after convergence (see TslContactProjectionSide). */
PetscErrorCode TslContactElement(const TslContactLaw *law, const TslContactInput *in, PetscReal R[], PetscReal K[], TslContactOutput *out);

/* After an increment converged: xi_old = out->xi, xi_anchor = out->xi_anchor (lambda is left to
 * TslContactAugmentedUpdate). */
PetscErrorCode TslContactHistoryUpdate(const TslContactOutput *out, TslContactHistory *h);

/* ---------------------------------------------------------------------------------------------------
 * Candidate search: uniform bin grid over the main segments' bounding boxes
 * ------------------------------------------------------------------------------------------------- */
typedef struct _n_TslContactBinGrid *TslContactBinGrid;

/* Builds the grid over nseg segments, seg_x[4*i..4*i+3] = (x1, y1, x2, y2) in current coordinates, each box
 * inflated by margin (length, >= 0). The bin size is about the mean inflated box size, so a segment covers
 * O(1) bins. The grid copies what it needs; destroy with TslContactBinGridDestroy. */
PetscErrorCode TslContactBinGridCreate(PetscInt nseg, const PetscReal seg_x[], PetscReal margin, TslContactBinGrid *grid);
PetscErrorCode TslContactBinGridDestroy(TslContactBinGrid *grid);

/* Candidate segments for point p[2]: every segment whose inflated box contains a point within distance
 * radius (box test, radius >= 0) of p. Writes at most cap indices (ascending) to cand[], sets *ncand to
 * the number found (may exceed cap: call again with a larger array) and *nbins (may be NULL) to the
 * number of bins visited. Not thread safe (uses the grid's marker array). */
PetscErrorCode TslContactBinGridQuery(TslContactBinGrid grid, const PetscReal p[], PetscReal radius, PetscInt cap, PetscInt cand[], PetscInt *ncand,
                                      PetscInt *nbins);

/* Number of bins in x and y (for logs and tests). */
PetscErrorCode TslContactBinGridGetSize(TslContactBinGrid grid, PetscInt *nx, PetscInt *ny);
