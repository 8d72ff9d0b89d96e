/* Explicit force records: the element forces of an explicit increment from data computed once.
 *
 * Why: an explicit increment evaluates every element's internal force and heat flow once, thousands of
 * times over. In this code's small-strain kinematics the element geometry (Jacobians, spatial gradients,
 * volumes) is that of the reference configuration and never changes, and with temperature-independent
 * properties the conduction R_theta = K_theta theta is linear. The generic kernel (kernels.c) recomputes
 * both at every call, through loops of run-time length sized for the largest family: about 6.5 k flops and
 * 5 us per C3D8T element per increment. A record per element holds what does not change, as compactly as
 * the arithmetic allows (the explicit loop streams the records from memory at every increment, and their
 * bytes, not the flops, bound it):
 *
 *   header   row, lambda, mu, alpha, the wave modulus (lambda + 2 mu; E / (1 - nu^2) in plane stress), hourglass
 *            kappa, the thickness modulus E_t (continuum shells: lambda and mu are then the shell plane's,
 *            nu E / (1 - nu^2) and G)
 *   points   at each mechanical point: a full row's inverse Jacobian A[e][d] = dxi_e/dx_d (the gradients
 *            dN_a/dx_d = sum_e dN_a/dxi_e A[e][d], the reference derivatives being the type's, in the
 *            shape), a reduced row's gradients G[d][a] themselves (its hourglass vectors need them); the
 *            volume dV (thickness or 2 pi r included); 1 / r (axisymmetric: the hoop strain N_a u_r / r);
 *            a continuum shell's frame Q (rows e1, e2, n; its points are stored as a full row's)
 *   K        the conduction matrix k int grad N_a . grad N_b dV (full rule), its strict upper triangle:
 *            its rows sum to zero, so (K theta)_a = sum_b K_ab (theta_b - theta_a)
 *   centre   a full row's bulk viscosity point: A, volume, 1 / r (a reduced row's point is the centre)
 *   hx       a reduced row's hourglass products h_k . x_d (the vectors gamma_k = (h_k - sum_d hx_kd G_d) / n,
 *            the h_k being the type's, in the shape)
 *
 * and TslElementFastForce evaluates the generic kernel's formulas from it (kernels.c, Mechanics with the
 * isotropic D written out: sigma = lambda tr(eps_mech) m + 2 mu eps_mech; Conduction; the hourglass
 * control of formulations.c; TslElementBulkViscosity), with loops whose lengths are compile-time
 * constants of each row, so the compiler unrolls and vectorises them. Results agree with the generic
 * path to rounding (tests/element/fast_records.c). Memory: C3D8T 0.96 kB, C3D8RT 0.57 kB per element
 * (2.4 and 1.0 kB with the gradients and the whole K stored).
 */
#include "element_impl.h"
#include <thermoslide/lanes.h>

#define HEADER 7

/* Offsets of the record's parts (constants once the row's sizes are): point q at P + q * ps (its A or G,
 * then dV, then 1 / r, then a continuum shell's frame Q at fr), the centre at C (A, volume, 1 / r; a reduced row's: its point), K, hx. */
typedef struct {
  PetscInt P, ps, dV, ri, fr, K, C, hx, size;
} Layout;

static inline Layout LayoutOf(PetscInt dim, PetscInt n, PetscInt nq, PetscInt nh, PetscBool axi, PetscBool shell)
{
  const PetscInt geo = nq > 1 ? dim * dim : dim * n; /* a point's A (full rows) or G (reduced rows) */
  Layout         L;
  L.P  = HEADER;
  L.ps = geo + 1 + (axi ? 1 : 0) + (shell ? 9 : 0);
  L.dV = geo, L.ri = geo + 1, L.fr = geo + 1 + (axi ? 1 : 0); /* within a point */
  L.K    = L.P + nq * L.ps;
  L.C    = nq > 1 ? L.K + n * (n - 1) / 2 : L.P;
  L.hx   = L.K + n * (n - 1) / 2 + (nq > 1 ? dim * dim + 1 + (axi ? 1 : 0) : 0);
  L.size = L.hx + nh * dim;
  return L;
}

/* Lanes: the kernel works on TSL_FAST_LANES elements of one row at a time, every real a vector of their
 * values (GCC/Clang vector extensions: the compiler maps them on 256-bit registers in the x86-64-v4 and -v3
 * clones, on pairs of SSE2 registers in the baseline one), so each instruction serves the batch's elements alike and
 * the sums over an element's nodes need no horizontal adds or shuffles. A batch's records are interleaved
 * by lane (value k of lane j at rec[k * W + j]); the unknowns and results likewise. */
#define W TSL_FAST_LANES
typedef TslV  V;
typedef TslVI VI;
#define Ld TslLd
#define St TslSt

/* Gradients gd[d][a] (V) of a point held as A (full rows): sum_e dN[e][a] A[e][d]. */
static inline __attribute__((always_inline)) void Gradients(const PetscInt dim, const PetscInt n, const PetscReal *A,
                                                            const PetscReal (*dN)[TSL_FAST_MAX_NODES], V gd[3][TSL_FAST_MAX_NODES])
{
  for (PetscInt d = 0; d < dim; d++) {
    V Aed[3];
    for (PetscInt e = 0; e < dim; e++) Aed[e] = Ld(A + (e * dim + d) * W);
    for (PetscInt a = 0; a < n; a++) {
      gd[d][a] = dN[0][a] * Aed[0];
      for (PetscInt e = 1; e < dim; e++) gd[d][a] += dN[e][a] * Aed[e];
    }
  }
}

/* The forces of one batch (see the file's head). Inlined into each row's function with constant sizes.
 * The unknowns are split by component first, so every sum over the nodes is over arrays of constant
 * length. A full row's point works in the reference derivatives: the displacement gradient in xi (H),
 * mapped by A; the stress mapped back by A and spread by the same derivatives. */
