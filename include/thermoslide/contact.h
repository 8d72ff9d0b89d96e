/* thermoslide contact kernels: 2D node-to-surface contact for coupled temperature-displacement
 * analysis (plane strain, plane stress, axisymmetric), on linear (line2) and quadratic (line3) faces.
 *
 * Everything here works on plain arrays: no MPI, no PETSc objects. The assembly calls
 * TslContactElement() once per active contact element (one secondary node against one main segment)
 * each Newton iteration, and keeps the per-secondary-node state (TslContactState: projection, anchor, multiplier) itself.
 * docs/contact.md describes the algorithm, formulas, units and signs in full.
 *
 * Conventions (as include/thermoslide/element.h):
 *   - nodal unknowns interleaved per node, (u_x, u_y, theta), and (u_x, u_y, theta, phi) for the
 *     axisymmetric kinematics with twist (TslContactNodeUnknowns); residual = internal - external;
 *     K = dR/du, row-major;
 *   - axisymmetric (with or without twist): x = r, y = z, forces and heat are totals around the
 *     circumference (2 pi r); with twist the slip has a circumferential component as well, the relative
 *     circumferential displacement w = R_s phi_s - R_m(xi) phi_m(xi) (R reference radii, phi the twist
 *     angle, u_theta = R phi as in the elements), and its friction force enters the phi rows as the
 *     moment R f_theta;
 *   - plane: forces and heat are per the given thickness.
 *   - A main segment is one element face of the main surface, its nodes in the face's own order (ends
 *     first, then the midside node: (m1, m2) for line2, (m1, m2, m3) for line3), main body on the left of
 *     m1 -> m2 (counter-clockwise elements). It is the curve x_m(xi) = sum_a N_a(xi) x_a, 0 <= xi <= 1 from
 *     m1 to m2, with the face family's shape functions N_a (TslContactFace). Its tangent is
 *     t = dx_m/dxi, tau = t/|t|, and the outward normal of the main body n = (tau_y, -tau_x) (pointing
 *     towards the secondary side); |t| is the segment's metric (its length for line2).
 *   - Gap g = (x_s - x_m(xi)) . n: positive = open clearance, negative = penetration.
 *   - Slip increment ds = |t| (xi - xi_old) > 0 when the secondary node moves towards m2 relative to the
 *     main surface. The shear stress tT has the sign of the slip it resists: the force on the secondary
 *     node is A (pN n - tT tau), the opposite force acts on the main nodes, distributed by N_a.
 *   - Heat flux q (per area) > 0 flows from the main surface into the secondary node.
 * Units are whatever the deck uses (force, length, time, temperature, energy consistent).
 */
#pragma once
#include <thermoslide/compat.h>
#include <thermoslide/element.h>

#define TSL_CONTACT_MAX_FACE_NODES 3 /* nodes of one main segment (line3) */
/* secondary, the segment's nodes, and the other nodes of the previous and the next segment (smoothing) */
#define TSL_CONTACT_MAX_NODES (1 + TSL_CONTACT_MAX_FACE_NODES + 2 * (TSL_CONTACT_MAX_FACE_NODES - 1))
#define TSL_CONTACT_MAX_NODE_DOF 4 /* (u_x, u_y, theta, phi): phi with twist only */
#define TSL_CONTACT_MAX_DOF      (TSL_CONTACT_MAX_NODES * TSL_CONTACT_MAX_NODE_DOF)

/* Unknowns per node of a contact element: 3 (u_x, u_y, theta), or 4 (u_x, u_y, theta, phi) for the
 * axisymmetric kinematics with twist, whose slip has a circumferential component. */
PetscInt TslContactNodeUnknowns(TslKinematics kin);

/* ---------------------------------------------------------------------------------------------------
 * Face families of contact surfaces
 * ------------------------------------------------------------------------------------------------- */

/* One row per face family (contact/face.c): the element catalogue's face geometry (its shape functions,
 * node count and order; node order: ends first, then the midside node) and what contact adds to it. The
 * kernels are written for any row: a new family is a row. */
typedef enum {
  TSL_CONTACT_FACE_LINE2 = 0, /* 2-node line: the default of a zeroed TslContactInput */
  TSL_CONTACT_FACE_LINE3,     /* 3-node line (end, end, middle) */
  TSL_CONTACT_FACE_NKINDS
} TslContactFaceKind;

