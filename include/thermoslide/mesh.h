/* thermoslide mesh distribution.
 *
 * Rank 0 holds the whole model only while partitioning: METIS_PartMeshDual splits the elements, each
 * node is owned by the lowest rank among the elements that use it, nodes are numbered contiguously per
 * rank (owned nodes in id order), and each rank receives a local TslModel holding its elements, their
 * nodes (owned first, then ghosts), the sets/surfaces filtered to them, and all non-mesh data.
 * Nodes named by an *EQUATION that touches a rank's nodes are added to that rank as ghosts, so
 * constraint rows can be formed locally.
 */
#pragma once
#include <thermoslide/model.h>

/* Rank 0, the whole model: every tie (model.h TslTie) as equations (TslEquation with tie set), one per
 * secondary node and dof, u_s - sum_k c_sk u_k = 0 with the dual-mortar weights of src/mesh/tie.c; ADJUST
 * moves the secondary nodes onto the main surface first. Called by TslMeshDistribute before partitioning, so
 * that the equations' closure brings every term to the ranks that need it. User errors name the tie's line. */
PetscErrorCode TslMeshTies(TslModel *g);

/* Collective. On rank 0, *global is the model read from the deck; it is destroyed (and nulled) here,
 * other ranks pass NULL. Every rank receives its local model in *local.
 * Options: -tsl_partition metis|axis_x|axis_y|axis_z  (axis_*: slabs by element centroid, to force
 * a chosen cut for tests; default metis). */
PetscErrorCode TslMeshDistribute(MPI_Comm comm, TslModel **global, TslModel **local);