static inline __attribute__((always_inline)) int Force(const PetscInt dim, const PetscInt n, const PetscInt nq, const PetscInt nh,
                                                       const PetscBool axi, const PetscBool ps, const PetscBool sf0, const PetscBool shell,
                                                       const PetscBool nl, const TslElementFastShape *shape, const PetscReal *rec, const PetscReal *u,
                                                       const PetscReal *ti, const PetscReal *v, PetscReal *ev, const PetscReal hinv,
                                                       const PetscReal *eta, const PetscReal *eta2, PetscReal *R, PetscReal *Rv, PetscReal *power,
                                                       PetscReal *qr, PetscReal *energy)
{
  const PetscInt nd     = dim + 1;
  const Layout   L      = LayoutOf(dim, n, nq, nh, axi, shell);
  const V        lambda = Ld(rec + 1 * W), mu = Ld(rec + 2 * W), alpha = Ld(rec + 3 * W);
  V              U[3][TSL_FAST_MAX_NODES], th[TSL_FAST_MAX_NODES], dth[TSL_FAST_MAX_NODES], F[3][TSL_FAST_MAX_NODES], Fth[TSL_FAST_MAX_NODES];
  V              en[2] = {{0}, {0}};
  const V        lps   = ps ? lambda / (lambda + 2 * mu) : (V){0}; /* plane stress: eps33 from sigma33 = 0 */
  VI             inv   = {0};                                      /* finite strain: lanes with det F <= 0 at a point */

  const PetscBool sf = sf0 && shape->sf ? PETSC_TRUE : PETSC_FALSE;
  V               Hc[3][3][4], Qs[3][3][4]; /* sum factorisation: H per class of points, Q summed per class */

  for (PetscInt a = 0; a < n; a++) {
    for (PetscInt d = 0; d < dim; d++) U[d][a] = Ld(u + (nd * a + d) * W), F[d][a] = (V){0};
    th[a] = Ld(u + (nd * a + dim) * W), dth[a] = th[a] - Ld(ti + a * W);
  }
  if (sf) /* H[i][e] at the 4 classes of points from the 4 differences along e */
    for (PetscInt e = 0; e < 3; e++)
      for (PetscInt i = 0; i < 3; i++) {
        V D[4];
        for (PetscInt p = 0; p < 4; p++) D[p] = U[i][shape->sf_pair[e][p][0]] - U[i][shape->sf_pair[e][p][1]];
        for (PetscInt c = 0; c < 4; c++) {
          Hc[e][i][c] = shape->sf_w[e][c][0] * D[0];
          for (PetscInt p = 1; p < 4; p++) Hc[e][i][c] += shape->sf_w[e][c][p] * D[p];
          Qs[e][i][c] = (V){0};
        }
      }
  for (PetscInt q = 0; q < nq; q++) {
    const PetscReal *P = rec + (L.P + q * L.ps) * W, *Nq = shape->N[q];
    const V          dV = Ld(P + L.dV * W);
    V                g[3][3], e[6], s[6], eth = {0}, tr, hoop = {0};
    for (PetscInt a = 0; a < n; a++) eth += Nq[a] * dth[a];
    eth *= alpha;
    if (axi) {
      for (PetscInt a = 0; a < n; a++) hoop += Nq[a] * U[0][a];
      hoop *= Ld(P + L.ri * W);
    }
    if (nq > 1) { /* g[i][d] = du_i/dx_d = sum_e H[i][e] A[e][d], H[i][e] = sum_a u_ia dN_a/dxi_e */
      const PetscReal(*dN)[TSL_FAST_MAX_NODES] = shape->dN[q];
      V H[3][3];
      for (PetscInt i = 0; i < dim; i++)
        for (PetscInt ee = 0; ee < dim; ee++) {
          if (sf) {
            H[i][ee] = Hc[ee][i][shape->sf_class[ee][q]];
            continue;
          }
          H[i][ee] = dN[ee][0] * U[i][0];
          for (PetscInt a = 1; a < n; a++) H[i][ee] += dN[ee][a] * U[i][a];
        }
      for (PetscInt i = 0; i < dim; i++)
        for (PetscInt d = 0; d < dim; d++) {
          g[i][d] = H[i][0] * Ld(P + d * W);
          for (PetscInt ee = 1; ee < dim; ee++) g[i][d] += H[i][ee] * Ld(P + (ee * dim + d) * W);
        }
    } else { /* g[i][d] = sum_a u_ia G[d][a] */
      for (PetscInt i = 0; i < dim; i++)
        for (PetscInt d = 0; d < dim; d++) {
          g[i][d] = (V){0};
          for (PetscInt a = 0; a < n; a++) g[i][d] += Ld(P + (d * n + a) * W) * U[i][a];
        }
    }
    V Fm[3][3], gs[3][3]; /* finite strain: F = I + g; gs, the gradient the strain is taken from */
    for (PetscInt i = 0; i < dim; i++)
      for (PetscInt d = 0; d < dim; d++) gs[i][d] = g[i][d];
    if (nl) {
      /* finite strain (kernels.c, MechPointFinite; St Venant-Kirchhoff on the reference configuration): the strain
       * rows below taken from gs = g + g^T g / 2, whose symmetric part is the Green-Lagrange E; the hoop's
       * E_33 = h + h^2 / 2; the free thermal stretch's E_th = eps_th + eps_th^2 / 2; and the stress spread as
       * P = F S (the first Piola-Kirchhoff stress) */
      V J;
      for (PetscInt i = 0; i < dim; i++)
        for (PetscInt d = 0; d < dim; d++) {
          Fm[i][d] = g[i][d] + (i == d ? 1.0 : 0.0);
          for (PetscInt k = 0; k < dim; k++) gs[i][d] += 0.5 * g[k][i] * g[k][d];
        }
      if (dim == 3)
        J = Fm[0][0] * (Fm[1][1] * Fm[2][2] - Fm[1][2] * Fm[2][1]) - Fm[0][1] * (Fm[1][0] * Fm[2][2] - Fm[1][2] * Fm[2][0]) +
            Fm[0][2] * (Fm[1][0] * Fm[2][1] - Fm[1][1] * Fm[2][0]);
      else
        J = (Fm[0][0] * Fm[1][1] - Fm[0][1] * Fm[1][0]) * (1 + hoop);
      inv |= (J <= 0);
      Fm[2][2] = dim == 3 ? Fm[2][2] : 1 + hoop;
      hoop += 0.5 * hoop * hoop;
      eth += 0.5 * eth * eth;
    }
    if (shell) {
      /* the continuum shell (kinematics.c, ShellLocal): the gradient in the frame, gl = Q g Q^T, the shell's
       * law there (lambda, mu the shell plane's; E_t; 5/6 mu across), and the stress back, Q^T S_l Q */
      const PetscReal *Fr = P + L.fr * W;
      const V          Et = Ld(rec + 6 * W), ks = (5.0 / 6.0) * mu;
      V                Qf[3][3], t[3][3], gl[3][3], Sl[3][3];
      for (PetscInt i = 0; i < 3; i++)
        for (PetscInt d = 0; d < 3; d++) Qf[i][d] = Ld(Fr + (3 * i + d) * W);
      for (PetscInt i = 0; i < 3; i++)
        for (PetscInt d = 0; d < 3; d++) t[i][d] = Qf[i][0] * gs[0][d] + Qf[i][1] * gs[1][d] + Qf[i][2] * gs[2][d];
      for (PetscInt i = 0; i < 3; i++)
        for (PetscInt j = 0; j < 3; j++) gl[i][j] = t[i][0] * Qf[j][0] + t[i][1] * Qf[j][1] + t[i][2] * Qf[j][2];
      e[0] = gl[0][0], e[1] = gl[1][1], e[2] = gl[2][2], e[3] = gl[0][1] + gl[1][0], e[4] = gl[0][2] + gl[2][0], e[5] = gl[1][2] + gl[2][1];
      tr   = e[0] + e[1] - 2 * eth;
      s[0] = (lambda * tr + 2 * mu * (e[0] - eth)) * dV, s[1] = (lambda * tr + 2 * mu * (e[1] - eth)) * dV, s[2] = Et * (e[2] - eth) * dV;
      s[3] = mu * e[3] * dV, s[4] = ks * e[4] * dV, s[5] = ks * e[5] * dV;
      if (energy)
        for (PetscInt r = 0; r < 6; r++) en[0] += 0.5 * s[r] * (r < 3 ? e[r] - eth : e[r]);
      Sl[0][0] = s[0], Sl[1][1] = s[1], Sl[2][2] = s[2], Sl[0][1] = Sl[1][0] = s[3], Sl[0][2] = Sl[2][0] = s[4], Sl[1][2] = Sl[2][1] = s[5];
      for (PetscInt i = 0; i < 3; i++)
        for (PetscInt d = 0; d < 3; d++) t[i][d] = Sl[i][0] * Qf[0][d] + Sl[i][1] * Qf[1][d] + Sl[i][2] * Qf[2][d];
      s[0] = Qf[0][0] * t[0][0] + Qf[1][0] * t[1][0] + Qf[2][0] * t[2][0];
      s[1] = Qf[0][1] * t[0][1] + Qf[1][1] * t[1][1] + Qf[2][1] * t[2][1];
      s[2] = Qf[0][2] * t[0][2] + Qf[1][2] * t[1][2] + Qf[2][2] * t[2][2];
      s[3] = Qf[0][0] * t[0][1] + Qf[1][0] * t[1][1] + Qf[2][0] * t[2][1];
      s[4] = Qf[0][0] * t[0][2] + Qf[1][0] * t[1][2] + Qf[2][0] * t[2][2];
      s[5] = Qf[0][1] * t[0][2] + Qf[1][1] * t[1][2] + Qf[2][1] * t[2][2];
    } else {
      e[0] = gs[0][0], e[1] = gs[1][1], e[3] = gs[0][1] + gs[1][0];
      if (dim == 3)
        e[2] = gs[2][2], e[4] = gs[0][2] + gs[2][0], e[5] = gs[1][2] + gs[2][1];
      else
        e[2] = ps ? eth - lps * (e[0] + e[1] - 2 * eth) : hoop, e[4] = e[5] = (V){0};
      tr = e[0] + e[1] + e[2] - 3 * eth;
      for (PetscInt r = 0; r < 3; r++) s[r] = (lambda * tr + 2 * mu * (e[r] - eth)) * dV;
      for (PetscInt r = 3; r < 6; r++) s[r] = mu * e[r] * dV;
      if (energy) /* 1/2 sigma : eps_mech dV, as the generic output (kernels.c, Mechanics) */
        for (PetscInt r = 0; r < 6; r++) en[0] += 0.5 * s[r] * (r < 3 ? e[r] - eth : e[r]);
    }
    {
      /* the stress as a matrix S[i][d] (dV included; finite strain: F S); F_ia += sum_d S[i][d] dN_a/dx_d */
      V S[3][3] = {{s[0], s[3], s[4]}, {s[3], s[1], s[5]}, {s[4], s[5], s[2]}};
      if (nl) {
        V P[3][3];
        for (PetscInt i = 0; i < dim; i++)
          for (PetscInt d = 0; d < dim; d++) {
            P[i][d] = Fm[i][0] * S[0][d];
            for (PetscInt k = 1; k < dim; k++) P[i][d] += Fm[i][k] * S[k][d];
          }
        for (PetscInt i = 0; i < dim; i++)
          for (PetscInt d = 0; d < dim; d++) S[i][d] = P[i][d];
        S[2][2] = dim == 3 ? S[2][2] : Fm[2][2] * s[2]; /* the hoop's P_33 = F_33 S_33 */
      }
      if (nq > 1) { /* through the reference derivatives: Q[i][e] = sum_d S[i][d] A[e][d] */
        const PetscReal(*dN)[TSL_FAST_MAX_NODES] = shape->dN[q];
        V Q[3][3];
        for (PetscInt i = 0; i < dim; i++)
          for (PetscInt ee = 0; ee < dim; ee++) {
            Q[i][ee] = S[i][0] * Ld(P + ee * dim * W);
            for (PetscInt d = 1; d < dim; d++) Q[i][ee] += S[i][d] * Ld(P + (ee * dim + d) * W);
          }
        if (sf)
          for (PetscInt i = 0; i < 3; i++)
            for (PetscInt ee = 0; ee < 3; ee++) Qs[ee][i][shape->sf_class[ee][q]] += Q[i][ee];
        else
          for (PetscInt i = 0; i < dim; i++)
            for (PetscInt a = 0; a < n; a++)
              for (PetscInt ee = 0; ee < dim; ee++) F[i][a] += dN[ee][a] * Q[i][ee];
      } else {
        for (PetscInt i = 0; i < dim; i++)
          for (PetscInt a = 0; a < n; a++)
            for (PetscInt d = 0; d < dim; d++) F[i][a] += Ld(P + (d * n + a) * W) * S[i][d];
      }
      if (axi) {
        const V sr = S[2][2] * Ld(P + L.ri * W);
        for (PetscInt a = 0; a < n; a++) F[0][a] += Nq[a] * sr;
      }
    }
  }
  if (sf) /* the classes' summed Q spread to the pairs: +- along e */
    for (PetscInt e = 0; e < 3; e++)
      for (PetscInt i = 0; i < 3; i++)
        for (PetscInt p = 0; p < 4; p++) {
          V G = shape->sf_w[e][0][p] * Qs[e][i][0];
          for (PetscInt c = 1; c < 4; c++) G += shape->sf_w[e][c][p] * Qs[e][i][c];
          F[i][shape->sf_pair[e][p][0]] += G, F[i][shape->sf_pair[e][p][1]] -= G;
        }
  for (PetscInt a = 0; a < n; a++) Fth[a] = (V){0};
  { /* (K theta)_a = sum_{b != a} K_ab (theta_b - theta_a), K's strict upper triangle row by row */
    const PetscReal *K = rec + L.K * W;
    for (PetscInt a = 0; a < n; a++)
      for (PetscInt b = a + 1; b < n; b++, K += W) {
        const V f = Ld(K) * (th[b] - th[a]);
        Fth[a] += f, Fth[b] -= f;
      }
  }
  if (nh) { /* reduced rows: gamma_k = (h_k - sum_d hx_kd G_d) / n at the one (centre) point; a continuum
             * shell's centre gradients from its centre's A */
    const PetscReal *G = rec + L.P * W, *hx = rec + L.hx * W;
    const V          kappa = Ld(rec + 5 * W);
    V                Gc[3][TSL_FAST_MAX_NODES];
    if (nq > 1)
      Gradients(dim, n, rec + L.C * W, shape->dNc, Gc);
    else
      for (PetscInt d = 0; d < dim; d++)
        for (PetscInt a = 0; a < n; a++) Gc[d][a] = Ld(G + (d * n + a) * W);
    for (PetscInt k = 0; k < nh; k++) {
      V gam[TSL_FAST_MAX_NODES];
      for (PetscInt a = 0; a < n; a++) {
        gam[a] = shape->h[k][a] - Ld(hx + (k * dim) * W) * Gc[0][a];
        for (PetscInt d = 1; d < dim; d++) gam[a] -= Ld(hx + (k * dim + d) * W) * Gc[d][a];
        gam[a] *= 1.0 / n;
      }
      for (PetscInt d = 0; d < dim; d++) {
        V qk = {0};
        for (PetscInt a = 0; a < n; a++) qk += gam[a] * U[d][a];
        if (energy) en[1] += 0.5 * kappa * qk * qk;
        qk *= kappa;
        for (PetscInt a = 0; a < n; a++) F[d][a] += gam[a] * qk;
      }
    }
  }
  if (Rv) { /* lanes without viscosity (eta = eta2 = 0) get zero forces and power; Rv == R: added to R's forces */
    const PetscReal *C  = rec + L.C * W;
    const V          Vc = Ld(C + L.dV * W), cd = Ld(rec + 4 * W);
    const PetscReal *Nc   = nq > 1 ? shape->Nc : shape->N[0];
    V                rate = {0}, tr = {0}, p, neg, gd[3][TSL_FAST_MAX_NODES], Jv = (V){0} + 1;
    if (nq > 1)
      Gradients(dim, n, C, shape->dNc, gd);
    else
      for (PetscInt d = 0; d < dim; d++)
        for (PetscInt a = 0; a < n; a++) gd[d][a] = Ld(C + (d * n + a) * W);
    if (nl) {
      /* finite strain (kernels.c, TslElementBulkViscosity): the rate J'/J of the current volume from v (never from
       * ev), the forces p dJ/du_c = p (cof F)_ik dN_a/dX_k (cof F = J F^-T; the hoop's F_33 adds
       * (F_11 F_22 - F_12 F_21) N_a / r to u_r's), power p J'/J J V */
      V Fc[3][3], cof[3][3], J, hc = {0};
      for (PetscInt i = 0; i < dim; i++)
        for (PetscInt k = 0; k < dim; k++) {
          Fc[i][k] = (i == k ? 1.0 : 0.0) + gd[k][0] * U[i][0];
          for (PetscInt a = 1; a < n; a++) Fc[i][k] += gd[k][a] * U[i][a];
        }
      if (axi) {
        for (PetscInt a = 0; a < n; a++) hc += Nc[a] * U[0][a];
        hc *= Ld(C + L.ri * W);
      }
      if (dim == 3) {
        for (PetscInt i = 0; i < 3; i++)
          for (PetscInt k = 0; k < 3; k++)
            cof[i][k] = Fc[(i + 1) % 3][(k + 1) % 3] * Fc[(i + 2) % 3][(k + 2) % 3] - Fc[(i + 1) % 3][(k + 2) % 3] * Fc[(i + 2) % 3][(k + 1) % 3];
        J = Fc[0][0] * cof[0][0] + Fc[0][1] * cof[0][1] + Fc[0][2] * cof[0][2];
      } else {
        const V f33 = 1 + hc;
        cof[0][0] = Fc[1][1] * f33, cof[0][1] = -Fc[1][0] * f33, cof[1][0] = -Fc[0][1] * f33, cof[1][1] = Fc[0][0] * f33;
        cof[2][2] = Fc[0][0] * Fc[1][1] - Fc[0][1] * Fc[1][0];
        J         = cof[2][2] * f33;
      }
      inv |= (J <= 0);
      for (PetscInt a = 0; a < n; a++) {
        V h[3];
        for (PetscInt i = 0; i < dim; i++) {
          h[i] = cof[i][0] * gd[0][a];
          for (PetscInt k = 1; k < dim; k++) h[i] += cof[i][k] * gd[k][a];
        }
        if (axi) h[0] += cof[2][2] * Nc[a] * Ld(C + L.ri * W);
        for (PetscInt d = 0; d < dim; d++) gd[d][a] = h[d];
      }
      Jv = J;
    } else if (axi) {
      const V ri = Ld(C + L.ri * W);
      for (PetscInt a = 0; a < n; a++) gd[0][a] += Nc[a] * ri;
    }
    if (v)
      for (PetscInt a = 0; a < n; a++)
        for (PetscInt d = 0; d < dim; d++) rate += gd[d][a] * Ld(v + (nd * a + d) * W);
    rate /= Jv;
    if (ev && !nl) { /* the volumetric strain at the centre, kept for the next evaluation's rate */
      for (PetscInt a = 0; a < n; a++)
        for (PetscInt d = 0; d < dim; d++) tr += gd[d][a] * U[d][a];
      if (!v) rate = (tr - Ld(ev)) * hinv;
      St(ev, tr);
    }
    neg = (V)((VI)rate & (rate < 0)); /* the quadratic term, in compression only */
    p   = Ld(eta) * cd * rate - Ld(eta2) * cd * neg * neg;
    if (Rv == R)
      for (PetscInt a = 0; a < n; a++)
        for (PetscInt d = 0; d < dim; d++) F[d][a] += p * gd[d][a] * Vc;
    else
      for (PetscInt a = 0; a < n; a++) {
        for (PetscInt d = 0; d < dim; d++) St(Rv + (nd * a + d) * W, p * gd[d][a] * Vc);
        St(Rv + (nd * a + dim) * W, (V){0});
      }
    St(power, p * rate * Jv * Vc); /* finite strain: the rate of the current volume J V */
    if (qr) St(qr, p * Jv * Vc), St(qr + W, rate);
  }
  for (PetscInt a = 0; a < n; a++) {
    for (PetscInt d = 0; d < dim; d++) St(R + (nd * a + d) * W, F[d][a]);
    St(R + (nd * a + dim) * W, Fth[a]);
  }
  if (energy) St(energy, en[0]), St(energy + W, en[1]);
  {
    int mask = 0;
    for (PetscInt j = 0; j < W; j++) mask |= inv[j] ? 1 << j : 0;
    return mask;
  }
}