typedef struct {
  const TslGeometry *geom; /* the catalogue's face family ("line2", "line3"): name, nnode, ncorner, order, shape */
  PetscInt           nq;   /* Gauss rule on [0, 1] for face integrals (exact for N_a |t| when |t| is a polynomial) */
  PetscReal          q_xi[5], q_w[5];
  /* control points of the face's Bernstein form, hull[i][a]: the face lies in their convex hull */
  PetscReal hull[TSL_CONTACT_MAX_FACE_NODES][TSL_CONTACT_MAX_FACE_NODES];
} TslContactFace;

/* N, dN/dxi and d2N/dxi2 of the face's nodes on the segment parameter xi = (1 + zeta)/2 (zeta the
 * geometry's own coordinate on [-1, 1]); any real xi: the face extends beyond its ends. */
void TslContactFaceShape(const TslContactFace *face, PetscReal xi, PetscReal N[], PetscReal dN[], PetscReal d2N[]);

/* The row of a family (NULL when out of range), and the family with a catalogue geometry name
 * (case-insensitive; -1 when contact does not support that face family). */
const TslContactFace *TslContactFaceGet(TslContactFaceKind kind);
PetscInt              TslContactFaceFind(const char *geometry_name);

/* Position p[2] and tangent t[2] = dx/dxi (either may be NULL) of a face with node coordinates
 * x[2*a + d] (nnode nodes, face order) at parameter xi (any real xi: the extended face). */
PetscErrorCode TslContactFaceEvaluate(TslContactFaceKind kind, const PetscReal x[], PetscReal xi, PetscReal p[], PetscReal t[]);

/* Closest point of p[2] on the extended (unsmoothed) face x[]: the root of (p - x(xi)) . t(xi) = 0 nearest
 * to the projection on the chord m1 -> m2, by safeguarded Newton; *xi is unclamped, limited to [-1, 2]
 * (beyond that the caller re-pairs and precision does not matter). Straight faces (order 1): the chord
 * projection, exactly. */
PetscErrorCode TslContactFaceProject(TslContactFaceKind kind, const PetscReal x[], const PetscReal p[], PetscReal *xi);

/* Bounding box (xmin, ymin, xmax, ymax) of the face x[]: that of its Bernstein control points, which
 * contains the curve. */
PetscErrorCode TslContactFaceBox(TslContactFaceKind kind, const PetscReal x[], PetscReal box[4]);

/* Tributary weights of the nodes of a secondary face, reference coordinates x[]:
 *   w[a] = int N_a ds over the face (a length; line2: L/2, L/2; straight line3 with the midside node in
 *   the middle: L/6, L/6, 2L/3, as the consistent nodal forces of a uniform pressure),
 * and *length = int ds (may be NULL). Integrated with the family's Gauss rule: exact for straight faces
 * (|t| a polynomial), to the rule's accuracy for curved ones. The contact area of a node is w times the
 * thickness or 2 pi r of the node (TslContactOutput.area), summed over the faces that share it. */
PetscErrorCode TslContactFaceIntegrate(TslContactFaceKind kind, const PetscReal x[], PetscReal w[], PetscReal *length);

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
  PetscReal              eps_n;    /* normal penalty stiffness (force/length^3: pressure per penetration) */
  PetscReal              p_offset; /* added to the normal pressure before its <.>: pN = <p_offset + eps_n (-g)>; 0 but for
                                      the kinematic corrector's last evaluation (TslContactKinematicLaw) */

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

/* The law of a node of a kinematic pair (explicit steps, MECHANICAL CONSTRAINT=KINEMATIC): penalty normal
 * with eps_n = eps (the stiffness per area that closes the node's predicted gap in one increment, or that
 * gives it the corrector passes' pressure; no augmentation), and penalty friction's stick with eps_t (the
 * closing stiffness, no elastic slip tolerance), so that a sticking node's predicted slip is undone in the
 * same increment. The thermal
 * interaction and LAGRANGE friction are the law's own. */
