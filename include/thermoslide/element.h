/* thermoslide element catalogue and element kernels.
 *
 * One table row per deck type name (CPE4T, CAX4T, C3D8T, ...). A row names a geometry family
 * (shape functions, faces, quadrature) and a kinematics / formulation; adding a type is a row plus,
 * at most, a small kernel. Nothing outside src/element/ may test for a particular type.
 *
 * Kernels work on plain arrays: no MPI, no PETSc objects, so they can be unit-tested alone.
 *
 * Nodal unknowns are interleaved per node in the order of the type's node_dof[] (displacements, then
 * theta last), ndof of them.
 * Voigt order for stress/strain output: 11, 22, 33, 12, 13, 23 (engineering shear strain).
 * For axisymmetric elements x = r, y = z; 11 = rr, 22 = zz, 33 = hoop, 12 = rz; integrals include 2*pi*r,
 * so forces and heat are totals around the circumference.
 */
#pragma once
#include <thermoslide/compat.h>
#include <thermoslide/material.h>

#define TSL_MAX_ELEM_NODES 27
#define TSL_MAX_FACES      6
#define TSL_MAX_FACE_NODES 9
#define TSL_MAX_QP         27
#define TSL_MAX_ELEM_DOF   (TSL_MAX_ELEM_NODES * 4)
#define TSL_MAX_SUB        8 /* linear sub-elements of a second-order family (tet10: 8 tet4) */
#define TSL_MAX_SUB_NODES  4

typedef struct {
  PetscInt  n;
  PetscReal xi[TSL_MAX_QP][3];
  PetscReal w[TSL_MAX_QP];
  PetscInt  degree; /* polynomial degree integrated exactly: per coordinate for the tensor-product rules of
                       line, quad and hex; total degree for triangles, tetrahedra and wedges */
} TslQuadrature;

/* A geometry family: reference element, shape functions, faces. Node numbering is the dialect's
 * (corners first, then midside nodes). Faces are numbered as in the dialect (S1..S6), face_node[]
 * lists the element-local node positions of each face in an order whose outward normal follows the
 * right-hand rule (3D) or whose edge direction keeps the body on the left (2D, counter-clockwise
 * elements); a quadratic face lists its corners first, then its midside nodes in the face family's
 * own order. Reference elements: [-1,1]^dim (line, quad, hex), the unit simplex (tri, tet: node 1
 * at the origin) and the unit triangle times [-1,1] (wedge). The families live in geometry.c. */
typedef struct TslGeometry {
  const char               *name; /* "quad4", "hex8", ... */
  PetscInt                  dim;  /* parametric dimension */
  PetscInt                  nnode;
  PetscInt                  ncorner; /* vertex nodes; they come first */
  PetscInt                  order;   /* 1 (linear) or 2 (quadratic) */
  PetscInt                  nface;
  PetscInt                  face_nnode[TSL_MAX_FACES];
  PetscInt                  face_node[TSL_MAX_FACES][TSL_MAX_FACE_NODES];
  const struct TslGeometry *face_geom[TSL_MAX_FACES];                 /* family of each face (line2, quad4, ...) */
  void (*shape)(const PetscReal xi[], PetscReal N[], PetscReal dN[]); /* dN: [nnode][dim] */
  PetscReal     node_xi[TSL_MAX_ELEM_NODES][3];                       /* reference coordinates of the nodes */
  PetscReal     ref_volume;                                           /* measure of the reference element */
  TslQuadrature full, reduced;
  /* The rule when the family is the face of an element (line2, line3, tri3, tri6, quad4): exact for the
   * product of two of its shape functions (degree 2 order; lines one more, for the r of axisymmetric
   * faces), so film and flux integrals are the consistent ones. n = 0 for a family that is never a face. */
  TslQuadrature as_face;
  /* The rule of the lumping weights (HRZ: int N_a^2 dV, of degree twice the order) where the full rule does
   * not integrate them exactly (tri6, tet10); n = 0: the full rule. */
  TslQuadrature lump;
  PetscInt      xdmf_type; /* XDMF mixed-topology cell type id */
  /* The cell's nodes in XDMF's (VTK's) order: the family's node xdmf_order[k] is the cell's k-th; NULL: the family's
   * own order. A wedge's base 1-2-3 runs the other way round there (VTK: its normal points away from 4-5-6). */
  const PetscInt *xdmf_order;
  /* Linear subdivision of a second-order family (line3: 2 line2, tri6: 4 tri3, tet10: 8 tet4; nsub = 0
   * otherwise). The "modified" types lump capacity and pressure loads on it, where the quadratic shape
   * functions would give zero or negative corner weights. sub_node[s][] are element-local node
   * positions, ordered so that a sub-element has a positive Jacobian when its parent has. */
  PetscInt                  nsub;
  const struct TslGeometry *sub_geom;
  PetscInt                  sub_node[TSL_MAX_SUB][TSL_MAX_SUB_NODES];
} TslGeometry;

