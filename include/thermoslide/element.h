/* thermoslide element catalogue and element kernels.
 *
 * One table row per deck type name (CPE4T, CAX4T, C3D8T, ...). A row names a geometry family
 * (shape functions, faces, quadrature) and a kinematics / formulation; adding a type is a row plus,
 * at most, a small kernel. Nothing outside src/element/ may test for a particular type.
 *
 * Kernels work on plain arrays: no MPI, no PETSc objects, so they can be unit-tested alone.
 *
 * Nodal unknowns are interleaved per node: (u_1, ..., u_dim, theta) with ndof = dim + 1.
 * Voigt order for stress/strain output: 11, 22, 33, 12, 13, 23 (engineering shear strain).
 * For axisymmetric elements x = r, y = z; 11 = rr, 22 = zz, 33 = hoop, 12 = rz; integrals include 2*pi*r,
 * so forces and heat are totals around the circumference.
 */
#pragma once
#include <thermoslide/compat.h>

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
  PetscInt      xdmf_type; /* XDMF mixed-topology cell type id */
  /* Linear subdivision of a second-order family (line3: 2 line2, tri6: 4 tri3, tet10: 8 tet4; nsub = 0
   * otherwise). The "modified" types lump capacity and face loads on it, where the quadratic shape
   * functions would give zero or negative corner weights. sub_node[s][] are element-local node
   * positions, ordered so that a sub-element has a positive Jacobian when its parent has. */
  PetscInt                  nsub;
  const struct TslGeometry *sub_geom;
  PetscInt                  sub_node[TSL_MAX_SUB][TSL_MAX_SUB_NODES];
} TslGeometry;

typedef enum {
  TSL_KIN_PLANE_STRAIN = 0,
  TSL_KIN_PLANE_STRESS,
  TSL_KIN_AXISYMMETRIC,
  TSL_KIN_SOLID3D,
} TslKinematics;

typedef struct {
  const char        *name; /* deck type name, upper case */
  const TslGeometry *geom;
  TslKinematics      kin;
  PetscInt           dim;         /* spatial dimension of the model (2 or 3) */
  PetscInt           ndof;        /* unknowns per node: dim displacements + temperature */
  PetscBool          reduced;     /* reduced integration (with hourglass control) */
  PetscBool          hybrid;      /* hybrid pressure formulation */
  const char        *description; /* for docs and -help */
} TslElementType;

/* Catalogue lookups. TslElementTypeFind is case-insensitive and returns -1 for an unknown name. */
PetscInt              TslElementTypeCount(void);
const TslElementType *TslElementTypeGet(PetscInt index);
PetscInt              TslElementTypeFind(const char *name);

/* Material data an element needs (from *MATERIAL and *SOLID SECTION). */
typedef struct {
  PetscReal E, nu, conductivity, density, specific_heat, alpha;
  PetscReal thickness; /* plane elements; ignored otherwise */
} TslElementMaterial;

/* Everything a coupled kernel needs for one element.
 *   x[nnode*3]      reference coordinates (z = 0 in 2D)
 *   u[nnode*ndof]   current nodal unknowns (displacements, theta)
 *   u_old[...]      unknowns at the start of the increment (for the heat-capacity term)
 *   theta_init[nnode] initial temperatures (thermal strain is alpha*(theta - theta_init))
 *   dt              increment; steady = PETSC_TRUE drops the capacity term */
typedef struct {
  const TslElementType     *type;
  const TslElementMaterial *mat;
  const PetscReal          *x, *u, *u_old, *theta_init;
  PetscReal                 dt;
  PetscBool                 steady;
} TslElementInput;

/* Residual R (internal forces and heat: conduction + capacity) and consistent tangent K = dR/du
 * (row-major, nd x nd with nd = nnode*ndof); K may be NULL. *inverted is set when any integration
 * point has a non-positive Jacobian determinant (R and K are then undefined). */
PetscErrorCode TslElementResidual(const TslElementInput *in, PetscReal R[], PetscReal K[], PetscBool *inverted);

typedef enum {
  TSL_FACE_PRESSURE = 0, /* value: pressure (force/area, positive pushing into the body) */
  TSL_FACE_FLUX,         /* value: heat flux per area into the body */
  TSL_FACE_FILM,         /* value: film coefficient h, value2: sink temperature; q_out = h (theta - sink) */
  TSL_BODY_FLUX          /* value: heat per volume into the body (face ignored) */
} TslFaceLoadKind;

/* Adds the face load's contribution to the residual R (as an internal-minus-external residual, i.e.
 * applied loads enter with a minus sign, the film's heat loss with a plus sign) and to K where the load
 * depends on the unknowns (film). face is 1-based (S1..S6). *heat returns the heat the load adds to the
 * body per unit time (flux: positive in; film: negative when heat leaves); may be NULL. */
PetscErrorCode TslElementFaceLoad(const TslElementInput *in, TslFaceLoadKind kind, PetscInt face, PetscReal value, PetscReal value2, PetscReal R[],
                                  PetscReal K[], PetscReal *heat);

/* Heat stored per element between u_old and u (lumped capacity): sum rho c V_a (theta_a - theta_old_a). */
PetscErrorCode TslElementHeatChange(const TslElementInput *in, PetscReal *dQ);

/* Integration-point averages of stress S[6], strain E[6] (total strain) and heat flux HFL[3] (-k grad theta). */
PetscErrorCode TslElementOutput(const TslElementInput *in, PetscReal S[6], PetscReal E[6], PetscReal HFL[3]);

/* Lumped nodal volume (with thickness or 2*pi*r) of each node of the element: the heat-capacity
 * weights, exposed for tests. */
PetscErrorCode TslElementNodalVolume(const TslElementInput *in, PetscReal vol[]);
