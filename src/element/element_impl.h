/* Private to src/element/: the kinematics and formulation tables and the integration-point helpers
 * shared by the kernels. */
#pragma once
#include <thermoslide/element.h>

/* The geometry families (geometry.c), referenced by the catalogue rows and by each other (faces,
 * sub-elements). */
extern const TslGeometry TslGeomLine2, TslGeomLine3, TslGeomTri3, TslGeomTri6, TslGeomQuad4, TslGeomQuad8, TslGeomTet4, TslGeomWedge6, TslGeomHex8,
    TslGeomHex20, TslGeomTet10, TslGeomWedge15;

/* What distinguishes one kinematic assumption from another, in one place (kinematics.c). The kernels
 * only read this row, so a new element type is a catalogue row, and a new kinematics a table row. */
struct TslKinematicsRow {
  const char *name;
  PetscBool   hoop;        /* eps_33 = u_r / r (axisymmetric) */
  PetscBool   free_normal; /* sigma_33 = 0 (plane stress): eps_33 is condensed out of D */
  PetscBool   revolve;     /* dV = 2 pi r dA */
  PetscBool   thickness;   /* dV = t dA (plane elements) */
  PetscBool   twist;       /* a third displacement unknown, the twist phi about the axis (u_theta = r phi) */
  PetscBool   reference;   /* eps_33 from the reference node (generalized plane strain) */
  PetscBool   shell;       /* continuum shell: plane stress in the plane normal to the stack direction,
                              sigma_nn from the thickness modulus (TslElementElasticity) */
  PetscInt (*rigid_modes)(const PetscReal x[3], PetscReal modes[6][3]);
};

const struct TslKinematicsRow *TslKinematicsRowGet(TslKinematics kin);

/* One integration point of an element in its reference configuration. */
typedef struct {
  PetscReal N[TSL_MAX_ELEM_NODES];
  PetscReal dNdx[TSL_MAX_ELEM_NODES][3]; /* spatial gradients; third component 0 in 2D */
  PetscReal Ji[3][3];                    /* inverse Jacobian Ji[e][d] = dxi_e/dx_d (dim x dim) */
  PetscReal x[3];                        /* position (x[0] = r for axisymmetric) */
  PetscReal xi[3];                       /* reference coordinates */
  PetscReal detJ;
  PetscReal dV; /* weight * detJ * (thickness or 2 pi r or 1) */
} TslElementPoint;

/* Evaluates the point at reference coordinates xi with quadrature weight w. Returns PETSC_FALSE when
 * the map is not valid there (detJ <= 0, or r <= 0 for axisymmetric elements). */
PetscBool TslElementPointEvaluate(const TslElementType *type, const TslElementSection *sec, const PetscReal x[], const PetscReal xi[], PetscReal w,
                                  TslElementPoint *p);

/* Voigt strain-displacement matrix B[6][nnode*dim] (engineering shear) at a point. */
void TslElementStrainMatrix(const TslElementType *type, const TslElementSection *sec, const PetscReal x[], const TslElementPoint *p,
                            PetscReal B[6][TSL_MAX_ELEM_NODES * 3]);

/* Finite strain (TslElementInput.nlgeom; docs/elements.md "Finite strain"): the displacement gradient H = F - I at a
 * point (kept apart from I, so that small strains keep their digits in E = (H + H^T + H^T H) / 2) and
 * each displacement column's dF/du_c, a few entries (row i, column K, value) of a 3 x 3 matrix. The components are
 * the kinematics' own: (x, y, z) in the plane and in 3D, (r, z, theta) in axisymmetry, where F_33 = (r + u_r) / r
 * and, with twist phi (rotation about the axis, as the twist dof), F_31 = (r + u_r) phi_,r, F_32 = (r + u_r) phi_,z
 * (the spatial basis turned with the point, so a rigid twist gives F = I). Generalized plane strain: F_33 = 1 +
 * eps_33 of the reference node's dofs; plane stress: F_33 = 1 here (the condensed elasticity never reads it).
 * Every kinematics' F is linear in u except twist's F_31, F_32 (the products u_r phi: TslGradientColumn has the
 * point's dF/du_c, and the kernel adds the second derivative's term). */
