/* thermoslide discrete problem: the coupled u-theta unknowns of a distributed mesh, the loads and
 * constraints active in the current step, and the assembly of residual and Jacobian.
 *
 * Unknowns are node-interleaved blocks in the order of the element rows' node_dof (displacements, theta
 * last), block size ndof (the rows say how many: dim + 1 for the continuum types), numbered
 * contiguously per rank (owned nodes); the local form of the ghosted vectors holds owned nodes first,
 * then ghosts, in the local model's node order.
 *
 * Constraints are applied by row operations during assembly (see docs/design.md):
 *   - a prescribed dof (*BOUNDARY) gets the row  u_d - g(t) = 0  and element rows of it are dropped;
 *   - an *EQUATION  sum c_k u_k = 0 eliminates its first dof a: element rows of a are added to the rows
 *     of the other terms with weight -c_k/c_a (T^T R), and row a becomes  u_a + sum (c_k/c_a) u_k = 0.
 * Both keep the Jacobian consistent with the residual (-snes_test_jacobian) and need no special solver.
 */
#pragma once
#include <thermoslide/model.h>
#include <thermoslide/element.h>
#include <petscsnes.h>
#include <stdint.h>

typedef struct _p_TslProblem *TslProblem;

/* Heat and energy totals of the current state (sums over all ranks). Rates are per unit time. */
typedef struct {
  PetscReal heat_in;        /* applied heat: CFLUX + surface and body fluxes */
  PetscReal film_out;       /* heat leaving through films */
  PetscReal radiation_out;  /* heat radiated to the ambient (*RADIATE, *SRADIATE) */
  PetscReal reaction_heat;  /* heat entering through prescribed temperatures (sum of RFL) */
  PetscReal stored_rate;    /* change of stored heat over the increment / dt (0 in steady state) */
  PetscReal interface_heat; /* heat crossing contact interfaces, main -> secondary (internal) */
  PetscReal dissipation;    /* frictional dissipation rate */
  PetscReal friction_heat;  /* part of the dissipation converted to heat (eta) */
  PetscReal plastic_work;   /* plastic work of the increment (int sigma : d eps_p dV; not a rate) */
  PetscReal plastic_heat;   /* the heat it gives per unit time (*INELASTIC HEAT FRACTION eta / dt) */
  PetscReal balance;        /* heat_in + reaction_heat + friction_heat + plastic_heat - film_out - radiation_out - stored_rate */
  PetscReal strain_energy, hourglass_energy; /* of the elements, as TslProblemEnergies (from the same pass) */
} TslHeatBalance;

/* Takes ownership of the local model. */
PetscErrorCode TslProblemCreate(MPI_Comm comm, TslModel *local, TslProblem *prob);
PetscErrorCode TslProblemDestroy(TslProblem *prob);
PetscErrorCode TslProblemGetModel(TslProblem prob, const TslModel **model);

/* The solution vector (ghosted global Vec, block size ndof) and the state at the start of the increment. */
PetscErrorCode TslProblemGetSolution(TslProblem prob, Vec *X);
PetscErrorCode TslProblemGetOldSolution(TslProblem prob, Vec *Xold);
/* Matrix with the exact nonzero pattern of the current constraints (re-preallocated by SetStep). */
PetscErrorCode TslProblemGetJacobian(TslProblem prob, Mat *J);
/* fn(ctx) is called before the Jacobian gets a new pattern (the matrix object stays; its old arrays are then
 * freed, the new ones allocated): a solver holding blocks of the old pattern lets go of them there, so that the
 * new matrix does not come on top of the old preconditioner. */
PetscErrorCode TslProblemSetRepatternCallback(TslProblem prob, PetscErrorCode (*fn)(void *), void *ctx);
/* Index sets of the displacement and temperature dofs owned here (for PCFIELDSPLIT). */
PetscErrorCode TslProblemGetFieldIS(TslProblem prob, IS *is_u, IS *is_theta);

/* Activates step s (0-based): loads and boundary conditions carried over and changed as the dialect says
 * (OP=MOD/NEW, amplitudes, RAMP/STEP). Rebuilds the matrix pattern. */
