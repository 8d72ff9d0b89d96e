/* Finite-sliding node-to-surface contact in the assembly (2D: plane and axisymmetric models).
 *
 * Each secondary node owned by this rank is paired with one main segment (or none): a face of the main
 * surface, line2 or line3, whose nodes (nper per face) the kernels take in face order. A rank that owns
 * secondary nodes of the pair holds the main faces they can reach (those whose reference box meets its
 * held region, plus their neighbours; see src/mesh/distribute.c) with their nodes as ghosts, so the
 * main-surface data it needs arrives with the ordinary ghost update in every Newton iteration, and the
 * contact blocks are inserted through the same constraint-aware path as element blocks (rows of ghost
 * nodes reach their owners through PETSc's stash). Before every search CheckHeldRegion proves that no
 * node can reach a face this rank does not hold, or stops the attempt naming the node (the job then restarts
 * with a larger margin, src/app/main.c, or stops for good with -tsl_contact_rebuild 0).
 *
 * Pairing: a bin grid over the current main segments gives the candidates of each secondary node (never
 * a loop over all pairs); the nearest segment whose projection lies inside it wins. A node whose
 * closest point is beyond the end of the main surface is out of contact: no force, no heat. Pairing is
 * fixed during a Newton solve; after convergence, nodes whose projection left their segment are
 * re-paired and the increment is solved again (the matrix pattern is rebuilt when pairing changes).
 *
 * History (projection at the start of the increment, sticking anchor, augmented-Lagrange multiplier) is
 * committed when an increment is accepted and restored on a cutback.
 *
 * The laws and the element kernel are in contact/ (include/thermoslide/contact.h).
 */
#include "problem_impl.h"

/* Projection parameters are dimensionless (fractions of a segment), so these hold in any length unit and
 * anywhere in space: a node within TSL_CONTACT_XI_TOL of a segment end counts as on the segment when
 * pairing; only a departure beyond TSL_CONTACT_DEPART_TOL after convergence re-pairs it. */
#define TSL_CONTACT_XI_TOL     1e-9
#define TSL_CONTACT_DEPART_TOL 1e-6

/* Local nodes of a contact element in kernel order: s, the segment's nodes, then (smoothing) the nodes of
 * the previous segment other than its end (shared with m1) and those of the next segment other than its
 * start (shared with m2), each in face order. */
static PetscInt ElementNodes(TslProblem p, const TslContactNode *cn, PetscInt nodes[TSL_CONTACT_MAX_NODES])
{
  const TslContactSurface *cs = &p->csurf[cn->pair];
  PetscInt                 n = 0, seg = cn->seg, np = cs->nper;

  nodes[n++] = cn->lnode;
  for (PetscInt a = 0; a < np; a++) nodes[n++] = cs->main_lnode[np * seg + a];
  if (cs->smooth > 0 && cs->prev[seg] >= 0)
    for (PetscInt a = 0; a < np; a++)
      if (a != 1) nodes[n++] = cs->main_lnode[np * cs->prev[seg] + a];
  if (cs->smooth > 0 && cs->next[seg] >= 0)
    for (PetscInt a = 1; a < np; a++) nodes[n++] = cs->main_lnode[np * cs->next[seg] + a];
  return n;
}

/* Reference coordinates (2) and current unknowns (u_x, u_y, theta[, phi]: cs->nu of them) of a local node,
 * taken from their slots among the node's (cs->slot: a twist model has phi before theta). */
static void NodeData(TslProblem p, const TslContactSurface *cs, const PetscScalar *xa, PetscInt l, PetscReal x[2], PetscReal u[])
{
  for (PetscInt c = 0; c < 2; c++) x[c] = p->m->node_xyz[3 * l + c];
  for (PetscInt c = 0; c < cs->nu; c++) u[c] = TslProblemSlotValue(p, xa, l, cs->slot[c]);
}

static void CurrentPosition(TslProblem p, const TslContactSurface *cs, const PetscScalar *xa, PetscInt l, PetscReal y[2])
{
  PetscReal x[2], u[TSL_CONTACT_MAX_NODE_DOF];
  NodeData(p, cs, xa, l, x, u);
  y[0] = x[0] + u[0], y[1] = x[1] + u[1];
}

/* Current coordinates x[2*a + d] of the nodes of main face seg. */
static void FacePosition(TslProblem p, const TslContactSurface *cs, const PetscScalar *xa, PetscInt seg, PetscReal x[])
{
  for (PetscInt a = 0; a < cs->nper; a++) CurrentPosition(p, cs, xa, cs->main_lnode[cs->nper * seg + a], &x[2 * a]);
}