#define TSL_GRADIENT_ENTRIES 6
typedef struct {
  PetscInt  n;
  PetscInt  i[TSL_GRADIENT_ENTRIES], k[TSL_GRADIENT_ENTRIES];
  PetscReal v[TSL_GRADIENT_ENTRIES];
} TslGradientColumn;
void TslElementDeformation(const TslElementType *type, const TslElementSection *sec, const PetscReal x[], const TslElementPoint *p, const PetscReal u[],
                           PetscReal H[3][3], TslGradientColumn col[]);

/* The centre of the reference element, the average of its corners (xi = 0 for quad4 and hex8, the centroid
 * for triangles, tetrahedra and wedges): the point of the hourglass control and of the bulk viscosity. */
static inline void TslElementCentre(const TslGeometry *g, PetscReal xi[3])
{
  for (PetscInt d = 0; d < 3; d++) xi[d] = 0;
  for (PetscInt a = 0; a < g->ncorner; a++)
    for (PetscInt d = 0; d < g->dim; d++) xi[d] += g->node_xi[a][d] / g->ncorner;
}

/* Elasticity of the kinematics at a material point: D[6][6] (plane stress: condensed so that
 * sigma_33 = 0) and its derivative dD in theta (NULL: not wanted). A continuum shell's D depends on the
 * stack direction at the point p (its section: the thickness modulus); p and sec may be NULL for the
 * other kinematics. */
void TslElementElasticity(const TslElementType *type, const TslElementSection *sec, const TslElementPoint *p, const TslMaterialPoint *mp,
                          PetscReal D[6][6], PetscReal dD[6][6]);
/* The modulus of the kinematics' dilatational waves, rho c_d^2: lambda + 2 mu, or E / (1 - nu^2) where the
 * normal stress is free (plane stress) or given by the thickness modulus (continuum shells). */
PetscReal TslElementWaveModulus(const TslElementType *type, const TslMaterialPoint *mp);
/* A continuum shell at a point: the frame Q (rows e1, e2, n; n the unit gradient of the stack coordinate) and
 * the thickness modulus of its section (the default 2 G from the material point). */
void TslElementShellFrame(const TslElementSection *sec, const TslElementPoint *p, PetscReal Q[3][3]);
/* The Voigt strain transformation of the frame Q (rows: the local axes): eps_local = T eps_global (engineering
 * shear), so sigma_global = T^T sigma_local and C_global = T^T C_local T */
void TslElementStrainTransform(const PetscReal Q[3][3], PetscReal T[6][6]);
/* The reference direction (0..2) along a continuum shell's thickness: its section's STACK DIRECTION less one,
 * 2 by default. */
static inline PetscInt TslElementShellStack(const TslElementSection *sec)
{
  return sec && sec->shell_stack >= 1 && sec->shell_stack <= 3 ? sec->shell_stack - 1 : 2;
}
PetscReal TslElementShellThicknessModulus(const TslElementSection *sec, const TslMaterialPoint *mp);
/* The continuum shell's hourglass sum bb = sum_a |grad N_a|^2 over the gradients' parts in the shell plane
 * (formulations.c, ShellHourglass). */
PetscReal TslElementShellHourglassSum(const TslElementSection *sec, const TslGeometry *g, const TslElementPoint *p);
/* The Lame constants of the isotropic material at a point (TslElementElasticity's, the force records'). */
void TslElementLame(const TslMaterialPoint *mp, PetscReal *lambda, PetscReal *mu);

