/* Rendezvous by key: answers and questions with keys of kl integers meet on the rank a hash of the key names, which
 * sends each question the answer with its key. No rank holds more than the answers and questions hashed to it, so the
 * exchange serves data of any global size (a restart point read on another rank count, src/solve/restart.c). */
#include <thermoslide/sys.h>
#include <stdlib.h>
#include <string.h>

static PetscMPIInt KeyRank(const int64_t *k, PetscInt kl, PetscMPIInt size)
{
  uint64_t h = 14695981039346656037ull;
  for (PetscInt i = 0; i < kl; i++) {
    uint64_t v = (uint64_t)k[i];
    for (int b = 0; b < 8; b++) h = (h ^ ((v >> (8 * b)) & 0xff)) * 1099511628211ull; /* FNV-1a */
  }
  return (PetscMPIInt)(h % (uint64_t)size);
}

/* qsort has no context: the keys being sorted */
static const int64_t *sort_keys;
static PetscInt       sort_kl;

static int KeyCompare(const int64_t *a, const int64_t *b, PetscInt kl)
{
  for (PetscInt i = 0; i < kl; i++)
    if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
  return 0;
}

static int IndexCompare(const void *pa, const void *pb)
{
  const PetscInt a = *(const PetscInt *)pa, b = *(const PetscInt *)pb;
  int            c = KeyCompare(&sort_keys[a * sort_kl], &sort_keys[b * sort_kl], sort_kl);
  return c ? c : (a < b ? -1 : a > b); /* stable: of equal keys the first offered is kept */
}

/* n items of kl keys and w reals, sent to the ranks their keys hash to; the received ones (*nr) in *rkey, *rval
 * (allocated), the counts sent and received per rank, and where item i went in the send order (pos[i]). */