/* Two functions per row, small strain (name) and finite strain (name##Nl), each cloned for x86-64-v4 and x86-64-v3
 * beside the baseline (TSL_CLONES, lanes.h); they return the mask of lanes with det F <= 0 (finite strain). */
#define FORCE_ROW(name, dim, n, nq, nh, axi, ps, sf, shell)                                                                                          \
  TSL_CLONES static int name(const TslElementFastShape *sh, const PetscReal *rec, const PetscReal *u, const PetscReal *ti, const PetscReal *v,       \
                             PetscReal *ev, PetscReal hinv, const PetscReal *eta, const PetscReal *eta2, PetscReal *R, PetscReal *Rv,                \
                             PetscReal *power, PetscReal *qr, PetscReal *energy)                                                                     \
  {                                                                                                                                                  \
    return Force(dim, n, nq, nh, axi, ps, sf, shell, PETSC_FALSE, sh, rec, u, ti, v, ev, hinv, eta, eta2, R, Rv, power, qr, energy);                 \
  }                                                                                                                                                  \
  TSL_CLONES static int name##Nl(const TslElementFastShape *sh, const PetscReal *rec, const PetscReal *u, const PetscReal *ti, const PetscReal *v,   \
                                 PetscReal *ev, PetscReal hinv, const PetscReal *eta, const PetscReal *eta2, PetscReal *R, PetscReal *Rv,            \
                                 PetscReal *power, PetscReal *qr, PetscReal *energy)                                                                 \
  {                                                                                                                                                  \
    return Force(dim, n, nq, nh, axi, ps, sf, shell, PETSC_TRUE, sh, rec, u, ti, v, ev, hinv, eta, eta2, R, Rv, power, qr, energy);                  \
  }
