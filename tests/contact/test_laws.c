/* Contact laws through the element kernel: table interpolation, penalty and augmented-Lagrange pressure,
 * penalty friction return mapping (stick, slip, continued sliding), the Lagrange friction mode dissipating
 * exactly mu p |slip|, gap conductance by pressure (spec values) and by clearance, gap radiation with the
 * spec's constants, and the frictional heat split between the surfaces. */
#include "check.h"

/* Lower block's top face: m1 = (2,0) -> m2 = (0,0); n = (0,1), tau = (-1,0), L = 2. */
static const PetscReal X1[2] = {2, 0}, X2[2] = {0, 0};

static TslContactInput FlatInput(PetscReal xs, PetscReal g)
{
  const PetscReal p[2] = {xs, g};
  TslContactInput in   = InputSetUp(p, X1, X2);

  in.thickness   = 2;
  in.length      = 0.5; /* A = 1 */
  in.hist.xi_old = in.hist.xi_anchor = (2 - xs) / 2;
  return in;
}

static PetscErrorCode CheckTable(TestLog *log)
{
  /* spec: k(p=100) = 20, k(p=200) = 5 */
  const PetscReal p[2] = {100, 200}, k[2] = {20, 5};
  PetscReal       v, dv;

  PetscFunctionBeginUser;
  PetscCall(TslTableEvaluate(2, p, k, 150, &v, &dv));
  Check(log, v, 12.5, 1e-14, "table: k(150)");
  Check(log, dv, -0.15, 1e-15, "table: dk/dp(150)");
  PetscCall(TslTableEvaluate(2, p, k, 50, &v, &dv));
  Check(log, v, 20, 0, "table: constant below first point");
  Check(log, dv, 0, 0, "table: zero slope below first point");
  PetscCall(TslTableEvaluate(2, p, k, 300, &v, &dv));
  Check(log, v, 5, 0, "table: constant beyond last point");
  PetscCall(TslTableEvaluate(2, p, k, 100, &v, &dv));
  Check(log, dv, -0.15, 1e-15, "table: breakpoint takes the slope on its right");
  PetscCall(TslTableEvaluate(1, p, k, 1e9, &v, &dv));
  Check(log, v, 20, 0, "table: single point is a constant");
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckNormal(TestLog *log)
{
  TslContactLaw    law;
  TslContactInput  in = FlatInput(1, -0.01);
  TslContactOutput out;
  PetscReal        R[9], lambda, change;

  PetscFunctionBeginUser;
  PetscCall(TslContactLawSetDefaults(&law));
  law.eps_n = 1e4;
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, out.pressure, 100, 1e-10, "penalty: CPRESS = eps_n <-g>");
  Check(log, (PetscReal)out.status, TSL_CONTACT_SLIP, 0, "penalty: frictionless contact is sliding");
  Check(log, out.area, 1, 1e-15, "plane: area = length * thickness");
  Check(log, R[1], -100, 1e-10, "penalty: secondary R_y = -A p (pushed out of the main body)");
  Check(log, R[4] + R[7], 100, 1e-10, "penalty: main nodes carry the reaction");
  Check(log, R[4], 50, 1e-10, "penalty: reaction split by shape functions");
  in = FlatInput(1, 0.01);
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, out.pressure, 0, 0, "penalty: open gap, no pressure");
  Check(log, (PetscReal)out.status, TSL_CONTACT_OPEN, 0, "penalty: open status");
  Check(log, PetscAbsReal(R[1]) + PetscAbsReal(R[4]), 0, 0, "penalty: open gap, no force");

  law.normal     = TSL_CONTACT_NORMAL_AUGMENTED;
  in             = FlatInput(1, -0.01);
  in.hist.lambda = 50;
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, out.pressure, 150, 1e-10, "augmented: p = <lambda + eps_n (-g)>");
  in             = FlatInput(1, 0.002);
  in.hist.lambda = 50;
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, out.pressure, 30, 1e-10, "augmented: multiplier holds contact across a small clearance");
  lambda = 50;
  PetscCall(TslContactAugmentedUpdate(law.eps_n, 0.002, &lambda, &change));
  Check(log, lambda, 30, 1e-10, "augmented update: lambda <- <lambda - eps_n g>");
  Check(log, change, 20, 1e-10, "augmented update: change");
  PetscCall(TslContactAugmentedUpdate(law.eps_n, 0.01, &lambda, NULL));
  Check(log, lambda, 0, 0, "augmented update: separation releases the multiplier");

  in         = FlatInput(3, -0.01);
  in.kin     = TSL_KIN_AXISYMMETRIC;
  in.x[1][0] = 4;
  in.x[2][0] = 2;
  law.normal = TSL_CONTACT_NORMAL_PENALTY;
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, out.area, 2 * PETSC_PI * 3 * 0.5, 1e-14, "axisymmetric: area = length * 2 pi r_s");
  Check(log, R[1], -100 * out.area, 1e-9, "axisymmetric: force is the total round the circumference");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Penalty Coulomb friction, mu = 0.1, eps_n = 1e4, all dissipation to heat: a constant stick stiffness
 * eps_t, or the automatic one mu p / elastic_slip when elastic_slip > 0. */
