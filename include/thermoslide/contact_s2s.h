/* thermoslide contact kernels: 2D surface-to-surface (segment-to-segment) contact.
 *
 * Contact is enforced at integration points of the secondary faces instead of at secondary nodes. Each
 * secondary face (line2 or line3) is cut at the projections of the main surface's face ends (the kinks of
 * the main surface and of the main shape functions), and each piece gets a Gauss rule exact for the
 * integrands of flat faces, so that a uniform pressure and a uniform heat flux are transmitted exactly
 * through a non-matching interface (the contact patch test). A point is a "virtual secondary node" of the
 * node-to-segment kernel (TslContactElement: same laws, friction, heat and smoothing) at
 *   x_p = sum_b N_b(zeta) x_b,  u_p = sum_b N_b(zeta) u_b   (N_b the secondary face's shape functions),
 * with tributary length the point's weight, and its residual and tangent are expanded to the secondary
 * face's nodes by the chain rule: R_b = N_b R_s, K_bj = N_b K_sj, K_ib = K_is N_b.
 *
 * Everything here works on plain arrays: no MPI, no PETSc objects. Conventions, units and signs are those
 * of include/thermoslide/contact.h; docs/contact.md ("Surface-to-surface") describes the method.
 * Secondary-face parameter zeta in [0, 1] from the face's first end to its second (the contact face
 * parameter of TslContactFaceShape).
 */
#pragma once
#include <thermoslide/contact.h>

/* Nodes of an expanded element: the secondary face's, then the kernel's nodes but the secondary one. */
#define TSL_CONTACT_S2S_MAX_NODES (TSL_CONTACT_MAX_FACE_NODES + TSL_CONTACT_MAX_NODES - 1)
#define TSL_CONTACT_S2S_MAX_DOF   (TSL_CONTACT_S2S_MAX_NODES * TSL_CONTACT_MAX_NODE_DOF)
#define TSL_CONTACT_S2S_MAX_GAUSS 4 /* points per piece */
/* 3D: the secondary face's nodes and the main face's (the kernel's node 0 being the virtual node) */
#define TSL_CONTACT_S2S3_MAX_NODES (2 * TSL_CONTACT3_MAX_FACE_NODES)
#define TSL_CONTACT_S2S3_MAX_DOF   (TSL_CONTACT_S2S3_MAX_NODES * TSL_CONTACT3_NU) /* also bounds the 2D element's */

/* Gauss points per piece of a secondary face family: 2 for line2 and 3 for line3, exact (degree 3 and 5)
 * for N_b N_a 2 pi r on flat faces (a uniform pressure and heat flux), the integrands of the patch test in
 * plane and axisymmetric models. */
PetscInt TslContactSegmentGaussPoints(TslContactFaceKind kind);

/* The break parameters of a secondary face (current coordinates y[2*b + d], family kind): the closest
 * points on the face of the np points pts[2*i + d] (the main faces' ends) that fall inside it by more than
 * tol (a fraction of the face), with 0 and 1, sorted, near-duplicates (closer than tol) merged. Writes at
 * most cap values to zeta[] and the count to *n (at least 2). */
PetscErrorCode TslContactSegmentBreaks(TslContactFaceKind kind, const PetscReal y[], PetscInt np, const PetscReal pts[], PetscReal tol, PetscInt cap,
                                       PetscReal zeta[], PetscInt *n);

/* The Gauss points of the piece [z0, z1] of a secondary face with reference coordinates X[2*b + d]:
 * *nq = TslContactSegmentGaussPoints(kind) parameters zeta[] and weights w[] (reference lengths:
 * Gauss weight x (z1 - z0) x |dX/dzeta|). The weights of the pieces of a face sum to its length (exactly
 * for straight faces). */
PetscErrorCode TslContactSegmentRule(TslContactFaceKind kind, const PetscReal X[], PetscReal z0, PetscReal z1, PetscInt *nq, PetscReal zeta[],
                                     PetscReal w[]);

/* Sets the virtual secondary node of a kernel input (in->x[0], in->u[0]) at parameter zeta of a secondary
 * face: reference coordinates X[2*b + d] and unknowns U[nu*b + c] of its nodes, nu unknowns per node
 * (TslContactNodeUnknowns(in->kin)). The rest of the input (main segment, law data, length = the point's
 * weight, history) is the caller's. */
PetscErrorCode TslContactPointSetUp(TslContactFaceKind kind, const PetscReal X[], const PetscReal U[], PetscReal zeta, TslContactInput *in);

/* Residual and tangent of a contact point at zeta of a secondary face of family kind: TslContactElement
 * of the input (its node 0 the virtual node set by TslContactPointSetUp) expanded to the element of the
 * secondary face's nodes (first, in face order) and the kernel's other nodes (main segment, smoothing
 * neighbours, in kernel order) and *added* to R[nu*(nsn + nnode - 1)], K likewise square (row-major, may be
 * NULL): the points of one face pair sum into one block without a copy each. out as TslContactElement's,
 * with out->nnode = nsn + nnode - 1. */
PetscErrorCode TslContactPointElement(const TslContactLaw *law, const TslContactInput *in, TslContactFaceKind kind, PetscReal zeta, PetscReal R[],
                                      PetscReal K[], TslContactOutput *out);