FORCE_ROW(Hex8Full, 3, 8, 8, 0, PETSC_FALSE, PETSC_FALSE, PETSC_TRUE, PETSC_FALSE)
FORCE_ROW(Hex8Reduced, 3, 8, 1, 4, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE)
FORCE_ROW(Quad4Full, 2, 4, 4, 0, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE)
FORCE_ROW(Quad4Reduced, 2, 4, 1, 1, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE)
FORCE_ROW(Quad4FullAxi, 2, 4, 4, 0, PETSC_TRUE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE)
FORCE_ROW(Quad4ReducedAxi, 2, 4, 1, 1, PETSC_TRUE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE)
FORCE_ROW(Tet4Full, 3, 4, 1, 0, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE)
FORCE_ROW(Tet10Full, 3, 10, 4, 0, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE)
FORCE_ROW(Wedge6Full, 3, 6, 6, 0, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE)
FORCE_ROW(Tri3Full, 2, 3, 1, 0, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE)
FORCE_ROW(Tri6Full, 2, 6, 3, 0, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE)
FORCE_ROW(Quad8Full, 2, 8, 9, 0, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE)
FORCE_ROW(Tri3FullAxi, 2, 3, 1, 0, PETSC_TRUE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE)
FORCE_ROW(Tri6FullAxi, 2, 6, 3, 0, PETSC_TRUE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE)
FORCE_ROW(Quad8FullAxi, 2, 8, 9, 0, PETSC_TRUE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE)
FORCE_ROW(Quad4FullPs, 2, 4, 4, 0, PETSC_FALSE, PETSC_TRUE, PETSC_FALSE, PETSC_FALSE)
FORCE_ROW(Quad4ReducedPs, 2, 4, 1, 1, PETSC_FALSE, PETSC_TRUE, PETSC_FALSE, PETSC_FALSE)
FORCE_ROW(Tri3FullPs, 2, 3, 1, 0, PETSC_FALSE, PETSC_TRUE, PETSC_FALSE, PETSC_FALSE)
FORCE_ROW(Tri6FullPs, 2, 6, 3, 0, PETSC_FALSE, PETSC_TRUE, PETSC_FALSE, PETSC_FALSE)
FORCE_ROW(Hex8Shell, 3, 8, 5, 4, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_TRUE)
FORCE_ROW(Wedge6Shell, 3, 6, 5, 4, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_TRUE)

