/* The contact kernels compiled a second time for values alone (the files of contact/values/, each including one
 * kernel source after this header): dual numbers with the two surface-parameter slots only, so that an
 * evaluation without a tangent (explicit steps, residual evaluations) neither computes nor copies the
 * element unknowns' derivatives. The same operations on the values: the same bits. TslContactElement and
 * TslContactElement3 hand a call without K to their copies here (contact/laws.c, contact/kernel3.c).
 *
 * Every external function of the four sources is renamed below (a new one without an entry fails to link:
 * "multiple definition"). */
#pragma once
#define TSL_DUAL_VALUES 1

#define TslContactFacePointDual     TslContactFacePointDual_Values
#define TslContactGeomSetUp         TslContactGeomSetUp_Values
#define TslContactProject           TslContactProject_Values
#define TslContactProjectDual       TslContactProjectDual_Values
#define TslContactProjectionSide    TslContactProjectionSide_Values
#define TslContactSmoothedNormal    TslContactSmoothedNormal_Values
#define TslContactStateTransfer     TslContactStateTransfer_Values
#define TslContactSurfaceDual       TslContactSurfaceDual_Values
#define TslContactSurfacePoint      TslContactSurfacePoint_Values
#define TslContactAugmentedUpdate   TslContactAugmentedUpdate_Values
#define TslContactDualExtract       TslContactDualExtract_Values
#define TslContactElement           TslContactElement_Values
#define TslContactFrictionLaw       TslContactFrictionLaw_Values
#define TslContactHeatFlux          TslContactHeatFlux_Values
#define TslContactKinematicLaw      TslContactKinematicLaw_Values
#define TslContactLawSetDefaults    TslContactLawSetDefaults_Values
#define TslContactNodeUnknowns      TslContactNodeUnknowns_Values
#define TslContactNormalPressure    TslContactNormalPressure_Values
#define TslContactResidualRows      TslContactResidualRows_Values
#define TslContactStateStart        TslContactStateStart_Values
#define TslContactStateUpdate       TslContactStateUpdate_Values
#define TslGapRadiationCoefficient  TslGapRadiationCoefficient_Values
#define TslTableEvaluate            TslTableEvaluate_Values
#define TslContactElement3          TslContactElement3_Values
#define TslContactProject3Raw       TslContactProject3Raw_Values
#define TslContactFace3Box          TslContactFace3Box_Values
#define TslContactFace3Evaluate     TslContactFace3Evaluate_Values
#define TslContactFace3Find         TslContactFace3Find_Values
#define TslContactFace3Get          TslContactFace3Get_Values
#define TslContactFace3HullBound    TslContactFace3HullBound_Values
#define TslContactFace3Inside       TslContactFace3Inside_Values
#define TslContactFace3Integrate    TslContactFace3Integrate_Values
#define TslContactFace3Nodes        TslContactFace3Nodes_Values
#define TslContactFace3PointDual    TslContactFace3PointDual_Values
#define TslContactFace3Project      TslContactFace3Project_Values
#define TslContactFace3Shape        TslContactFace3Shape_Values
#define TslContactFace3ShapeValues  TslContactFace3ShapeValues_Values
#define TslContactFace3Size         TslContactFace3Size_Values
#define TslContactFace3Solve        TslContactFace3Solve_Values
#define TslContactSolve2            TslContactSolve2_Values
#define TslContactStateStart3       TslContactStateStart3_Values
#define TslContactStateTransfer3    TslContactStateTransfer3_Values