void TslContactKinematicLaw(TslContactLaw *law, PetscReal eps, PetscReal eps_t, PetscReal p_offset);

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
  /* twist only: the relative circumferential displacement w = R_s phi_s - R_m(xi) phi_m(xi) (a length)
   * at the start of the increment, and its sticking anchor (the circumferential slip from the anchor is
   * w - w_anchor); unchanged by a move to a neighbouring segment (w is continuous along the surface) */
  PetscReal w_old, w_anchor;
  /* 3D only (TslContactElement3): the second surface parameter of the projection at the start of the
   * increment and of the sticking anchor, in the face geometry's own reference coordinates (xi_old,
   * xi_anchor then hold the first one) */
  PetscReal eta_old, eta_anchor;
} TslContactState;

typedef enum { TSL_CONTACT_OPEN = 0, TSL_CONTACT_STICK, TSL_CONTACT_SLIP } TslContactStatus;

/* Input of one contact element. Node order: 0 = secondary s, 1..nper = the main segment's nodes in face
 * order (nper = nodes of the face family), then the optional neighbour nodes used for smoothing: the nodes
 * of the previous segment other than m1 (the end it shares with this one), in that segment's face order,
 * if x_prev is given, then those of the next segment other than m2, if x_next is given. For line2 that is
 * s, m1, m2, m0, m3; for line3 s, m1, m2, m3 (midside), then p1, p3 of the previous and n2, n3 of the next
 * segment. The neighbours are of the same family as the segment. */
typedef struct {
  TslKinematics      kin;                                  /* plane strain or stress, axisymmetric (with or without twist) */
  TslContactFaceKind face;                                 /* family of the main segments (0 = line2) */
  PetscReal          thickness;                            /* plane models (length); ignored for axisymmetry */
  PetscReal          length;                               /* tributary length of the secondary node on its own surface (reference) */
  PetscReal          x[1 + TSL_CONTACT_MAX_FACE_NODES][2]; /* reference coordinates of s and the segment's nodes */
  PetscReal          u[1 + TSL_CONTACT_MAX_FACE_NODES][TSL_CONTACT_MAX_NODE_DOF]; /* current unknowns (u_x, u_y, theta[, phi]) of the same */
  /* the previous / the next segment's other nodes (see above): reference coordinates [nper-1][2] and
   * unknowns [nper-1][nu], nu = TslContactNodeUnknowns(kin); NULL at a surface end */
  const PetscReal  *x_prev, *u_prev;
  const PetscReal  *x_next, *u_next;
  PetscReal         smoothing; /* fraction s of the segment parameter rounded at each end, 0 <= s < 0.5 */
  PetscReal         dt;        /* increment (time) for the dissipation rate; > 0 when friction heats */
  TslContactState hist;
} TslContactInput;

/* Closest-point (normal) projection of the current secondary position onto the current, smoothed
 * segment: solves (x_s - x_m(xi)) . tau(xi) = 0 for xi by Newton, where tau, n are the smoothed unit
 * tangent and normal. Outputs: *xi unclamped (outside [0,1] when the node is beyond a segment end), *g gap
 * at that projection (on the extended segment), n[2] normal there (any output may be NULL). Thermal
 * unknowns are ignored. */
PetscErrorCode TslContactProject(const TslContactInput *in, PetscReal *xi, PetscReal *g, PetscReal n[]);

/* The main segment of an input at parameter xi (current coordinates): position x[2] and smoothed unit
 * outward normal n[2] (either may be NULL). */
PetscErrorCode TslContactSurfacePoint(const TslContactInput *in, PetscReal xi, PetscReal x[], PetscReal n[]);

/* Which side of the segment an (unclamped) projection lies: -1 before m1 (xi < -tol), +1 beyond m2
 * (xi > 1 + tol), 0 on the segment. The caller re-pairs the node with the neighbouring segment on that side,
 * or, at a surface end, declares it out of contact (no force, no heat). */
PetscInt TslContactProjectionSide(PetscReal xi, PetscReal tol);

/* Re-expresses history parameters when the node moves to the neighbouring segment on `side` (+1 next,
 * -1 previous), to first order in the distance from the shared node: with L_from = |t| of the segment left
 * and L_to = |t| of the segment entered, both at the shared node (the segments' lengths for line2),
 * xi' = (xi - 1) L_from / L_to for side +1, 1 + xi L_from / L_to for side -1, applied to xi_old and
 * xi_anchor so slip and sticking stress carry over. */