typedef enum {
  TSL_KIN_PLANE_STRAIN = 0,
  TSL_KIN_PLANE_STRESS,
  TSL_KIN_GENERALIZED_PLANE_STRAIN,
  TSL_KIN_AXISYMMETRIC,
  TSL_KIN_AXISYMMETRIC_TWIST,
  TSL_KIN_SOLID3D,
  TSL_KIN_CONTINUUM_SHELL,
  TSL_NKIN
} TslKinematics;

#define TSL_MAX_NODE_DOF 4

/* Rows of the kinematics and formulation tables (element_impl.h): opaque outside src/element/. */
typedef struct TslKinematicsRow TslKinematicsRow;
typedef struct TslFormulation   TslFormulation;

/* One deck type: a geometry family, a kinematics (plane strain, plane stress, axisymmetric, 3D: the
 * strain, the measure dV and the rigid modes) and a formulation (integration, hourglass control, hybrid
 * pressure, lumping: the operations). The row owns no behaviour of its own; everything a caller needs
 * goes through the functions below, so nothing outside src/element/ tests for a type or a kinematics. */
typedef struct {
  const char           *name; /* deck type name, upper case */
  const TslGeometry    *geom;
  const TslFormulation *form;
  /* the kinematics and what follows from it (one macro per kinematics in catalogue.c fills these) */
  TslKinematics kin;
  PetscInt      dim;                         /* spatial dimension of the model (2 or 3) */
  PetscInt      ndof;                        /* unknowns per node */
  PetscInt      node_dof[TSL_MAX_NODE_DOF];  /* the dialect's dof number of each nodal unknown: 1..3, 5, 11; 0 unused */
  PetscInt      nextra;                      /* extra nodes at the end of the element's node list (CPEG: the reference node) */
  PetscInt      extra_dof[TSL_MAX_NODE_DOF]; /* the dialect's dofs of the extra node's slots (CPEG: 3, 4, 5), 0 unused */
  PetscBool     pore;                        /* a pore pressure type (CPE4PT, ...): its dof 8 exists in the dialect and is
                                                not active in the procedures thermoslide runs (docs/elements.md) */
  const char   *description;                 /* for docs and -help */
} TslElementType;

/* Catalogue lookups. TslElementTypeFind is case-insensitive and returns -1 for an unknown name. */
PetscInt              TslElementTypeCount(void);
const TslElementType *TslElementTypeGet(PetscInt index);
PetscInt              TslElementTypeFind(const char *name);
/* Is the row's name only the coupled reading of a CalculiX mechanical name (CPE6T for CPE6: no such type in the
 * dialect), so that a deck may not name it directly? */
PetscBool TslElementTypeMechanicalOnly(const TslElementType *t);
/* Is the type a heat-transfer one (DC2D4, DC3D8, ...): the temperature its only unknown? */
static inline PetscBool TslElementTypeHeatOnly(const TslElementType *t)
{
  return t->ndof == 1 ? PETSC_TRUE : PETSC_FALSE;
}
/* The catalogue index of the heat-transfer type with t's interpolation and measure (t itself for a DC type), -1
 * if there is none (catalogue.c). */
PetscInt TslElementTypeHeatCounterpart(const TslElementType *t);
/* Position of the temperature among a node's unknowns (the last one). */
static inline PetscInt TslElementTypeThetaSlot(const TslElementType *t)
{
  return t->ndof - 1;
}
/* Does the type take pressure loads on the linear subdivision of its face `face` (0-based) rather than on
 * the face's own shape functions? The modified types on their quadratic 3D faces (tri6 -> 4 tri3), where the
 * quadratic corner weights would be zero or negative. Contact follows it: such a face on a main surface is
 * its sub-faces (src/mesh/distribute.c). */