typedef int (*ForceFn)(const TslElementFastShape *, const PetscReal *, const PetscReal *, const PetscReal *, const PetscReal *, PetscReal *,
                       PetscReal, const PetscReal *, const PetscReal *, PetscReal *, PetscReal *, PetscReal *, PetscReal *, PetscReal *);

/* The rows: which (family, formulation, kinematics) have a record, and its sizes. */
typedef struct {
  const TslGeometry    *geom;
  const TslFormulation *form;
  TslKinematics         kin;
  PetscInt              nq, nh;
  ForceFn               force, force_nl; /* small and finite strain */
  PetscBool             sf;              /* sum-factorised (hex8's full rule) */
} FastRow;

static const FastRow Rows[] = {
    {&TslGeomHex8, &TslFormFull, TSL_KIN_SOLID3D, 8, 0, Hex8Full, Hex8FullNl, PETSC_TRUE},
    {&TslGeomHex8, &TslFormReduced, TSL_KIN_SOLID3D, 1, 4, Hex8Reduced, Hex8ReducedNl, PETSC_FALSE},
    {&TslGeomQuad4, &TslFormFull, TSL_KIN_PLANE_STRAIN, 4, 0, Quad4Full, Quad4FullNl, PETSC_FALSE},
    {&TslGeomQuad4, &TslFormReduced, TSL_KIN_PLANE_STRAIN, 1, 1, Quad4Reduced, Quad4ReducedNl, PETSC_FALSE},
    {&TslGeomQuad4, &TslFormFull, TSL_KIN_AXISYMMETRIC, 4, 0, Quad4FullAxi, Quad4FullAxiNl, PETSC_FALSE},
    {&TslGeomQuad4, &TslFormReduced, TSL_KIN_AXISYMMETRIC, 1, 1, Quad4ReducedAxi, Quad4ReducedAxiNl, PETSC_FALSE},
    {&TslGeomTet4, &TslFormFull, TSL_KIN_SOLID3D, 1, 0, Tet4Full, Tet4FullNl, PETSC_FALSE},
    {&TslGeomTet10, &TslFormModified, TSL_KIN_SOLID3D, 4, 0, Tet10Full, Tet10FullNl,
     PETSC_FALSE}, /* modified: lumping and pressure faces differ, not the force */
    {&TslGeomTet10, &TslFormFullSubFace, TSL_KIN_SOLID3D, 4, 0, Tet10Full, Tet10FullNl, PETSC_FALSE}, /* C3D10T: the same force */
    {&TslGeomWedge6, &TslFormFull, TSL_KIN_SOLID3D, 6, 0, Wedge6Full, Wedge6FullNl, PETSC_FALSE},
    {&TslGeomTri3, &TslFormFull, TSL_KIN_PLANE_STRAIN, 1, 0, Tri3Full, Tri3FullNl, PETSC_FALSE},
    {&TslGeomTri6, &TslFormModified, TSL_KIN_PLANE_STRAIN, 3, 0, Tri6Full, Tri6FullNl, PETSC_FALSE},
    {&TslGeomTri6, &TslFormFull, TSL_KIN_PLANE_STRAIN, 3, 0, Tri6Full, Tri6FullNl, PETSC_FALSE}, /* the full tri6 (CPE6T ...): the same force */
    {&TslGeomQuad8, &TslFormFull, TSL_KIN_PLANE_STRAIN, 9, 0, Quad8Full, Quad8FullNl, PETSC_FALSE},
    {&TslGeomTri3, &TslFormFull, TSL_KIN_AXISYMMETRIC, 1, 0, Tri3FullAxi, Tri3FullAxiNl, PETSC_FALSE},
    {&TslGeomTri6, &TslFormModified, TSL_KIN_AXISYMMETRIC, 3, 0, Tri6FullAxi, Tri6FullAxiNl, PETSC_FALSE},
    {&TslGeomTri6, &TslFormFull, TSL_KIN_AXISYMMETRIC, 3, 0, Tri6FullAxi, Tri6FullAxiNl, PETSC_FALSE}, /* the full tri6 (CPE6T ...): the same force */
    {&TslGeomQuad8, &TslFormFull, TSL_KIN_AXISYMMETRIC, 9, 0, Quad8FullAxi, Quad8FullAxiNl, PETSC_FALSE},
    {&TslGeomQuad4, &TslFormFull, TSL_KIN_PLANE_STRESS, 4, 0, Quad4FullPs, Quad4FullPsNl, PETSC_FALSE},
    {&TslGeomQuad4, &TslFormReduced, TSL_KIN_PLANE_STRESS, 1, 1, Quad4ReducedPs, Quad4ReducedPsNl, PETSC_FALSE},
    {&TslGeomTri3, &TslFormFull, TSL_KIN_PLANE_STRESS, 1, 0, Tri3FullPs, Tri3FullPsNl, PETSC_FALSE},
    {&TslGeomTri6, &TslFormModified, TSL_KIN_PLANE_STRESS, 3, 0, Tri6FullPs, Tri6FullPsNl, PETSC_FALSE},
    {&TslGeomTri6, &TslFormFull, TSL_KIN_PLANE_STRESS, 3, 0, Tri6FullPs, Tri6FullPsNl, PETSC_FALSE}, /* the full tri6 (CPE6T ...): the same force */
    {&TslGeomHex8, &TslFormContinuumShell, TSL_KIN_CONTINUUM_SHELL, 5, 4, Hex8Shell, Hex8ShellNl, PETSC_FALSE}, /* the default 5 Simpson points */
    {&TslGeomWedge6, &TslFormContinuumShell, TSL_KIN_CONTINUUM_SHELL, 5, 4, Wedge6Shell, Wedge6ShellNl,
     PETSC_FALSE}, /* xi eta, xi eta zeta vanish: zero vectors */
};