PetscErrorCode TslProblemSetStep(TslProblem prob, PetscInt s);
/* Time of the increment being solved: step time t (end of increment), increment dt, total time. */
PetscErrorCode TslProblemSetTime(TslProblem prob, PetscReal step_time, PetscReal dt, PetscReal total_time);
/* The step time last set (at a step's start: the time the step before ended at). */
PetscReal      TslProblemGetStepTime(TslProblem prob);
/* Mises plasticity: the state the last TslProblemHeatBalance found at its solution becomes the committed one (an
 * accepted increment; a cutback keeps the committed state, so nothing is rolled back). */
PetscErrorCode TslProblemCommitState(TslProblem prob);
/* A digest of this rank's layout (nodes with their ids and coordinates, dofs, elements, contact nodes), for checking that a
 * continuation has the model and partition its restart point was written with. */
PetscErrorCode TslProblemLayoutDigest(TslProblem prob, uint64_t *digest);
/* Restart (src/physics/state.c, for src/solve/restart.c): the problem's state beyond the solution and the step's
 * tables (its contact nodes' pairing, history and slip, the plastic points' state, the surface-to-surface points,
 * whose number varies with the cut), current and committed (an explicit increment's pairing search follows its
 * commit), in the deck's own terms, so that a continuation on any rank count or partition reads it: blobs of reals, each
 * under a key of TSL_BLOB_KEY integers made of natural indices (a kind, then e.g. the pair and the node), local indices
 * written as natural ones (a pairing's main face as its first three nodes). StateBlobs gives this rank's (*n of them,
 * keys key[TSL_BLOB_KEY*i..], lengths len[i], the values one after the other in val; PetscFree each array).
 * StateFromBlobs asks fetch, collectively (a fixed number of rounds on every rank), for the blobs this rank's
 * contact nodes, plastic elements and faces need, and takes them in; the solution must be in place already (the 3D
 * nodal normals are computed from it). A state the point lacks, or a pairing with a main face this partition does
 * not hold, is an error. The matrix pattern is marked stale (the pairing is the point's). */
#define TSL_BLOB_KEY 5
typedef PetscErrorCode (*TslBlobFetch)(void *ctx, PetscInt n, const int64_t key[], const PetscInt len[], PetscReal val[], PetscBool found[]);
PetscErrorCode TslProblemStateBlobs(TslProblem prob, PetscInt *n, int64_t **key, PetscInt **len, PetscReal **val);
PetscErrorCode TslProblemStateFromBlobs(TslProblem prob, TslBlobFetch fetch, void *ctx);
/* Collective: a digest of the mesh (nodes with ids and coordinates, elements, contact nodes) independent of the rank
 * count, for checking that a continuation on another one has the model its point was written with. */
PetscErrorCode TslProblemMeshDigest(TslProblem prob, uint64_t *digest);
/* A digest of the model's materials, sections, interactions and contact pairs (the same on every rank), for checking
 * that a continuation has the physics its restart point was written with. */
PetscErrorCode TslProblemModelDigest(TslProblem prob, uint64_t *digest);
/* After step s: for each material whose *PLASTIC data depend on temperature, whether the nodal temperatures of its
 * elements left the temperatures the data cover (the end values hold there, as in the dialect): a warning naming the
 * keyword's line, once per material in the run. Collective. */
PetscErrorCode TslProblemPlasticTemperatureCheck(TslProblem prob, PetscInt s);
/* *TEMPERATURE, FILE= (src/physics/tfile.c): every step's results file checked against the model (the same nodes, the
 * frames it names, NT in them); collective, an error at the keyword's line. Before the run writes anything. */
PetscErrorCode TslProblemTemperatureFilesCheck(TslProblem prob);
/* The capacity term's time discretisation, chosen by the solver (src/solve/): the residual gets
 * shift (Q(theta) - Q(theta_old)) per node and the Jacobian shift dQ/dtheta, with Q the lumped heat
 * content (element.h). Backward Euler: shift = 1/dt; steady state: 0. The kernels know nothing of it. */
PetscErrorCode TslProblemSetCapacityRate(TslProblem prob, PetscReal shift);
/* The step time of the first corner (tabular point) of an amplitude followed in this step that
 * lies strictly after t and before t_end; t_end if there is none. Increments end there, so that a history
 * with reversals is followed exactly (the slip of an increment is its path, not the chord). */
PetscErrorCode TslProblemNextAmplitudeCorner(TslProblem prob, PetscReal t, PetscReal t_end, PetscReal *tb);
/* The message of the last convergence-type failure decided by all ranks (a contact projection that did
 * not converge, an injected failure): shown with the cutback it caused. */