PetscErrorCode TslContactStateTransfer(PetscInt side, PetscReal L_from, PetscReal L_to, TslContactState *h);

/* Smoothed unit outward normal at parameter xi of the straight segment x1 -> x2 (line2, current
 * coordinates, 2 each), blending with the neighbouring segments' normals over the fraction s at each end
 * (x0 = start of the previous segment, x3 = end of the next segment, NULL at surface ends). The weight of
 * the neighbour's normal is w = h(1 - xi/s)/2 near m1 (h(t) = 3t^2 - 2t^3, clamped to [0,1]), so at the
 * node both segments give the normalised average normal with zero derivative: the normal field is C1 along
 * the surface. TslContactSurfacePoint does the same for any face family. */
PetscErrorCode TslContactSmoothedNormal(const PetscReal x0[], const PetscReal x1[], const PetscReal x2[], const PetscReal x3[], PetscReal s,
                                        PetscReal xi, PetscReal n[]);

/* ---------------------------------------------------------------------------------------------------
 * The contact element kernel
 * ------------------------------------------------------------------------------------------------- */
typedef struct {
  PetscInt         nnode;            /* 1 + nper + (nper - 1) ((x_prev != NULL) + (x_next != NULL)); R and K have nu*nnode rows */
  PetscInt         nu;               /* unknowns per node (TslContactNodeUnknowns) */
  PetscReal        xi;               /* projection used (= xi_raw unless beyond [-1, 2]) */
  PetscReal        xi_raw;           /* unclamped projection (see TslContactProjectionSide) */
  PetscInt         side;             /* TslContactProjectionSide(xi_raw, 0) */
  PetscReal        normal[2];        /* unit normal used (outward from main) */
  PetscReal        gap;              /* g (length), negative = penetration */
  PetscReal        area;             /* A = length * thickness, or length * 2 pi r_s (reference r of s) */
  PetscReal        pressure;         /* CPRESS = pN >= 0 */
  PetscReal        slip;             /* slip increment ds = |t| (xi - xi_old) (length), CSLIP increment */
  PetscReal        shear;            /* CSHEAR = tT (signed like the slip it resists) */
  PetscReal        slip_dissipative; /* part of ds that dissipates (ds in LAGRANGE mode, plastic slip in PENALTY) */
  /* twist only (zero otherwise): the circumferential components, w = R_s phi_s - R_m(xi) phi_m(xi) */
  PetscReal        w;                     /* relative circumferential displacement (length) */
  PetscReal        slip_circ;             /* circumferential slip increment w - w_old, > 0 when s turns ahead of the main surface */
  PetscReal        shear_circ;            /* circumferential shear stress (signed like the slip it resists) */
  PetscReal        slip_dissipative_circ; /* its dissipative part */
  PetscReal        conductance;      /* k used */
  PetscReal        radiation_C;      /* C used */
  PetscReal        heat_flux;        /* q = q_cond + q_rad per area, main -> secondary (HFLA) */
  PetscReal        dissipation_rate; /* tT * slip_dissipative / dt per area (power/area) */
  PetscReal        heat_generation;  /* eta * dissipation_rate per area */
  TslContactStatus status;
  PetscReal        xi_anchor; /* updated sticking anchor: store with TslContactStateUpdate after convergence */
  PetscReal        w_anchor;  /* updated circumferential anchor (twist) */
  /* 3D only (TslContactElement3; zero in 2D): the second surface parameter (used and unclamped), its anchor,
   * the third component of the normal, and whether the projection lies on the face (0) or beyond an edge
   * (1, by more than the tolerance of TslContactFace3Inside): the caller re-pairs the node then. In 3D,
   * slip/shear are the components along the first unit tangent t1 and slip_circ/shear_circ those along
   * t2 = n x t1 (t1 = the normalised part of dx/dxi orthogonal to n). */
  PetscReal eta, eta_raw, eta_anchor, normal_z;
  PetscInt  outside;
} TslContactOutput;