/* The record row of a coupled type (a heat-transfer type has none: its records would be the conduction alone,
 * which the generic kernel forms at no mechanical cost). */
static PetscInt RowOf(const TslElementType *t)
{
  for (PetscInt r = 0; r < (PetscInt)(sizeof(Rows) / sizeof(Rows[0])); r++)
    if (Rows[r].geom == t->geom && Rows[r].form == t->form && Rows[r].kin == t->kin && t->nextra == 0 && !TslElementTypeHeatOnly(t) &&
        t->form->quadrature(t->geom, NULL)->n == Rows[r].nq) /* the row's compile-time point count is the rule's */
      return r;
  return -1;
}

static Layout RowLayout(PetscInt r)
{
  const FastRow *row = &Rows[r];
  return LayoutOf(row->geom->dim, row->geom->nnode, row->nq, row->nh, TslKinematicsRowGet(row->kin)->revolve, TslKinematicsRowGet(row->kin)->shell);
}

/* The sum factorisation of hex8's full rule (the shape's sf_* fields): derived from the shape functions and
 * the rule, and used only when every derivative matches it exactly (shape->sf). */
static void SumFactors(const TslGeometry *g, const TslQuadrature *quad, TslElementFastShape *shape)
{
  shape->sf = PETSC_FALSE;
  if (g->dim != 3 || g->nnode != 8 || quad->n != 8) return;
  for (PetscInt e = 0; e < 3; e++) {
    const PetscInt f = (e + 1) % 3, h = (e + 2) % 3;
    PetscInt       np = 0, nc = 0, qc[4];
    for (PetscInt a = 0; a < 8; a++) { /* pairs: the two nodes differing in xi_e alone */
      if (!(g->node_xi[a][e] > 0)) continue;
      for (PetscInt b = 0; b < 8; b++)
        if (g->node_xi[b][e] < 0 && g->node_xi[b][f] == g->node_xi[a][f] && g->node_xi[b][h] == g->node_xi[a][h] && np < 4)
          shape->sf_pair[e][np][0] = a, shape->sf_pair[e][np][1] = b, np++;
    }
    if (np != 4) return;
    for (PetscInt q = 0; q < 8; q++) { /* classes: the points sharing (xi_f, xi_h) */
      PetscInt c = 0;
      while (c < nc && !(quad->xi[qc[c]][f] == quad->xi[q][f] && quad->xi[qc[c]][h] == quad->xi[q][h])) c++;
      if (c == nc) {
        if (nc == 4) return;
        qc[nc++] = q;
      }
      shape->sf_class[e][q] = c;
    }
    if (nc != 4) return;
    for (PetscInt c = 0; c < 4; c++)
      for (PetscInt p = 0; p < 4; p++) shape->sf_w[e][c][p] = shape->dN[qc[c]][e][shape->sf_pair[e][p][0]];
    for (PetscInt q = 0; q < 8; q++) /* every derivative as the factorisation says, exactly */
      for (PetscInt p = 0; p < 4; p++) {
        const PetscReal w = shape->sf_w[e][shape->sf_class[e][q]][p];
        if (shape->dN[q][e][shape->sf_pair[e][p][0]] != w || shape->dN[q][e][shape->sf_pair[e][p][1]] != -w) return;
      }
  }
  shape->sf = PETSC_TRUE;
}

