/* Structured meshes of one catalogue type on a box, assembled straight from the element kernels into a
 * SeqAIJ matrix and solved by LU: the multi-element tests of the formulations (convergence on a
 * manufactured solution, locking, hourglass control). Serial, PETSC_COMM_SELF only; no deck, no mesh
 * module.
 *
 * The box is cut into ncell[d] cells per direction; a cell is one element of a quad/hex family, two
 * triangles or two prisms, or six tetrahedra (the Kuhn split along the cell diagonal, the same in every
 * cell, hence conforming). Every node of an element is placed through the affine map of its reference
 * coordinates node_xi[] onto the cell, so the catalogue's own node numbering (corners, then midside
 * nodes) is used and a second-order family gets its midside nodes on the fine lattice of half cells.
 * Unknowns are node-major, ndof per node in the type's order (displacements, theta last). */
#pragma once
#include "check.h"
#include "element_impl.h"
#include <petscksp.h>

#define GRID_MAX_QP 512 /* up to 8 Gauss points per direction in 3D */

/* A quadrature of any order on a family's reference element: Gauss-Legendre per direction, collapsed
 * (Duffy) onto the simplex directions of triangles, tetrahedra and prisms. npd points per direction. */
typedef struct {
  PetscInt  n;
  PetscReal xi[GRID_MAX_QP][3], w[GRID_MAX_QP];
} GridRule;

/* A face load of the kernels (TslElementFaceLoad: kind, value, value2) on every element face lying on
 * the plane x_d = plane, or (kind TSL_BODY_FLUX, d and plane unused) a body flux on every element;
 * GridAssemble includes it in R and K. */
typedef struct {
  PetscInt        d;
  PetscReal       plane;
  TslFaceLoadKind kind;
  PetscReal       value, value2;
} GridFaceLoad;

#define GRID_MAX_FACE_LOADS 4

/* The section points at the grid's own material: a Grid is set up in place and never copied. */
typedef struct {
  const TslElementType *type;
  TslMaterial           mat;
  TslElementSection     sec;
  PetscInt              ncell[3];
  PetscReal             lo[3], hi[3];
  PetscInt              nnode, nelem, nen, ndof;
  PetscReal            *x;          /* [nnode*3] */
  PetscReal            *theta_init; /* [nnode] */
  PetscInt             *conn;       /* [nelem*nen] in the catalogue's node order */
  PetscInt              nload;      /* face loads (GridAddFaceLoad), none after GridCreate */
  GridFaceLoad          load[GRID_MAX_FACE_LOADS];
} Grid;

typedef struct {
  PetscBool   factored; /* the LU factorisation succeeded (no zero pivot) */
  const char *failure;  /* PETSc's reason when it did not */
  PetscReal   residual; /* max |F - R(u)| over the free rows after the step, relative to before it */
} GridSolveInfo;

/* Gauss-Legendre points and weights on [-1, 1], n <= 8 here. */
void GridGauss(PetscInt n, PetscReal x[], PetscReal w[]);
/* Number of leading reference directions that span a unit simplex (0 quad/hex/line, 2 tri/wedge, 3 tet). */
PetscInt GridSimplexDims(const TslGeometry *g);
void     GridRuleCreate(const TslGeometry *g, PetscInt npd, GridRule *rule);

/* Mesh of [lo, hi] (2D types: the first two directions) with ncell[d] cells per direction. Material:
 * GridSetMaterial. Free with GridDestroy. */
/* The rows a convergence test refines, with its coarsest mesh and the rates it asserts: PETSC_FALSE for the
 * twist and generalized plane strain rows, which share their families and in-plane terms with the
 * axisymmetric and plane strain rows (their own terms are checked by element_coupled_kernels). n0: cells
 * per side of the coarsest mesh (2D: 2; 3D: 2 linear, 1 quadratic, at most 729 nodes at 4 cells);
 * min: the smallest L2 and H1 rates (2.7 / 1.8 second order, 1.8 / 0.85 linear). */
PetscBool GridConvergenceRow(const TslElementType *t, PetscInt *n0, PetscReal min[2]);
PetscErrorCode GridCreate(const TslElementType *type, const PetscInt ncell[], const PetscReal lo[], const PetscReal hi[], Grid *grid);
void           GridSetMaterial(Grid *grid, PetscReal E, PetscReal nu, PetscReal k, PetscReal alpha, PetscReal theta_init, PetscReal thickness);
PetscErrorCode GridDestroy(Grid *grid);

/* The kernel input of element e with global unknowns u (NULL: zero): fills xe[nen*3], ue[nen*ndof],
 * th0[nen] and points in at them. */