PetscBool TslElementTypeSubdividedFace(const TslElementType *t, PetscInt face);
/* Do the type's kernels take finite strain (TslElementInput.nlgeom)? All but the incompatible-mode types. */
PetscBool TslElementTypeFiniteStrain(const TslElementType *t);
/* Does the type take Mises plasticity (*PLASTIC; kernels.c)? If not, *why names what it lacks. */
PetscBool TslElementTypePlasticSupported(const TslElementType *t, const char **why);
/* Short names of the type's formulation and kinematics (docs, messages). */
const char *TslElementTypeFormulationName(const TslElementType *t);
const char *TslElementTypeKinematicsName(const TslElementType *t);
/* Do two types share their kinematics (may they form one body)? May they be in one model (the same
 * nodal unknowns and the same measure: no axisymmetric body beside a planar one)? */
PetscBool TslElementTypeSameKinematics(const TslElementType *a, const TslElementType *b);
PetscBool TslElementTypeSameModel(const TslElementType *a, const TslElementType *b);
/* What other modules need of a kinematics (contact: the measure of an interface and its slip
 * components): does dV revolve about the axis (2 pi r), does it carry a twist unknown? */
PetscBool TslKinematicsRevolves(TslKinematics kin);
PetscBool TslKinematicsTwists(TslKinematics kin);
/* Does the type carry dialect dof number dof at its nodes? The list of its dofs ("1, 2, 11") in buf. */
PetscBool   TslElementTypeHasDof(const TslElementType *t, PetscInt dof);
const char *TslElementTypeDofList(const TslElementType *t, char *buf, size_t len);
/* Rigid-body modes the kinematics admits at point x (relative to a body centre): modes[m][3]
 * displacement components; returns their number (3 plane, 1 axisymmetric, 6 in 3D). */
PetscInt TslElementTypeRigidModes(const TslElementType *t, const PetscReal x[3], PetscReal modes[6][3]);

/* Section data an element needs: its material (property tables, material.h), the out-of-plane
 * thickness of plane elements (1 when not given; ignored otherwise) and, for continuum shells
 * (*SHELL SECTION), the number of Simpson points through the thickness (0: the default 5), the
 * thickness modulus (0: the default, twice the shear modulus at the point's temperature) and the stack
 * direction, the element's reference direction along the thickness, as the dialect's STACK DIRECTION=1..3
 * (0: the default, 3). */
typedef struct {
  const TslMaterial *mat;
  PetscReal          thickness;
  PetscInt           shell_points;
  PetscReal          thickness_modulus;
  PetscInt           shell_stack;
} TslElementSection;

/* The section keyword a type takes: "SHELL SECTION" (continuum shells) or "SOLID SECTION". */
const char *TslElementTypeSectionKeyword(const TslElementType *t);
/* May a continuum shell of type t stack along its reference direction stack (0..2)? A hex8 along any, a
 * wedge6 along its third only (the triangle's extrusion). */
PetscBool TslElementTypeStackAllowed(const TslElementType *t, PetscInt stack);

/* Everything a kernel needs for one element: no time step, no old state (time discretisation is the
 * solver's business, src/solve/):
 *   x[nnode*3]        reference coordinates (z = 0 in 2D)
 *   u[nnode*ndof]     current nodal unknowns, node-major in the type's node_dof order (theta last)
 *   theta_init[nnode] initial temperatures (the thermal strain's reference)
 * nnode counts the type's extra nodes too (geom->nnode + nextra; CPEG: the reference node last, whose
 * slots carry extra_dof); element vectors have nd = nnode * ndof entries. */
typedef struct {
  const TslElementType    *type;
  const TslElementSection *sec;
  const PetscReal         *x, *u, *theta_init;
  /* Mises plasticity (*PLASTIC): the committed state at each mechanical point, TslMaterialPlasticState reals a point
   * (plastic strain, Voigt with engineering shear; equivalent plastic strain; the back stress); pstate_new (NULL: not wanted) gets the
   * state the current u reaches from it; inelastic_rate scales the plastic work of the increment into a heat rate
   * (1 / dt; 0: no plastic heating, as in steady and static steps). pstate NULL: an elastic element. */
  const PetscReal *pstate;
  PetscReal       *pstate_new;
  PetscReal        inelastic_rate;
  PetscReal        dt; /* the increment's time, for a rate-dependent yield stress (*RATE DEPENDENT: the rate dl / dt) */
  /* finite strain (*STEP, NLGEOM; docs/elements.md "Finite strain"): the mechanical terms on the reference configuration
   * with the Green-Lagrange strain and the second Piola-Kirchhoff stress, the outputs S Cauchy and E logarithmic, pressure
   * on the deformed face, the bulk viscosity on the current volume; plastic and incompatible-mode elements keep small
   * strain (the reader warns) */
  PetscBool nlgeom;
} TslElementInput;
/* Mechanical points of the type (the plastic state's points). */
PetscInt TslElementTypeMechanicalPoints(const TslElementType *t, const TslElementSection *sec);

