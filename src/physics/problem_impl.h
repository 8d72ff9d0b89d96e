/* Private layout of TslProblem, shared by the files of src/physics/. */
#pragma once
#include <thermoslide/problem.h>

/* Amplitude codes besides an index into model->amplitudes[]. */
#define TSL_AMP_DEFAULT (-1) /* the step's default: RAMP or STEP */
#define TSL_AMP_HOLD    (-2) /* carried over from an earlier step: constant */

/* A value that follows the step's loading history: v(t) = amplitude or ramp from v0 to v1. */
typedef struct {
  PetscBool active;
  PetscReal v0, v1;
  PetscInt  amp;
} TslHistoryValue;

/* A distributed (face or body) load on one local element. */
typedef struct {
  PetscInt        elem, face; /* local element, face 1..6 (0: body) */
  TslFaceLoadKind kind;
  TslHistoryValue value;      /* pressure, flux or film coefficient */
  TslHistoryValue sink;       /* film sink temperature */
  PetscInt        film_amp;   /* amplitude scaling the film coefficient, or -1 */
  PetscInt        seq;        /* order of definition (later replaces earlier) */
} TslFaceRecord;

struct _p_TslProblem {
  MPI_Comm  comm;
  TslModel *m;
  PetscInt  dim, ndof, nn, nown; /* local nodes, owned nodes */
  PetscInt  rstart;              /* first owned global dof */

  Vec                    X, Xold, Xl, Fl; /* Xl, Fl: ghosted work vectors */
  Vec                    Rraw;            /* unconstrained residual of the last post-processed state */
  Mat                    J;
  ISLocalToGlobalMapping l2g;
  IS                     is_u, is_theta;

  PetscInt           *elem_lnode; /* local node of each element node (model elem_ptr layout) */
  TslElementMaterial *emat;       /* [nelem] */
  PetscReal          *theta_init; /* [nn] */
  PetscReal           row_scale[2]; /* constraint-row scale for displacement and temperature dofs */

  /* step state */
  PetscInt      step;
  PetscBool     steady;
  TslAmpDefault amp_default;
  PetscReal     period, t, dt, ttot;

  TslHistoryValue *bc;    /* [nn*ndof] prescribed values (owned and ghost dofs) */
  TslHistoryValue *nload; /* [nn*ndof] nodal loads (CLOAD, CFLUX), owned dofs only */
  PetscInt         nface, face_seq;
  TslFaceRecord   *face;       /* sorted by element */
  PetscInt        *face_start; /* [nelem+1] CSR over face[] */

  /* equations: dep[d] = index into m->equations if local dof d is eliminated, else -1 */
  PetscInt  *dep;
  PetscInt **eq_ldof; /* [nequation][n] local dof of each term */
};

/* Element data gathered from the local (ghosted) arrays; xa / xoa may be NULL (zeros). */
typedef struct {
  PetscInt  n, nd;
  PetscInt  ld[TSL_MAX_ELEM_DOF];
  PetscReal x[TSL_MAX_ELEM_NODES * 3], u[TSL_MAX_ELEM_DOF], uo[TSL_MAX_ELEM_DOF], ti[TSL_MAX_ELEM_NODES];
  TslElementInput in;
} TslElemData;

void           TslProblemGather(TslProblem p, PetscInt e, const PetscScalar *xa, const PetscScalar *xoa, TslElemData *d);
PetscReal      TslProblemEvalHistory(TslProblem p, const TslHistoryValue *h);
PetscErrorCode TslProblemLocalNode(TslProblem p, PetscInt gnum, PetscInt *lnode);
PetscErrorCode TslProblemPreallocate(TslProblem p);
PetscErrorCode TslProblemCheckElements(TslProblem p);