static PetscErrorCode PenaltyFrictionLaw(PetscReal eps_t, PetscReal elastic_slip, TslContactLaw *law)
{
  PetscFunctionBeginUser;
  PetscCall(TslContactLawSetDefaults(law));
  law->eps_n        = 1e4;
  law->friction     = TSL_CONTACT_FRICTION_PENALTY;
  law->mu           = 0.1;
  law->eps_t        = eps_t;
  law->elastic_slip = elastic_slip;
  law->eta          = 1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A flat contact with gap g whose secondary node has moved by -dx in x (+dx along tau), over dt = 0.5. */
static TslContactInput MovedInput(PetscReal g, PetscReal dx)
{
  TslContactInput in = FlatInput(1, g);
  in.u[0][0]         = -dx;
  in.dt              = 0.5;
  return in;
}

/* Penalty Coulomb friction: mu = 0.1, p = 100 (limit 10), eps_t = 1000. The secondary node moves by -dx in
 * x, i.e. +dx along tau = (-1, 0). */
static PetscErrorCode CheckPenaltyFriction(TestLog *log)
{
  TslContactLaw    law;
  TslContactInput  in;
  TslContactOutput out;
  PetscReal        R[9];

  PetscFunctionBeginUser;
  PetscCall(PenaltyFrictionLaw(1e3, 0, &law));
  in = MovedInput(-0.01, 0.005);
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, out.slip, 0.005, 1e-14, "stick: slip increment along tau");
  Check(log, (PetscReal)out.status, TSL_CONTACT_STICK, 0, "stick: status");
  Check(log, out.shear, 5, 1e-10, "stick: tT = eps_t * slip");
  Check(log, R[0], -5, 1e-10, "stick: friction force on secondary opposes the motion (+x), R = -F");
  Check(log, out.dissipation_rate, 0, 0, "stick: no dissipation (elastic slip)");
  Check(log, out.xi_anchor, in.hist.xi_anchor, 0, "stick: anchor kept");

  in.u[0][0] = -0.02;
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, (PetscReal)out.status, TSL_CONTACT_SLIP, 0, "slip: status");
  Check(log, out.shear, 10, 1e-10, "slip: tT = mu p");
  Check(log, out.slip_dissipative, 0.01, 1e-12, "slip: plastic slip = (trial - mu p)/eps_t");
  Check(log, out.dissipation_rate, 10 * 0.01 / 0.5, 1e-10, "slip: dissipation rate = tT * plastic slip / dt");
  Check(log, out.xi_anchor, out.xi - 10 / (1e3 * 2), 1e-14, "slip: anchor follows to the elastic limit");
  /* continued sliding over the next increment: all new motion dissipates */
  PetscCall(TslContactStateUpdate(&out, &in.hist));
  in.u[0][0] = -0.03;
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, out.slip, 0.01, 1e-12, "continued slip: increment");
  Check(log, out.slip_dissipative, 0.01, 1e-12, "continued slip: whole increment is plastic");
  /* reversal: slide back by 0.03 from the last converged state */
  PetscCall(TslContactStateUpdate(&out, &in.hist));
  in.u[0][0] = 0.0;
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, out.shear, -10, 1e-10, "reversal: tT = -mu p");
  Check(log, out.slip_dissipative, -0.03 + 0.02, 1e-12, "reversal: plastic slip = slip - 2 mu p / eps_t");
  Check(log, out.dissipation_rate, 10 * 0.01 / 0.5, 1e-10, "reversal: dissipation positive");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Automatic penalty friction (the default of plain *FRICTION): mu = 0.1, p = 100, allowed elastic slip
 * 0.01, so the stick stiffness is mu p / 0.01 = 1000 as above, but it follows the pressure. */