/* Formulation: how the strain terms are integrated and what is added to them. Function pointers where
 * behaviour differs; the generic kernel (kernels.c) calls them.
 *   quadrature   the integration points of the mechanical terms (conduction always uses the full rule)
 *   pressure     number of independent pressure terms of a hybrid formulation at a point, and their
 *                values P[] (NULL: displacement formulation)
 *   hourglass    stabilisation added to a reduced-integration element (NULL: none); adds to R and K
 *                (may be NULL) and returns the stabilisation energy
 *   nodal_volume the lumping weights V_a (the explicit procedure's capacity and mass, and the implicit
 *                capacity unless consistent_capacity; the body flux is consistent, kernels.c)
 *   pressure_face_rule, thermal_face_rule
 *                the points of a face integral of a pressure, and of a surface flux or film: the face
 *                family's own shape functions with its as_face rule (exact for N_a N_b, the film), or
 *                for the pressure of a modified element its linear sub-faces (positive nodal weights)
 *   consistent_capacity
 *                the implicit procedures' capacity of a second-order family is the consistent matrix
 *                int rho c N_a N_b dV (TslElementHeatContent); linear families keep the lumped one */
typedef struct {
  PetscInt  n;
  PetscReal N[TSL_MAX_QP * 4][TSL_MAX_FACE_NODES]; /* face shape values at each point */
  PetscReal dN[TSL_MAX_QP * 4][TSL_MAX_FACE_NODES][2];
  PetscReal w[TSL_MAX_QP * 4];
} TslFaceRule;

struct TslFormulation {
  const char *name;
  const TslQuadrature *(*quadrature)(const TslGeometry *g, const TslElementSection *sec); /* sec may be NULL: its defaults */
  PetscInt (*pressure)(const TslGeometry *g, const TslElementPoint *p, PetscReal P[]);
  PetscErrorCode (*hourglass)(const TslElementInput *in, const TslMaterialPoint *mp, PetscReal R[], PetscReal K[], PetscReal *energy);
  PetscBool (*nodal_volume)(const TslElementInput *in, PetscReal vol[]);
  void (*pressure_face_rule)(const TslGeometry *g, PetscInt face, TslFaceRule *rule);
  void (*thermal_face_rule)(const TslGeometry *g, PetscInt face, TslFaceRule *rule);
  PetscBool consistent_capacity;
  /* incompatible modes (NULL: none): the reference derivatives dP[k][0..2] of each bubble P_k at xi, their number */
  PetscInt (*incompatible)(const TslGeometry *g, const PetscReal xi[], PetscReal dP[][3]);
};

/* Incompatible modes: at most one per reference direction, in each of 3 displacement components. */
#define TSL_MAX_ENHANCED 9
/* and their families' full rules have at most 2 x 2 x 2 points */
#define TSL_INCOMPATIBLE_QP 8

/* Hybrid pressure spaces are at most linear: 1 + dim terms. */
#define TSL_MAX_PRESSURE 4

/* The formulations (formulations.c). */
extern const TslFormulation TslFormFull, TslFormFullSubFace, TslFormHybridSubFace, TslFormReducedQuadraticHybrid, TslFormReduced,
    TslFormReducedQuadratic, TslFormReducedQuadraticShell, TslFormHybrid, TslFormReducedHybrid, TslFormModified, TslFormModifiedHybrid,
    TslFormContinuumShell, TslFormIncompatible;

/* Hourglass control of the one-point quad4 and hex8 (formulations.c): the Flanagan-Belytschko vectors
 * gamma[k][a] = (h_k[a] - sum_d hx[k][d] dN_a/dx_d) / n at the centre point p (returns their number: 1 in
 * 2D, 4 in 3D; hx[k][d] = h_k . x_d, NULL: not wanted) and bb = sum_a |grad N_a|^2; the stiffness kappa =
 * s mu dV bb. TslElementHourglassVectors: the base vectors h_k (products of reference coordinates at the
 * nodes). Shared by the generic kernel and the explicit records (fast.c). */
PetscInt  TslElementHourglassVectors(const TslGeometry *g, PetscReal h[4][TSL_MAX_ELEM_NODES]);
PetscInt  TslElementHourglassBase(const TslElementInput *in, const TslElementPoint *p, PetscReal gamma[4][TSL_MAX_ELEM_NODES], PetscReal hx[4][3],
                                  PetscReal *bb);
PetscReal TslElementHourglassKappa(PetscReal mu, PetscReal dV, PetscReal bb);
