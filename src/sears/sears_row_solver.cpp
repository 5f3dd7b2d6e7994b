// The time integration of a damped Sears row, solve_sears_row() (declared in
// sears_simulation.hpp; docs/sears.md "Buildings in a row", docs/speed.md). One class holds the
// state of a run; its members are named after the symbols of the equations (u, v, F, S, H, ...).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "sears/newmark_storeys.hpp"
#include "sears/sears_row_layout.hpp"
#include "sears/sears_simulation.hpp"
#include "sears/translation_bound.hpp"
#include "solver/hermite.hpp"

namespace pound::sears {
namespace {

// Longer steps through smooth contact forces (docs/speed.md): the next step's length is
// kStepSafety times the one the error estimate allows; kNoLongStep marks a step that must be
// a fine one (SearsRowSolver::step_error).
constexpr double kStepSafety = 0.9;
constexpr double kNoLongStep = std::numeric_limits<double>::infinity();

// Nonlinear Gauss-Seidel on F_s = law_s(delta_pred_s - sum_t S(s,t) F_t). Sites marked in
// `frozen` keep F_s = 0 (the caller has shown that their faces stay apart).
void solve_forces(const std::vector<ContactLaw>& laws, const Eigen::MatrixXd& S,
                  const Eigen::VectorXd& delta_pred, const std::vector<char>& frozen,
                  Eigen::VectorXd& F) {
  const int n = static_cast<int>(F.size());
  for (int it = 0; it < 500; ++it) {
    double change = 0.0, scale = 1e-300;
    for (int s = 0; s < n; ++s) {
      if (frozen[s]) continue;
      const double r = delta_pred(s) - S.row(s).dot(F) + S(s, s) * F(s);
      const double f = laws[s].solve_implicit(r, S(s, s));
      change = std::max(change, std::fabs(f - F(s)));
      scale = std::max(scale, f);
      F(s) = f;
    }
    if (change <= 1e-13 * scale) return;
  }
  throw NumericalError("damped Sears model: contact forces did not converge in 500 sweeps");
}

// Newmark average acceleration (Chopra sec. 5.4) solved for the end-of-step acceleration,
// which keeps m a = P exact for free bodies (momentum to round-off):
//   Mt a_{i+1} = p_{i+1} - C (v + h/2 a) - K (u + h v + h^2/4 a),  Mt = M + h/2 C + h^2/4 K
//   u_{i+1} = u + h v + h^2/4 (a + a_{i+1}),  v_{i+1} = v + h/2 (a + a_{i+1}).
// Mt^-1 is applied once, so that a step costs one matrix-vector product:
//   a_{i+1} = -(Mt^-1 M 1) ag - [Mt^-1 C, Mt^-1 K] [v + h/2 a; u + h v + h^2/4 a].
struct NewmarkOperator {
  Eigen::MatrixXd CK;  // [Mt^-1 C, Mt^-1 K], n x 2n (column-major)
  Eigen::VectorXd g;   // Mt^-1 M 1

  NewmarkOperator(const AssembledRow& a, const Eigen::LLT<Eigen::MatrixXd>& mt)
      : CK(a.dofs(), 2 * a.dofs()), g(mt.solve(a.M * Eigen::VectorXd::Ones(a.dofs()))) {
    CK.leftCols(a.dofs()) = mt.solve(a.C);
    CK.rightCols(a.dofs()) = mt.solve(a.K);
  }
};

Eigen::MatrixXd newmark_matrix(const AssembledRow& a, double h) {
  return a.M + (0.5 * h) * a.C + (0.25 * h * h) * a.K;
}

// The operators of one loaded step of h = m fine steps (m = 1 .. SearsSteps::longest): with the
// contact forces P = -sum_s F_s (e_L - e_R), a_{i+1} = a_hat - H F, H = Mt^-1 [e_L - e_R],
// u_{i+1} = u_hat - h^2/4 H F, the overlaps' compliance S, and for yielding storeys R = Mt^-1 B.
struct StepOperators {
  double h;
  NewmarkOperator nm;
  Eigen::MatrixXd H, S, R;
};

class SearsRowSolver {
 public:
  SearsRowSolver(const SearsRowProblem& p, const SearsRowModel& model);
  SearsRowResult run();