/* Internal force and heat flow: R_u = int B^T sigma dV (+ hourglass forces), R_theta = int grad N . q
 * dV with q = k grad theta, and the consistent tangent K = dR/du (row-major, nd x nd, nd = nnode*ndof;
 * may be NULL). No capacity and no inertia: those come from TslElementLumped. *inverted is set when the
 * map is not valid at some point (R, K then undefined). */
/* PETSC_FALSE for an element that TslElementInternal would report inverted (a non-positive Jacobian at a
 * point of the full or the mechanical rule), at the cost of the geometry alone. */
PetscBool      TslElementValid(const TslElementInput *in);
PetscErrorCode TslElementInternal(const TslElementInput *in, PetscReal R[], PetscReal K[], PetscBool *inverted);
/* The same, and energy[0], energy[1] the element's strain energy int 1/2 sigma : eps_mech dV and hourglass energy
 * as TslElementOutput's (at no extra element pass: the implicit history takes them from its heat-balance residual),
 * energy[2] the plastic work of the increment int sigma : d eps_p dV and energy[3] the heat it gives per unit time
 * (eta inelastic_rate energy[2]). */
PetscErrorCode TslElementInternalEnergy(const TslElementInput *in, PetscReal R[], PetscReal K[], PetscBool *inverted, PetscReal energy[4]);
/* The same without the tangent, a plastic element's heat sources (N_a eta w inelastic_rate dV, energy[3] their sum) apart in
 * heat[TslElementTypeNodes] instead of in R's heat rows: the explicit procedure deposits them as the energy of the move,
 * whatever the length of the next increment (docs/explicit.md "Plastic heat"). heat is zeroed; an elastic element's stays 0. */
PetscErrorCode TslElementInternalPlasticHeat(const TslElementInput *in, PetscReal R[], PetscBool *inverted, PetscReal energy[4], PetscReal heat[]);
/* Nodes of the element's vectors: the family's nodes and the type's extra nodes. */
static inline PetscInt TslElementTypeNodes(const TslElementType *t)
{
  return t->geom->nnode + t->nextra;
}

/* Bulk viscosity of explicit steps: nodal forces of the pressure (lambda + 2 mu) (eta1 eps_vol_dot - eta2
 * eps_vol_dot^2), the quadratic term only when eps_vol_dot < 0 (compression), at the element centre
 * (eps_vol_dot from the nodal velocities v[], laid out as in->u) added to R; *power is the rate it dissipates
 * (>= 0). eta1 = b1 L_e / c_d, eta2 = (b2 L_e / c_d)^2, i.e. Abaqus's b1 rho c_d L_e and rho (b2 L_e)^2 (kernels.c).
 * qr (NULL: not wanted) gets the pressure times the centre's volume, q = p V, and eps_vol_dot (power = q eps_vol_dot):
 * the explicit loop books the viscous work per element from them (docs/explicit.md "Bulk viscosity"). */
PetscErrorCode TslElementBulkViscosity(const TslElementInput *in, const PetscReal v[], PetscReal eta1, PetscReal eta2, PetscReal R[],
                                       PetscReal *power, PetscReal qr[2]);
/* The right Cauchy-Green tensor C = F^T F at the element's centre (Voigt order 11 22 33 12 13 23, from in->u on the
 * reference in->x): the element's shape now, blind to rigid rotations. PETSC_FALSE for an inverted element. */
PetscBool TslElementCentreStretch(const TslElementInput *in, PetscReal C[6]);
/* The angle the element has turned by at its centre, theta = atan2(|axial(F - F^T)| / 2, (tr F - 1) / 2) with F = I + grad u
 * (exact for a rigid turn, and for a turn with a uniform stretch in the plane of a planar element; 0 for a heat-transfer
 * type). PETSC_FALSE for an inverted element. */
PetscBool TslElementCentreRotation(const TslElementInput *in, PetscReal *theta);