static PetscErrorCode Scatter(MPI_Comm comm, PetscInt kl, PetscInt w, PetscInt n, const int64_t key[], const PetscReal val[], PetscMPIInt scnt[], PetscMPIInt rcnt[],
                              PetscInt pos[], PetscInt *nr, int64_t **rkey, PetscReal **rval)
{
  PetscMPIInt size, *sd, *rd, *sk, *rk, *sv, *rv;
  PetscInt   *dest, *off, total = 0;
  int64_t    *skey;
  PetscReal  *sval = NULL;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(PetscCalloc2(n, &dest, size + 1, &off));
  PetscCall(PetscMalloc6(size, &sd, size, &rd, size, &sk, size, &rk, size, &sv, size, &rv));
  for (PetscMPIInt r = 0; r < size; r++) scnt[r] = 0;
  for (PetscInt i = 0; i < n; i++) dest[i] = KeyRank(&key[i * kl], kl, size), scnt[dest[i]]++;
  for (PetscMPIInt r = 0; r < size; r++) off[r + 1] = off[r] + scnt[r];
  PetscCall(PetscMalloc1(n * kl + 1, &skey));
  if (w) PetscCall(PetscMalloc1(n * w + 1, &sval));
  for (PetscInt i = 0; i < n; i++) {
    PetscInt at = off[dest[i]]++;
    pos[i]      = at;
    memcpy(&skey[at * kl], &key[i * kl], sizeof(int64_t) * kl);
    if (w) memcpy(&sval[at * w], &val[i * w], sizeof(PetscReal) * w);
  }
  PetscCallMPI(MPI_Alltoall(scnt, 1, MPI_INT, rcnt, 1, MPI_INT, comm));
  sd[0] = rd[0] = 0;
  for (PetscMPIInt r = 0; r < size; r++) {
    if (r) sd[r] = sd[r - 1] + scnt[r - 1], rd[r] = rd[r - 1] + rcnt[r - 1];
    total += rcnt[r];
  }
  /* the displacements in MPI's int as well; decided on every rank together */
  {
    PetscInt big = (PetscInt64)n * PetscMax(kl, w) >= PETSC_MPI_INT_MAX || (PetscInt64)total * PetscMax(kl, w) >= PETSC_MPI_INT_MAX;
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &big, 1, MPIU_INT, MPI_MAX, comm));
    PetscCheck(!big, comm, PETSC_ERR_SUP, "rendezvous: too many items on one rank for one exchange (this rank: %" PetscInt_FMT " sent, %" PetscInt_FMT " received)", n, total);
  }
  for (PetscMPIInt r = 0; r < size; r++) {
    sk[r] = (PetscMPIInt)(scnt[r] * kl), rk[r] = (PetscMPIInt)(rcnt[r] * kl), sv[r] = (PetscMPIInt)(scnt[r] * w), rv[r] = (PetscMPIInt)(rcnt[r] * w);
  }
  {
    PetscMPIInt *dk, *drk, *dv, *drv;
    PetscCall(PetscMalloc4(size, &dk, size, &drk, size, &dv, size, &drv));
    for (PetscMPIInt r = 0; r < size; r++) dk[r] = (PetscMPIInt)(sd[r] * kl), drk[r] = (PetscMPIInt)(rd[r] * kl), dv[r] = (PetscMPIInt)(sd[r] * w), drv[r] = (PetscMPIInt)(rd[r] * w);
    PetscCall(PetscMalloc1(total * kl + 1, rkey));
    PetscCallMPI(MPI_Alltoallv(skey, sk, dk, MPI_INT64_T, *rkey, rk, drk, MPI_INT64_T, comm));
    *rval = NULL;
    if (w) {
      PetscCall(PetscMalloc1(total * w + 1, rval));
      PetscCallMPI(MPI_Alltoallv(sval, sv, dv, MPIU_REAL, *rval, rv, drv, MPIU_REAL, comm));
    }
    PetscCall(PetscFree4(dk, drk, dv, drv));
  }
  *nr = total;
  PetscCall(PetscFree(skey));
  PetscCall(PetscFree(sval));
  PetscCall(PetscFree6(sd, rd, sk, rk, sv, rv));
  PetscCall(PetscFree2(dest, off));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslRendezvous(MPI_Comm comm, PetscInt kl, PetscInt w, PetscInt na, const int64_t akey[], const PetscReal aval[], PetscInt nq, const int64_t qkey[],
                             PetscReal qval[], PetscBool found[])
{
  PetscMPIInt size, *acnt, *racnt, *qcnt, *rqcnt, *sc, *rc, *sd, *rd;
  PetscInt    nra, nrq, *apos, *qpos, *order;
  int64_t    *rakey, *rqkey;
  PetscReal  *raval, *rqval, *reply, *back;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(PetscMalloc4(size, &acnt, size, &racnt, size, &qcnt, size, &rqcnt));
  PetscCall(PetscMalloc2(na + 1, &apos, nq + 1, &qpos));
  PetscCall(Scatter(comm, kl, w, na, akey, aval, acnt, racnt, apos, &nra, &rakey, &raval));
  PetscCall(Scatter(comm, kl, 0, nq, qkey, NULL, qcnt, rqcnt, qpos, &nrq, &rqkey, &rqval));
  /* the answers hashed here in key order, each question answered by binary search */
  PetscCall(PetscMalloc1(nra + 1, &order));
  for (PetscInt i = 0; i < nra; i++) order[i] = i;
  sort_keys = rakey, sort_kl = kl;
  qsort(order, (size_t)nra, sizeof(PetscInt), IndexCompare);
  PetscCall(PetscMalloc1(nrq * (w + 1) + 1, &reply));
  for (PetscInt q = 0; q < nrq; q++) {
    const int64_t *k  = &rqkey[q * kl];
    PetscInt       lo = 0, hi = nra; /* the first answer not below k */
    while (lo < hi) {
      PetscInt mid = (lo + hi) / 2;
      if (KeyCompare(&rakey[order[mid] * kl], k, kl) < 0) lo = mid + 1;
      else hi = mid;
    }
    if (lo < nra && !KeyCompare(&rakey[order[lo] * kl], k, kl)) {
      if (w) memcpy(&reply[q * (w + 1)], &raval[order[lo] * w], sizeof(PetscReal) * w);
      reply[q * (w + 1) + w] = 1;
    } else {
      for (PetscInt j = 0; j <= w; j++) reply[q * (w + 1) + j] = 0;
    }
  }
  /* the replies back in the order the questions were sent */
  PetscCall(PetscMalloc4(size, &sc, size, &rc, size, &sd, size, &rd));
  for (PetscMPIInt r = 0; r < size; r++) sc[r] = (PetscMPIInt)(rqcnt[r] * (w + 1)), rc[r] = (PetscMPIInt)(qcnt[r] * (w + 1));
  sd[0] = rd[0] = 0;
  for (PetscMPIInt r = 1; r < size; r++) sd[r] = sd[r - 1] + sc[r - 1], rd[r] = rd[r - 1] + rc[r - 1];
  PetscCall(PetscMalloc1(nq * (w + 1) + 1, &back));
  PetscCallMPI(MPI_Alltoallv(reply, sc, sd, MPIU_REAL, back, rc, rd, MPIU_REAL, comm));
  for (PetscInt q = 0; q < nq; q++) {
    const PetscReal *b = &back[qpos[q] * (w + 1)];
    if (w) memcpy(&qval[q * w], b, sizeof(PetscReal) * w);
    found[q] = (PetscBool)(b[w] > 0);
  }
  PetscCall(PetscFree(back));
  PetscCall(PetscFree4(sc, rc, sd, rd));
  PetscCall(PetscFree(reply));
  PetscCall(PetscFree(order));
  PetscCall(PetscFree(rakey));
  PetscCall(PetscFree(raval));
  PetscCall(PetscFree(rqkey));
  PetscCall(PetscFree(rqval));
  PetscCall(PetscFree2(apos, qpos));
  PetscCall(PetscFree4(acnt, racnt, qcnt, rqcnt));
  PetscFunctionReturn(PETSC_SUCCESS);
}