 private:
  void loads(const Eigen::VectorXd& f, std::vector<EndLoads>& to) const;
  double ag_at(double t) const { return p.motion ? p.motion->at(t) : 0.0; }
  // Overlap at the start of the step at site s (both slabs awake).
  double overlap_now(int s) const;
  // Sleeping slabs (runs of fine steps).
  void update_guards();
  void wake(int k);
  void fall_asleep();
  void finish_sleep();
  void predict_overlaps();
  bool guards_hold();
  // Dormant slabs (runs of coarse steps).
  void wake_dormant(int k);
  void wake_all_dormant();
  bool site_dormant(int s) const;
  double overlap_bound(int s) const { return approach_bound(s) - a.sites[s].gap; }
  // Approach u_L - u_R of the faces of site s (floors plus internal vibration); with a dormant
  // slab, its upper bound.
  double approach_bound(int s) const;
  void wake_site(int s);
  // Steps.
  void newmark_predict(double h, const NewmarkOperator& op, double t_next);
  void newmark_update(double h);
  // One step through contacts of m fine steps from t = i dt (m from the forces' smoothness,
  // at most trial_multiple(i)); returns m.
  long fine_step(long i);
  // The multiple a step through contacts from t = i dt with forces f tries first: m_next, but
  // within room(i, f), which it divides into steps of nearly equal length.
  long trial_multiple(long i, const Eigen::VectorXd& f) const;
  // How many fine steps a step from t = i dt with forces f may span: to the end of the coarse
  // interval, or, while every slab carries a force and none sleeps, to the next record sample;
  // never past the end of the run.
  long room(long i, const Eigen::VectorXd& f) const;
  // The largest e / (tol F) over the sites of the step just solved (m fine steps): the error of
  // its linear force, estimated from the second divided difference (docs/speed.md);
  // kNoLongStep when the step must be a fine one.
  double step_error(long m);
  void coarse_step(double t_next);
  void storey_pass(double h, const Eigen::MatrixXd& R, bool contacts);
  void add_energy(double h, double t_next);
  bool contact_free();
  // Results after a step.
  void record_sites(bool coarse, double h, double t_next);
  void record_peaks(bool coarse, double ag);

  const SearsRowProblem& p;
  const SearsRowModel& model;
  const BuildingRow& row;
  const AssembledRow a;
  RowContactLayout L;
  const SearsSteps st;
  const double dt, hc;  // fine and coarse step [s]
  const long steps;     // fine steps in the run
  long per_sample = 0;  // fine steps per record sample (0: the record spacing is not a multiple)
  const bool event;
  const int n, ns, nf;  // floor DOFs, contact sites, colliding floors

  // ops[m - 1]: steps of m fine steps through contacts; the modal banks' recurrence m - 1.
  std::vector<StepOperators> ops;
  const NewmarkOperator nm_coarse;  // coarse steps carry no contact force (event stepping)
  long longest = 1;                 // ops.size(): the longest step through contacts [fine steps]
  int level = 0;                    // ops[level]: the step being solved
  TranslationBound bound;

  // Yielding storeys (sears/newmark_storeys.hpp): a_i+1 = a_hat + R r_i+1 - H F, R = Mt^-1 B
  // for each step size; r iterated with the storeys' return maps.
  NewmarkStoreys storeys;
  Eigen::MatrixXd R_coarse;
  Eigen::VectorXd r_next, a_base, u_end;
  // Energy balance (p.track_energy): the work terms of each step, trapezoidal in the step's
  // end values, which Newmark's average-acceleration scheme balances exactly for linear storeys.
  Eigen::VectorXd u_prev, v_prev, cv;
  double e_input = 0.0, e_damping = 0.0, e_contact = 0.0;

  // Floor state [m], [m/s], [m/s^2]; contact forces [N] and overlaps [m] per site.
  Eigen::VectorXd u, v, acc, F, F_next, delta_pred, delta, u_hat, a_next, work2;
  SearsRowResult out;
  std::vector<bool> in_contact;
  std::vector<EndLoads> begin, end;
  std::vector<SectionValues> pred, disp, accel;
  std::vector<ModalBank::StepResult> fused;
  std::vector<int> pred_level;  // pred[k] holds predict(begin) of slab k by ops[pred_level - 1]
  // Longer steps through smooth contact forces (docs/speed.md): the forces at the start of the
  // previous step [N] and its length [s] (0: none since the start), the next step's multiple.
  Eigen::VectorXd F_prev;
  double h_prev = 0.0;
  long m_next = 1;
  std::vector<double> modal_bound;
  std::vector<double> site_approach;  // TranslationBound::approach per site, contact_free() [m]
  // Runs without contacts: each site's face approach and its rate at the last step's end, for
  // the peak approach between steps (SiteResult::peak_approach) [m], [m/s].
  std::vector<double> free_approach, free_approach_rate;
  bool modal_bound_valid = false;  // modal_bound holds since the last fine step

  // Sleeping slabs (event stepping, docs/speed.md): during a run of fine steps, a slab none of
  // whose sites carries a force at the start of the coarse interval is not stepped. Its faces
  // are known only to within free_bound of their values when it fell asleep (w0): a free mode
  // keeps R_n, so |w(t) - w0| <= face_motion_bound(hc) for the whole interval. A site with a
  // sleeping slab ("guarded") keeps F = 0 as long as the upper bound of its end-of-step overlap
  // stays negative; otherwise its sleeping slabs wake: they are brought to the step's start by
  // unloaded fine steps (the same recurrence the awake path applies) and the step's forces are
  // solved again with the site included. At the end of the interval a slab still asleep takes
  // one exact free step of hc.
  std::vector<char> asleep, guarded;
  std::vector<long> slept;  // fine steps skipped since the slab fell asleep
  std::vector<SectionValues> w0;
  std::vector<double> free_bound;
  int n_asleep = 0;
  const EndLoads no_load{};

