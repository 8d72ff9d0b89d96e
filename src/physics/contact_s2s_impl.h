/* Surface-to-surface contact in the assembly: the data that src/physics/contact_s2s.c (2D, and what both
 * dimensions share: assembly, commit, rollback, outputs) and src/physics/contact_s2s3.c (3D: clipping,
 * history carried across a new cut) both see. */
#pragma once
#include "problem_impl.h"
#include <thermoslide/contact_s2s.h>

#define S2S_DEPART_TOL 1e-6 /* after convergence, a point this far (fraction) beyond its face re-pairs */

typedef struct {
  PetscInt           pair, nsn;
  TslContactFaceKind kind; /* 2D: the face family; 3D: its TslContactFace3Find family */
  PetscInt           lnode[TSL_CONTACT3_MAX_FACE_NODES];
  PetscBool          assemble;
  PetscInt           first, npt, first_c, npt_c; /* its points, current and committed */
} S2SFace;

typedef struct {
  PetscInt         seg;
  PetscReal        zeta, length;                 /* 2D: parameter on the secondary face; weight (length, 3D area) */
  PetscReal        N[TSL_CONTACT3_MAX_FACE_NODES]; /* 3D: the secondary face's interpolation at the point */
  TslContactState  hist;
  TslContactOutput out;
} S2SPoint;

struct _n_TslContactS2S {
  PetscInt   nface;
  S2SFace   *face;
  PetscInt   npt, cap, npt_c, cap_c;
  S2SPoint  *pt, *pt_c;
  PetscReal *trib;            /* [nn] int N_b ds (3D: dA) over the held faces of each node (reference) */
  PetscReal *cslip, *cslip_c; /* [nn] accumulated slip */
};

/* Shared by both dimensions (contact_s2s.c). */
PetscErrorCode TslS2SPush(TslContactS2S s, const S2SPoint *pt);
/* A point list of capacity *cap grown to hold n (its contents not kept). */
PetscErrorCode TslS2SReserve(S2SPoint **pts, PetscInt *cap, PetscInt n);
/* The secondary node a point of face fc stands for in the node-to-surface kernels (its weight and history),
 * and the local nodes of the point's expanded element: the face's, then the kernel element's others
 * (kn[1..nk), kn[0] being that stand-in node); *n of them. */
void TslS2SPointNode(const S2SFace *fc, const S2SPoint *pt, TslContactNode *cn);
void TslS2SPointNodes(const S2SFace *fc, const PetscInt kn[], PetscInt nk, PetscInt nodes[], PetscInt *n);
/* Whether the points new[0..nnew) are the old ones (same main faces, same places: *same), and whether the
 * sequence of main faces changed (a new matrix pattern: *changed). */
void TslS2SCompareCut(const S2SPoint *old, PetscInt nold, const S2SPoint *pnew, PetscInt nnew, PetscBool *same, PetscBool *changed);

/* 3D (contact_s2s3.c). */
PetscErrorCode TslS2S3FaceData(TslProblem p, const S2SFace *fc, const PetscScalar *xa, PetscReal X[], PetscReal U[]);
/* The kernel input of the last point's face pair (TslS2S3PointInput): the points of one pair come one after the
 * other and share everything but their own place, weight, history and projection start. fc = NULL: empty; the
 * caller empties it whenever the state xa changes. */
typedef struct {
  const S2SFace   *fc;
  PetscInt         seg, n, nodes[TSL_CONTACT_S2S3_MAX_NODES];
  TslContactInput3 in;
  PetscReal        X[3 * TSL_CONTACT3_MAX_FACE_NODES], U[TSL_CONTACT3_NU * TSL_CONTACT3_MAX_FACE_NODES];
} S2S3InputCache;
PetscErrorCode TslS2S3PointInput(TslProblem p, const S2SFace *fc, const S2SPoint *pt, const PetscScalar *xa, S2S3InputCache *cache,
                                 TslContactInput3 *in, PetscInt nodes[], PetscInt *n);
PetscErrorCode TslS2S3SearchPair(TslProblem p, PetscInt k, S2SPoint *old, PetscInt nold, const PetscScalar *xa, PetscInt *changed);
PetscBool      TslS2S3Departed(TslProblem p, const S2SPoint *pt, PetscInt pair);
PetscErrorCode TslS2S3Normals(TslProblem p, const PetscScalar *xa);