static PetscErrorCode CheckAutomaticPenaltyFriction(TestLog *log)
{
  TslContactLaw    law;
  TslContactInput  in;
  TslContactOutput out;
  PetscReal        R[9];

  PetscFunctionBeginUser;
  PetscCall(PenaltyFrictionLaw(0, 0.01, &law));
  in = MovedInput(-0.01, 0.005);
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, (PetscReal)out.status, TSL_CONTACT_STICK, 0, "automatic: stick below the elastic slip");
  Check(log, out.shear, 5, 1e-10, "automatic: tT = mu p slip / elastic slip");
  in = MovedInput(-0.02, 0.005); /* twice the pressure: twice the stick stiffness, same elastic limit */
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, out.shear, 10, 1e-10, "automatic: stick stiffness follows the pressure");
  in = MovedInput(-0.01, 0.02);
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, (PetscReal)out.status, TSL_CONTACT_SLIP, 0, "automatic: slip beyond the elastic slip");
  Check(log, out.shear, 10, 1e-10, "automatic slip: tT = mu p");
  Check(log, out.slip_dissipative, 0.01, 1e-12, "automatic slip: plastic slip = slip - elastic slip");
  Check(log, out.xi_anchor, out.xi - 0.01 / 2, 1e-14, "automatic slip: anchor at the elastic limit");
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckLagrangeFriction(TestLog *log)
{
  TslContactLaw    law;
  TslContactInput  in;
  TslContactOutput out;
  PetscReal        R[9];
  const PetscReal  slips[] = {0.02, -0.013, 1e-6, 0.3};

  PetscFunctionBeginUser;
  PetscCall(TslContactLawSetDefaults(&law));
  law.eps_n    = 1e4;
  law.friction = TSL_CONTACT_FRICTION_LAGRANGE;
  law.mu       = 0.1;
  law.slip_tol = 1e-9;
  for (PetscInt i = 0; i < 4; i++) {
    in         = FlatInput(1, -0.01);
    in.dt      = 0.25;
    in.u[0][0] = -slips[i];
    PetscCall(TslContactElement(&law, &in, R, NULL, &out));
    /* exactly, not to a tolerance: the point of the mode */
    Check(log, out.dissipation_rate * in.dt, law.mu * out.pressure * PetscAbsReal(out.slip),
          4 * PETSC_MACHINE_EPSILON * law.mu * out.pressure * PetscAbsReal(out.slip), "Lagrange: dissipation = mu p |slip| (slip %g)",
          (double)slips[i]);
    Check(log, out.slip, slips[i], 1e-14, "Lagrange: slip %g", (double)slips[i]);
  }
  in         = FlatInput(1, -0.01);
  in.u[0][0] = -0.5e-9;
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, out.shear, 0.1 * 100 * 0.5, 1e-6, "Lagrange: regularised below slip_tol (tT = mu p ds/tol)");
  Check(log, (PetscReal)out.status, TSL_CONTACT_STICK, 0, "Lagrange: reported as stick below slip_tol");
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckConduction(TestLog *log)
{
  const PetscReal  p[2] = {100, 200}, k[2] = {20, 5}, d[2] = {0, 0.1}, kd[2] = {100, 10};
  TslContactLaw    law;
  TslContactInput  in;
  TslContactOutput out;
  PetscReal        R[9], q3;

  PetscFunctionBeginUser;
  PetscCall(TslContactLawSetDefaults(&law));
  law.eps_n       = 1e4;
  law.conductance = TSL_CONTACT_CONDUCTANCE_PRESSURE;
  law.k_n         = 2;
  law.k_arg       = p;
  law.k_value     = k;
  in              = FlatInput(1.5, -0.01); /* xi = 0.25 */
  in.u[0][2]      = 5;
  in.u[1][2]      = 10;
  in.u[2][2]      = 30; /* theta_main = 0.75*10 + 0.25*30 = 15 */
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, out.conductance, 20, 1e-10, "conduction: k(p=100) = 20 (spec)");
  Check(log, out.heat_flux, 200, 1e-9, "conduction: q = k (theta_main - theta_secondary)");
  Check(log, R[2], -200, 1e-9, "conduction: heat into the secondary node (R = -q A)");
  Check(log, R[5], 0.75 * 200, 1e-9, "conduction: out of m1 by N1");
  Check(log, R[2] + R[5] + R[8], 0, 1e-10, "conduction: heat balance across the interface");
  q3         = out.heat_flux;
  in.x[0][1] = -0.02; /* p = 200 */
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, out.conductance, 5, 1e-10, "conduction: k(p=200) = 5 (spec)");
  Check(log, q3 / out.heat_flux, 4, 1e-12, "conduction: same temperatures carry 1/4 of the flux (spec step 4)");
  in.x[0][1] = 0.01;
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, out.heat_flux, 0, 0, "conduction by pressure: none across an open gap");

  law.conductance = TSL_CONTACT_CONDUCTANCE_CLEARANCE;
  law.k_arg       = d;
  law.k_value     = kd;
  in.x[0][1]      = 0.05;
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, out.conductance, 55, 1e-9, "conduction by clearance: k(0.05)");
  in.x[0][1] = 0.2;
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, out.conductance, 0, 0, "conduction by clearance: zero beyond the last clearance");
  in.x[0][1] = -0.05;
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, out.conductance, 100, 1e-12, "conduction by clearance: closed gap uses k(0)");
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckRadiation(TestLog *log)
{
  const PetscReal  dF[1] = {0}, F[1] = {1e-6};
  const PetscReal  sb = 5.670374419e-8;
  TslContactLaw    law;
  TslContactInput  in;
  TslContactOutput out;
  PetscReal        C, dC, R[9], tm = 100 + 273.16, ts = 50 + 273.16;

  PetscFunctionBeginUser;
  PetscCall(TslGapRadiationCoefficient(sb, 1, 0.5, 0.5, &C, &dC));
  Check(log, C, sb / 3, 1e-22, "radiation: C = F sigma / (1/eA + 1/eB - 1)");
  Check(log, dC, sb / 3, 1e-22, "radiation: dC/dF");
  /* the spec's constants as a coefficient of 1e-6 (view factor 1e-6, black surfaces, sigma = 1) */
  PetscCall(TslGapRadiationCoefficient(1, 1e-6, 1, 1, &C, NULL));
  Check(log, C, 1e-6, 1e-20, "radiation: spec constants give C = 1e-6");

  PetscCall(TslContactLawSetDefaults(&law));
  law.eps_n       = 1e4;
  law.F_n         = 1;
  law.F_clearance = dF;
  law.F_value     = F;
  law.sigma       = 1;
  law.theta_zero  = -273.16;
  in              = FlatInput(1, -0.01);
  in.u[0][2]      = 50;
  in.u[1][2] = in.u[2][2] = 100;
  PetscCall(TslContactElement(&law, &in, R, NULL, &out));
  Check(log, out.radiation_C, 1e-6, 1e-20, "radiation: kernel uses C = 1e-6");
  CheckRel(log, out.heat_flux, 1e-6 * (tm * tm * tm * tm - ts * ts * ts * ts), 1e-13, 0,
           "radiation: q = C [(theta_m - theta_Z)^4 - (theta_s - theta_Z)^4]");
  Check(log, R[2] + R[5] + R[8], 0, 1e-12, "radiation: heat balance");
  {
    const PetscReal d2[2] = {0, 1}, F2[2] = {1e-6, 1e-6};
    law.F_n         = 2;
    law.F_clearance = d2;
    law.F_value     = F2;
    in.x[0][1]      = 0.5;
    PetscCall(TslContactElement(&law, &in, R, NULL, &out));
    CheckRel(log, out.heat_flux, 1e-6 * (tm * tm * tm * tm - ts * ts * ts * ts), 1e-13, 0,
             "radiation: continues across an open gap within the table");
    in.x[0][1] = 2.0;
    PetscCall(TslContactElement(&law, &in, R, NULL, &out));
    Check(log, out.heat_flux, 0, 0, "radiation: zero beyond the last tabulated clearance");
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Frictional heating: eta = 0.5 of the dissipation becomes heat, f of it into the secondary surface. */
static PetscErrorCode CheckHeatGeneration(TestLog *log)
{
  TslContactLaw    law;
  TslContactInput  in;
  TslContactOutput out;
  PetscReal        R[9];
  const PetscReal  fs[2] = {0.5, 0.8};

  PetscFunctionBeginUser;
  PetscCall(TslContactLawSetDefaults(&law));
  law.eps_n    = 1e4;
  law.friction = TSL_CONTACT_FRICTION_LAGRANGE;
  law.mu       = 0.1;
  law.eta      = 0.5;
  for (PetscInt i = 0; i < 2; i++) {
    law.f      = fs[i];
    in         = FlatInput(1.2, -0.01);
    in.dt      = 0.1;
    in.u[0][0] = -0.04;
    PetscCall(TslContactElement(&law, &in, R, NULL, &out));
    Check(log, out.heat_generation, 0.5 * out.dissipation_rate, 1e-12, "heat generation: r = eta D (f=%g)", (double)fs[i]);
    Check(log, -(R[2] + R[5] + R[8]), law.eta * out.area * out.dissipation_rate, 1e-10, "heat generation: split sums to eta * A * D (f=%g)",
          (double)fs[i]);
    Check(log, -R[2], fs[i] * law.eta * out.area * out.dissipation_rate, 1e-10, "heat generation: fraction f into the secondary node (f=%g)",
          (double)fs[i]);
    Check(log, R[5] / R[8], (1 - out.xi) / out.xi, 1e-10, "heat generation: main share distributed by N_a (f=%g)", (double)fs[i]);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  TestLog log = {0, 0};

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(CheckTable(&log));
  PetscCall(CheckNormal(&log));
  PetscCall(CheckPenaltyFriction(&log));
  PetscCall(CheckAutomaticPenaltyFriction(&log));
  PetscCall(CheckLagrangeFriction(&log));
  PetscCall(CheckConduction(&log));
  PetscCall(CheckRadiation(&log));
  PetscCall(CheckHeatGeneration(&log));
  PetscCall(PetscFinalize());
  return Summary(&log);
}