/* Residual R[nu*nnode] (internal - external: the contact force on a node enters with a minus sign, heat
 * flowing into a node with a minus sign) and consistent (unsymmetric) tangent K = dR/du (row-major,
 * nu*nnode x nu*nnode, may be NULL) of one node-to-segment contact element, plus diagnostics (out, may be
 * NULL). nu = TslContactNodeUnknowns(in->kin); node order as TslContactInput. Without neighbours this is
 * the element of s and the segment's nodes (9 entries for line2, 12 for line3; 12 and 16 with twist).
 *   R_s  = -A (pN n - tT tau),             R_a  = +A N_a (pN n - tT tau),        a = the segment's nodes
 *   Rth_s = -A (q + f eta D),              Rth_a = +A N_a (q - (1 - f) eta D)
 *   Rphi_s = +A tW R_s,                    Rphi_a = -A N_a R_m(xi) tW            (twist only)
 * with N_a the face's shape functions at xi (line2: 1 - xi, xi), (tT, tW) the in-plane and the
 * circumferential shear (Coulomb on the 2-vector: |(tT, tW)| <= mu pN, slip along the trial traction),
 * R_s and R_m(xi) = N_a R_a reference radii,
 * q = k (theta_m - theta_s) + C [(theta_m - theta_Z)^4 - (theta_s - theta_Z)^4],
 * theta_m = N_a theta_a, D = (tT, tW) . (dissipative slip) / dt the dissipation rate per area. Beyond a segment end the element works on the
 * extended segment (xi outside [0,1], frozen only beyond [-1,2]); when out->side != 0 the caller must
 * re-pair or drop the node after convergence (see TslContactProjectionSide). */
PetscErrorCode TslContactElement(const TslContactLaw *law, const TslContactInput *in, PetscReal R[], PetscReal K[], TslContactOutput *out);

/* After an increment converged: xi_old = out->xi, xi_anchor = out->xi_anchor, w_old = out->w,
 * w_anchor = out->w_anchor, and in 3D eta_old = out->eta, eta_anchor = out->eta_anchor (lambda is left to
 * TslContactAugmentedUpdate). */
PetscErrorCode TslContactStateUpdate(const TslContactOutput *out, TslContactState *h);

/* A new contact starts stress-free at parameter xi of the input's segment: xi_old = xi_anchor = xi,
 * w_old = w_anchor = the relative circumferential displacement there (twist; 0 otherwise), lambda = 0.
 * in->hist is not read. */
PetscErrorCode TslContactStateStart(const TslContactInput *in, PetscReal xi, TslContactState *h);

/* ---------------------------------------------------------------------------------------------------
 * 3D node-to-surface (contact/face3.c, contact/kernel3.c): a secondary node against one main face
 *
 * Faces are the catalogue's 2D families used as faces of 3D elements: tri3 (C3D4T, C3D6T ends), quad4
 * (C3D8T family, C3D6T sides) and tri6 (C3D10MT), nodes in the catalogue's face order, whose right-hand
 * normal points out of the main body (towards the secondary side). Surface parameters are the face
 * geometry's own reference coordinates (xi, eta): [-1,1]^2 for quads, the unit triangle for triangles.
 * A main surface may mix families (wedge sides and ends): the family is per face.
 * Nodal unknowns (u_x, u_y, u_z, theta): four per node. Forces and heat are totals on the secondary
 * node's tributary area (TslContactFace3Integrate). Signs and laws as in 2D: g = (x_s - x_m) . n,
 * residual = internal - external, q > 0 from the main surface into the secondary node.
 * ------------------------------------------------------------------------------------------------- */
#define TSL_CONTACT3_MAX_FACE_NODES 6 /* tri6: the largest face of the catalogue's 3D families (fits TSL_CONTACT_MAX_DOF) */
#define TSL_CONTACT3_NU             4 /* (u_x, u_y, u_z, theta) */

/* Face family of a catalogue geometry name for 3D contact (tri3, quad4, tri6; case-insensitive), -1 when
 * 3D contact does not support it; its node count. */
PetscInt TslContactFace3Find(const char *geometry_name);
PetscInt TslContactFace3Nodes(PetscInt kind);

/* Position p[3] and unit normal n[3] (right-hand rule on the face order; either may be NULL) of a face,
 * node coordinates x[3*a + d], at reference coordinates xi[2] (any real values: the extended face). */
PetscErrorCode TslContactFace3Evaluate(PetscInt kind, const PetscReal x[], const PetscReal xi[], PetscReal p[], PetscReal n[]);

