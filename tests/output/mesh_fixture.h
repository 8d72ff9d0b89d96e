/* A small mixed quad/triangle mesh (or, with quads, one of quadrilaterals alone) for the output tests, with a deliberately scrambled distribution:
 * each rank owns nodes and elements scattered over the natural numbering, listed in descending
 * natural order, so that nothing lines up with rank order by accident. Field values are known in
 * closed form, so any run (1 or n ranks) is checked against the same figures. */
#pragma once
#include <thermoslide/output.h>

typedef struct {
  PetscInt   nx, ny, N, M;      /* nodes per row / column, node and element totals */
  PetscReal *xyz;               /* [N][3] */
  PetscInt  *type, *ptr, *conn; /* global connectivity in natural order (the test may hold it) */
} TestMesh;

typedef struct {
  PetscInt   nnode, nelem;
  PetscInt  *node_nat, *node_id, *elem_nat, *elem_id, *type, *ptr, *conn;
  PetscReal *xyz;
} TestLocal;

PetscErrorCode TestMeshCreate(PetscInt nx, PetscInt ny, PetscBool quads, TestMesh *m);
PetscErrorCode TestMeshDestroy(TestMesh *m);
PetscErrorCode TestLocalCreate(const TestMesh *m, PetscMPIInt rank, PetscMPIInt size, TestLocal *l);
PetscErrorCode TestLocalDestroy(TestLocal *l);
/* Writes the whole mesh of l through out. */
PetscErrorCode TestSetMesh(TslOutput out, const TestMesh *m, const TestLocal *l);
/* Values [n][ncomp] of a node (on_cells false) or element field for the items of l. */
PetscErrorCode TestFieldValues(const TestLocal *l, PetscBool on_cells, PetscInt frame, PetscInt field, PetscInt ncomp, PetscReal **vals);

static inline PetscInt TestNodeId(PetscInt n)
{
  return 100 + 7 * n;
}
static inline PetscInt TestElemId(PetscInt e)
{
  return 5000 + 3 * e;
}
/* Exact in binary: all values are integers plus 1/4 or 1/8. */
static inline PetscReal TestValue(PetscInt frame, PetscInt field, PetscInt item, PetscInt comp)
{
  return (PetscReal)(frame * 100000 + field * 10000 + 10 * item + comp) + (field % 2 ? 0.25 : -0.125);
}