/* Explicit force records (fast.c). In a small-strain analysis with temperature-independent properties the
 * geometry of an element never changes and its conduction is linear, so the explicit force loop need not
 * re-evaluate either at every increment: an element's record holds its points' inverse Jacobians (or, for
 * one-point rows, gradients) and volumes, its conduction matrix's upper triangle, the centre point of the
 * bulk viscosity, the hourglass products and its elastic constants, and TslElementFastForce computes from it
 * what TslElementInternal and TslElementBulkViscosity would (the same formulas, to rounding), with loops of
 * fixed length, four elements at a time (TslElementFastForceBatch).
 * Rows: the displacement formulations (full, reduced with hourglass control, modified) of plane strain, plane
 * stress, axisymmetric and 3D solids, on every family (tri3, tri6, quad4, quad8, tet4, tet10, wedge6, hex8), and
 * the continuum shells SC8RT and SC6RT with their default section (5 Simpson points, stack direction 3: the
 * shell's law in each point's frame); hybrid, generalized plane strain, twist and temperature-dependent
 * materials keep the generic path.
 *   TslElementFastShape     the type's shape values and reference derivatives at its mechanical points and
 *                           centre, and its hourglass base vectors (one per type, shared by its elements);
 *                           PETSC_FALSE when the type has no fast row
 *   TslElementFastSize      reals in the element's record; 0: no fast path for this element
 *   TslElementFastBuild     fills the record; PETSC_FALSE for an inverted element
 *   TslElementFastForce     R (internal force and heat flow, laid out as TslElementInternal's), Rv (bulk
 *                           viscosity forces, when eta > 0 or eta2 > 0: TslElementBulkViscosity's eta1,
 *                           eta2) and the power dissipated by the viscosity
 * u[] and v[] are laid out as in->u (theta last at each node), ti[] the nodal initial temperatures.
 * nl: the finite-strain forces (TslElementInput.nlgeom: the same record, the reference configuration's geometry being
 * what a total Lagrangian form needs) in place of the small-strain ones, the bulk viscosity's rate J'/J from v (ev is
 * then neither read nor written: the caller passes v). The force functions return the mask of lanes (bit j: lane j)
 * whose det F <= 0 at a point (nl only; 0 at small strain): an element turned inside out, which the caller reports as
 * the generic kernel's `inverted`. */
#define TSL_FAST_MAX_NODES 10  /* tet10 */
#define TSL_FAST_MAX_QP    9   /* quad8's full rule */
#define TSL_FAST_MAX_SIZE  192 /* reals in the largest record */
#define TSL_FAST_LANES     4   /* elements per batch */
typedef struct {
  PetscInt  row;                                       /* the fast row (-1: none) */
  PetscInt  size;                                      /* reals in its records */
  PetscReal N[TSL_FAST_MAX_QP][TSL_FAST_MAX_NODES];    /* N[q][a] at the mechanical points */
  PetscReal dN[TSL_FAST_MAX_QP][3][TSL_FAST_MAX_NODES]; /* dN_a/dxi_e there, [q][e][a] */
  PetscReal Nc[TSL_FAST_MAX_NODES], dNc[3][TSL_FAST_MAX_NODES]; /* the same at the centre (bulk viscosity) */
  PetscReal h[4][TSL_FAST_MAX_NODES];                   /* hourglass base vectors (reduced rows) */
  /* hex8's full rule, sum-factorised (fast.c, SumFactors): along reference direction e the nodes pair up,
   * sf_pair[e][p] = {node at xi_e = +1, node at xi_e = -1}, and dN_a/dxi_e at point q is +-sf_w[e][c][p] with
   * c = sf_class[e][q] one of the 4 classes of points sharing their other two coordinates */
  PetscBool sf;
  PetscInt  sf_pair[3][4][2], sf_class[3][8];
  PetscReal sf_w[3][4][4];
} TslElementFastShape;

PetscBool TslElementFastShapeGet(const TslElementType *t, TslElementFastShape *shape);
PetscInt  TslElementFastSize(const TslElementInput *in);
PetscBool TslElementFastBuild(const TslElementInput *in, PetscReal rec[]);
int       TslElementFastForce(const TslElementFastShape *shape, PetscBool nl, const PetscReal rec[], const PetscReal u[], const PetscReal ti[],
                              const PetscReal v[], PetscReal eta, PetscReal eta2, PetscReal R[], PetscReal Rv[], PetscReal *power);