/* Closest point of p[3] on the extended (unsmoothed) face x[]: reference coordinates xi[2], by
 * safeguarded Newton from the face centre (exact in one step for flat tri3); limited to a band of one face
 * size around the face (beyond it the caller re-pairs and precision does not matter). */
PetscErrorCode TslContactFace3Project(PetscInt kind, const PetscReal x[], const PetscReal p[], PetscReal xi[]);

/* Whether reference coordinates xi[2] lie on the face, with a tolerance tol in reference units
 * (tri: xi, eta >= -tol, xi + eta <= 1 + tol; quad: |xi|, |eta| <= 1 + tol). */
PetscBool TslContactFace3Inside(PetscInt kind, const PetscReal xi[], PetscReal tol);

/* Bounding box (xmin, ymin, zmin, xmax, ymax, zmax) of the face x[]: of the control points of its
 * Bernstein form, which contains it (its nodes for the linear families). */
PetscErrorCode TslContactFace3Box(PetscInt kind, const PetscReal x[], PetscReal box[6]);
/* How far the box of a face (TslContactFace3Box) can move when no node moves by more than 1 in any
 * coordinate: the largest sum of |hull coefficients| of a control point (1 for flat families, more for
 * quadratic ones, whose control points extrapolate the nodes). */
PetscReal TslContactFace3HullBound(PetscInt kind);

/* Tributary areas of the nodes of a secondary face, reference coordinates x[]: w[a] = int N_a dA (tri3,
 * quad4); tri6 (whose consistent corner weights are zero) takes the weights of its linear subdivision into
 * four tri3, A/12 per corner and A/4 per midside node of a flat face, as the modified elements do for
 * pressure; *area = int dA (may be NULL). Sums to the face area exactly for flat faces. */
PetscErrorCode TslContactFace3Integrate(PetscInt kind, const PetscReal x[], PetscReal w[], PetscReal *area);

/* Shape functions N[] of the face family `kind` at the reference coordinates xi[2]. */
void TslContactFace3ShapeValues(PetscInt kind, const PetscReal xi[2], PetscReal N[]);

/* Input of one 3D contact element: node 0 is the secondary node s, nodes 1..nper the main face's in face
 * order. */
typedef struct {
  PetscInt  face;                                            /* TslContactFace3Find family of the main face */
  PetscReal area;                                            /* tributary area of s (reference) */
  PetscReal x[1 + TSL_CONTACT3_MAX_FACE_NODES][3];           /* reference coordinates */
  PetscReal u[1 + TSL_CONTACT3_MAX_FACE_NODES][TSL_CONTACT3_NU]; /* current unknowns (u_x, u_y, u_z, theta) */
  /* Smoothing: unit normals at the face's nodes (the average of the normals of the main faces around each
   * node, computed by the caller from the converged configuration at the start of the increment and held
   * fixed during it). The normal used is n = normalise((1 - beta) n_face + beta sum_a N_a nn_a), beta = 1
   * on the face's edges, falling smoothly to 0 at the fraction `smoothing` of the face from every edge,
   * so that neighbouring faces agree on their shared edge. smoothing = 0: the face's own normal (nn ignored). */
  PetscReal nodal_normal[TSL_CONTACT3_MAX_FACE_NODES][3];
  PetscReal smoothing;
  PetscReal dt;   /* increment (time), > 0 when friction heats */
  TslContactState hist; /* xi_old, eta_old, xi_anchor, eta_anchor, lambda (w_* unused) */
  /* Where the projection's Newton iterations start when has_guess is set and it lies inside the face (else
   * at xi_old, eta_old, or the face's centre): the same face's last projection, one iteration from converged
   * when the state has not moved since (a Jacobian after the residual at the same state). The result is the
   * same projection to its tolerance. */
  PetscReal guess[2];
  PetscBool has_guess;
} TslContactInput3;