/* The metric |dx/dxi| of main face seg at its start (xi = 0) or end (xi = 1), current configuration. */
static PetscErrorCode FaceMetric(TslProblem p, const TslContactSurface *cs, const PetscScalar *xa, PetscInt seg, PetscReal xi, PetscReal *L)
{
  PetscReal x[2 * TSL_CONTACT_MAX_FACE_NODES], t[2];

  PetscFunctionBeginUser;
  FacePosition(p, cs, xa, seg, x);
  PetscCall(TslContactFaceEvaluate(cs->face, x, xi, NULL, t));
  *L = PetscSqrtReal(t[0] * t[0] + t[1] * t[1]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Storage of the neighbours' nodes that a TslContactInput points to (problem_impl.h). */
typedef TslContactNeighbourData NeighbourData;

/* The kernel input of secondary node cn on its segment cn->seg at the state xa (history included), its
 * local nodes in kernel order (*n of them); in points into nb. */
static void ElementInput(TslProblem p, const TslContactNode *cn, const PetscScalar *xa, TslContactInput *in, PetscInt nodes[], PetscInt *n,
                         NeighbourData *nb)
{
  const TslContactSurface *cs = &p->csurf[cn->pair];
  PetscInt                 k  = 0;

  *n = ElementNodes(p, cn, nodes);
  memset(in, 0, sizeof(*in));
  in->kin       = cs->kin;
  in->face      = cs->face;
  in->thickness = cs->thickness;
  in->length    = cn->length;
  for (PetscInt a = 0; a <= cs->nper; a++) NodeData(p, cs, xa, nodes[k++], in->x[a], in->u[a]);
  if (cs->smooth > 0 && cs->prev[cn->seg] >= 0) {
    for (PetscInt j = 0; j < cs->nper - 1; j++) NodeData(p, cs, xa, nodes[k++], &nb->xp[2 * j], &nb->up[cs->nu * j]);
    in->x_prev = nb->xp, in->u_prev = nb->up;
  }
  if (cs->smooth > 0 && cs->next[cn->seg] >= 0) {
    for (PetscInt j = 0; j < cs->nper - 1; j++) NodeData(p, cs, xa, nodes[k++], &nb->xn[2 * j], &nb->un[cs->nu * j]);
    in->x_next = nb->xn, in->u_next = nb->un;
  }
  in->smoothing = cs->smooth;
  in->dt        = p->dt > 0 ? p->dt : 1.0;
  in->hist      = cn->hist;
}

PetscErrorCode TslProblemContactAssemble(TslProblem p, AsmMode mode, const PetscScalar *xa, PetscScalar *f, Mat A, AsmHeat *heat)
{
  PetscReal     R[TSL_CONTACT_MAX_DOF], K[TSL_CONTACT_MAX_DOF * TSL_CONTACT_MAX_DOF];
  NeighbourData nb;

  PetscFunctionBeginUser;
  if (mode == ASM_RESIDUAL && !p->select_kinematic) p->chatter_count = 0;
  for (PetscInt i = 0; i < p->ncnode; i++) {
    TslContactNode          *cn = &p->cnode[i];
    const TslContactSurface *cs;
    const TslContactLaw     *law;
    TslContactLaw            kl;
    const TslContactStatus   was = cn->out.status;
    TslContactInput          in;
    TslContactInput3         in3;
    PetscInt                 nodes[TSL_CONTACT_MAX_NODES], n, nu, ld[TSL_CONTACT_MAX_DOF];

    if (cn->seg < 0) continue;
    cs = &p->csurf[cn->pair];
    if (cs->kinematic != p->select_kinematic) continue; /* the other enforcement's evaluation */
    if (cs->kinematic) {
      if (!(cn->k_kin > 0)) continue; /* both sides prescribed (or no mass): nothing to correct */
      kl  = cs->law;
      law = &kl;
      const PetscReal ek = TslProblemContactKinematicPenalty(p, cn);
      TslContactKinematicLaw(&kl, ek, ek, cn->settled ? cn->p_kin : 0);
    } else law = &cs->law;
    nu = cs->nu;
    if (cs->dim == 3) PetscCall(TslProblemContact3Input(p, cn, xa, &in3, nodes, &n));
    else ElementInput(p, cn, xa, &in, nodes, &n, &nb);
    for (PetscInt a = 0; a < n; a++)
      for (PetscInt c = 0; c < nu; c++) ld[nu * a + c] = TslProblemSlotDof(p, nodes[a], cs->slot[c]);
    if (mode == ASM_PATTERN) {
      PetscCall(TslProblemInsert(p, mode, A, f, nu * n, ld, NULL, NULL));
      continue;
    }
    if (cs->dim == 3) PetscCall(TslContactElement3(law, &in3, R, mode == ASM_JACOBIAN ? K : NULL, &cn->out));
    else PetscCall(TslContactElement(law, &in, R, mode == ASM_JACOBIAN ? K : NULL, &cn->out));
    cn->fresh = PETSC_TRUE;
    if (f || A) PetscCall(TslProblemInsert(p, mode, A, f, nu * n, ld, R, mode == ASM_JACOBIAN ? K : NULL));
    if (mode == ASM_RESIDUAL && !cs->kinematic) TslProblemContactChatterNote(p, was, cn->out.status, cn->lnode);
    if (mode == ASM_RESIDUAL)
      PetscCall(PetscInfo(NULL, "contact node %" PetscInt_FMT ": segment %" PetscInt_FMT " xi %g gap %g p %g slip %g shear %g slip_circ %g shear_circ %g q %g status %d\n",
                          p->m->node_id[cn->lnode], cn->seg, (double)cn->out.xi_raw, (double)cn->out.gap, (double)cn->out.pressure,
                          (double)cn->out.slip, (double)cn->out.shear, (double)cn->out.slip_circ, (double)cn->out.shear_circ, (double)cn->out.heat_flux, (int)cn->out.status));
    if (heat) {
      heat->interface += cn->out.heat_flux * cn->out.area;
      heat->dissipation += cn->out.dissipation_rate * cn->out.area;
      heat->friction_heat += cn->out.heat_generation * cn->out.area;
    }
  }
  if (!p->select_kinematic) PetscCall(TslProblemContactS2SAssemble(p, mode, xa, f, A, heat));
  if (mode == ASM_RESIDUAL && !p->select_kinematic) p->chatter_run = p->chatter_count ? p->chatter_run + 1 : 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemContactChatterReset(TslProblem p)
{
  PetscFunctionBeginUser;
  p->chatter_run = p->chatter_count = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemContactChatter(TslProblem p, PetscInt *run, PetscInt *count, PetscInt *node)
{
  /* the longest run of any rank and the smallest node id that changed (as a maximum of its negative); the
   * changes of the last evaluation summed */
  PetscInt mx[2] = {p->chatter_run, p->chatter_count ? -p->chatter_node : PETSC_MIN_INT};

  PetscFunctionBeginUser;
  *count = p->chatter_count;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, mx, 2, MPIU_INT, MPI_MAX, p->comm));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, count, 1, MPIU_INT, MPI_SUM, p->comm));
  *run  = mx[0];
  *node = mx[1] == PETSC_MIN_INT ? -1 : -mx[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Moves a node's history from segment `from` to segment `to` along the surface (neighbour by neighbour),
 * each step re-scaled by the metrics of the two faces at their shared node; *moved is PETSC_FALSE when
 * `to` is not within a few segments (the history then starts afresh). */
static PetscErrorCode TransferHistory(TslProblem p, const TslContactSurface *cs, const PetscScalar *xa, PetscInt from, PetscInt to,
                                      TslContactState *h, PetscBool *moved)
{
  PetscFunctionBeginUser;
  *moved = PETSC_FALSE;
  for (PetscInt side = -1; side <= 1 && !*moved; side += 2) {
    TslContactState t = *h;
    PetscInt          s = from;
    for (PetscInt step = 0; step < 4 && s >= 0; step++) {
      PetscInt  nb = side > 0 ? cs->next[s] : cs->prev[s];
      PetscReal Lf, Lt;
      if (nb < 0) break;
      PetscCall(FaceMetric(p, cs, xa, s, side > 0 ? 1 : 0, &Lf));
      PetscCall(FaceMetric(p, cs, xa, nb, side > 0 ? 0 : 1, &Lt));
      PetscCall(TslContactStateTransfer(side, Lf, Lt, &t));
      s = nb;
      if (s == to) {
        *h     = t;
        *moved = PETSC_TRUE;
        break;
      }
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Pairs every owned secondary node with its main segment at the state xa. *changed counts the nodes
 * whose segment changed (this rank). */
static PetscErrorCode Search(TslProblem p, const PetscScalar *xa, PetscInt *changed)
{
  PetscInt *cand, cap = 64;

  PetscFunctionBeginUser;
  *changed = 0;
  PetscCall(PetscMalloc1(cap, &cand));
  for (PetscInt k = 0; k < p->ncsurf; k++) {
    TslContactSurface *cs = &p->csurf[k];
    const PetscInt     np = cs->nper;
    PetscReal         *seg_box, *seg_x;
    TslContactBinGrid  grid;

    if (!cs->active) continue;
    if (cs->dim == 3) {
      PetscCall(TslProblemContact3Search(p, k, xa, changed));
      continue;
    }
    PetscCall(PetscMalloc2(4 * cs->nmain, &seg_box, 2 * np * cs->nmain, &seg_x));
    for (PetscInt s = 0; s < cs->nmain; s++) {
      FacePosition(p, cs, xa, s, &seg_x[2 * np * s]);
      PetscCall(TslContactFaceBox(cs->face, &seg_x[2 * np * s], &seg_box[4 * s]));
    }
    PetscCall(TslContactBinGridCreate(cs->nmain, seg_box, cs->search_radius, &grid));
    for (PetscInt i = 0; i < p->ncnode; i++) {
      TslContactNode *cn = &p->cnode[i];
      PetscReal       y[2], best_d = PETSC_MAX_REAL, best_xi = 0;
      PetscInt        ncand, best = -1;
      PetscBool       best_inside = PETSC_FALSE;

      if (cn->pair != k) continue;
      CurrentPosition(p, cs, xa, cn->lnode, y);
      PetscCall(TslContactBinGridQueryGrow(grid, y, cs->search_radius, &cap, &cand, &ncand));
      for (PetscInt c = 0; c < ncand; c++) {
        const PetscReal *x  = &seg_x[2 * np * cand[c]];
        PetscReal        L2 = PetscSqr(x[2] - x[0]) + PetscSqr(x[3] - x[1]), xi, xc, q[2], t[2], dist, gap;
        PetscBool        inside;
        if (L2 <= 0) continue;
        /* closest point on the face (the chord projection for a straight one) */
        PetscCall(TslContactFaceProject(cs->face, x, y, &xi));
        /* tolerances relative to the segment: a node on a segment end stays "inside" whatever the
         * round-off of coordinates far from the origin, and equal distances are a tie (first wins) */
        inside = (PetscBool)(xi >= -TSL_CONTACT_XI_TOL && xi <= 1 + TSL_CONTACT_XI_TOL);
        xc     = PetscMin(1, PetscMax(0, xi));
        PetscCall(TslContactFaceEvaluate(cs->face, x, xc, q, t));
        q[0] -= y[0], q[1] -= y[1];
        dist = PetscSqrtReal(q[0] * q[0] + q[1] * q[1]);
        /* outward normal (t_y, -t_x)/|t|: body of the main surface on the left of the segment */
        gap = (-q[0] * t[1] + q[1] * t[0]) / PetscSqrtReal(t[0] * t[0] + t[1] * t[1]);
        if (gap < -cs->search_radius) continue; /* behind the surface: another body, not a contact */
        if ((inside && !best_inside) || (inside == best_inside && dist < best_d - TSL_CONTACT_XI_TOL * PetscSqrtReal(L2))) {
          best = cand[c], best_d = dist, best_xi = xi, best_inside = inside;
        }
      }
      /* a face held only as a neighbour, or one whose neighbour is not held, never pairs: CheckHeldRegion
       * guarantees that no node reaches one, so this is a defect, not a node out of contact */
      PetscCheck(best < 0 || (!cs->ring[best] && cs->prev[best] != -2 && cs->next[best] != -2), PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "contact node %" PetscInt_FMT " reached main face %" PetscInt_FMT " at the edge of the part of the main surface held here",
                 p->m->node_id[cn->lnode], best);
      /* beyond an end of the main surface (-1; not -2, a neighbour held elsewhere): out of contact */
      if (best >= 0 && !best_inside && ((best_xi < 0 && cs->prev[best] == -1) || (best_xi > 1 && cs->next[best] == -1))) best = -1;
      if (best != cn->seg) {
        PetscBool moved = PETSC_FALSE;

        (*changed)++;
        /* the history follows the node to a nearby segment; a new contact starts afresh */
        if (best >= 0 && cn->seg >= 0) PetscCall(TransferHistory(p, cs, xa, cn->seg, best, &cn->hist, &moved));
        cn->seg = best;
        if (best >= 0 && !moved) {
          /* stress-free at the pairing point, the circumferential anchor (twist) at the relative twist there */
          TslContactInput in;
          PetscInt        nodes[TSL_CONTACT_MAX_NODES], n;
          NeighbourData   nb;

          ElementInput(p, cn, xa, &in, nodes, &n, &nb);
          PetscCall(TslContactStateStart(&in, PetscMin(1, PetscMax(0, best_xi)), &cn->hist));
        }
      }
    }
    PetscCall(TslContactBinGridDestroy(&grid));
    PetscCall(PetscFree2(seg_box, seg_x));
  }
  PetscCall(PetscFree(cand));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective. Can a secondary node (or a secondary face, surface to surface) of this rank reach a main
 * face the rank does not hold? A face not held has a reference box outside the held region B; its current
 * box lies within hull * D of its reference box, D the largest displacement of any main-surface node
 * (per coordinate, a maximum over the owners). The search finds the faces whose current box meets the
 * node's query box, its current position +- the search radius. So a query box inside B shrunk by hull * D
 * meets only held faces. If some query box is not, the part held must be rebuilt: the run stops (all
 * ranks) naming the node, the rank and the margin; the driver saves the last converged state, and with
 * restarts left (-tsl_contact_rebuild) the job restarts from its start with twice the margin that would
 * have avoided it (src/app/main.c), otherwise the message says which margin to rerun with. */
static PetscErrorCode CheckHeldRegion(TslProblem p, const PetscScalar *xa)
{
  const TslModel *m   = p->m;
  const PetscInt  dim = p->dim;
  PetscReal      *D, *Dg, worst[2] = {0, 0}, *all;
  PetscInt        wpair = -1, wnode = -1;
  PetscMPIInt     rank, size, root = -1;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc2(3 * p->ncsurf, &D, 3 * p->ncsurf, &Dg));
  for (PetscInt k = 0; k < p->ncsurf; k++) {
    const TslContactPair    *pair = &m->pairs[k];
    const TslContactSurface *cs   = &p->csurf[k];
    for (PetscInt i = 0; i < pair->nmain_own; i++) {
      const PetscInt l = TslModelNodeIndex(m, pair->main_own[i]);
      for (PetscInt d = 0; l >= 0 && d < dim; d++) D[3 * k + d] = PetscMax(D[3 * k + d], PetscAbsReal(TslProblemSlotValue(p, xa, l, cs->slot[d])));
    }
  }
  PetscCall(MPIU_Allreduce(D, Dg, (PetscMPIInt)(3 * p->ncsurf), MPIU_REAL, MPIU_MAX, p->comm));
  for (PetscInt k = 0; k < p->ncsurf; k++) {
    const TslContactPair    *pair = &m->pairs[k];
    const TslContactSurface *cs   = &p->csurf[k];
    PetscReal                lo[3], hi[3], excess;
    PetscInt                 node;
    if (!pair->held) continue;
    {
      /* a rank that holds every face of the main surface, none of them only as a neighbour, misses none */
      PetscBool all = (PetscBool)(pair->nmain == pair->nmain_global);
      for (PetscInt f = 0; f < pair->nmain && all; f++)
        if (cs->ring[f]) all = PETSC_FALSE;
      if (all) continue;
    }
    for (PetscInt d = 0; d < dim; d++) lo[d] = pair->held_box[d] + cs->hull * Dg[3 * k + d], hi[d] = pair->held_box[3 + d] - cs->hull * Dg[3 * k + d];
    for (PetscInt i = 0; i < p->ncnode; i++) {
      const TslContactNode *cn = &p->cnode[i];
      if (cn->pair != k) continue;
      for (PetscInt d = 0; d < dim; d++) {
        const PetscReal y = m->node_xyz[3 * cn->lnode + d] + TslProblemSlotValue(p, xa, cn->lnode, cs->slot[d]);
        const PetscReal e = PetscMax(lo[d] - (y - cs->search_radius), (y + cs->search_radius) - hi[d]);
        if (e > worst[0]) worst[0] = e, wpair = k, wnode = m->node_id[cn->lnode];
      }
    }
    PetscCall(TslProblemContactS2SReach(p, k, xa, lo, hi, &excess, &node));
    if (excess > worst[0]) worst[0] = excess, wpair = k, wnode = node;
  }
  PetscCallMPI(MPI_Comm_rank(p->comm, &rank));
  PetscCallMPI(MPI_Comm_size(p->comm, &size));
  PetscCall(PetscMalloc1(size, &all));
  PetscCallMPI(MPI_Allgather(&worst[0], 1, MPIU_REAL, all, 1, MPIU_REAL, p->comm));
  for (PetscMPIInt r = 0; r < size; r++)
    if (all[r] > 0 && (root < 0 || all[r] > all[root])) root = r;
  PetscCall(PetscFree(all));
  if (root >= 0) {
    char      msg[1024] = "", what[160];
    PetscInt  info[2]   = {wpair, wnode}, rebuilds = 0;
    PetscReal need, rerun = 0;
    PetscCallMPI(MPI_Bcast(info, 2, MPIU_INT, root, p->comm));
    PetscCallMPI(MPI_Bcast(worst, 1, MPIU_REAL, root, p->comm));
    /* restarts left (the job's driver, src/app/main.c, counts them down) */
    PetscCall(PetscOptionsGetInt(NULL, NULL, "-tsl_contact_rebuild", &rebuilds, NULL));
    {
      const TslContactPair *pair = &m->pairs[info[0]];
      const PetscReal      *Dk   = &Dg[3 * info[0]];
      need                       = pair->margin + worst[0];
      if (rebuilds > 0) {
        /* twice what would have avoided it (the sliding may go on: doubling bounds the work redone to that
         * of one more run), and never less than any pair's margin now (the option sets all pairs') */
        rerun = 2 * need;
        for (PetscInt k = 0; k < p->ncsurf; k++) rerun = PetscMax(rerun, m->pairs[k].margin);
        PetscCall(PetscSNPrintf(what, sizeof(what), "the held part is rebuilt: the job restarts from its start with -tsl_contact_margin %g", (double)rerun));
      } else
        PetscCall(PetscSNPrintf(what, sizeof(what),
                                "rerun with -tsl_contact_margin %g or more (the margin that would have avoided it here; more if the sliding goes on)",
                                (double)need));
      PetscCall(PetscSNPrintf(msg, sizeof(msg),
                              "contact pair %" PetscInt_FMT " (%s on %s): secondary node %" PetscInt_FMT " on rank %d can reach main faces that rank does "
                              "not hold: its search box (current position +- the search radius %g) leaves the rank's held region (the reference box "
                              "of its secondary nodes inflated by the margin %g, shrunk by the main surface's largest displacement %g) by %g; %s",
                              info[0] + 1, pair->secondary, pair->main, info[1], (int)root, (double)p->csurf[info[0]].search_radius, (double)pair->margin,
                              (double)PetscSqrtReal(Dk[0] * Dk[0] + Dk[1] * Dk[1] + Dk[2] * Dk[2]), (double)worst[0], what));
    }
    PetscCall(PetscFree2(D, Dg));
    if (rerun > 0) {
      /* not an error for the user: the log says what happens, and the stop (a blank message, which the
       * error handler does not print) unwinds to the driver, which saves the converged increments */
      p->margin_rerun = rerun;
      PetscCall(PetscPrintf(p->comm, "%s\n", msg));
      SETERRQ(p->comm, PETSC_ERR_USER_INPUT, " ");
    }
    SETERRQ(p->comm, PETSC_ERR_USER_INPUT, "%s", msg);
  }
  PetscCall(PetscFree2(D, Dg));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemGetMarginRerun(TslProblem p, PetscReal *margin)
{
  PetscFunctionBeginUser;
  *margin = p->margin_rerun;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective. Pairs secondary nodes at the current solution (after checking that every node's reach is
 * held here); rebuilds the matrix pattern when pairing changed anywhere. */
PetscErrorCode TslProblemContactSearch(TslProblem p, PetscBool *repattern)
{
  Vec                xl;
  const PetscScalar *xa;
  PetscInt           changed, g, moved;

  PetscFunctionBeginUser;
  *repattern = PETSC_FALSE;
  p->search_moved = 0;
  if (!p->ncsurf) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(TslProblemGetLocalSolution(p, &xl, &xa));
  PetscCall(TslPhaseBegin(TSL_PHASE_SEARCH));
  {
    /* a node beyond the held region stops the attempt (the job may restart): let go of the local form first */
    PetscErrorCode ierr = CheckHeldRegion(p, xa);
    if (ierr) {
      PetscCall(TslPhaseEnd(TSL_PHASE_SEARCH));
      PetscCall(TslProblemRestoreLocalSolution(p, &xl, &xa));
    }
    PetscCall(ierr);
  }
  PetscCall(Search(p, xa, &changed));
  {
    PetscInt c2, rc;
    PetscCall(TslProblemContactS2SSearch(p, xa, &c2, &rc));
    moved = changed + rc; /* a node re-paired changes its segment: counted in changed */
    changed += c2;
  }
  PetscCall(TslPhaseEnd(TSL_PHASE_SEARCH));
  PetscCall(TslProblemRestoreLocalSolution(p, &xl, &xa));
  if (!p->s2s_reported) { /* what a surface-to-surface pair costs: its points, each a kernel evaluation */
    PetscInt *cnt, *sum;
    p->s2s_reported = PETSC_TRUE;
    PetscCall(PetscMalloc2(2 * p->ncsurf, &cnt, 2 * p->ncsurf, &sum));
    TslProblemContactS2SCount(p, cnt);
    PetscCall(MPIU_Allreduce(cnt, sum, (PetscMPIInt)(2 * p->ncsurf), MPIU_INT, MPI_SUM, p->comm));
    for (PetscInt k = 0; k < p->ncsurf; k++)
      if (sum[2 * k])
        PetscCall(PetscPrintf(p->comm,
                              "contact pair %" PetscInt_FMT ": surface to surface, %" PetscInt_FMT " integration points on %" PetscInt_FMT
                              " secondary faces at the first search (%.1f per face; each point is one evaluation of the contact kernel)\n",
                              k + 1, sum[2 * k + 1], sum[2 * k], (double)sum[2 * k + 1] / (double)sum[2 * k]));
    PetscCall(PetscFree2(cnt, sum));
  }
  if (p->pattern_stale) changed++;
  p->pattern_stale = PETSC_FALSE;
  PetscCall(MPIU_Allreduce(&moved, &p->search_moved, 1, MPIU_INT, MPI_SUM, p->comm));
  PetscCall(MPIU_Allreduce(&changed, &g, 1, MPIU_INT, MPI_SUM, p->comm));
  if (g) {
    PetscCall(PetscInfo(NULL, "contact pairing changed for %" PetscInt_FMT " secondary nodes\n", g));
    if (!p->matrix_free) PetscCall(TslProblemPreallocate(p)); /* explicit steps build no matrix */
    *repattern = PETSC_TRUE;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Nodes (this rank) whose projection at their last evaluation left their segment: a node on a segment end
 * may fall outside [0,1] by round-off, so only a real departure counts. */
static PetscInt Departed(TslProblem p)
{
  PetscInt n = 0;
  for (PetscInt i = 0; i < p->ncnode; i++) {
    const TslContactNode    *cn = &p->cnode[i];
    const TslContactSurface *cs = &p->csurf[cn->pair];
    if (cn->seg < 0) continue;
    if (cs->dim == 3 ? TslProblemContact3Departed(p, cn, TSL_CONTACT_DEPART_TOL) : TslContactProjectionSide(cn->out.xi_raw, TSL_CONTACT_DEPART_TOL) != 0)
      n++;
  }
  return n;
}

/* Collective. After a converged solve: nodes whose projection left their segment need re-pairing, and
 * augmented-Lagrange multipliers are updated. *again is set when the increment must be solved again,
 * *augmented when that is because the multipliers changed. */
PetscErrorCode TslProblemContactUpdate(TslProblem p, PetscBool *again, PetscBool *repattern, PetscBool *augmented)
{
  PetscInt  loc[2] = {0, 0}, g[2];
  PetscReal change = 0, scale = 0, gc[2], lc[2];

  PetscFunctionBeginUser;
  *again = *repattern = *augmented = PETSC_FALSE;
  if (!p->ncsurf) PetscFunctionReturn(PETSC_SUCCESS);
  {
    /* the contact elements at the converged state (outputs only: no residual, no matrix) */
    Vec                xl;
    const PetscScalar *xa;
    PetscCall(TslProblemGetLocalSolution(p, &xl, &xa));
    PetscCall(TslProblemContactAssemble(p, ASM_RAW, xa, NULL, NULL, NULL));
    PetscCall(TslProblemRestoreLocalSolution(p, &xl, &xa));
  }
  loc[0] = Departed(p);
  for (PetscInt i = 0; i < p->ncnode; i++) {
    TslContactNode          *cn = &p->cnode[i];
    const TslContactSurface *cs = &p->csurf[cn->pair];
    if (cn->seg < 0) continue;
    if (cs->law.normal == TSL_CONTACT_NORMAL_AUGMENTED) {
      PetscReal c, lambda = cn->hist.lambda; /* applied below only if the increment is solved again */
      PetscCall(TslContactAugmentedUpdate(cs->law.eps_n, cn->out.gap, &lambda, &c));
      change = PetscMax(change, PetscAbsReal(c));
      scale  = PetscMax(scale, cn->out.pressure);
    }
  }
  PetscCall(TslProblemContactS2SUpdate(p, &loc[0], &change, &scale));
  lc[0] = change, lc[1] = scale;
  PetscCall(MPIU_Allreduce(loc, g, 1, MPIU_INT, MPI_SUM, p->comm));
  PetscCall(MPIU_Allreduce(lc, gc, 2, MPIU_REAL, MPIU_MAX, p->comm));
  if (g[0]) {
    /* a search that changes nothing at this state (no node re-paired, every surface-to-surface face cut as
     * before) would give the next solve the same equations at the same point: it takes no step and the same
     * points depart again, until -tsl_contact_max_its fails the increment. A surface-to-surface point pairs by
     * its piece's middle projected onto the main faces (the closest point) and departs by its own projection
     * along the main surface's normal; on a curved secondary face near a main face's end the two may differ
     * while the point is open (the Hertz cylinder: an increment converged, then 6 further solves of 0 steps
     * each until the limit, at every cutback). The point then stays on its extended face, as a node does
     * within a solve. */
    PetscCall(TslProblemContactSearch(p, repattern));
    *again = (PetscBool)(p->search_moved > 0);
    if (!*again) PetscCall(PetscInfo(NULL, "%" PetscInt_FMT " contact points left their faces; a new search at this state changes nothing\n", g[0]));
  }
  /* multipliers change only when another solve follows, so that the accepted state is the one solved */
  /* relative to the largest pressure only (no absolute floor: pressures may be 1e-7 in kN/mm^2); with no
   * pressure anywhere the multipliers are already zero after one update and the change is exactly 0 */
  if (gc[1] > 0 || gc[0] > 0)
    PetscCall(PetscInfo(NULL, "augmented Lagrange: largest multiplier change %g, largest pressure %g\n", (double)gc[0], (double)gc[1]));
  if (gc[0] > p->augment_tol * gc[1]) {
    *again = *augmented = PETSC_TRUE;
    for (PetscInt i = 0; i < p->ncnode; i++) {
      TslContactNode          *cn = &p->cnode[i];
      const TslContactSurface *cs = &p->csurf[cn->pair];
      PetscReal                c;
      if (cn->seg >= 0 && cs->law.normal == TSL_CONTACT_NORMAL_AUGMENTED)
        PetscCall(TslContactAugmentedUpdate(cs->law.eps_n, cn->out.gap, &cn->hist.lambda, &c));
    }
    PetscCall(TslProblemContactS2SAugment(p));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* An accepted increment: its contact state becomes the start of the next one (3D: and its configuration
 * gives the nodal normals of the next increment's smoothing). */
PetscErrorCode TslProblemContactCommit(TslProblem p)
{
  PetscBool normals = PETSC_FALSE;

  PetscFunctionBeginUser;
  /* the ghost update is collective: every rank takes part (dim and smoothing are the same on all ranks),
   * also one that owns no secondary node of the pair (it used to skip it, and a 2-rank 3D run whose pair
   * was split hung in the next ghost update) */
  for (PetscInt k = 0; k < p->ncsurf; k++) normals = (PetscBool)(normals || (p->csurf[k].dim == 3 && p->csurf[k].smooth > 0));
  if (normals) {
    Vec                xl;
    const PetscScalar *xa;
    PetscCall(TslProblemGetLocalSolution(p, &xl, &xa));
    for (PetscInt k = 0; k < p->ncsurf; k++)
      if (p->csurf[k].dim == 3 && p->csurf[k].active && p->csurf[k].smooth > 0) PetscCall(TslProblemContact3Normals(p, &p->csurf[k], xa));
    PetscCall(TslProblemRestoreLocalSolution(p, &xl, &xa));
  }
  for (PetscInt i = 0; i < p->ncnode; i++) {
    TslContactNode *cn = &p->cnode[i];
    /* a kinematic pair's node is evaluated by the corrector of an increment: one that was not (the first
     * force evaluation of an explicit step, or k_kin = 0) has no new state to commit */
    if (cn->seg >= 0 && (cn->fresh || !p->csurf[cn->pair].kinematic)) {
      PetscCall(TslContactStateUpdate(&cn->out, &cn->hist));
      cn->cslip += PetscHypotReal(cn->out.slip, cn->out.slip_circ); /* the slip vector's length (twist: 2 components) */
    }
    cn->fresh   = PETSC_FALSE;
    cn->seg_c   = cn->seg;
    cn->hist_c  = cn->hist;
    cn->cslip_c = cn->cslip;
  }
  PetscCall(TslProblemContactS2SCommit(p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Collective. An explicit increment (src/solve/explicit.c): the contact state of the forces just evaluated
 * becomes the history of the next increment (friction anchors, slip), then the pairing search runs when
 * asked (every few increments) or when a node's projection left its face. *nrepair: nodes re-paired. */
PetscErrorCode TslProblemContactExplicitIncrement(TslProblem p, PetscBool search, PetscInt *nrepair)
{
  PetscInt  loc, g;
  PetscReal change = 0, scale = 0;
  PetscBool repattern;

  PetscFunctionBeginUser;
  *nrepair = 0;
  if (!p->ncsurf) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(TslProblemContactCommit(p));
  loc = Departed(p);
  PetscCall(TslProblemContactS2SUpdate(p, &loc, &change, &scale));
  PetscCall(MPIU_Allreduce(&loc, &g, 1, MPIU_INT, MPI_SUM, p->comm));
  if (g || search) {
    PetscCall(TslProblemContactSearch(p, &repattern));
    *nrepair = g;
    if (p->s2s) {
      /* a surface-to-surface face cut anew has new points without outputs until the next force evaluation,
       * and a frame may be written before that: evaluate them at this state (values only, nothing inserted;
       * the history was carried over by the search) so that CPRESS, HFLA, ... are those of the state */
      Vec                xl;
      const PetscScalar *xa;
      PetscCall(TslProblemGetLocalSolution(p, &xl, &xa));
      PetscCall(TslProblemContactS2SAssemble(p, ASM_RAW, xa, NULL, NULL, NULL));
      PetscCall(TslProblemRestoreLocalSolution(p, &xl, &xa));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* An explicit step's contact (explicit_step) or an implicit one's. MECHANICAL CONSTRAINT=KINEMATIC applies to
 * explicit steps only. The stick of plain *FRICTION: implicit steps allow the automatic elastic slip (the stick
 * stiffness mu pN / e_max, soft enough for Newton: issue 8); explicit steps stick with the normal penalty eps_n,
 * as Abaqus/Explicit does (its SLIP TOLERANCE and ELASTIC SLIP are Abaqus/Standard settings). With e_max an
 * explicit slide lost heat wherever the interface rang: every opening restarted a node's stick from zero and it
 * had to slide e_max (0.005 of a facet) again before it dissipated, a fifth of the heat of a two-block slide
 * whose pressure chattered at 100 Hz (docs/explicit.md, "Friction in explicit steps"). The normal penalty is the
 * interface's own stiffness: the stable increment's nodal bound (contact_bound.c) bounds the norm of each
 * point's block, k n n^T then and k I now, alike. */
PetscErrorCode TslProblemContactSetExplicit(TslProblem p, PetscBool explicit_step, PetscBool *any)
{
  PetscFunctionBeginUser;
  *any = PETSC_FALSE;
  for (PetscInt k = 0; k < p->ncsurf; k++) {
    TslContactSurface *cs = &p->csurf[k];
    cs->kinematic         = (PetscBool)(explicit_step && p->m->pairs[k].kinematic);
    if (cs->kinematic) *any = PETSC_TRUE; /* the pairs are the model's, the same on every rank */
    if (cs->elastic_slip_implicit > 0) {
      cs->law.elastic_slip = explicit_step ? 0 : cs->elastic_slip_implicit;
      cs->law.eps_t        = explicit_step ? cs->law.eps_n : 0;
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscReal TslProblemContactNodeArea(TslProblem p, const TslContactNode *cn)
{
  const TslContactSurface *cs = &p->csurf[cn->pair];
  PetscReal                A  = cn->length;
  if (cs->dim != 3) A *= TslKinematicsRevolves(cs->kin) ? 2 * PETSC_PI * p->m->node_xyz[3 * cn->lnode] : cs->thickness;
  return A;
}

/* A rejected increment: back to the state at its start. Pairing that changed during the attempt left the
 * matrix pattern of the attempt, so the next search rebuilds it. */
PetscErrorCode TslProblemContactRollback(TslProblem p)
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < p->ncnode; i++) {
    TslContactNode *cn = &p->cnode[i];
    if (cn->seg != cn->seg_c) p->pattern_stale = PETSC_TRUE;
    cn->seg   = cn->seg_c;
    cn->hist  = cn->hist_c;
    cn->cslip = cn->cslip_c;
  }
  PetscCall(TslProblemContactS2SRollback(p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Contact node fields over owned nodes (zero where a node is not a secondary node):
 * CPRESS contact pressure, CSLIP accumulated slip, CSTATUS 0 open / 1 stick / 2 slip, HFLA heat flux per
 * area into the secondary surface. */
PetscErrorCode TslProblemContactNodeField(TslProblem p, TslContactField kind, PetscReal vals[])
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < p->ncnode; i++) {
    const TslContactNode *cn = &p->cnode[i];
    PetscReal             v  = 0;
    if (cn->seg >= 0) {
      if (kind == TSL_CONTACT_FIELD_PRESSURE)
        v = cn->out.pressure;
      else if (kind == TSL_CONTACT_FIELD_STATUS)
        v = (PetscReal)cn->out.status;
      else if (kind == TSL_CONTACT_FIELD_HEAT_FLUX)
        v = cn->out.heat_flux;
    }
    if (kind == TSL_CONTACT_FIELD_SLIP) v = cn->cslip;
    vals[cn->lnode] = v;
  }
  PetscCall(TslProblemContactS2SNodeField(p, kind, vals));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The contact law of an interaction, in the kernel's terms; penalty = the default normal penalty. */
static PetscErrorCode SetUpLaw(TslProblem p, const TslContactPair *pair, PetscReal seg_length, PetscReal penalty, TslContactLaw *law)
{
  const TslModel       *m  = p->m;
  const TslInteraction *it = &m->interactions[pair->interaction_index];
  char                  loc[PETSC_MAX_PATH_LEN + 32];

  PetscFunctionBeginUser;
  PetscCall(TslContactLawSetDefaults(law));
  law->normal =
      it->behavior.given && it->behavior.enforcement == TSL_CONTACT_AUGMENTED_LAGRANGE ? TSL_CONTACT_NORMAL_AUGMENTED : TSL_CONTACT_NORMAL_PENALTY;
  law->eps_n = it->behavior.given && it->behavior.penalty_stiffness > 0 ? it->behavior.penalty_stiffness : penalty;
  PetscCheck(!(it->friction.given && it->friction.rough), PETSC_COMM_SELF, PETSC_ERR_SUP, "%s: *FRICTION, ROUGH is not supported yet",
             TslLocString(m, it->friction.loc, loc, sizeof(loc)));
  if (it->friction.given && it->friction.mu > 0) {
    law->mu       = it->friction.mu;
    law->friction = it->friction.lagrange ? TSL_CONTACT_FRICTION_LAGRANGE : TSL_CONTACT_FRICTION_PENALTY;
    /* stick stiffness: CalculiX's stick slope when given, otherwise the dialect's automatic penalty that
     * allows an elastic slip of SLIP TOLERANCE (0.005) times the facet size. The normal penalty used to
     * be the default: six orders stiffer, its stick limit (3e-8 for the two-block decks) sat at the
     * Poisson mismatch of two pressed blocks, and Newton cycled between slipping one way and the other
     * (issue 8, item 8). */
    law->eps_t        = it->friction.stick_slope;
    law->elastic_slip = it->friction.stick_slope > 0    ? 0
                        : it->friction.elastic_slip > 0 ? it->friction.elastic_slip /* ELASTIC SLIP=: a length */
                                                        : it->friction.slip_tolerance * seg_length;
    /* LAGRANGE: sign(slip) is regularised over a slip far below any slip that heats (1e-4 of a segment):
     * sharper makes Newton oscillate at sticking nodes, and every finite slip still dissipates mu p |ds| */
    law->slip_tol = 1e-4 * seg_length;
  }
  if (it->conductance.given) {
    law->conductance = it->conductance.by_pressure ? TSL_CONTACT_CONDUCTANCE_PRESSURE : TSL_CONTACT_CONDUCTANCE_CLEARANCE;
    law->k_n         = it->conductance.n;
    law->k_arg       = it->conductance.abscissa;
    law->k_value     = it->conductance.value;
  }
  if (it->radiation.given) {
    PetscCheck(
        m->has_stefan_boltzmann && m->has_absolute_zero, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
        "%s: *GAP RADIATION needs *PHYSICAL CONSTANTS, ABSOLUTE ZERO= and STEFAN BOLTZMANN=", TslLocString(m, it->radiation.loc, loc, sizeof(loc)));
    law->F_n           = it->radiation.n;
    law->F_clearance   = it->radiation.clearance;
    law->F_value       = it->radiation.view_factor;
    law->eps_main      = it->radiation.emissivity_main;
    law->eps_secondary = it->radiation.emissivity_secondary;
    law->sigma         = m->stefan_boltzmann;
    law->theta_zero    = m->absolute_zero;
  }
  /* without *GAP HEAT GENERATION friction dissipates without heating the bodies */
  law->eta = it->heat_generation.given ? it->heat_generation.fraction : 0.0;
  law->f   = it->heat_generation.given ? it->heat_generation.weight_secondary : 0.5;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Job-log lines per pair: which ranks own its secondary nodes and its main-surface nodes, the margin of
 * the held regions and how many main faces each rank holds. */
static PetscErrorCode ReportPartition(TslProblem p)
{
  const TslModel *m = p->m;
  PetscMPIInt     size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(p->comm, &size));
  for (PetscInt k = 0; k < m->npair; k++) {
    const TslContactPair *c       = &m->pairs[k];
    PetscInt              mine[3] = {c->nsec > 0 || c->nsface > 0, c->nmain_own > 0, c->nmain}, *all;
    char                  line[2][256], *held;
    size_t                hl = 0;
    PetscCall(PetscMalloc1(3 * size, &all));
    PetscCallMPI(MPI_Allgather(mine, 3, MPIU_INT, all, 3, MPIU_INT, p->comm));
    for (PetscInt w = 0; w < 2; w++) {
      size_t len = 0;
      line[w][0] = 0;
      for (PetscMPIInt r = 0; r < size; r++)
        if (all[3 * r + w]) {
          PetscCall(PetscSNPrintf(line[w] + len, sizeof(line[w]) - len, "%s%d", len ? " " : "", (int)r));
          PetscCall(PetscStrlen(line[w], &len));
        }
    }
    PetscCall(PetscPrintf(p->comm, "contact pair %" PetscInt_FMT " (%s on %s): secondary nodes on ranks %s; main-surface nodes on ranks %s\n", k + 1,
                          c->secondary, c->main, line[0], line[1]));
    PetscCall(PetscMalloc1(24 * size + 1, &held));
    held[0] = 0;
    for (PetscMPIInt r = 0; r < size; r++) {
      PetscCall(PetscSNPrintf(held + hl, 24 * size + 1 - hl, "%s%" PetscInt_FMT, r ? " " : "", all[3 * r + 2]));
      PetscCall(PetscStrlen(held, &hl));
    }
    if (c->margin_default)
      PetscCall(PetscPrintf(p->comm, "contact pair %" PetscInt_FMT ": margin %g (default: 2 x (largest prescribed displacement %g + search radius %g)); main faces held by rank 0..%d: %s of %" PetscInt_FMT "\n",
                            k + 1, (double)c->margin, (double)c->margin_disp, (double)c->margin_radius, (int)size - 1, held, c->nmain_global));
    else
      PetscCall(PetscPrintf(p->comm, "contact pair %" PetscInt_FMT ": margin %g (-tsl_contact_margin); main faces held by rank 0..%d: %s of %" PetscInt_FMT "\n", k + 1,
                            (double)c->margin, (int)size - 1, held, c->nmain_global));
    PetscCall(PetscFree(held));
    PetscCall(PetscFree(all));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Young's modulus of local element e: the only place contact reads a material. Materials are tables
 * in temperature: the first *ELASTIC row, the value the mesh code used to take. */
static PetscReal ElementModulus(TslProblem p, PetscInt e)
{
  return p->esec[e].mat->prop[TSL_PROP_ELASTIC].value[0][0];
}

/* Collective. The default normal penalty of each pair, 10 E / (mean main face length), E the Young's
 * modulus of the element of the pair's first main face. Only the rank that holds that element knows its
 * material: the others contribute -1 to a maximum over the ranks (E > 0 is checked at set-up). */
static PetscErrorCode DefaultPenalties(TslProblem p, PetscReal penalty[])
{
  const TslModel *m = p->m;
  PetscReal      *E, *Eall;

  PetscFunctionBeginUser;
  if (!m->npair) PetscFunctionReturn(PETSC_SUCCESS); /* every rank has all pairs */
  PetscCall(PetscMalloc2(m->npair, &E, m->npair, &Eall));
  for (PetscInt k = 0; k < m->npair; k++) {
    PetscInt e = m->pairs[k].main_element >= 0 ? TslModelElementIndex(m, m->pairs[k].main_element) : -1;
    E[k]       = e >= 0 ? ElementModulus(p, e) : -1;
  }
  PetscCall(MPIU_Allreduce(E, Eall, (PetscMPIInt)m->npair, MPIU_REAL, MPIU_MAX, p->comm));
  for (PetscInt k = 0; k < m->npair; k++) {
    const TslContactPair *pair = &m->pairs[k];
    penalty[k]                 = pair->mean_length > 0 ? 10.0 * PetscMax(Eall[k], 0) / pair->mean_length : 0;
    PetscCall(PetscInfo(NULL, "contact pair %" PetscInt_FMT ": default normal penalty %g = 10 E / mean main face length (E %g, length %g)\n", k + 1,
                        (double)penalty[k], (double)Eall[k], (double)pair->mean_length));
  }
  PetscCall(PetscFree2(E, Eall));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemContactSetUp(TslProblem p)
{
  const TslModel *m = p->m;
  PetscInt        n = 0;
  PetscReal      *penalty;

  PetscFunctionBeginUser;
  p->augment_tol = 1e-3;
  PetscOptionsBegin(p->comm, NULL, "thermoslide contact", NULL);
  PetscCall(TslOptionsReal(PetscOptionsObject, "-tsl_contact_augment_tol", "augmented Lagrange: multiplier change that ends the augmentations", 0,
                           PETSC_TRUE, 1, PETSC_FALSE, &p->augment_tol));
  PetscOptionsEnd();
  PetscCall(PetscMalloc1(m->npair + 1, &penalty));
  PetscCall(DefaultPenalties(p, penalty));
  p->ncsurf = m->npair;
  PetscCall(PetscCalloc1(m->npair, &p->csurf));
  for (PetscInt k = 0; k < m->npair; k++) n += m->pairs[k].nsec;
  PetscCall(PetscCalloc1(n, &p->cnode));
  for (PetscInt k = 0; k < m->npair; k++) {
    const TslContactPair *pair = &m->pairs[k];
    TslContactSurface    *cs   = &p->csurf[k];
    const TslContactFace *face = TslContactFaceGet((TslContactFaceKind)pair->main_face);

    cs->dim = p->dim;
    PetscCheck(cs->dim == 3 || (face && face->geom->nnode == pair->nper), PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "contact pair %" PetscInt_FMT ": face family %" PetscInt_FMT " does not have %" PetscInt_FMT " nodes", k + 1, pair->main_face,
               pair->nper);
    cs->kin       = (TslKinematics)pair->kin;
    cs->face      = (TslContactFaceKind)pair->main_face;
    cs->nper      = pair->nper;
    cs->thickness = pair->thickness;
    cs->smooth    = pair->smooth;
    cs->nmain     = pair->nmain;
    cs->active    = (PetscBool)(pair->nsec > 0);
    PetscCall(PetscMalloc4(cs->nper * pair->nmain + 1, &cs->main_lnode, pair->nmain + 1, &cs->prev, pair->nmain + 1, &cs->next, pair->nmain + 1, &cs->kind));
    PetscCall(PetscMalloc1(pair->nmain + 1, &cs->ring));
    for (PetscInt s = 0; s < pair->nmain; s++) {
      cs->prev[s] = pair->main_prev[s];
      cs->next[s] = pair->main_next[s];
      cs->kind[s] = pair->main_kind[s];
      cs->ring[s] = pair->main_ring[s];
      for (PetscInt a = 0; a < cs->nper; a++) {
        PetscInt i = cs->nper * s + a;

        cs->main_lnode[i] = pair->main_node[i] >= 0 ? TslModelNodeIndex(m, pair->main_node[i]) : -1;
        PetscCheck(!cs->active || pair->main_node[i] < 0 || cs->main_lnode[i] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                   "main-surface node %" PetscInt_FMT " is not local", pair->main_node[i]);
      }
    }
    PetscCall(SetUpLaw(p, pair, pair->mean_length, penalty[k], &cs->law));
    cs->elastic_slip_implicit = cs->law.friction == TSL_CONTACT_FRICTION_PENALTY ? cs->law.elastic_slip : 0; /* see TslProblemContactSetExplicit */
    /* the held region's shrink per unit of main-surface motion: the pair's face family (2D: one per pair;
     * 3D: the first face's, the degree of a wedge's tri and quad faces alike) */
    if (cs->dim == 3) cs->hull = TslContactFace3HullBound(pair->main_face);
    else {
      cs->hull = 1;
      for (PetscInt i = 0; face && i < face->geom->nnode; i++) {
        PetscReal sum = 0;
        for (PetscInt a = 0; a < face->geom->nnode; a++) sum += PetscAbsReal(face->hull[i][a]);
        cs->hull = PetscMax(cs->hull, sum);
      }
    }
    /* the kernels see (u_x, u_y, theta) per node, and the twist phi (dof 5) after them on twist models,
     * whose slip has a circumferential component */
    cs->nu      = cs->dim == 3 ? TSL_CONTACT3_NU : TslContactNodeUnknowns(cs->kin);
    cs->slot[0] = TslProblemDofSlot(p, 1);
    cs->slot[1] = TslProblemDofSlot(p, 2);
    cs->slot[2] = TslProblemDofSlot(p, 11);
    cs->slot[3] = TslProblemDofSlot(p, 5);
    if (cs->dim == 3) {
      /* 3D kernels see (u_x, u_y, u_z, theta); smoothing by the nodal normals, first of the reference state */
      cs->slot[2] = TslProblemDofSlot(p, 3);
      cs->slot[3] = TslProblemDofSlot(p, 11);
      PetscCheck((cs->slot[2] >= 0 || p->nu == 0) && cs->slot[3] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "3D contact needs the displacements 1..3 and the temperature 11");
      PetscCall(PetscCalloc1(3 * p->nn, &cs->nnormal));
      PetscCall(TslProblemContact3Normals(p, cs, NULL));
    }
    /* a heat-transfer model has no displacement: the kernels see it as zero, the deck's geometry (TslProblemSlotValue) */
    PetscCheck(((cs->slot[0] >= 0 && cs->slot[1] >= 0) || p->nu == 0) && cs->slot[cs->dim == 3 ? 3 : 2] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "contact needs the displacements 1, 2 and the temperature 11 among the nodal unknowns");
    PetscCheck(cs->dim == 3 || (cs->nu == 4) == (cs->slot[3] >= 0), PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "contact pair %" PetscInt_FMT ": the twist dof 5 is %s the nodal unknowns but the pair's kinematics is %s", k + 1,
               cs->slot[3] >= 0 ? "among" : "not among", cs->nu == 4 ? "with twist" : "without twist");
    /* candidates within one mean segment length, or the largest tabulated clearance */
    cs->search_radius = pair->mean_length;
    if (cs->law.conductance == TSL_CONTACT_CONDUCTANCE_CLEARANCE) cs->search_radius = PetscMax(cs->search_radius, cs->law.k_arg[cs->law.k_n - 1]);
    if (cs->law.F_n) cs->search_radius = PetscMax(cs->search_radius, cs->law.F_clearance[cs->law.F_n - 1]);
    for (PetscInt i = 0; i < pair->nsec; i++) {
      TslContactNode *cn = &p->cnode[p->ncnode++];
      cn->pair           = k;
      cn->lnode          = TslModelNodeIndex(m, pair->sec_node[i]);
      cn->length         = pair->sec_length[i];
      cn->seg = cn->seg_c = -1;
      PetscCheck(cn->lnode >= 0 && cn->lnode < p->nown, PETSC_COMM_SELF, PETSC_ERR_PLIB, "secondary node %" PetscInt_FMT " is not owned here",
                 pair->sec_node[i]);
    }
  }
  PetscCall(PetscFree(penalty));
  PetscCall(TslProblemContactS2SSetUp(p));
  PetscCall(ReportPartition(p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode TslProblemContactDestroy(TslProblem p)
{
  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < p->ncsurf; k++) {
    PetscCall(PetscFree4(p->csurf[k].main_lnode, p->csurf[k].prev, p->csurf[k].next, p->csurf[k].kind));
    PetscCall(PetscFree(p->csurf[k].ring));
    PetscCall(PetscFree(p->csurf[k].nnormal));
  }
  PetscCall(PetscFree(p->csurf));
  PetscCall(PetscFree(p->cnode));
  PetscCall(TslProblemContactS2SDestroy(p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* For surface-to-surface contact (src/physics/contact_s2s.c): the kernel input of a node, and node data. */
void TslProblemContactElementInput(TslProblem p, const TslContactNode *cn, const PetscScalar *xa, TslContactInput *in, PetscInt nodes[], PetscInt *n,
                                   TslContactNeighbourData *nb)
{
  ElementInput(p, cn, xa, in, nodes, n, nb);
}

void TslProblemContactNodeData(TslProblem p, const TslContactSurface *cs, const PetscScalar *xa, PetscInt l, PetscReal x[2], PetscReal u[])
{
  NodeData(p, cs, xa, l, x, u);
}

PetscErrorCode TslProblemContactFaceMetric(TslProblem p, const TslContactSurface *cs, const PetscScalar *xa, PetscInt seg, PetscReal xi, PetscReal *L)
{
  return FaceMetric(p, cs, xa, seg, xi, L);
}
