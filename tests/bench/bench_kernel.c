/* Element kernel cost per catalogue row, in CPU time of this thread (robust to a loaded machine):
 * residual (internal force + heat flow) and residual + tangent of one element, on a mildly distorted
 * unit element with a nonzero state, plus the flop-free floor of touching the element arrays.
 * For the types with an explicit force record (src/element/fast.c): TslElementFastForceBatch per element
 * (batches of TSL_FAST_LANES), on one batch (in cache) and streamed over 64 MB of batches with the next
 * batch prefetched as the explicit loop does, so the difference is the memory traffic's share. Then, for the types that
 * take *PLASTIC, the same element flowing at every point (Mises, isotropic hardening, and combined hardening with two
 * back stresses): residual and residual + tangent, and their ratios to the elastic kernel's and, for the explicit
 * steps, to the elastic force record's (issue 47's goals: 1.5 implicit, 1.3 explicit). Prints figures only (ctest -L
 * bench). usage: bench_kernel [seconds per figure, default 0.2; a negative value -N runs exactly N calls per figure,
 * for instruction counts with perf stat] [TYPE] */
#define _POSIX_C_SOURCE 200809L
#include <thermoslide/element.h>
#include <thermoslide/material.h>
#include <time.h>
#include <string.h>
#include <stdio.h>