PetscErrorCode TslProblemGetFailureMessage(TslProblem prob, const char **msg);
/* Writes the prescribed values at the current time into X (owned dofs) and updates ghosts. */
PetscErrorCode TslProblemApplyPrescribed(TslProblem prob, Vec X);

/* SNES callbacks (ctx = the problem). */
PetscErrorCode TslProblemFormFunction(SNES snes, Vec X, Vec F, void *ctx);
PetscErrorCode TslProblemFormJacobian(SNES snes, Vec X, Mat J, Mat P, void *ctx);

/* After convergence: reactions (RF, RFL), heat balance of the increment and field values for output.
 * Arrays are allocated by the callee and freed with PetscFree: node fields [nnode_owned][ncomp],
 * element fields [nelem][ncomp]. */
PetscErrorCode TslProblemHeatBalance(TslProblem prob, TslHeatBalance *hb);
/* Strain energy of the elements and the energy of the reduced-integration types' hourglass control
 * (collective; the element outputs ELSE and ELASE summed). */
PetscErrorCode TslProblemEnergies(TslProblem prob, PetscReal *strain, PetscReal *hourglass);
/* The largest element rotation of the current state (TslElementCentreRotation) over all ranks, and an element (its id)
 * that has it (collective). */
PetscErrorCode TslProblemLargestRotation(TslProblem prob, PetscReal *omega, PetscInt *elem_id);

/* Output fields, one table row each (fields.c): nodal U, NT, RF, RFL, CPRESS, CSLIP, CSTATUS, HFLA and
 * element S, E, HFL, ELSE (strain energy), ELASE (hourglass-control energy). TslFieldFind returns -1 for
 * an unknown name. TslProblemField allocates vals (free with PetscFree): [owned nodes][ncomp] or
 * [local elements][ncomp]. */
typedef enum { TSL_FIELD_NODE = 0, TSL_FIELD_ELEMENT = 1 } TslFieldKind;
PetscInt TslFieldCount(void);
PetscInt TslFieldFind(const char *name);
/* deflt: written without an *OUTPUT request (0 no, 1 yes, 2 when the model has contact pairs) */
const char    *TslFieldName(PetscInt i, TslFieldKind *kind, PetscInt *deflt);
PetscErrorCode TslProblemField(TslProblem prob, PetscInt i, PetscInt *ncomp, PetscReal **vals);
/* Does the model have field i? The displacement's fields (U, RF, S, E, CPRESS, CSLIP, CSTATUS, ELSE, ELASE) do not
 * exist in a heat-transfer model (no displacement unknowns): they are neither written by default nor on request. */
PetscBool TslProblemFieldAvailable(TslProblem prob, PetscInt i);
/* Contact (collective). Search: pairs secondary nodes at the current solution, rebuilding the matrix
 * pattern when pairing changed (then *repattern: hand the new matrix to the solver). Update: after a
 * converged solve, re-pairs nodes that left their segment and updates augmented-Lagrange multipliers;
 * *again: solve the increment again; *augmented: the multipliers changed, so the next solve must take at
 * least one Newton step (otherwise the gaps, and so the next update, stay the same). Commit / Rollback:
 * accept or reject the increment's contact state. */
PetscErrorCode TslProblemContactSearch(TslProblem prob, PetscBool *repattern);
/* After a stop because a secondary node left its rank's held region of the main surface with
 * -tsl_contact_rebuild left: the -tsl_contact_margin to restart the job with (0: no such stop). */
PetscErrorCode TslProblemGetMarginRerun(TslProblem prob, PetscReal *margin);
PetscErrorCode TslProblemContactUpdate(TslProblem prob, PetscBool *again, PetscBool *repattern, PetscBool *augmented);
PetscErrorCode TslProblemContactCommit(TslProblem prob);
PetscErrorCode TslProblemContactRollback(TslProblem prob);
/* Contact that does not settle: Reset before a solve; after one, collectively, *run is the number of residual
 * evaluations in a row, up to the last, in which some secondary node (or surface-to-surface point) changed
 * between open and closed, *count how many changed at the last one and *node the global id of one of them
 * (-1: none). A law that jumps at closure can leave a Newton solve alternating between the two states. */