PetscBool TslElementFastShapeGet(const TslElementType *t, TslElementFastShape *shape)
{
  const PetscInt       r = RowOf(t);
  const TslGeometry   *g = t->geom;
  const TslQuadrature *quad;
  PetscReal            dN[TSL_MAX_ELEM_NODES * 3], N[TSL_MAX_ELEM_NODES], xi0[3], h[4][TSL_MAX_ELEM_NODES];
  PetscInt             nh;

  memset(shape, 0, sizeof(*shape));
  shape->row = r;
  if (r < 0 || RowLayout(r).size > TSL_FAST_MAX_SIZE) return PETSC_FALSE;
  shape->size = RowLayout(r).size;
  quad        = t->form->quadrature(g, NULL);
  for (PetscInt q = 0; q < quad->n; q++) {
    g->shape(quad->xi[q], N, dN);
    for (PetscInt a = 0; a < g->nnode; a++) {
      shape->N[q][a] = N[a];
      for (PetscInt e = 0; e < g->dim; e++) shape->dN[q][e][a] = dN[g->dim * a + e];
    }
  }
  TslElementCentre(g, xi0);
  g->shape(xi0, N, dN);
  for (PetscInt a = 0; a < g->nnode; a++) {
    shape->Nc[a] = N[a];
    for (PetscInt e = 0; e < g->dim; e++) shape->dNc[e][a] = dN[g->dim * a + e];
  }
  if (Rows[r].sf) SumFactors(g, quad, shape);
  nh = PetscMin(TslElementHourglassVectors(g, h), 4);
  for (PetscInt k = 0; k < nh; k++)
    for (PetscInt a = 0; a < PetscMin(g->nnode, TSL_FAST_MAX_NODES); a++) shape->h[k][a] = h[k][a];
  return PETSC_TRUE;
}

PetscInt TslElementFastSize(const TslElementInput *in)
{
  const PetscInt r = RowOf(in->type);
  if (r < 0 || TslMaterialIsTemperatureDependent(in->sec->mat) || TslMaterialIsPlastic(in->sec->mat) || RowLayout(r).size > TSL_FAST_MAX_SIZE)
    return 0;
  if (in->type->form->quadrature(in->type->geom, in->sec) != in->type->form->quadrature(in->type->geom, NULL))
    return 0; /* a shell section's own rule */
  return RowLayout(r).size;
}

/* A point of a full row (A = its inverse Jacobian), or of a reduced row (its gradients G[d][a]), then its
 * volume, 1 / r and a continuum shell's frame, at P. */
static void StorePoint(const TslElementPoint *p, PetscInt n, PetscInt dim, PetscBool full, PetscBool axi, PetscBool shell,
                       const TslElementSection *sec, const Layout *L, PetscReal P[])
{
  if (shell) {
    PetscReal Q[3][3];
    TslElementShellFrame(sec, p, Q);
    for (PetscInt i = 0; i < 3; i++)
      for (PetscInt d = 0; d < 3; d++) P[L->fr + 3 * i + d] = Q[i][d];
  }
  if (full)
    for (PetscInt e = 0; e < dim; e++)
      for (PetscInt d = 0; d < dim; d++) P[e * dim + d] = p->Ji[e][d];
  else
    for (PetscInt a = 0; a < n; a++)
      for (PetscInt d = 0; d < dim; d++) P[d * n + a] = p->dNdx[a][d];
  P[L->dV] = p->dV;
  if (axi) P[L->ri] = 1.0 / p->x[0];
}

/* Point p's share of the conduction matrix's strict upper triangle: k grad N_a . grad N_b dV, a < b. */
static void ConductionAdd(const TslElementPoint *p, PetscInt n, PetscInt dim, PetscReal k, PetscReal K[TSL_MAX_ELEM_NODES][TSL_MAX_ELEM_NODES])
{
  for (PetscInt a = 0; a < n; a++)
    for (PetscInt b = a + 1; b < n; b++) {
      PetscReal kab = 0;
      for (PetscInt d = 0; d < dim; d++) kab += p->dNdx[a][d] * p->dNdx[b][d];
      K[a][b] += k * kab * p->dV;
    }
}

PetscBool TslElementFastBuild(const TslElementInput *in, PetscReal rec[])
{
  const TslElementType *t = in->type;
  const TslGeometry    *g = t->geom;
  const PetscInt        r = RowOf(t), n = g->nnode, dim = g->dim;
  const PetscBool       axi = TslKinematicsRowGet(t->kin)->revolve, shell = TslKinematicsRowGet(t->kin)->shell;
  const TslQuadrature  *quad = t->form->quadrature(g, in->sec);
  const PetscBool       full = quad->n > 1 ? PETSC_TRUE : PETSC_FALSE;
  PetscReal             xi0[3], K[TSL_MAX_ELEM_NODES][TSL_MAX_ELEM_NODES] = {{0}};
  Layout                L;
  TslMaterialPoint      mp;
  TslElementPoint       p;
  PetscReal             lambda, mu;

  if (r < 0 || quad != t->form->quadrature(g, NULL)) return PETSC_FALSE; /* the row's shape is the default rule's */
  L = RowLayout(r);
  for (PetscInt i = 0; i < L.size; i++) rec[i] = 0;
  TslMaterialEval(in->sec->mat, 0, &mp);
  TslElementLame(&mp, &lambda, &mu);
  if (shell) { /* the shell plane's: plane stress lambda nu E / (1 - nu^2), and G */
    lambda = mp.nu * mp.E / (1 - mp.nu * mp.nu);
    rec[6] = TslElementShellThicknessModulus(in->sec, &mp);
  }
  /* rec[4]: the bulk viscosity's modulus, the kinematics' wave modulus as the generic kernel takes it
   * (lambda + 2 mu; plane stress E / (1 - nu^2)) */
  rec[0] = (PetscReal)r, rec[1] = lambda, rec[2] = mu, rec[3] = mp.alpha, rec[4] = TslElementWaveModulus(t, &mp);
  /* the mechanical points, and the conduction by the full rule in every formulation: the same points when
   * the mechanical rule is the full one (each evaluated once) */
  for (PetscInt q = 0; q < quad->n; q++) {
    if (!TslElementPointEvaluate(t, in->sec, in->x, quad->xi[q], quad->w[q], &p)) return PETSC_FALSE;
    StorePoint(&p, n, dim, full, axi, shell, in->sec, &L, &rec[L.P + q * L.ps]);
    if (quad == &g->full) ConductionAdd(&p, n, dim, mp.k, K);
  }
  for (PetscInt q = 0; quad != &g->full && q < g->full.n; q++) {
    if (!TslElementPointEvaluate(t, in->sec, in->x, g->full.xi[q], g->full.w[q], &p)) return PETSC_FALSE;
    ConductionAdd(&p, n, dim, mp.k, K);
  }
  for (PetscInt a = 0, k = L.K; a < n; a++)
    for (PetscInt b = a + 1; b < n; b++) rec[k++] = K[a][b];
  /* the centre: the bulk viscosity's point and the hourglass control's (xi = 0 for quad4 and hex8) */
  TslElementCentre(g, xi0);
  if (!TslElementPointEvaluate(t, in->sec, in->x, xi0, g->ref_volume, &p)) return PETSC_FALSE;
  if (full) StorePoint(&p, n, dim, full, axi, PETSC_FALSE, in->sec, &L, &rec[L.C]);
  if (Rows[r].nh) {
    PetscReal gamma[4][TSL_MAX_ELEM_NODES], hx[4][3], bb;
    PetscInt  nh = TslElementHourglassBase(in, &p, gamma, hx, &bb);
    if (nh != Rows[r].nh) return PETSC_FALSE;
    rec[5] = TslElementHourglassKappa(mu, p.dV, shell ? TslElementShellHourglassSum(in->sec, g, &p) : bb);
    for (PetscInt k = 0; k < nh; k++)
      for (PetscInt d = 0; d < dim; d++) rec[L.hx + k * dim + d] = hx[k][d];
  }
  return PETSC_TRUE;
}