/* The element's strain energy int 1/2 sigma : eps_mech dV and hourglass energy from its record, as
 * TslElementOutput's strain_energy and hourglass_energy (the explicit history rows' ALLSE). */
void TslElementFastEnergy(const TslElementFastShape *shape, PetscBool nl, const PetscReal rec[], const PetscReal u[], const PetscReal ti[],
                          PetscReal *strain, PetscReal *hourglass);
/* The same for a batch of TSL_FAST_LANES elements of one type at once (what the explicit loop calls): every
 * array interleaved by lane, value k of lane j at [k * TSL_FAST_LANES + j] (records, u, ti, v, R, Rv),
 * eta[], eta2[], power[], strain[], hourglass[] one per lane. v and Rv are NULL together (no bulk
 * viscosity: power 0); otherwise a lane with eta = eta2 = 0 gets zero forces and power, and Rv may be R itself
 * (the viscous forces added to the internal ones, as the explicit loop takes them). qr (NULL: not
 * wanted; 2 per lane) gets each lane's q = p V in qr[j] and eps_vol_dot in qr[W + j], as TslElementBulkViscosity's.
 * ev (NULL: none; one per lane) keeps each lane's volumetric strain at the centre between evaluations: with v
 * the rate is v's and ev gets the strain of u; with v NULL (and Rv not NULL) the rate is (strain of u - ev) hinv,
 * the difference quotient over the increment h = 1 / hinv since ev's evaluation, which equals v's when
 * v = (u - u_then) / h, as central differences make it, without v's gather.
 * TslElementFastInterleave stores a record (or any array of size reals) as lane `lane` of a batch. */
int  TslElementFastForceBatch(const TslElementFastShape *shape, PetscBool nl, const PetscReal rec[], const PetscReal u[], const PetscReal ti[],
                              const PetscReal v[], PetscReal ev[], PetscReal hinv, const PetscReal eta[], const PetscReal eta2[], PetscReal R[],
                              PetscReal Rv[], PetscReal power[], PetscReal qr[]);
void TslElementFastEnergyBatch(const TslElementFastShape *shape, PetscBool nl, const PetscReal rec[], const PetscReal u[], const PetscReal ti[],
                               PetscReal strain[], PetscReal hourglass[]);
/* An implicit residual's part of a batch: R (interleaved) and, when energy is not NULL, each lane's strain
 * energy in energy[j] and hourglass energy in energy[TSL_FAST_LANES + j], from one evaluation. */
int  TslElementFastResidualBatch(const TslElementFastShape *shape, PetscBool nl, const PetscReal rec[], const PetscReal u[], const PetscReal ti[],
                                 PetscReal R[], PetscReal energy[]);
void TslElementFastInterleave(PetscInt size, PetscInt lane, const PetscReal rec[], PetscReal batch[]);

/* Lumped nodal quantities of the element at its current temperatures:
 *   Q[a] heat content  rho V_a e(theta_a)  (material.h: e = int c dtheta)
 *   C[a] dQ/dtheta_a = rho V_a c(theta_a)
 *   M[a] mass rho V_a
 * with V_a the row's lumped nodal volume (row sums; sub-elements for the modified types). Any of the
 * arrays may be NULL. The explicit procedure's (and, through TslElementHeatContent, the implicit capacity of
 * the linear families). */
PetscErrorCode TslElementLumped(const TslElementInput *in, PetscReal Q[], PetscReal C[], PetscReal M[]);

/* The heat content of the element's nodes for the implicit procedures, the term their time discretisation
 * differentiates (the solver adds shift (Q - Q_old) and shift C):
 *   Q[a]          the nodal heat content,
 *   C[a n + b]    dQ_a / dtheta_b, n = the element's nodes (may be NULL).
 * Second-order families (TslElementCapacityConsistent): the consistent capacity, Q_a = int N_a rho e(theta) dV;
 * their lumped weights (HRZ, linear sub-elements) do not match the distribution of the conduction and of
 * the flux across an element and put spurious modes into a transient (docs/elements.md, "Capacity").
 * Linear families: TslElementLumped's Q and C on the diagonal. Either way the heat stored in an increment is
 * sum_a Q(theta) - Q(theta_old). The explicit procedure keeps TslElementLumped. */
PetscErrorCode TslElementHeatContent(const TslElementInput *in, PetscReal Q[], PetscReal C[]);
/* Whether the row's implicit capacity is the consistent matrix (TslElementHeatContent). */
PetscBool TslElementCapacityConsistent(const TslElementType *t);