/* Residual R[4*(1 + nper)] and consistent tangent K = dR/du (row-major, may be NULL) of one 3D node-to-face
 * contact element, plus diagnostics (out, may be NULL; out->nnode = 1 + nper, out->nu = 4):
 *   R_s = -A (pN n - tT),  R_a = +A N_a (pN n - tT)     (tT the tangential traction vector, in the plane)
 *   Rth_s = -A (q + f eta D),  Rth_a = +A N_a (q - (1 - f) eta D)
 * The projection solves (x_s - x_m(xi)) . a_alpha = 0 (a_alpha the face's tangents made orthogonal to the
 * smoothed normal); slip from the start of the increment ds and from the anchor e are the tangential parts
 * of x_m(xi) - x_m(xi_old) and x_m(xi) - x_m(xi_anchor) on the current face; Coulomb friction (penalty with
 * return mapping, or LAGRANGE) on the 2-vector of their components along (t1, t2), as 2D's law with twist.
 * The updated anchor (out->xi_anchor, eta_anchor) is the face point whose tangential offset from x_m(xi)
 * is the elastic slip. Beyond an edge the element works on the extended face (reference coordinates
 * limited to a band of one face size); out->outside asks the caller to re-pair after convergence. */
PetscErrorCode TslContactElement3(const TslContactLaw *law, const TslContactInput3 *in, PetscReal R[], PetscReal K[], TslContactOutput *out);

/* A new contact starts stress-free at xi[2] of the input's face: xi_old = xi_anchor = xi[0], eta_old =
 * eta_anchor = xi[1], lambda = 0, w_* = 0. */
PetscErrorCode TslContactStateStart3(PetscReal xi[], TslContactState *h);

/* Moves history to another face when a node is re-paired: the face points of xi_old/eta_old and of the
 * anchor on the face `from` (current coordinates x_from[], family kind_from) are projected onto the face
 * `to` (x_to[], kind_to, extended) and their reference coordinates there replace them; lambda is kept. */
PetscErrorCode TslContactStateTransfer3(PetscInt kind_from, const PetscReal x_from[], PetscInt kind_to, const PetscReal x_to[], TslContactState *h);

/* ---------------------------------------------------------------------------------------------------
 * Candidate search: uniform bin grid over the main segments' bounding boxes
 * ------------------------------------------------------------------------------------------------- */
typedef struct _n_TslContactBinGrid *TslContactBinGrid;

/* Builds the grid over nseg segments, seg_x[4*i..4*i+3] = two opposite corners of segment i's bounding box
 * (x1, y1, x2, y2) in current coordinates: the end points of a straight segment, TslContactFaceBox of a
 * curved one. Each box is inflated by margin (length, >= 0). The bin size is about the mean inflated box size, so a segment covers
 * O(1) bins. The grid copies what it needs; destroy with TslContactBinGridDestroy. */
PetscErrorCode TslContactBinGridCreate(PetscInt nseg, const PetscReal seg_x[], PetscReal margin, TslContactBinGrid *grid);
/* The same in dim = 2 or 3: seg_x[2*dim*i ..] = two opposite corners of face i's box (x1, y1[, z1], x2, y2[, z2]);
 * queries then take p[dim]. TslContactBinGridCreate is dim = 2. */
PetscErrorCode TslContactBinGridCreateDim(PetscInt dim, PetscInt nseg, const PetscReal seg_x[], PetscReal margin, TslContactBinGrid *grid);
PetscErrorCode TslContactBinGridDestroy(TslContactBinGrid *grid);

/* Candidate segments for point p[2]: every segment whose inflated box contains a point within distance
 * radius (box test, radius >= 0) of p. Writes at most cap indices (ascending) to cand[], sets *ncand to
 * the number found (may exceed cap: call again with a larger array) and *nbins (may be NULL) to the
 * number of bins visited. Not thread safe (uses the grid's marker array). */
PetscErrorCode TslContactBinGridQuery(TslContactBinGrid grid, const PetscReal p[], PetscReal radius, PetscInt cap, PetscInt cand[], PetscInt *ncand,
                                      PetscInt *nbins);

/* The same query into a growing array: *cand (PetscMalloc'ed, *cap entries) is enlarged when more faces
 * than *cap are found, so that all *ncand candidates are listed. */
PetscErrorCode TslContactBinGridQueryGrow(TslContactBinGrid grid, const PetscReal p[], PetscReal radius, PetscInt *cap, PetscInt **cand, PetscInt *ncand);

/* Number of bins in x and in the other directions (y, or y times z in 3D; for logs and tests). */
PetscErrorCode TslContactBinGridGetSize(TslContactBinGrid grid, PetscInt *nx, PetscInt *ny);
