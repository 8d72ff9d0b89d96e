/* The problem's committed state for restart points (src/solve/restart.c): contact nodes, 3D main-surface normals
 * and plastic points, packed as bytes in this rank's layout, and a digest of that layout. */
#include "problem_impl.h"

static void Put(char **at, const void *src, size_t n)
{
  if (n) memcpy(*at, src, n);
  *at += n;
}

static void Take(const char **at, void *dst, size_t n)
{
  if (n) memcpy(dst, *at, n);
  *at += n;
}

PetscErrorCode TslProblemStateSize(TslProblem p, size_t *bytes, const char **unsupported)
{
  size_t n = p->ncnode * sizeof(TslContactNode) + p->npstate * sizeof(PetscReal);

  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < p->ncsurf; k++)
    if (p->csurf[k].nnormal) n += 3 * p->nn * sizeof(PetscReal);
  *bytes       = n;
  *unsupported = NULL;
  if (p->s2s) *unsupported = "surface-to-surface contact pairs (their points' state is not saved yet)";
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemStatePack(TslProblem p, void *buf)
{
  char *at = (char *)buf;

  PetscFunctionBeginUser;
  Put(&at, p->cnode, p->ncnode * sizeof(TslContactNode));
  for (PetscInt k = 0; k < p->ncsurf; k++)
    if (p->csurf[k].nnormal) Put(&at, p->csurf[k].nnormal, 3 * p->nn * sizeof(PetscReal));
  Put(&at, p->pstate, p->npstate * sizeof(PetscReal));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemStateUnpack(TslProblem p, const void *buf)
{
  const char *at = (const char *)buf;

  PetscFunctionBeginUser;
  Take(&at, p->cnode, p->ncnode * sizeof(TslContactNode));
  for (PetscInt k = 0; k < p->ncsurf; k++)
    if (p->csurf[k].nnormal) Take(&at, p->csurf[k].nnormal, 3 * p->nn * sizeof(PetscReal));
  Take(&at, p->pstate, p->npstate * sizeof(PetscReal));
  if (p->npstate) PetscCall(PetscArraycpy(p->pstate_new, p->pstate, p->npstate));
  PetscCall(TslProblemContactRollback(p)); /* the current state from the committed one */
  p->pattern_stale = PETSC_TRUE;           /* the pairing is the point's, not the set-up's */
  PetscFunctionReturn(PETSC_SUCCESS);
}

static void Mix(uint64_t *h, const void *data, size_t n)
{
  const unsigned char *c = (const unsigned char *)data;
  for (size_t i = 0; i < n; i++) *h = (*h ^ c[i]) * 1099511628211ull; /* FNV-1a */
}

PetscErrorCode TslProblemLayoutDigest(TslProblem p, uint64_t *digest)
{
  const TslModel *m = p->m;
  uint64_t        h = 14695981039346656037ull;
  PetscInt        sizes[6];

  PetscFunctionBeginUser;
  sizes[0] = p->nn, sizes[1] = p->nown, sizes[2] = p->ndof, sizes[3] = m->nelem, sizes[4] = p->ncnode, sizes[5] = p->npstate;
  Mix(&h, sizes, sizeof(sizes));
  Mix(&h, m->node_id, p->nn * sizeof(PetscInt));
  Mix(&h, m->elem_id, m->nelem * sizeof(PetscInt));
  Mix(&h, m->elem_type, m->nelem * sizeof(m->elem_type[0]));
  Mix(&h, p->elem_lnode, m->elem_ptr[m->nelem] * sizeof(PetscInt));
  for (PetscInt i = 0; i < p->ncnode; i++) Mix(&h, &p->cnode[i].lnode, sizeof(PetscInt));
  *digest = h;
  PetscFunctionReturn(PETSC_SUCCESS);
}