PetscErrorCode TslProblemContactChatterReset(TslProblem prob);
PetscErrorCode TslProblemContactChatter(TslProblem prob, PetscInt *run, PetscInt *count, PetscInt *node);
/* Explicit steps: commit the contact state of the forces just evaluated, then re-pair when asked or when a
 * node left its face (*nrepair: how many left). */
PetscErrorCode TslProblemContactExplicitIncrement(TslProblem prob, PetscBool search, PetscInt *nrepair);
/* Collective. The interface's share of the explicit stable increment (src/physics/contact_bound.c): the
 * limits of the normal penalty on the lumped masses and of the heat exchange on the lumped capacities M
 * (a ghosted vector of the solution's layout; W a work vector like it), nodal Gershgorin bounds over every
 * node-to-surface and surface-to-surface point, and the global ids of the nodes that set them (-1 and
 * PETSC_MAX_REAL: none). */
PetscErrorCode TslProblemContactIncrements(TslProblem prob, Vec M, Vec W, PetscReal *dt_mech, PetscInt *node_mech, PetscReal *dt_heat, PetscInt *node_heat);

/* Largest temperature change over the increment (all ranks). */
PetscErrorCode TslProblemMaxTemperatureChange(TslProblem prob, PetscReal *dtheta);
/* 2-norms of a vector in the problem's layout over its displacement rows and its temperature rows (residuals,
 * solutions, updates: the per-field convergence test). */
PetscErrorCode TslProblemFieldNorms(TslProblem prob, Vec F, PetscReal *norm_u, PetscReal *norm_theta);
/* ... in the norm of type (NORM_2 or NORM_INFINITY: the largest entry of each field) */
PetscErrorCode TslProblemFieldNormsType(TslProblem prob, Vec F, NormType type, PetscReal *norm_u, PetscReal *norm_theta);
/* The dialect's instantaneous flux of each field at the last residual evaluation (collective): the mean of |R_i|
 * over the displacement (q[0]) and the temperature (q[1]) components of every element's force vector (internal
 * force; conducted and stored heat), the scale of *CONTROLS, PARAMETERS=FIELD's residual test. */
PetscErrorCode TslProblemElementFlux(TslProblem prob, PetscReal q[2]);
/* Whether the residual evaluations gather that flux (off by default: it costs a pass over every element's vector) */
PetscErrorCode TslProblemSetElementFlux(TslProblem prob, PetscBool on);
/* Collective. The largest nodal translation of the solution X over the model's size (the diagonal of the bounding
 * box of the reference coordinates); reference nodes and rotations are left out. */
PetscErrorCode TslProblemDisplacementReach(TslProblem prob, Vec X, PetscReal *reach);

/* ---- explicit dynamics (src/solve/explicit.c): vectors, no matrix -------------------------------
 * Every Vec below is a duplicate of the solution vector (ghosted, block size ndof). */

/* Explicit steps set this before TslProblemSetStep: no Jacobian pattern is built for the step. */
PetscErrorCode TslProblemSetMatrixFree(TslProblem prob, PetscBool matrix_free);

/* The explicit force records of the local elements (element.h, TslElementFastForce): built once (use true;
 * false frees them and every element takes the generic kernels, -tsl_explicit_records 0). *nfast (elements
 * with a record, all ranks) and *mbytes (the records' memory, largest rank) may be NULL. Collective. */
PetscErrorCode TslProblemExplicitRecords(TslProblem prob, PetscBool use, PetscInt *nfast, PetscReal *mbytes);
/* The records' state carried from one explicit evaluation to the next (each lane's volumetric strain at its last,
 * the bulk viscosity's rate), for restart points: *ev and its length *n (NULL, 0: no records), and *lane the place
 * in it of each local element's (-1: an element without a record; may be NULL). Not collective. */
PetscErrorCode TslProblemExplicitCarried(TslProblem prob, PetscReal **ev, PetscInt *n, const PetscInt **lane);
/* A finite-strain (NLGEOM) explicit step's per-element memory of the stable increments, for restart points: each local
 * element's centre C = F^T F at its last stable-increment evaluation and the increments found then, TSL_STABLE_SHAPE
 * reals per element at [TSL_STABLE_SHAPE e] (dynamics.c, StableElement); NULL at small strain. Not collective. */
#define TSL_STABLE_SHAPE 8
PetscErrorCode TslProblemStableShapes(TslProblem prob, PetscReal **shape);
/* The same records for the implicit residuals (internal force, heat flow and the history's energies; the
 * tangent stays the generic kernels'): use builds them if no explicit step has (collective: *nfast, *mbytes
 * as above), false leaves them to explicit steps. */
