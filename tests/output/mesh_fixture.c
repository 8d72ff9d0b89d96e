#include "mesh_fixture.h"

PetscErrorCode TestMeshCreate(PetscInt nx, PetscInt ny, PetscBool quads, TestMesh *m)
{
  PetscInt nsq = (nx - 1) * (ny - 1), e = 0, k = 0;

  PetscFunctionBeginUser;
  m->nx = nx;
  m->ny = ny;
  m->N  = nx * ny;
  m->M  = 0;
  for (PetscInt j = 0; j < ny - 1; j++)
    for (PetscInt i = 0; i < nx - 1; i++) m->M += (i + j) % 2 && !quads ? 2 : 1;
  PetscCall(PetscMalloc4(3 * m->N, &m->xyz, m->M, &m->type, m->M + 1, &m->ptr, 6 * nsq, &m->conn));
  for (PetscInt j = 0; j < ny; j++)
    for (PetscInt i = 0; i < nx; i++) {
      PetscReal *x = m->xyz + 3 * (j * nx + i);
      x[0]         = 0.5 * i;
      x[1]         = 0.25 * j + 0.125 * i;
      x[2]         = 0;
    }
  m->ptr[0] = 0;
  for (PetscInt j = 0; j < ny - 1; j++)
    for (PetscInt i = 0; i < nx - 1; i++) {
      const PetscInt n00 = j * nx + i, n10 = n00 + 1, n01 = n00 + nx, n11 = n01 + 1;
      if ((i + j) % 2 == 0 || quads) { /* quad, XDMF 5 */
        m->type[e]   = 5;
        m->conn[k++] = n00, m->conn[k++] = n10, m->conn[k++] = n11, m->conn[k++] = n01;
        m->ptr[++e] = k;
      } else { /* two triangles, XDMF 4 */
        m->type[e]   = 4;
        m->conn[k++] = n00, m->conn[k++] = n10, m->conn[k++] = n11;
        m->ptr[++e]  = k;
        m->type[e]   = 4;
        m->conn[k++] = n00, m->conn[k++] = n11, m->conn[k++] = n01;
        m->ptr[++e] = k;
      }
    }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TestMeshDestroy(TestMesh *m)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree4(m->xyz, m->type, m->ptr, m->conn));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscMPIInt NodeOwner(PetscInt n, PetscMPIInt size)
{
  return (PetscMPIInt)((n / 3 + n) % size);
}
static PetscMPIInt ElemOwner(PetscInt e, PetscMPIInt size)
{
  return (PetscMPIInt)((e * e + 1) % size);
}

PetscErrorCode TestLocalCreate(const TestMesh *m, PetscMPIInt rank, PetscMPIInt size, TestLocal *l)
{
  PetscInt nconn = 0, k = 0, a = 0;

  PetscFunctionBeginUser;
  l->nnode = l->nelem = 0;
  for (PetscInt n = 0; n < m->N; n++) l->nnode += NodeOwner(n, size) == rank;
  for (PetscInt e = 0; e < m->M; e++)
    if (ElemOwner(e, size) == rank) l->nelem++, nconn += m->ptr[e + 1] - m->ptr[e];
  PetscCall(PetscMalloc3(l->nnode, &l->node_nat, l->nnode, &l->node_id, 3 * l->nnode, &l->xyz));
  PetscCall(PetscMalloc5(l->nelem, &l->elem_nat, l->nelem, &l->elem_id, l->nelem, &l->type, l->nelem + 1, &l->ptr, nconn, &l->conn));
  for (PetscInt n = m->N - 1; n >= 0; n--) {
    if (NodeOwner(n, size) != rank) continue;
    l->node_nat[k] = n;
    l->node_id[k]  = TestNodeId(n);
    for (int d = 0; d < 3; d++) l->xyz[3 * k + d] = m->xyz[3 * n + d];
    k++;
  }
  k         = 0;
  l->ptr[0] = 0;
  for (PetscInt e = m->M - 1; e >= 0; e--) {
    if (ElemOwner(e, size) != rank) continue;
    l->elem_nat[k] = e;
    l->elem_id[k]  = TestElemId(e);
    l->type[k]     = m->type[e];
    for (PetscInt j = m->ptr[e]; j < m->ptr[e + 1]; j++) l->conn[a++] = m->conn[j];
    l->ptr[++k] = a;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TestLocalDestroy(TestLocal *l)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree3(l->node_nat, l->node_id, l->xyz));
  PetscCall(PetscFree5(l->elem_nat, l->elem_id, l->type, l->ptr, l->conn));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TestSetMesh(TslOutput out, const TestMesh *m, const TestLocal *l)
{
  PetscFunctionBeginUser;
  PetscCall(
      TslOutputSetMesh(out, m->N, l->nnode, l->node_nat, l->node_id, l->xyz, m->M, l->nelem, l->elem_nat, l->elem_id, l->type, l->ptr, l->conn));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TestFieldValues(const TestLocal *l, PetscBool on_cells, PetscInt frame, PetscInt field, PetscInt ncomp, PetscReal **vals)
{
  const PetscInt  n   = on_cells ? l->nelem : l->nnode;
  const PetscInt *nat = on_cells ? l->elem_nat : l->node_nat;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(n * ncomp, vals));
  for (PetscInt k = 0; k < n; k++)
    for (PetscInt c = 0; c < ncomp; c++) (*vals)[k * ncomp + c] = TestValue(frame, field, nat[k], c);
  PetscFunctionReturn(PETSC_SUCCESS);
}