void GridElementInput(const Grid *grid, PetscInt e, const PetscReal u[], PetscReal xe[], PetscReal ue[], PetscReal th0[], TslElementInput *in);

/* Smallest det J over the nodes and the full-rule points of every element, and the number of points
 * where the map is not valid (TslElementPointEvaluate false). */
PetscErrorCode GridMinJacobian(const Grid *grid, PetscReal *min_detJ, PetscInt *invalid);

/* Is node a on the plane x_d = value? Does face f (0-based) of element e lie on it? */
PetscBool GridOnPlane(const Grid *grid, PetscInt a, PetscInt d, PetscReal value);
PetscBool GridFaceOnPlane(const Grid *grid, PetscInt e, PetscInt f, PetscInt d, PetscReal value);

/* Adds a face load on the plane x_d = plane, or a uniform body flux q (heat per volume) on every element
 * (at most GRID_MAX_FACE_LOADS in all). GridFaceHeat sums the heat the grid's thermal loads add to the
 * body per unit time at u (the kernels' heat: flux and body flux in, film -h (theta - sink)). */
PetscErrorCode GridAddFaceLoad(Grid *grid, PetscInt d, PetscReal plane, TslFaceLoadKind kind, PetscReal value, PetscReal value2);
PetscErrorCode GridAddBodyFlux(Grid *grid, PetscReal q);
PetscErrorCode GridFaceHeat(const Grid *grid, const PetscReal u[], PetscReal *heat);

/* w[a] += int_S N_a dA over the element faces lying on the plane x_d = value (dA with the thickness
 * or 2 pi r of the kinematics): the consistent nodal weights of a uniform traction there. */
PetscErrorCode GridFaceWeights(const Grid *grid, PetscInt d, PetscReal value, PetscReal w[]);

/* A manufactured problem as callbacks: field gives the exact value f and gradient g of the unknown in
 * slot (0 .. ndof-1, theta last) at x; source the load densities s[slot] at x (body force, heat source). */
typedef void (*GridFieldFn)(void *ctx, PetscInt slot, const PetscReal x[3], PetscReal *f, PetscReal g[3]);
typedef void (*GridSourceFn)(void *ctx, const PetscReal x[3], PetscReal s[]);

/* The consistent load of the densities, F[ndof n + i] = sum_e int N_a s_i dV, with the rule. */
PetscErrorCode GridLoadVector(const Grid *grid, const GridRule *rule, GridSourceFn source, void *ctx, PetscReal F[]);
/* Squared errors of each unknown slot against the exact field, with the rule and the measure dV of the
 * kinematics: l2[i] = int (u_i - u_h,i)^2 dV, h1[i] = int |grad (u_i - u_h,i)|^2 dV. */
PetscErrorCode GridErrors(const Grid *grid, const PetscReal u[], const GridRule *rule, GridFieldFn field, void *ctx, PetscReal l2[], PetscReal h1[]);

/* Internal force and heat flow R(u) and (K not NULL) the tangent, assembled from TslElementInternal and
 * the grid's face loads. */
PetscErrorCode GridCreateMatrix(const Grid *grid, Mat *K);
PetscErrorCode GridAssemble(const Grid *grid, const PetscReal u[], PetscReal R[], Mat K);

/* One Newton step for R(u) = F from u, which holds the prescribed values on the rows fix[]: the rows of
 * fix[] are replaced by identity rows (row elimination, zero increment), the rest solved by LU
 * (KSPPREONLY + PCLU). Exact for the linear problems of the tests; info->residual shows it. */
/* Steady conduction against a manufactured temperature: the displacement dofs, and the temperature of
 * the nodes on the given planes (coordinate dir[k] == value[k]), are held at the exact field; the rest is
 * solved with the load F (ndof per node). u: the solution (ndof per node, allocated by the caller);
 * err: the L2 and H1 errors of the temperature (PETSC_MAX_REAL when the matrix could not be factored). */
PetscErrorCode GridSolveConduction(const Grid *grid, const GridRule *rule, const PetscReal F[], PetscInt nplane, const PetscInt dir[],
                                   const PetscReal value[], GridFieldFn exact, void *ctx, PetscReal u[], GridSolveInfo *info, PetscReal err[2]);
PetscErrorCode GridSolve(const Grid *grid, const PetscReal F[], PetscInt nfix, const PetscInt fix[], PetscReal u[], GridSolveInfo *info);

/* Sums over the elements of TslElementOutput's strain and hourglass energies. */
PetscErrorCode GridEnergies(const Grid *grid, const PetscReal u[], PetscReal *strain, PetscReal *hourglass);