static double CpuNow(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static void Constant(TslPropertyTable *t, PetscReal v0, PetscReal v1)
{
  t->n           = 1;
  t->value[0][0] = v0, t->value[0][1] = v1;
}

/* The benchmark's element of type t: a mildly distorted unit element with a nonzero state, an elastic material with
 * every property (sec takes it) */
static void Element(const TslElementType *t, TslMaterial *mat, TslElementSection *sec, PetscReal x[], PetscReal u[])
{
  const TslGeometry *g = t->geom;
  PetscCallAbort(PETSC_COMM_SELF, PetscMemzero(mat, sizeof(*mat)));
  Constant(&mat->prop[TSL_PROP_ELASTIC], 200e3, 0.3);
  Constant(&mat->prop[TSL_PROP_CONDUCTIVITY], 10, 0);
  Constant(&mat->prop[TSL_PROP_DENSITY], 2, 0);
  Constant(&mat->prop[TSL_PROP_SPECIFIC_HEAT], 3, 0);
  Constant(&mat->prop[TSL_PROP_EXPANSION], 1e-5, 0);
  *sec = (TslElementSection){mat, 0.5, 0, 0, 0};
  for (PetscInt a = 0; a < g->nnode; a++) {
    for (PetscInt d = 0; d < t->dim; d++) x[3 * a + d] = 0.5 * g->node_xi[a][d] + 0.02 * PetscSinReal(3.1 * a + 1.3 * d) + (d == 0 ? 2 : 0);
    for (PetscInt i = 0; i < t->ndof; i++) u[t->ndof * a + i] = 1e-4 * PetscCosReal(1.7 * a + i);
    u[t->ndof * a + t->ndof - 1] = 20 + a;
  }
  for (PetscInt a = g->nnode; a < TslElementTypeNodes(t); a++) x[3 * a] = 0.3; /* reference node of generalized plane strain */
}

/* ns per call of TslElementInternal (K or not), repeated for about `budget` seconds */
static PetscErrorCode Time(const TslElementInput *in, PetscBool tangent, double budget, double *ns)
{
  static PetscReal R[TSL_MAX_ELEM_DOF], K[TSL_MAX_ELEM_DOF * TSL_MAX_ELEM_DOF];
  PetscBool        inv;
  long             n = 0, batch = 64;
  double           t0 = CpuNow(), t;

  PetscFunctionBeginUser;
  do {
    for (long i = 0; i < batch; i++) PetscCall(TslElementInternal(in, R, tangent ? K : NULL, &inv));
    n += batch;
    t = CpuNow() - t0;
  } while (budget > 0 ? t < budget : n < -budget);
  PetscCheck(!inv, PETSC_COMM_SELF, PETSC_ERR_PLIB, "inverted benchmark element");
  *ns = 1e9 * t / n;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ns per element of TslElementFastForceBatch over nrec batches (size * TSL_FAST_LANES reals each: the
 * element's record in every lane), for about `budget` seconds */
static double TimeRecords(const TslElementFastShape *shape, PetscBool nl, const PetscReal *recs, PetscInt size, PetscInt nrec,
                          const TslElementInput *in, double budget)
{
  enum { W = TSL_FAST_LANES };
  static PetscReal R[TSL_MAX_ELEM_DOF * W], Rv[TSL_MAX_ELEM_DOF * W], v[TSL_MAX_ELEM_DOF * W], u[TSL_MAX_ELEM_DOF * W], ti[TSL_MAX_ELEM_NODES * W];
  const PetscInt   n = in->type->geom->nnode, nd = n * in->type->ndof;
  PetscReal        w[W], eta[W] = {1e-6, 1e-6, 1e-6, 1e-6}, eta2[W] = {1e-12, 1e-12, 1e-12, 1e-12}, sum = 0;
  long             k  = 0;
  double           t0 = CpuNow(), t;

  for (PetscInt j = 0; j < W; j++) {
    for (PetscInt i = 0; i < nd; i++) v[i * W + j] = 1e-3 * i;
    TslElementFastInterleave(nd, j, in->u, u);
    TslElementFastInterleave(n, j, in->theta_init, ti);
  }
  do {
    for (PetscInt c = 0; c < 1024; c += nrec) /* at least 1024 calls between clock reads */
      for (PetscInt b = 0; b < nrec; b++) {
        const PetscReal *next = recs + ((b + 1) % nrec) * size * W; /* as the explicit loop: the next batch non-temporal */
        for (PetscInt k = 0; k < size * W; k += 8) __builtin_prefetch(next + k, 0, 0);
        (void)TslElementFastForceBatch(shape, nl, recs + b * size * W, u, ti, v, NULL, 0, eta, eta2, R, Rv, w, NULL);
        sum += R[0];
      }
    k += nrec >= 1024 ? nrec : 1024;
    t = CpuNow() - t0;
  } while (budget > 0 ? t < budget : k < -budget);
  if (sum == 12345.678) printf(" ");
  return 1e9 * t / (k * W);
}

/* The record figures of the element in (small or finite strain): on one batch (f_ns) and streamed (fs_ns); 0 without a row */
static PetscErrorCode RecordNs(const TslElementInput *in, PetscBool nl, double budget, double *f_ns, double *fs_ns)
{
  TslElementFastShape shape;

  PetscFunctionBeginUser;
  *f_ns = *fs_ns = 0;
  if (TslElementFastShapeGet(in->type, &shape)) {
    const PetscInt size = TslElementFastSize(in), nrec = (64 << 20) / (size * TSL_FAST_LANES * (PetscInt)sizeof(PetscReal));
    PetscReal     *recs, rec[TSL_FAST_MAX_SIZE];
    PetscCall(PetscMalloc1(size * TSL_FAST_LANES * nrec, &recs));
    PetscCheck(TslElementFastBuild(in, rec), PETSC_COMM_SELF, PETSC_ERR_PLIB, "inverted benchmark element");
    for (PetscInt j = 0; j < TSL_FAST_LANES; j++) TslElementFastInterleave(size, j, rec, recs);
    for (PetscInt b = 1; b < nrec; b++) PetscCall(PetscArraycpy(recs + b * size * TSL_FAST_LANES, recs, size * TSL_FAST_LANES));
    *f_ns  = TimeRecords(&shape, nl, recs, size, 1, in, budget);
    *fs_ns = TimeRecords(&shape, nl, recs, size, nrec, in, budget);
    PetscCall(PetscFree(recs));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  double        budget = argc > 1 ? atof(argv[1]) : 0.2;
  static double plastic[1024][4]; /* each row's elastic residual, jacobian, record and streamed record ns */

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "%-9s %6s %5s %12s %12s %12s %12s %10s %10s\n", "type", "nodes", "dofs", "residual_ns", "jacobian_ns",
                        "res_ns/node", "jac_ns/node", "record_ns", "streamed"));
  for (PetscInt k = 0; k < TslElementTypeCount(); k++) {
    const TslElementType *t = TslElementTypeGet(k);
    TslMaterial           mat;
    TslElementSection     sec;
    PetscReal             x[TSL_MAX_ELEM_NODES * 3] = {0}, u[TSL_MAX_ELEM_DOF] = {0}, ti[TSL_MAX_ELEM_NODES] = {0};
    TslElementInput       in;
    double                r_ns, j_ns, f_ns = 0, fs_ns = 0;
    const PetscInt        nn = TslElementTypeNodes(t);

    if (argc > 2 && strcmp(argv[2], t->name)) continue;
    Element(t, &mat, &sec, x, u);
    in = (TslElementInput){.type = t, .sec = &sec, .x = x, .u = u, .theta_init = ti};
    PetscCall(Time(&in, PETSC_FALSE, budget, &r_ns));
    PetscCall(Time(&in, PETSC_TRUE, budget, &j_ns));
    PetscCall(RecordNs(&in, PETSC_FALSE, budget, &f_ns, &fs_ns));
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "%-9s %6" PetscInt_FMT " %5" PetscInt_FMT " %12.0f %12.0f %12.0f %12.0f %10.0f %10.0f\n", t->name, nn,
                          nn * t->ndof, r_ns, j_ns, r_ns / nn, j_ns / nn, f_ns, fs_ns));
    plastic[k][0] = r_ns, plastic[k][1] = j_ns, plastic[k][2] = f_ns, plastic[k][3] = fs_ns;
  }
  /* the plastic kernels: every point flowing from a zero state (yield 5 against elastic stresses of about 20) */
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "\nplastic (every point flowing): ns per element and the ratio to the elastic kernel (explicit: to its force record)\n"));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "%-9s %-9s %12s %12s %9s %9s %9s\n", "type", "hardening", "residual_ns", "jacobian_ns", "res/el", "jac/el", "res/rec"));
  for (PetscInt k = 0; k < TslElementTypeCount(); k++) {
    const TslElementType *t = TslElementTypeGet(k);
    const char           *why;
    if ((argc > 2 && strcmp(argv[2], t->name)) || t->ndof < 2 || !TslElementTypePlasticSupported(t, &why)) continue;
    for (PetscInt law = 0; law < 2; law++) {
      TslMaterial       mat;
      TslElementSection sec;
      PetscReal         x[TSL_MAX_ELEM_NODES * 3] = {0}, u[TSL_MAX_ELEM_DOF] = {0}, ti[TSL_MAX_ELEM_NODES] = {0}, *st;
      TslElementInput   in;
      double            r_ns, j_ns;
      Element(t, &mat, &sec, x, u);
      mat.plastic.n = 2, mat.plastic.row[0][0] = 5, mat.plastic.row[1][0] = 105, mat.plastic.row[1][1] = 0.1;
      if (law) mat.plastic.nback = 2, mat.plastic.nkt = 1, mat.plastic.kt_C[0][0] = 4e4, mat.plastic.kt_gamma[0][0] = 400, mat.plastic.kt_C[0][1] = 1e3, mat.plastic.n = 1;
      mat.heat_fraction = 0.9;
      PetscCall(PetscCalloc1(TslMaterialPlasticState(&mat) * TslElementTypeMechanicalPoints(t, &sec), &st));
      in = (TslElementInput){.type = t, .sec = &sec, .x = x, .u = u, .theta_init = ti, .pstate = st, .inelastic_rate = 1.0, .dt = 1.0};
      PetscCall(Time(&in, PETSC_FALSE, budget, &r_ns));
      PetscCall(Time(&in, PETSC_TRUE, budget, &j_ns));
      PetscCall(PetscFree(st));
      {
        char rec[32] = "-";
        if (plastic[k][2] > 0) snprintf(rec, sizeof(rec), "%.2f", r_ns / plastic[k][2]);
        PetscCall(PetscPrintf(PETSC_COMM_SELF, "%-9s %-9s %12.0f %12.0f %9.2f %9.2f %9s\n", t->name, law ? "combined" : "isotropic", r_ns, j_ns, r_ns / plastic[k][0],
                              j_ns / plastic[k][1], rec));
      }
    }
  }
  /* finite strain (NLGEOM): the same elastic element with the kinematics of an NLGEOM step, generic and by its record
   * (what explicit steps and implicit residuals take under NLGEOM; issue 48's goals: 1.5x for C3D8T's kernel, 1.3x for
   * the explicit C3D8RT record) */
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "\nfinite strain (NLGEOM): ns per element and the ratios to the small-strain kernel and record\n"));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "%-9s %12s %12s %9s %9s %10s %10s %9s %9s\n", "type", "residual_ns", "jacobian_ns", "res/el", "jac/el",
                        "record_ns", "streamed", "rec/rec", "str/str"));
  for (PetscInt k = 0; k < TslElementTypeCount(); k++) {
    const TslElementType *t = TslElementTypeGet(k);
    TslMaterial           mat;
    TslElementSection     sec;
    PetscReal             x[TSL_MAX_ELEM_NODES * 3] = {0}, u[TSL_MAX_ELEM_DOF] = {0}, ti[TSL_MAX_ELEM_NODES] = {0};
    TslElementInput       in;
    double                r_ns, j_ns, f_ns, fs_ns;
    char                  rr[32] = "-", ss[32] = "-";
    if ((argc > 2 && strcmp(argv[2], t->name)) || t->ndof < 2 || !TslElementTypeFiniteStrain(t)) continue;
    Element(t, &mat, &sec, x, u);
    in = (TslElementInput){.type = t, .sec = &sec, .x = x, .u = u, .theta_init = ti, .nlgeom = PETSC_TRUE};
    PetscCall(Time(&in, PETSC_FALSE, budget, &r_ns));
    PetscCall(Time(&in, PETSC_TRUE, budget, &j_ns));
    PetscCall(RecordNs(&in, PETSC_TRUE, budget, &f_ns, &fs_ns));
    if (plastic[k][2] > 0) snprintf(rr, sizeof(rr), "%.2f", f_ns / plastic[k][2]), snprintf(ss, sizeof(ss), "%.2f", fs_ns / plastic[k][3]);
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "%-9s %12.0f %12.0f %9.2f %9.2f %10.0f %10.0f %9s %9s\n", t->name, r_ns, j_ns, r_ns / plastic[k][0],
                          j_ns / plastic[k][1], f_ns, fs_ns, rr, ss));
  }
  PetscCall(PetscFinalize());
  return 0;
}