PetscErrorCode TslProblemImplicitRecords(TslProblem prob, PetscBool use, PetscInt *nfast, PetscReal *mbytes);

/* Rates of the heat terms of the last force evaluation, summed over all ranks. */
typedef struct {
  PetscReal heat_in;        /* applied heat: CFLUX + surface and body fluxes */
  PetscReal film_out;       /* heat leaving through films */
  PetscReal radiation_out;  /* heat radiated to the ambient */
  PetscReal interface_heat; /* heat crossing contact interfaces (main -> secondary) */
  PetscReal dissipation;    /* frictional dissipation */
  PetscReal friction_heat;  /* part of it converted to heat */
  PetscReal viscous;        /* rate dissipated by the bulk viscosity, sum of q eps_vol_dot (0 without viscosity) */
  PetscReal viscous_prev;   /* the previous evaluation's q times this one's eps_vol_dot (its work's second half) */
  PetscReal plastic_work;   /* plastic work of the move since the previous evaluation (*PLASTIC), committed by this one */
  PetscReal plastic_heat;   /* its heat (*INELASTIC HEAT FRACTION), a rate over that move's increment h */
} TslExplicitRates;

/* Unconstrained nodal vectors at the current solution and time, ghost contributions summed (collective):
 *   Fi  element internal forces, and every heat row (internal flow, fluxes, films) in residual form;
 *   Fe  applied mechanical loads (CLOAD, DLOAD) as forces;
 *   Fc  contact forces and contact heat in residual form (may be NULL when the model has no pairs);
 * Fi also holds the bulk viscosity forces (TslElementBulkViscosity with eta[e], eta2[e] per local element: the
 * linear and the quadratic coefficient, both 0 skips it) of the velocities V, computed in the same element pass;
 * q[e] (NULL: no bulk viscosity; V, eta and eta2 are then not read) is each element's q = p V, read as the
 * previous evaluation's (for rates->viscous_prev) and overwritten with this one's (zero it to start).
 * h > 0 says that the state moved from the previous evaluation's by exactly h V (a central-difference update,
 * prescribed dofs included): the elements with a force record then take their volumetric strain rate as the
 * difference of their centre strains over h and V is not read by them; h = 0 (the first evaluation of a step)
 * reads V everywhere. The residual of the implicit code is Fi - Fe + Fc; an explicit increment sets
 * M a = Fe - Fi - Fc. Qp (NULL: they are in Fi's heat rows) gets the plastic elements' heat sources apart, positive,
 * a rate over h, the move's increment: the explicit procedure deposits h Qp, the heat of the move, over an
 * increment of any length (TslElementInternalPlasticHeat). */
PetscErrorCode TslProblemExplicitForces(TslProblem prob, Vec Fi, Vec Fe, Vec Fc, Vec Qp, Vec V, const PetscReal eta[], const PetscReal eta2[], PetscReal q[],
                                        PetscReal h, TslExplicitRates *rates);
/* The initial velocities of the deck (*INITIAL CONDITIONS, TYPE=VELOCITY) at the owned dofs into V (zeroed
 * first; the temperature slots stay zero), for the first explicit step after TslProblemSetStep: a dof held by
 * a boundary condition of that step (or pinned) keeps zero, the condition wins; *held counts those dofs where a
 * nonzero velocity was given, over all ranks. Collective. */
PetscErrorCode TslProblemInitialVelocity(TslProblem prob, Vec V, PetscInt *held);
/* The contact of an explicit step (explicit_step true) or of an implicit one (false; src/physics/contact.c): the
 * pairs with MECHANICAL CONSTRAINT=KINEMATIC become kinematic or ordinary again (*any: some pair is, the same on
 * all ranks), and plain *FRICTION sticks with the normal penalty in explicit steps, with its automatic elastic
 * slip in implicit ones (docs/explicit.md, "Friction in explicit steps").
 * Kinematic contact (src/physics/contact_kinematic.c; docs/explicit.md). Kinematic pairs are left out of
 * TslProblemExplicitForces' Fc and of the stable increment's contact term. KinematicStiffness (collective):
 * each kinematic node's stiffness that closes its gap in an increment with h h_avg = hh, from the lumped
 * masses M and the prescribed-dof mask Mask (ghosts updated), W a work vector. KinematicForces (collective):
 * the kinematic pairs' forces and heat at the current solution (the predicted state, its ghosts current) into Fk, as Fc, and
 * their heat rates. */