void TslElementFastInterleave(PetscInt size, PetscInt lane, const PetscReal rec[], PetscReal batch[])
{
  for (PetscInt k = 0; k < size; k++) batch[k * W + lane] = rec[k];
}

static inline ForceFn RowForce(const TslElementFastShape *shape, PetscBool nl)
{
  return nl ? Rows[shape->row].force_nl : Rows[shape->row].force;
}

int TslElementFastForceBatch(const TslElementFastShape *shape, PetscBool nl, const PetscReal rec[], const PetscReal u[], const PetscReal ti[],
                             const PetscReal v[], PetscReal ev[], PetscReal hinv, const PetscReal eta[], const PetscReal eta2[], PetscReal R[],
                             PetscReal Rv[], PetscReal power[], PetscReal qr[])
{
  if (!Rv)
    for (PetscInt j = 0; j < W; j++) {
      power[j] = 0;
      if (qr) qr[j] = qr[W + j] = 0;
    }
  return RowForce(shape, nl)(shape, rec, u, ti, v, ev, hinv, eta, eta2, R, Rv, power, qr, NULL);
}

int TslElementFastResidualBatch(const TslElementFastShape *shape, PetscBool nl, const PetscReal rec[], const PetscReal u[], const PetscReal ti[],
                                PetscReal R[], PetscReal energy[])
{
  return RowForce(shape, nl)(shape, rec, u, ti, NULL, NULL, 0, NULL, NULL, R, NULL, NULL, NULL, energy);
}

void TslElementFastEnergyBatch(const TslElementFastShape *shape, PetscBool nl, const PetscReal rec[], const PetscReal u[], const PetscReal ti[],
                               PetscReal strain[], PetscReal hourglass[])
{
  PetscReal R[TSL_MAX_ELEM_DOF * W], energy[2 * W];

  (void)TslElementFastResidualBatch(shape, nl, rec, u, ti, R, energy);
  for (PetscInt j = 0; j < W; j++) strain[j] = energy[j], hourglass[j] = energy[W + j];
}

/* One element: its record and data copied into every lane of a batch (tests and benchmarks; the explicit
 * loop calls the batch functions). */
typedef struct {
  PetscReal rec[TSL_FAST_MAX_SIZE * W], u[TSL_MAX_ELEM_DOF * W], ti[TSL_FAST_MAX_NODES * W], v[TSL_MAX_ELEM_DOF * W], R[TSL_MAX_ELEM_DOF * W],
      Rv[TSL_MAX_ELEM_DOF * W];
} Single;

static void SingleFill(const TslElementFastShape *shape, const PetscReal rec[], const PetscReal u[], const PetscReal ti[], const PetscReal v[],
                       Single *s)
{
  const FastRow *row = &Rows[shape->row];
  const PetscInt n = row->geom->nnode, nd = n * (row->geom->dim + 1);

  for (PetscInt j = 0; j < W; j++) {
    TslElementFastInterleave(RowLayout(shape->row).size, j, rec, s->rec);
    TslElementFastInterleave(nd, j, u, s->u);
    TslElementFastInterleave(n, j, ti, s->ti);
    if (v) TslElementFastInterleave(nd, j, v, s->v);
  }
}

int TslElementFastForce(const TslElementFastShape *shape, PetscBool nl, const PetscReal rec[], const PetscReal u[], const PetscReal ti[],
                        const PetscReal v[], PetscReal eta, PetscReal eta2, PetscReal R[], PetscReal Rv[], PetscReal *power)
{
  Single          s;
  const FastRow  *row = &Rows[shape->row];
  const PetscInt  nd  = row->geom->nnode * (row->geom->dim + 1);
  const PetscBool bv  = (eta > 0 || eta2 > 0) && Rv ? PETSC_TRUE : PETSC_FALSE;
  PetscReal       e1[W], e2[W], w[W];
  int             mask;

  for (PetscInt j = 0; j < W; j++) e1[j] = eta, e2[j] = eta2;
  SingleFill(shape, rec, u, ti, bv ? v : NULL, &s);
  mask = TslElementFastForceBatch(shape, nl, s.rec, s.u, s.ti, bv ? s.v : NULL, NULL, 0, e1, e2, s.R, bv ? s.Rv : NULL, w, NULL);
  for (PetscInt i = 0; i < nd; i++) {
    R[i] = s.R[i * W];
    if (bv) Rv[i] = s.Rv[i * W];
  }
  *power = w[0];
  return mask & 1;
}

void TslElementFastEnergy(const TslElementFastShape *shape, PetscBool nl, const PetscReal rec[], const PetscReal u[], const PetscReal ti[],
                          PetscReal *strain, PetscReal *hourglass)
{
  Single    s;
  PetscReal se[W], hg[W];

  SingleFill(shape, rec, u, ti, NULL, &s);
  TslElementFastEnergyBatch(shape, nl, s.rec, s.u, s.ti, se, hg);
  *strain = se[0], *hourglass = hg[0];
}