typedef enum {
  TSL_FACE_PRESSURE = 0, /* value: pressure (force/area, positive pushing into the body) */
  TSL_FACE_FLUX,         /* value: heat flux per area into the body */
  TSL_FACE_FILM,         /* value: film coefficient h, sink: sink temperature; q_out = h (theta - sink) */
  TSL_BODY_FLUX,         /* value: heat per volume into the body (face ignored); consistent, int N_a q dV */
  TSL_BODY_GRAV,         /* value: g, axis[0..2] the unit direction: force rho g n per volume (TslElementBodyForce) */
  TSL_BODY_CENTRIF,      /* value: omega^2, axis[] a point and the unit direction of the spin axis: rho omega^2 r_perp */
  TSL_FACE_RADIATION     /* value: sigma eps, sink: ambient temperature, zero: absolute zero;
                            q_out = sigma eps [(theta - zero)^4 - (sink - zero)^4] */
} TslFaceLoadKind;

/* A face load's numbers at the current time: value (pressure, flux, film coefficient h, or the radiation
 * coefficient sigma eps), the film's sink or the radiation's ambient temperature, and the absolute zero of
 * the deck's temperature scale (*PHYSICAL CONSTANTS, ABSOLUTE ZERO; radiation only). */
typedef struct {
  PetscReal value, sink, zero;
} TslFaceLoadValue;

/* Adds the face load's contribution to the residual R (as an internal-minus-external residual, i.e.
 * applied loads enter with a minus sign, the heat lost by a film or radiation with a plus sign) and to K
 * where the load depends on the unknowns (film, radiation). face is 1-based (S1..S6). *heat returns the heat
 * the load adds to the body per unit time (flux: positive in; film, radiation: negative when heat leaves); may
 * be NULL. */
PetscErrorCode TslElementFaceLoad(const TslElementInput *in, TslFaceLoadKind kind, PetscInt face, const TslFaceLoadValue *v, PetscReal R[],
                                  PetscReal K[], PetscReal *heat);

/* Is the kind a body force (TslElementBodyForce) rather than a face load or heat? */
static inline PetscBool TslFaceLoadKindIsBodyForce(TslFaceLoadKind kind)
{
  return kind == TSL_BODY_GRAV || kind == TSL_BODY_CENTRIF ? PETSC_TRUE : PETSC_FALSE;
}

/* Body force per volume b on the reference configuration, as consistent nodal forces added to R in residual
 * form, R_u(a) -= int N_a rho b dV, with the family's full rule (TslElementFaceLoad's body flux: kernels.c):
 *   TSL_BODY_GRAV     b = value axis[0..2] (g times the unit direction)
 *   TSL_BODY_CENTRIF  b = value r_perp, r_perp = (x - x0) - ((x - x0) . a) a, x0 = axis[0..2], a = axis[3..5]
 *                     (unit); value = omega^2
 * rho is the density at the initial temperature (the reference state's mass, as small strain keeps it), so the
 * load depends on no unknown: its tangent is zero, exactly (the centrifugal load's stiffness -rho omega^2 (I - a a)
 * of a deforming body is a large-displacement term, absent in a small-strain step). force[3] (may be NULL) gets
 * int rho b dV, the element's total. Nothing is added for an inverted element (TslElementInternal reports it). */
PetscErrorCode TslElementBodyForce(const TslElementInput *in, TslFaceLoadKind kind, PetscReal value, const PetscReal axis[6], PetscReal R[],
                                   PetscReal force[3]);

/* Element results: integration-point averages of stress S (Voigt 11 22 33 12 13 23), total strain E
 * (engineering shear) and heat flux HFL = -k grad theta; strain energy and the hourglass-control energy
 * of the element (zero for fully integrated types). */
typedef struct {
  PetscReal S[6], E[6], HFL[3];
  PetscReal strain_energy, hourglass_energy;
  PetscReal PE[6], PEEQ; /* plastic strain (engineering shear) and equivalent plastic strain: point averages (0: elastic) */
} TslElementResult;

PetscErrorCode TslElementOutput(const TslElementInput *in, TslElementResult *res);

/* Lumped nodal volume (with thickness or 2*pi*r) of each node of the element: the capacity and mass
 * weights, exposed for tests. */
PetscErrorCode TslElementNodalVolume(const TslElementInput *in, PetscReal vol[]);