  // Dormant slabs (event stepping, docs/speed.md): during a run of coarse steps a slab whose
  // free vibration can raise neither its peak accelerations nor an overlap is not stepped. A
  // free mode keeps R_n, so for all later free motion the faces stay within swing = 2 sum R_n
  // of their values when the slab went dormant (dw0), and the internal accelerations within
  // free_accel_bound(). A site with a dormant slab takes the upper bound of its overlap; the
  // slab wakes (ModalBank::advance_free over the skipped coarse steps) as soon as a bound does
  // not settle a question: the coarse-step test, a possible overlap, a possible new peak, or
  // a fine step.
  std::vector<char> dormant;
  std::vector<long> dormant_steps;
  std::vector<SectionValues> dw0;
  std::vector<double> swing, accel_bound;
  int n_dormant = 0;
  long coarse_in_run = 0;  // coarse steps since the last fine step
};

SearsRowSolver::SearsRowSolver(const SearsRowProblem& p_in, const SearsRowModel& model_in)
    : p(p_in),
      model(model_in),
      row(*p_in.row),
      a(assemble(row)),
      L(make_layout(row, a, model)),
      st(sears_row_steps(row, p.motion, model)),
      dt(st.fine_s),
      hc(st.coarse_s),
      steps(static_cast<long>(std::ceil(p.t_end / dt - 1e-9))),
      event(st.ratio > 1),
      n(a.dofs()),
      ns(static_cast<int>(a.sites.size())),
      nf(static_cast<int>(L.floors.size())),
      nm_coarse(a, Eigen::LLT<Eigen::MatrixXd>(newmark_matrix(a, hc))),
      bound(a, p.motion ? p.motion->pga() : 0.0),
      storeys(a, p.u0.size() ? p.u0 : Eigen::VectorXd::Zero(a.dofs())) {
  build_banks(L, row, model, dt);
  if (event)
    for (auto& b : L.banks) b.set_free_step(hc);
  Eigen::MatrixXd Dsites = Eigen::MatrixXd::Zero(n, ns);  // columns e_L - e_R
  for (int s = 0; s < ns; ++s) {
    Dsites(a.sites[s].dof_left, s) = 1.0;
    Dsites(a.sites[s].dof_right, s) = -1.0;
  }
  // A run without contacts at a row with contact sites never carries a force, so its steps
  // off the coarse grid (the end of the run) are fine ones: one length.
  longest = !p.contacts && ns > 0 ? 1 : st.longest;
  for (long m = 1; m <= longest; ++m) {
    const double h = m * dt;
    const Eigen::LLT<Eigen::MatrixXd> mt(newmark_matrix(a, h));
    if (m > 1)
      for (auto& b : L.banks) b.add_step(h);
    StepOperators o{h, NewmarkOperator(a, mt), mt.solve(Dsites), {}, {}};
    o.S = (0.25 * h * h) * Dsites.transpose() * o.H + modal_compliance(L, static_cast<int>(m - 1));
    if (!storeys.linear()) o.R = storeys.influence(mt);
    ops.push_back(std::move(o));
  }

  const Eigen::VectorXd m_ones = a.M * Eigen::VectorXd::Ones(n);
  u = p.u0.size() ? p.u0 : Eigen::VectorXd::Zero(n);
  v = p.v0.size() ? p.v0 : Eigen::VectorXd::Zero(n);
  if (storeys.linear()) {
    acc = a.M.ldlt().solve(-m_ones * ag_at(0.0) - a.C * v - a.K * u);
  } else {
    // f = K u - B r (sears/newmark_storeys.hpp).
    R_coarse = storeys.influence(Eigen::LLT<Eigen::MatrixXd>(newmark_matrix(a, hc)));
    Eigen::VectorXd Br = storeys.correction();
    for (int j = 0; j < n; ++j)
      if (a.storeys[j].below >= 0) Br(a.storeys[j].below) -= storeys.correction()(j);
    acc = a.M.ldlt().solve(-m_ones * ag_at(0.0) - a.C * v - a.K * u + Br);
    r_next = storeys.correction();
  }
  F = Eigen::VectorXd::Zero(ns);
  F_next = F;
  F_prev = F;
  delta_pred.resize(ns);
  delta.resize(ns);
  u_hat.resize(n);
  a_next.resize(n);
  work2.resize(2 * n);
  for (int s = 0; s < ns; ++s)
    delta(s) = u(a.sites[s].dof_left) - u(a.sites[s].dof_right) - a.sites[s].gap;
  out.dt_s = dt;
  out.coarse_dt_s = hc;
  RowResult& r = out.row;
  r.peak_disp = r.peak_drift = r.peak_abs_accel = Eigen::VectorXd::Zero(n);
  r.sites.assign(ns, SiteResult{});
  for (const auto& f : L.floors) out.slabs.push_back(SlabPeaks{f.building, f.floor, 0.0, 0.0});
  in_contact.assign(ns, false);
  out.contacts.assign(ns, SiteContacts{});
  for (int s = 0; s < ns; ++s) {
    in_contact[s] = delta(s) > 0.0;
    if (in_contact[s]) out.contacts[s].phases.push_back(ContactPhase{});  // open at t = 0
  }
  begin.resize(nf);
  end.resize(nf);
  pred.resize(nf);
  disp.resize(nf);
  accel.resize(nf);
  fused.resize(nf);
  pred_level.assign(nf, 0);
  modal_bound.assign(nf, 0.0);
  site_approach.assign(ns, 0.0);
  asleep.assign(nf, 0);
  guarded.assign(ns, 0);
  slept.assign(nf, 0);
  w0.resize(nf);
  free_bound.assign(nf, 0.0);
  dormant.assign(nf, 0);
  dormant_steps.assign(nf, 0);
  dw0.resize(nf);
  swing.assign(nf, 0.0);
  accel_bound.assign(nf, 0.0);
  free_approach.assign(ns, 0.0);
  free_approach_rate.assign(ns, 0.0);
  if (p.motion && p.motion->dt > 0.0) {
    const double x = p.motion->dt / dt;
    const long k = std::lround(x);
    if (k >= 1 && std::fabs(x - k) <= 1e-9 * x) per_sample = k;
  }
  for (int s = 0; s < ns && !p.contacts; ++s) {
    free_approach[s] = approach_bound(s);
    free_approach_rate[s] = v(a.sites[s].dof_left) - v(a.sites[s].dof_right);
    r.sites[s].peak_approach = free_approach[s];
  }
}

void SearsRowSolver::loads(const Eigen::VectorXd& f, std::vector<EndLoads>& to) const {
  for (int i = 0; i < nf; ++i) {
    to[i].left_N = L.floors[i].site_left >= 0 ? f(L.floors[i].site_left) : 0.0;
    to[i].right_N = L.floors[i].site_right >= 0 ? -f(L.floors[i].site_right) : 0.0;
  }
}

double SearsRowSolver::overlap_now(int s) const {
  return u(a.sites[s].dof_left) - u(a.sites[s].dof_right) + disp[L.site_left_floor[s]].right -
         disp[L.site_right_floor[s]].left - a.sites[s].gap;
}

void SearsRowSolver::update_guards() {
  for (int s = 0; s < ns; ++s)
    guarded[s] = asleep[L.site_left_floor[s]] || asleep[L.site_right_floor[s]];
}

void SearsRowSolver::wake(int k) {  // slab k to the start of the current step
  for (long j = 0; j < slept[k]; ++j) L.banks[k].step(no_load, no_load, fused[k]);
  if (slept[k] > 0) {
    disp[k] = fused[k].disp;
    accel[k] = fused[k].accel;
    pred[k] = fused[k].next_pred;
    pred_level[k] = 1;
  }
  asleep[k] = 0;
  slept[k] = 0;
  --n_asleep;
  ++out.counts.slab_wakes;
}

void SearsRowSolver::fall_asleep() {  // at a point of the coarse grid, before fine steps
  for (int k = 0; k < nf; ++k) {
    const int sl = L.floors[k].site_left, sr = L.floors[k].site_right;
    const bool free_slab = (sl < 0 || (F(sl) == 0.0 && !in_contact[sl])) &&
                           (sr < 0 || (F(sr) == 0.0 && !in_contact[sr]));
    if (!free_slab) continue;
    asleep[k] = 1;
    slept[k] = 0;
    w0[k] = disp[k];
    free_bound[k] = L.banks[k].face_motion_bound(hc);
    ++n_asleep;
    ++out.counts.slab_sleeps;
  }
  update_guards();
}

void SearsRowSolver::finish_sleep() {  // at the next point of the coarse grid
  for (int k = 0; k < nf; ++k) {
    if (!asleep[k]) continue;
    if (slept[k] == st.ratio) {
      L.banks[k].step_free(fused[k]);
    } else {
      for (long j = 0; j < slept[k]; ++j) L.banks[k].step(no_load, no_load, fused[k]);
    }
    disp[k] = fused[k].disp;
    accel[k] = fused[k].accel;
    pred_level[k] = 0;
    asleep[k] = 0;
    slept[k] = 0;
  }
  n_asleep = 0;
  update_guards();
}

// End-of-step overlaps without contact forces, delta_pred; for a guarded site an upper bound.
void SearsRowSolver::predict_overlaps() {
  for (int k = 0; k < nf; ++k)
    if (!asleep[k] && pred_level[k] != level + 1) {
      pred[k] = L.banks[k].predict(begin[k], level);
      pred_level[k] = level + 1;
    }
  for (int s = 0; s < ns; ++s) {
    const int kl = L.site_left_floor[s], kr = L.site_right_floor[s];
    const double wl = asleep[kl] ? w0[kl].right + free_bound[kl] : pred[kl].right;
    const double wr = asleep[kr] ? w0[kr].left - free_bound[kr] : pred[kr].left;
    delta_pred(s) =
        u_hat(a.sites[s].dof_left) - u_hat(a.sites[s].dof_right) + wl - wr - a.sites[s].gap;
  }
}

// True when every guarded site's end-of-step overlap bound is below zero (with a margin for
// round-off); otherwise wakes the sleeping slabs of the failing sites and returns false.
bool SearsRowSolver::guards_hold() {
  bool hold = true;
  for (int s = 0; s < ns; ++s) {
    if (!guarded[s]) continue;
    const int kl = L.site_left_floor[s], kr = L.site_right_floor[s];
    const double bound_end = delta_pred(s) - ops[level].S.row(s).dot(F_next);
    const double scale = std::fabs(u_hat(a.sites[s].dof_left)) +
                         std::fabs(u_hat(a.sites[s].dof_right)) + std::fabs(a.sites[s].gap) +
                         std::fabs(w0[kl].right) + std::fabs(w0[kr].left) + free_bound[kl] +
                         free_bound[kr];
    if (bound_end < -kGuardRoundOff * scale) continue;
    hold = false;
    if (asleep[kl]) wake(kl);
    if (asleep[kr]) wake(kr);
  }
  if (!hold) {
    update_guards();
    for (int s = 0; s < ns; ++s)
      if (!guarded[s]) delta(s) = overlap_now(s);  // exact again (was stale while guarded)
  }
  return hold;
}

void SearsRowSolver::wake_dormant(int k) {
  L.banks[k].advance_free(dormant_steps[k], fused[k]);
  disp[k] = fused[k].disp;
  accel[k] = fused[k].accel;
  pred_level[k] = 0;
  dormant[k] = 0;
  dormant_steps[k] = 0;
  --n_dormant;
  ++out.counts.dormant_wakes;
}

void SearsRowSolver::wake_all_dormant() {
  for (int k = 0; k < nf; ++k)
    if (dormant[k]) wake_dormant(k);
}

bool SearsRowSolver::site_dormant(int s) const {
  return dormant[L.site_left_floor[s]] || dormant[L.site_right_floor[s]];
}

// Approach of the faces now at site s (the overlap plus the gap); with a dormant slab, its
// upper bound.
double SearsRowSolver::approach_bound(int s) const {
  const int kl = L.site_left_floor[s], kr = L.site_right_floor[s];
  const double wl = dormant[kl] ? dw0[kl].right + swing[kl] : disp[kl].right;
  const double wr = dormant[kr] ? dw0[kr].left - swing[kr] : disp[kr].left;
  return u(a.sites[s].dof_left) - u(a.sites[s].dof_right) + wl - wr;
}

void SearsRowSolver::wake_site(int s) {  // both slabs of site s awake, delta(s) exact
  if (dormant[L.site_left_floor[s]]) wake_dormant(L.site_left_floor[s]);
  if (dormant[L.site_right_floor[s]]) wake_dormant(L.site_right_floor[s]);
  delta(s) = overlap_now(s);
}

// a_next = Mt^-1 (p_{i+1} - C (v + h/2 a) - K (u + h v + h^2/4 a)), without contact forces:
// one product of [Mt^-1 C, Mt^-1 K] with [v + h/2 a; u + h v + h^2/4 a].
void SearsRowSolver::newmark_predict(double h, const NewmarkOperator& op, double t_next) {
  for (int j = 0; j < n; ++j) {
    work2(j) = v(j) + (0.5 * h) * acc(j);
    work2(n + j) = u(j) + h * v(j) + (0.25 * h * h) * acc(j);
  }
  a_next = op.g * (-ag_at(t_next));
  a_next.noalias() -= op.CK * work2;
}

void SearsRowSolver::newmark_update(double h) {
  u += h * v + (0.25 * h * h) * (acc + a_next);
  v += (0.5 * h) * (acc + a_next);
  acc = a_next;
}

long SearsRowSolver::room(long i, const Eigen::VectorXd& f) const {
  bool cross = longest > 1 && n_asleep == 0 && per_sample > 0;
  for (int k = 0; k < nf && cross; ++k) {
    const int sl = L.floors[k].site_left, sr = L.floors[k].site_right;
    cross = (sl >= 0 && f(sl) > 0.0) || (sr >= 0 && f(sr) > 0.0);
  }
  const long r = cross ? per_sample - i % per_sample : st.ratio - i % st.ratio;
  return std::min(r, steps - i);
}

long SearsRowSolver::trial_multiple(long i, const Eigen::VectorXd& f) const {
  const long r = room(i, f);
  if (r <= m_next) return r;
  const long k = (r + m_next - 1) / m_next;  // steps to cover the room
  return (r + k - 1) / k;
}

// One step of Th. 8.8 made implicit in the contact forces (sears_simulation.hpp), of m fine
// steps: m = 1 unless the contact forces are smooth enough for a longer step (docs/speed.md,
// "Longer steps through smooth contact forces"). A longer step is solved first (nothing of the
// state changes but sleeping slabs woken to the step's start) and taken only if the forces'
// linear interpolation error over it stays within model.contact_step_tolerance; otherwise the
// step is solved again shorter.
long SearsRowSolver::fine_step(long i) {
  long m = trial_multiple(i, F);
  double worst = 0.0;
  loads(F, begin);
  for (;;) {
    level = static_cast<int>(m - 1);
    const StepOperators& o = ops[level];
    newmark_predict(o.h, o.nm, (i + m) * dt);
    if (storeys.linear()) {
      u_hat = u + o.h * v + (0.25 * o.h * o.h) * (acc + a_next);
      F_next.setZero();
      if (p.contacts && ns > 0) {
        F_next = F;  // warm start (zero at guarded sites)
        do {
          predict_overlaps();
          solve_forces(L.laws, o.S, delta_pred, guarded, F_next);
        } while (n_asleep > 0 && !guards_hold());
      }
    } else {
      storey_pass(o.h, o.R, true);
    }
    worst = step_error(m);
    if (m == 1 || worst <= 1.0) break;
    ++out.counts.long_step_rejections;
    // The error grows as h^2.
    m = std::max(1L, std::min(m - 1, static_cast<long>(m * kStepSafety / std::sqrt(worst))));
  }
  const StepOperators& o = ops[level];
  if (ns > 0) a_next.noalias() -= o.H * F_next;
  newmark_update(o.h);
  if (!storeys.linear()) storeys.commit();
  loads(F_next, end);
  // The next step's multiple (the error grows as h^2); the banks predict for it.
  m_next = worst > 0.0 ? static_cast<long>(m * kStepSafety / std::sqrt(worst)) : longest;
  m_next = std::clamp(m_next, 1L, longest);
  const long m_after = i + m < steps ? trial_multiple(i + m, F_next) : 1;
  for (int k = 0; k < nf; ++k) {
    if (asleep[k]) {
      slept[k] += m;
      continue;
    }
    L.banks[k].step(begin[k], end[k], fused[k], level, static_cast<int>(m_after - 1));
    disp[k] = fused[k].disp;
    accel[k] = fused[k].accel;
    pred[k] = fused[k].next_pred;
    pred_level[k] = static_cast<int>(m_after);
  }
  if (m > 1) ++out.counts.long_steps;
  F_prev = F;
  h_prev = o.h;
  return m;
}

double SearsRowSolver::step_error(long m) {
  const double tol = model.contact_step_tolerance;
  if (longest == 1 || !(tol > 0.0)) return 0.0;
  const double h = m * dt;
  double worst = 0.0;
  for (int s = 0; s < ns; ++s) {
    // A site whose two slabs sleep keeps F = 0 by their bound over the whole coarse interval.
    // A contact that starts or ends within the step, any other site without force (a contact
    // could start and end within a longer step unseen, as within a coarse step without its
    // bound; with one slab awake the guard is checked at the step's end only), or no previous
    // step: the fine step.
    if (asleep[L.site_left_floor[s]] && asleep[L.site_right_floor[s]]) continue;
    const double f0 = F(s), f1 = F_next(s), fm = F_prev(s);
    if (f0 == 0.0 || f1 == 0.0 || !(h_prev > 0.0)) return kNoLongStep;
    // F[t_i-1, t_i, t_i+1] = F''/2; a quadratic departs from its chord over h by F'' h^2 / 8.
    const double d2 = 2.0 * ((f1 - f0) / h - (f0 - fm) / h_prev) / (h + h_prev);
    worst = std::max(worst, std::fabs(d2) * h * h / (8.0 * tol * std::max(f0, f1)));
  }
  return worst;
}

// The step with yielding storeys: a_next = a_hat + R r_next (and - H F_next), r_next from the
// storeys' return maps at the end-of-step displacements, iterated to a fixed point; with
// `contacts` the contact forces are solved again in every pass (warm started).
void SearsRowSolver::storey_pass(double h, const Eigen::MatrixXd& R, bool contacts) {
  a_base = a_next;
  r_next = storeys.correction();
  F_next.setZero();
  if (contacts && p.contacts && ns > 0) F_next = F;  // warm start (zero at guarded sites)
  for (int pass = 0;; ++pass) {
    a_next = a_base;
    a_next.noalias() += R * r_next;
    u_hat = u + h * v + (0.25 * h * h) * (acc + a_next);
    if (contacts && p.contacts && ns > 0) {
      do {
        predict_overlaps();
        solve_forces(L.laws, ops[level].S, delta_pred, guarded, F_next);
      } while (n_asleep > 0 && !guards_hold());
      u_end = u_hat;
      u_end.noalias() -= (0.25 * h * h) * (ops[level].H * F_next);
    } else {
      u_end = u_hat;
    }
    if (storeys.trial(u, u_end, r_next)) return;
    ++out.counts.storey_iterations;
    if (pass == 50)
      throw NumericalError(
          "damped Sears model: the yielding storeys did not converge in 50 passes of a step");
  }
}

void SearsRowSolver::coarse_step(double t_next) {  // F = 0 at both ends
  newmark_predict(hc, nm_coarse, t_next);
  if (!storeys.linear()) storey_pass(hc, R_coarse, false);
  newmark_update(hc);
  if (!storeys.linear()) storeys.commit();
  F_next.setZero();
  loads(F_next, end);
  // Without contacts the modes are never loaded and stay at rest (zero displacement and
  // acceleration, as initialised): nothing to step.
  if (p.contacts)
    for (int k = 0; k < nf; ++k) {
      if (dormant[k]) {
        ++dormant_steps[k];
        ++out.counts.dormant_slab_steps;
        continue;
      }
      L.banks[k].step_free(fused[k]);
      disp[k] = fused[k].disp;
      accel[k] = fused[k].accel;
      pred_level[k] = 0;
    }
}

// True when no contact can start within the next coarse step (docs/speed.md): no force acts
// now, and at every site the bound on the faces' approach (building translation plus the
// internal vibration of both slabs), times kCoarseBoundSafety, stays below the gap.
bool SearsRowSolver::contact_free() {
  if (!p.contacts || ns == 0) return true;
  // A test that fails at a site with a dormant slab is repeated with the site's exact overlap.
  auto holds = [&](auto&& test) {
    for (int s = 0; s < ns; ++s) {
      if (test(s)) continue;
      if (!site_dormant(s)) return false;
      wake_site(s);
      if (!test(s)) return false;
    }
    return true;
  };
  if (!holds([&](int s) { return !in_contact[s] && F(s) == 0.0 && delta(s) < 0.0; })) return false;
  if (storeys.linear())
    bound.set_state(u, v);
  else
    bound.set_state(u, v, storeys.strain_by_building(u));
  // The building translation alone first (cheap); each site's bound is kept for the full test
  // below (waking a dormant slab changes the overlap, not the buildings' state).
  if (!holds([&](int s) {
        site_approach[s] = bound.approach(a.sites[s].dof_left, a.sites[s].dof_right, v, hc);
        return kCoarseBoundSafety * site_approach[s] < -delta(s);
      }))
    return false;
  // Free modes only lose energy, so the bound taken after the last fine step stays valid
  // through every following coarse step (dormant or not).
  if (!modal_bound_valid)
    for (int k = 0; k < nf; ++k) modal_bound[k] = L.banks[k].face_motion_bound(hc);
  modal_bound_valid = true;
  return holds([&](int s) {
    const double b =
        site_approach[s] + modal_bound[L.site_left_floor[s]] + modal_bound[L.site_right_floor[s]];
    return kCoarseBoundSafety * b < -delta(s);
  });
}

// Contact sites: events, peaks, impulse (force linear over the step).
void SearsRowSolver::record_sites(bool coarse, double h, double t_next) {
  RowResult& r = out.row;
  for (int s = 0; s < ns; ++s) {
    if (guarded[s]) continue;     // no force and no contact (shown by guards_hold)
    double d = overlap_bound(s);  // exact unless a slab is dormant
    if (site_dormant(s) && !(d < 0.0)) {
      wake_site(s);
      d = delta(s);
    }
    if (coarse && p.contacts && d > 0.0) ++out.counts.bound_violations;
    SiteResult& sr = r.sites[s];
    if (!p.contacts) {
      // Without contacts the modes stay at rest (coarse_step, fine_step with zero loads) and
      // the faces move with the floors: the approach is that of the floors, its peak between
      // the step's ends from their cubic Hermite interpolant (solver/hermite.hpp).
      const double ap = approach_bound(s);
      const double rate = v(a.sites[s].dof_left) - v(a.sites[s].dof_right);
      const Hermite c{free_approach[s], ap, h * free_approach_rate[s], h * rate};
      sr.peak_approach = std::max(sr.peak_approach, c.max_over_step());
      free_approach[s] = ap;
      free_approach_rate[s] = rate;
    }
    const double step_impulse = 0.5 * (F(s) + F_next(s)) * h;
    sr.impulse += step_impulse;
    sr.peak_force = std::max(sr.peak_force, F_next(s));
    sr.peak_penetration = std::max(sr.peak_penetration, d);
    const double t_cross = delta(s) != d ? t_next - h + h * delta(s) / (delta(s) - d) : t_next;
    std::vector<ContactPhase>& phases = out.contacts[s].phases;
    if (!in_contact[s] && d > 0.0) {
      in_contact[s] = true;
      ++sr.impacts;
      ++r.events;
      if (sr.first_contact < 0.0) sr.first_contact = t_cross;
      phases.push_back(ContactPhase{t_cross, -1.0, 0.0, 0.0});
    } else if (in_contact[s] && !(d > 0.0)) {
      in_contact[s] = false;
      ++r.events;
      sr.last_separation = t_cross;
      phases.back().end_s = t_cross;
      phases.back().impulse_Ns += step_impulse;  // the force falls to zero in this step
    }
    if (in_contact[s]) {
      phases.back().peak_force_N = std::max(phases.back().peak_force_N, F_next(s));
      phases.back().impulse_Ns += step_impulse;
    }
    delta(s) = d;
  }
  if (!coarse && ns > 0 && (F.cwiseAbs().maxCoeff() > 0.0 || F_next.cwiseAbs().maxCoeff() > 0.0))
    ++out.counts.fine_in_contact;
}

void SearsRowSolver::record_peaks(bool coarse, double ag) {
  RowResult& r = out.row;
  // Floor peaks (relative displacement, storey drift, absolute acceleration).
  for (std::size_t b = 0; b < row.buildings.size(); ++b)
    for (int j = 0; j < row.buildings[b].floors(); ++j) {
      const int k = a.offset[b] + j;
      r.peak_disp(k) = std::max(r.peak_disp(k), std::fabs(u(k)));
      r.peak_drift(k) = std::max(r.peak_drift(k), std::fabs(j ? u(k) - u(k - 1) : u(k)));
      r.peak_abs_accel(k) = std::max(r.peak_abs_accel(k), std::fabs(acc(k) + ag));
    }
  // Slab faces and centres: floor (rigid) + internal acceleration (Th. 7.5, 8.3).
  if (coarse) ++coarse_in_run;
  for (int k = 0; k < nf; ++k) {
    if (asleep[k]) continue;  // sampled again when it wakes or the interval ends
    const double a0 = acc(L.floors[k].dof) + ag;
    SlabPeaks& pk = out.slabs[k];
    const double lowest_peak = std::min(pk.face_accel, pk.centre_accel);
    if (dormant[k]) {
      if (std::fabs(a0) + accel_bound[k] <= lowest_peak) continue;  // no new peak possible
      wake_dormant(k);
    }
    const SectionValues& ai = accel[k];
    double face = 0.0;
    if (L.floors[k].site_left >= 0) face = std::max(face, std::fabs(a0 + ai.left));
    if (L.floors[k].site_right >= 0) face = std::max(face, std::fabs(a0 + ai.right));
    pk.face_accel = std::max(pk.face_accel, face);
    pk.centre_accel = std::max(pk.centre_accel, std::fabs(a0 + ai.centre));
    // After a coarse step (and every kDormancyRetry coarse steps of a run), an awake slab
    // whose free vibration cannot raise its peaks now goes dormant.
    if (coarse && p.contacts && model.sleeping_slabs && coarse_in_run % kDormancyRetry == 1) {
      accel_bound[k] = L.banks[k].free_accel_bound();
      if (std::fabs(a0) + accel_bound[k] <= std::min(pk.face_accel, pk.centre_accel)) {
        dormant[k] = 1;
        dormant_steps[k] = 0;
        dw0[k] = disp[k];
        swing[k] = 2.0 * L.banks[k].free_face_bound();
        ++n_dormant;
        ++out.counts.dormant_runs;
      }
    }
  }
}

SearsRowResult SearsRowSolver::run() {
  RowResult& r = out.row;
  long i = 0;
  while (i < steps) {
    const bool on_grid = event && i % st.ratio == 0 && i + st.ratio <= steps;
    const bool coarse = on_grid && contact_free();
    if (!coarse && n_dormant > 0) wake_all_dormant();
    if (!coarse) coarse_in_run = 0;
    if (on_grid && !coarse && p.contacts && model.sleeping_slabs) fall_asleep();
    if (p.track_energy) {
      u_prev = u;
      v_prev = v;
    }
    double h = hc;
    if (coarse) {
      i += st.ratio;
      coarse_step(i * dt);
      ++out.counts.coarse;
      m_next = 1;
      F_prev = F;
      h_prev = hc;
    } else {
      // A step through contacts (SearsRowSolver::room says how far it may reach).
      const long m = fine_step(i);
      i += m;
      h = m * dt;
      modal_bound_valid = false;
      ++out.counts.fine;
      if (n_asleep > 0 && i % st.ratio == 0) finish_sleep();
    }
    const double t_next = i * dt;
    if (!u.allFinite())
      throw NumericalError("damped Sears model: non-finite state at t = " + std::to_string(t_next) +
                           " s");
    const double ag = ag_at(t_next);
    if (p.track_energy) add_energy(h, t_next);
    record_sites(coarse, h, t_next);
    F = F_next;
    record_peaks(coarse, ag);
    if (p.record_history) {
      r.history.t.push_back(t_next);
      r.history.u.push_back(u);
      r.history.a_abs.push_back(acc + Eigen::VectorXd::Constant(n, ag));
      r.history.force.push_back(F);
      Eigen::VectorXd shear(n);
      for (int k = 0; k < n; ++k) shear(k) = storeys.shear(u, k);
      r.history.shear.push_back(shear);
    }
  }
  wake_all_dormant();
  for (auto& c : out.contacts) count_impacts(c, model.impact_force_fraction);
  r.u_end = u;
  r.v_end = v;
  r.t_end = steps * dt;
  r.steps = out.counts.fine + out.counts.coarse;
  r.hysteretic_energy.resize(n);
  for (int k = 0; k < n; ++k) r.hysteretic_energy(k) = storeys.dissipated(u, k);
  if (p.track_energy) {
    EnergyBalance& e = r.energy;
    e.input = e_input;
    e.damping = e_damping;
    e.contact = e_contact;
    e.kinetic = 0.5 * v.dot(a.M * v);
    e.strain = storeys.stored(u);
    e.hysteretic = r.hysteretic_energy.sum();
  }
  return std::move(out);
}

// The step's work terms (Newmark average acceleration: u_i+1 - u_i = h (v_i + v_i+1) / 2 and
// M (v_i+1 - v_i) = h (p - C v - f) averaged over the step's ends, so that the kinetic energy
// changes by exactly the work of the averaged forces on the displacement increment):
// input -du^T M 1 (ag_i + ag_i+1) / 2, damping h v_avg^T C v_avg, contact
// sum_s (F_i + F_i+1) / 2 (du_L - du_R).
void SearsRowSolver::add_energy(double h, double t_next) {
  const double ag_avg = 0.5 * (ag_at(t_next - h) + ag_at(t_next));
  double mdu = 0.0;
  for (int k = 0; k < n; ++k) mdu += a.M(k, k) * (u(k) - u_prev(k));
  e_input -= ag_avg * mdu;
  const Eigen::VectorXd v_avg = 0.5 * (v + v_prev);
  e_damping += h * v_avg.dot(a.C * v_avg);
  for (int k = 0; k < ns; ++k) {
    const int l = a.sites[k].dof_left, rr = a.sites[k].dof_right;
    e_contact += 0.5 * (F(k) + F_next(k)) * ((u(l) - u_prev(l)) - (u(rr) - u_prev(rr)));
  }
}

}  // namespace

SearsRowResult solve_sears_row(const SearsRowProblem& p, const SearsRowModel& model) {
  return SearsRowSolver(p, model).run();
}

}  // namespace pound::sears
