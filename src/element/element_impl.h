/* Private to src/element/: integration-point geometry and the kinematics table shared by the kernels. */
#pragma once
#include <thermoslide/element.h>

/* The geometry families (geometry.c), referenced by the catalogue rows and by each other (faces,
 * sub-elements). */
extern const TslGeometry TslGeomLine2, TslGeomLine3, TslGeomTri3, TslGeomTri6, TslGeomQuad4, TslGeomQuad8, TslGeomTet4, TslGeomWedge6, TslGeomHex8,
    TslGeomTet10;

/* What distinguishes one kinematic assumption from another, in one place (kinematics.c). The kernels
 * only read these flags, so a new element type is a catalogue row, and a new kinematics a table row. */
typedef struct {
  PetscBool hoop;        /* eps_33 = u_r / r (axisymmetric) */
  PetscBool free_normal; /* sigma_33 = 0 (plane stress): eps_33 is condensed out of D */
  PetscBool revolve;     /* dV = 2 pi r dA */
  PetscBool thickness;   /* dV = t dA (plane elements) */
} TslKinematicsInfo;

const TslKinematicsInfo *TslKinematicsInfoGet(TslKinematics kin);

/* One integration point of an element in its reference configuration. */
typedef struct {
  PetscReal N[TSL_MAX_ELEM_NODES];
  PetscReal dNdx[TSL_MAX_ELEM_NODES][3]; /* spatial gradients; third component 0 in 2D */
  PetscReal x[3];                        /* position (x[0] = r for axisymmetric) */
  PetscReal detJ;
  PetscReal dV; /* weight * detJ * (thickness or 2 pi r or 1) */
} TslElementPoint;

/* Evaluates the point at reference coordinates xi with quadrature weight w. Returns PETSC_FALSE when
 * the map is not valid there (detJ <= 0, or r <= 0 for axisymmetric elements). */
PetscBool TslElementPointEvaluate(const TslElementType *type, const TslElementMaterial *mat, const PetscReal x[], const PetscReal xi[], PetscReal w,
                                  TslElementPoint *p);

/* Voigt strain-displacement matrix B[6][nnode*dim] (engineering shear) at a point. */
void TslElementStrainMatrix(const TslElementType *type, const TslElementPoint *p, PetscReal B[6][TSL_MAX_ELEM_NODES * 3]);

/* Effective elasticity D[6][6] for the kinematics (plane stress: condensed so that sigma_33 = 0) and the
 * thermal stress per unit temperature rise beta = D m alpha (m = normal-components indicator). */
void TslElementElasticity(TslKinematics kin, const TslElementMaterial *mat, PetscReal D[6][6], PetscReal beta[6]);