/* The chain rule of a contact point: R, K of a kernel element with nk nodes of nu unknowns, node 0 the
 * virtual secondary node x_p = sum_b N_b x_b, expanded to the element of the secondary face's nsn nodes
 * (first) and the kernel's other nodes: R_b = N_b R_s, K_bj = N_b K_sj, K_ib = K_is N_b,
 * K_bb' = N_b K_ss N_b', added to R[nu*(nsn + nk - 1)], K likewise square (either may be NULL; Kk then
 * unused). */
PetscErrorCode TslContactPointExpand(PetscInt nu, PetscInt nk, PetscInt nsn, const PetscReal N[], const PetscReal Rk[], const PetscReal Kk[], PetscReal R[],
                                     PetscReal K[]);

/* ---------------------------------------------------------------------------------------------------
 * 3D surface-to-surface (contact/clip3.c): overlap of a secondary face with a main face by polygon clipping,
 * integration points on the overlap, the 3D node-to-surface kernel at a point. docs/contact.md,
 * "3D surface-to-surface".
 * ------------------------------------------------------------------------------------------------- */
#define TSL_CONTACT_CLIP_MAX_VERTICES 16 /* a convex n-gon clipped by a convex m-gon has at most n + m vertices */
#define TSL_CONTACT_TRI_GAUSS         6  /* points of the triangle rule (degree 4) */
/* points of one (secondary face, main face) overlap: up to 4 linear pieces (tri6), each polygon fanned into
 * at most TSL_CONTACT_CLIP_MAX_VERTICES triangles (a fan from its centroid) */
#define TSL_CONTACT_OVERLAP_MAX_POINTS (4 * TSL_CONTACT_CLIP_MAX_VERTICES * TSL_CONTACT_TRI_GAUSS)

/* Sutherland-Hodgman: the part of the polygon P (n vertices P[2*i + d], any simple polygon) inside the
 * convex polygon C (m vertices, counter-clockwise). Writes the vertices to Q (room for cap), returns their
 * count (0: no overlap; more than cap: an error). */
PetscErrorCode TslContactClipPolygon(PetscInt n, const PetscReal P[], PetscInt m, const PetscReal C[], PetscInt cap, PetscReal Q[], PetscInt *nq);

/* Signed area of the polygon P (n vertices P[2*i + d]): > 0 counter-clockwise. */
PetscReal TslContactPolygonArea(PetscInt n, const PetscReal P[]);

/* One integration point on a secondary face: the face's interpolation N_b at the point (its own shape
 * functions for tri3 and quad4; for tri6 those of the linear sub-triangle holding the point, as the modified
 * elements lump pressure), and its weight (reference area). */
typedef struct {
  PetscReal N[TSL_CONTACT3_MAX_FACE_NODES];
  PetscReal w;
} TslContactOverlapPoint;

/* The overlap of a secondary face (family skind, TslContactFace3Find; reference coordinates X[3*b + d] and
 * current y[3*b + d]) with a main face (mkind, current ym[]): each linear piece of the secondary face (the
 * face, or tri6's four sub-triangles) is flattened onto its plane (centroid, area normal n_s), the main
 * face's corners are projected onto that plane along n_s, the main polygon is clipped by the piece's
 * (Sutherland-Hodgman) and the overlap fanned from its vertex centroid into triangles, each with the
 * 6-point rule of degree 4 (a triangle or quadrilateral overlap takes one rule on the whole: docs/contact.md).
 * A point's parameters on the piece come from the plane coordinates (affine for triangles, the bilinear
 * inverse for quads) and its weight is the plane weight times the reference-to-plane area ratio
 * dA_ref/dA_plane there, so the weights are reference areas: their sum is the reference area of the overlap
 * (the whole face's area when the main face covers it). Exact integration of N_b N_a (a uniform pressure and
 * heat flux) on flat faces with affine parameter maps (triangles, parallelograms). Faces whose normals do not oppose (n_s . n_m >= 0), or with
 * no overlap, give *npt = 0. *dist (may be NULL): the signed distance along n_s from the secondary face's
 * plane to the main face's plane at the overlap's centroid (> 0 open; meaningless when *npt = 0). Writes at
 * most cap points. */
PetscErrorCode TslContactOverlap3(PetscInt skind, const PetscReal X[], const PetscReal y[], PetscInt mkind, const PetscReal ym[], PetscInt cap,
                                  TslContactOverlapPoint pt[], PetscInt *npt, PetscReal *dist);

/* Sets the virtual secondary node of a 3D kernel input (in->x[0], in->u[0]): x_p = sum_b N_b X_b,
 * u_p = sum_b N_b U_b over the nsn nodes of the secondary face (X[3*b + d], U[4*b + c]). */
void TslContactPointSetUp3(PetscInt nsn, const PetscReal N[], const PetscReal X[], const PetscReal U[], TslContactInput3 *in);

/* Residual and tangent of a 3D contact point: TslContactElement3 of the input (node 0 the virtual node of
 * TslContactPointSetUp3, area = the point's weight) expanded to the secondary face's nsn nodes, then the main
 * face's (TslContactPointExpand), added to R[4*(nsn + nper)], K square (may be NULL); out->nnode = nsn + nper. */
PetscErrorCode TslContactPointElement3(const TslContactLaw *law, const TslContactInput3 *in, PetscInt nsn, const PetscReal N[], PetscReal R[],
                                       PetscReal K[], TslContactOutput *out);