PetscErrorCode TslProblemContactSetExplicit(TslProblem prob, PetscBool explicit_step, PetscBool *any);
PetscErrorCode TslProblemContactKinematicStiffness(TslProblem prob, Vec M, Vec Mask, Vec W, PetscReal hh);
/* Collective. A further corrector pass (projected Jacobi on the contact problem, linearised): each kinematic
 * node's gap after the correction -hh M^-1 Fk (Fk the corrector's forces so far, summed on their owners) from
 * its predicted gap and the relative normal displacement, the pressure change -k_s g / A_s that closes it,
 * limited so that the node's pressure stays >= 0. change[0], change[1]: the largest change and the largest
 * pressure over the ranks; change[2] the largest complementarity residual of the linearised gaps (a penetration,
 * or the opening of a node still pressed) over its pair's search radius. The changes are applied (CPRESS) and
 * their forces put in W (zeroed first, summed on their owners; *applied) while change[0] > tol change[1], and
 * (gap_tol > 0) after that while change[2] is above gap_tol and below 0.9 of *residual (the previous pass's,
 * updated here: the iteration still closes the gaps); else nothing changes. */
PetscErrorCode TslProblemContactKinematicPass(TslProblem prob, Vec Fk, Vec M, Vec Mask, Vec W, PetscReal hh, PetscReal tol, PetscReal gap_tol,
                                              PetscReal *residual, PetscReal change[3], PetscBool *applied);
/* After passes: each kinematic node that penetrates at the predicted state or that the passes left pressed gets
 * the pressure offset that gives it the passes' pressure at its predicted gap, so that evaluating the kinematic
 * pairs again at the predicted state (TslProblemExplicitKinematicForces) gives those pressures with the friction
 * and heat that go with them. */
PetscErrorCode TslProblemContactKinematicSettle(TslProblem prob);
PetscErrorCode TslProblemExplicitKinematicForces(TslProblem prob, Vec Fk, TslExplicitRates *rates);
/* Lumped nodal mass in the displacement slots (element e's mass times scale[e]; scale NULL: 1) and lumped
 * capacity dQ/dtheta in the temperature slot, at the current temperatures (collective). An element with a
 * non-positive lumped mass at a node is a user error naming it. */
PetscErrorCode TslProblemLumpedMass(TslProblem prob, const PetscReal scale[], Vec M);
/* *DAMPING of each local element's material: alpha[e] (mass-proportional, 1/time) and beta[e] (stiffness-proportional,
 * time); 0 without. */
PetscErrorCode TslProblemElementDamping(TslProblem prob, PetscReal alpha[], PetscReal beta[]);
/* Each local element's stable increments with its unscaled lumped mass: mechanical 2 / omega_max and thermal
 * 2 / lambda_max, from the largest eigenvalues of M^-1 K_uu and C^-1 K_thth of the element (no global
 * eigenvalue exceeds the largest element one). dt_heat is PETSC_MAX_REAL for an element without conduction. */
PetscErrorCode TslProblemStableIncrements(TslProblem prob, PetscReal dt_mech[], PetscReal dt_heat[]);
/* 1 at the owned dofs held by a prescribed value, pinned (slots a kinematics does not use) or tied (a tie's
 * secondary dof: TslProblemApplyPrescribed sets it from its main dofs), 0 elsewhere. */
PetscErrorCode TslProblemConstrainedMask(TslProblem prob, Vec mask);
/* Explicit steps with ties (docs/explicit.md, "Ties"): moves each owned tie-secondary entry of a lumped mass or
 * force vector V (global, owned entries complete) to its main dofs with the tie's weights, V_k += c_sk V_s, and
 * zeroes it; a secondary dof under a *BOUNDARY keeps its own. Collective; nothing to do without ties. */
PetscErrorCode TslProblemTieMove(TslProblem prob, Vec V);

/* Rank 0, on the whole model before distribution: every body has its rigid-body modes removed by
 * prescribed displacements in every step, and a prescribed temperature or film in steady-state steps.
 * A violation is a user error naming the step and a node of the body. */
PetscErrorCode TslModelCheckSupports(TslModel *global);
