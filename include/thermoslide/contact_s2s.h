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

/* Gauss points per piece of a secondary face family: 3 for line2 and 4 for line3, exact (degree 5 and 7)
 * for N_b N_a (pressure, heat flux) 2 pi r on flat faces with a linear pressure, the integrands of the
 * patch test in plane and axisymmetric models. */
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
 * neighbours, in kernel order): R[nu*(nsn + nnode - 1)], K likewise square (row-major, may be NULL).
 * out as TslContactElement's, with out->nnode = nsn + nnode - 1. */
PetscErrorCode TslContactPointElement(const TslContactLaw *law, const TslContactInput *in, TslContactFaceKind kind, PetscReal zeta, PetscReal R[],
                                      PetscReal K[], TslContactOutput *out);
