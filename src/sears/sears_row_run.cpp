// One run of a damped Sears row (sears/sears_row_run.hpp): set-up, the run's loop, coarse steps,
// recording and the end.
#include "sears/sears_row_run.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "solver/hermite.hpp"

namespace pound::sears::detail {

RowContactLayout SearsRowRun::layout_for(const BuildingRow& row, const AssembledRow& a,
                                         const SearsRowModel& model, const SearsSteps& stepping) {
  RowContactLayout layout = make_layout(row, a, model);
  build_banks(layout, row, model, stepping.fine_s);
  if (stepping.ratio > 1)
    for (auto& b : layout.banks) b.set_free_step(stepping.coarse_s);
  return layout;
}

SearsRowRun::SearsRowRun(const SearsRowProblem& p_in, const SearsRowModel& model_in)
    : p(p_in),
      model(model_in),
      row(*p_in.row),
      assembled(assemble(row)),
      ground(assembled, p_in.ground),
      stepping(sears_row_steps(row, p_in.ground ? p_in.ground->dt() : 0.0, model)),
      dt(stepping.fine_s),
      hc(stepping.coarse_s),
      steps(static_cast<long>(std::ceil(p.t_end / dt - 1e-9))),
      event(stepping.ratio > 1),
      layout(layout_for(row, assembled, model, stepping)),
      n(assembled.dofs()),
      ns(static_cast<int>(assembled.sites.size())),
      nf(static_cast<int>(layout.floors.size())),
      nm_coarse(assembled, Eigen::LLT<Eigen::MatrixXd>(newmark_matrix(assembled, hc)), ground),
      bound(assembled, p_in.ground ? p_in.ground->pga() : 0.0),
      storeys(assembled, p.u0.size() ? p.u0 : Eigen::VectorXd::Zero(assembled.dofs())),
      u(floors.u),
      v(floors.v),
      acc(floors.acc),
      rec(assembled, assembled.storeys, p.contacts, p.record_history),
      slabs(layout.banks, out.counts) {
  slab_only =
      std::all_of(assembled.sites.begin(), assembled.sites.end(), [&](const ContactSite& s) {
        auto unit = [&](int d) {
          return assembled.influence.size() != n || assembled.influence(d) == 1.0;
        };
        return slab_site(s) && unit(s.dof_left) && unit(s.dof_right);
      });
  any_cap = std::any_of(layout.laws.begin(), layout.laws.end(),
                        [](const SlabContactLaw& l) { return !std::isinf(l.force_cap_N); });
  plain = slab_only && !any_cap;
  build_operators();
  initial_state();
  if (stepping.lumped > 0) {
    lumped_problem.row = &assembled;
    lumped_problem.ground = p.ground;
    lumped_problem.t_end = p.t_end;
    lumped_problem.record_history = p.record_history;
    lumped_problem.track_energy = p.track_energy;
    lumped_problem.collapse_drift_ratio = p.collapse_drift_ratio;
    lumped_settings = p.integrator;
    lumped_settings.control = StepControl::adaptive;
    lumped_settings.h_max = stepping.lumped_s();  // its grid is h_L
    lumped = std::make_unique<FreeStretches>(lumped_problem, lumped_settings);
    lumped_bound.assign(nf, 0.0);
    // Located stretches (sears_located.cpp) where the bound is not proved: the sites' points
    // on DOFs with mass (their accelerations enter the approach's quintic).
    located = !bound.valid();
    for (int s = 0; s < ns; ++s)
      for (const SitePoint* q : {&left_point(s), &right_point(s)})
        for (int k = 0; k < q->count; ++k)
          located = located && assembled.M(q->dof[k], q->dof[k]) > 0.0;
  }
}

// ops[m - 1] for steps of m = 1 .. longest fine steps through contacts (StepOperators).
void SearsRowRun::build_operators() {
  // Columns e_L - e_R: the sides' points, F w_k on each of their DOFs (a slab: its floor, 1; a
  // struck column point: its floors by the fixed-end reactions, docs/contact-geometry.md).
  Eigen::MatrixXd Dsites = Eigen::MatrixXd::Zero(n, ns);
  for (int s = 0; s < ns; ++s) {
    const SitePoint &l = left_point(s), &r = right_point(s);
    for (int k = 0; k < l.count; ++k) Dsites(l.dof[k], s) += l.weight[k];
    for (int k = 0; k < r.count; ++k) Dsites(r.dof[k], s) -= r.weight[k];
  }
  // A run without contacts at a row with contact sites never carries a force, so its steps
  // off the coarse grid (the end of the run) are fine ones: one length.
  longest = !p.contacts && ns > 0 ? 1 : stepping.longest;
  for (long m = 1; m <= longest; ++m) {
    const double h = m * dt;
    const Eigen::LLT<Eigen::MatrixXd> mt(newmark_matrix(assembled, h));
    if (m > 1)
      for (auto& b : layout.banks) b.add_step(h);
    StepOperators o{h, NewmarkOperator(assembled, mt, ground), mt.solve(Dsites), {}, {}};
    o.S = (0.25 * h * h) * Dsites.transpose() * o.H +
          modal_compliance(layout, static_cast<int>(m - 1));
    if (!storeys.linear()) o.R = storeys.influence(mt);
    ops.push_back(std::move(o));
  }
}

// M^-1 x for the diagonal mass matrix (a massless base DOF, a first-order DOF held by its
// dashpot, gets 0: Newmark's step matrix M + h/2 C + h^2/4 K stays regular without its mass).
Eigen::VectorXd SearsRowRun::solve_mass(const Eigen::VectorXd& x) const {
  Eigen::VectorXd a = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < n; ++i)
    if (assembled.M(i, i) > 0.0) a(i) = x(i) / assembled.M(i, i);
  return a;
}

void SearsRowRun::initial_state() {
  const AssembledRow& a = assembled;
  // M ag at t = 0 (the ground's acceleration under each floor).
  const Eigen::VectorXd m_ag = a.M * Eigen::Map<const Eigen::VectorXd>(ground.acc(0.0), n);
  u = p.u0.size() ? p.u0 : Eigen::VectorXd::Zero(n);
  v = p.v0.size() ? p.v0 : Eigen::VectorXd::Zero(n);
  if (storeys.linear()) {
    acc = solve_mass(-m_ag - a.C * v - a.K * u);
  } else {
    // f = K u - B r (sears/newmark_storeys.hpp).
    R_coarse = storeys.influence(Eigen::LLT<Eigen::MatrixXd>(newmark_matrix(a, hc)));
    const Eigen::VectorXd Br = storeys.forces(storeys.correction());
    acc = solve_mass(-m_ag - a.C * v - a.K * u + Br);
    r_next = storeys.correction();
  }
  F = Eigen::VectorXd::Zero(ns);
  F_next = F;
  F_prev = F;
  delta_pred.resize(ns);
  delta.resize(ns);
  u_hat.resize(n);
  a_next.resize(n);
  floors.work.resize(2 * n);
  for (auto* g : {&gd, &gv, &gd_next, &gv_next}) g->assign(ns, 0.0);
  ground_at(0.0, gd, gv);
  crush.assign(ns, 0.0);
  crush_phase.assign(ns, 0.0);
  gap_.resize(ns);
  for (int s = 0; s < ns; ++s) gap_[s] = a.sites[s].gap + crush[s];
  for (int s = 0; s < ns; ++s)
    delta(s) = left_point(s).of(u.data()) - right_point(s).of(u.data()) - gap(s) + gd[s];
  out.dt_s = dt;
  out.coarse_dt_s = hc;
  rec.set_collapse(a.storeys, p.collapse_drift_ratio);
  rec.start(u);
  if (std::isfinite(p.collapse_drift_ratio))
    for (const auto& st : a.storeys)
      failure_check = failure_check || (st.kg > 0.0 && !st.law->linear());
  for (const auto& f : layout.floors) out.slabs.push_back(SlabPeaks{f.building, f.floor, 0.0, 0.0});
  in_contact.assign(ns, false);
  out.contacts.assign(ns, SiteContacts{});
  for (int s = 0; s < ns; ++s) {
    in_contact[s] = delta(s) > 0.0;
    if (in_contact[s]) out.contacts[s].phases.push_back(ContactPhase{});  // open at t = 0
  }
  begin.resize(nf);
  end.resize(nf);
  modal_bound.assign(nf, 0.0);
  site_approach.assign(ns, 0.0);
  guarded.assign(ns, 0);
  free_approach.assign(ns, 0.0);
  free_approach_rate.assign(ns, 0.0);
  if (p.ground && p.ground->dt() > 0.0) {
    const double x = p.ground->dt() / dt;
    const long k = std::lround(x);
    if (k >= 1 && std::fabs(x - k) <= 1e-9 * x) per_sample = k;
  }
  for (int s = 0; s < ns && !p.contacts; ++s) {
    free_approach[s] = approach_bound(s);
    free_approach_rate[s] = left_point(s).of(v.data()) - right_point(s).of(v.data()) + gv[s];
  }
}

void SearsRowRun::loads(const Eigen::VectorXd& f, std::vector<EndLoads>& to) const {
  for (int i = 0; i < nf; ++i) {
    to[i].left_N = layout.floors[i].site_left >= 0 ? f(layout.floors[i].site_left) : 0.0;
    to[i].right_N = layout.floors[i].site_right >= 0 ? -f(layout.floors[i].site_right) : 0.0;
  }
}

void SearsRowRun::wake_site(int s) {
  const int l = left_slab(s), r = right_slab(s);
  if (l >= 0 && slabs.dormant(l)) slabs.wake_dormant(l);
  if (r >= 0 && slabs.dormant(r)) slabs.wake_dormant(r);
  delta(s) = overlap_now(s);
}

void SearsRowRun::coarse_step(double t_next) {  // F = 0 at both ends
  floors.predict(hc, nm_coarse, ag_at(t_next), a_next);
  hold_still(a_next);
  if (!storeys.linear()) storey_pass(hc, R_coarse, false);
  floors.update(hc, a_next);
  if (!storeys.linear()) storeys.commit();
  F_next.setZero();
  loads(F_next, end);
  // Without contacts the modes are never loaded and stay at rest (zero displacement and
  // acceleration, as initialised): nothing to step.
  if (p.contacts)
    for (int k = 0; k < nf; ++k) {
      if (slabs.dormant(k))
        slabs.skip_dormant(k);
      else
        slabs.step_free(k);
    }
}

// True when no contact can start within the next coarse step (docs/speed.md): no force acts
// now, and at every site the bound on the faces' approach (building translation plus the
// internal vibration of both slabs), times kCoarseBoundSafety, stays below the gap.
bool SearsRowRun::contact_free(double h) {
  if (!p.contacts || ns == 0) return true;
  if (!bound.valid()) return false;  // a massless base: located stretches (sears_located.cpp)
  return slab_only ? contact_free_of<true>(h) : contact_free_of<false>(h);
}

template <bool Slabs>
bool SearsRowRun::contact_free_of(double h) {
  // A test that fails at a site with a dormant slab is repeated with the site's exact overlap.
  auto holds = [&](auto&& test) {
    for (int s = 0; s < ns; ++s) {
      if (test(s)) continue;
      if (!site_dormant(s, Slabs)) return false;
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
        const ContactSite& site = assembled.sites[s];  // a slab site: its floors' DOFs
        site_approach[s] = Slabs ? bound.approach(site.dof_left, site.dof_right, v, gv[s], h)
                                 : bound.approach(left_point(s), right_point(s), v, gv[s], h);
        return kCoarseBoundSafety * site_approach[s] < -delta(s);
      }))
    return false;
  // Free modes only lose energy, so the bound taken after the last fine step stays valid
  // through every following coarse step (dormant or not); the lumped steps' longer horizon has
  // its own.
  const bool lumped_step = h != hc;
  std::vector<double>& mb = lumped_step ? lumped_bound : modal_bound;
  bool& valid = lumped_step ? lumped_bound_valid : modal_bound_valid;
  if (!valid) {
    for (int k = 0; k < nf; ++k) mb[k] = slabs.bank(k).face_motion_bound(h);
    valid = true;
  }
  return holds([&](int s) {
    const int l = left_slab(s), r = right_slab(s);
    const double b =
        site_approach[s] + (slab(Slabs, l) ? mb[l] : 0.0) + (slab(Slabs, r) ? mb[r] : 0.0);
    return kCoarseBoundSafety * b < -delta(s);
  });
}

template <bool Slabs>
__attribute__((always_inline)) inline void SearsRowRun::record_site(int s, bool coarse, double h,
                                                                    double t_next) {
  double d = overlap_bound(s, Slabs);  // exact unless a slab is dormant
  if (site_dormant(s, Slabs) && !(d < 0.0)) {
    wake_site(s);
    d = delta(s);
  }
  if (coarse && p.contacts && d > 0.0) ++out.counts.bound_violations;
  if (!p.contacts) {
    // Without contacts the modes stay at rest (coarse_step, fine_step with zero loads) and
    // the faces move with the floors: the approach is that of the floors, its peak between
    // the step's ends from their cubic Hermite interpolant (solver/hermite.hpp).
    const double ap = approach_bound(s, Slabs);
    const ContactSite& site = assembled.sites[s];
    const double rate = Slabs ? v(site.dof_left) - v(site.dof_right) + gv[s]
                              : left_point(s).of(v.data()) - right_point(s).of(v.data()) + gv[s];
    rec.approach_over_step(s, Hermite{free_approach[s], ap, h * free_approach_rate[s], h * rate});
    free_approach[s] = ap;
    free_approach_rate[s] = rate;
  }
  const double step_impulse = 0.5 * (F(s) + F_next(s)) * h;
  rec.impulse(s, step_impulse);
  rec.force(s, F_next(s));
  rec.penetration(s, d + (crush[s] - crush_phase[s]));  // 0 + 0 without a cap
  const double t_cross = delta(s) != d ? t_next - h + h * delta(s) / (delta(s) - d) : t_next;
  std::vector<ContactPhase>& phases = out.contacts[s].phases;
  if (!in_contact[s] && d > 0.0) {
    in_contact[s] = true;
    rec.contact_started(s, t_cross);
    ++rec.result().events;
    phases.push_back(ContactPhase{t_cross, -1.0, 0.0, 0.0});
  } else if (in_contact[s] && !(d > 0.0)) {
    in_contact[s] = false;
    ++rec.result().events;
    rec.contact_ended(s, t_cross);
    crush_phase[s] = crush[s];
    phases.back().end_s = t_cross;
    phases.back().impulse_Ns += step_impulse;  // the force falls to zero in this step
  }
  if (in_contact[s]) {
    phases.back().peak_force_N = std::max(phases.back().peak_force_N, F_next(s));
    phases.back().impulse_Ns += step_impulse;
  }
  delta(s) = d;
}

// Contact sites: events, peaks, impulse (force linear over the step).
void SearsRowRun::record_sites(bool coarse, double h, double t_next) {
  // Guarded sites: no force and no contact (shown by guards_hold). The slab-only path is
  // chosen once per run (slab_only).
  if (slab_only) {
    for (int s = 0; s < ns; ++s)
      if (!guarded[s]) record_site<true>(s, coarse, h, t_next);
  } else {
    for (int s = 0; s < ns; ++s)
      if (!guarded[s]) record_site<false>(s, coarse, h, t_next);
  }
  if (!coarse && ns > 0 && (F.cwiseAbs().maxCoeff() > 0.0 || F_next.cwiseAbs().maxCoeff() > 0.0))
    ++out.counts.fine_in_contact;
}

// Crushing faces (issue 36; docs/sears.md, "The force cap"): where a step ends with a site's
// force at PF_max and the law's own penetration past d_cap, the excess becomes permanent
// indentation: the site's gap widens by it (gap()), and its work PF_max dc leaves the contact's
// energy for the crushing's. Sites without force (guarded ones among them) do not crush.
void SearsRowRun::crush_faces() {
  for (int s = 0; s < ns; ++s) {
    if (guarded[s] || F_next(s) == 0.0) continue;
    const double dc = layout.laws[s].crush_increment(delta(s), F_next(s));
    if (!(dc > 0.0)) continue;
    crush[s] += dc;
    gap_[s] = assembled.sites[s].gap + crush[s];
    delta(s) -= dc;
    e_crushing += layout.laws[s].force_cap_N * dc;
  }
}

inline void SearsRowRun::record_slab(int k, bool coarse, const double* ag) {
  const double a0 = acc(layout.floors[k].dof) + ag[layout.floors[k].dof];
  SlabPeaks& pk = out.slabs[k];
  const double lowest_peak = std::min(pk.face_accel, pk.centre_accel);
  if (slabs.dormant(k)) {
    if (slabs.peaks_bounded(k, std::fabs(a0), lowest_peak)) return;  // no new peak possible
    slabs.wake_dormant(k);
  }
  const SectionValues& ai = slabs.accel(k);
  double face = 0.0;
  if (layout.floors[k].site_left >= 0) face = std::max(face, std::fabs(a0 + ai.left));
  if (layout.floors[k].site_right >= 0) face = std::max(face, std::fabs(a0 + ai.right));
  pk.face_accel = std::max(pk.face_accel, face);
  pk.centre_accel = std::max(pk.centre_accel, std::fabs(a0 + ai.centre));
  // After a coarse step (and every kDormancyRetry coarse steps of a run), an awake slab
  // whose free vibration cannot raise its peaks now goes dormant.
  if (coarse && p.contacts && model.sleeping_slabs && coarse_in_run % kDormancyRetry == 1)
    slabs.try_dormant(k, std::fabs(a0), std::min(pk.face_accel, pk.centre_accel));
}

void SearsRowRun::record_peaks(bool coarse, const double* ag, double t_next, double h) {
  // Floor peaks (relative displacement, storey drift, absolute acceleration).
  rec.sampled_peaks(u, acc.data(), ag, t_next, h);
  // Slab faces and centres: floor (rigid) + internal acceleration (Th. 7.5, 8.3).
  if (coarse) ++coarse_in_run;
  for (int k = 0; k < nf; ++k)
    if (!slabs.asleep(k)) record_slab(k, coarse, ag);  // asleep: sampled when it wakes
}

// Stretches without contact on the lumped solver's steps (issue 30; docs/speed.md): from the
// point i of the h_L grid, the floors go on FreeStretches one step of h_L at a time and the slabs
// by their exact free recurrence, for as long as the bound of contact_free() over h_L shows that
// no contact can start in the next one; the Newmark steps then go on from the state reached.
// Returns the fine step index reached.
long SearsRowRun::lumped_stretch(long i) {
  const long per = stepping.lumped * stepping.ratio;  // fine steps per lumped step
  const double hl = stepping.lumped_s();
  start_stretch(i);
  bool stop = false;
  do {
    i += per;
    const double t_next = i * dt;
    stop = lumped->advance_to(t_next, rec);
    ++out.counts.lumped;
    for (int k = 0; k < nf && p.contacts; ++k) slabs.step_free(k, stepping.lumped);
    leave_stretch();
    record_sites(true, hl, t_next);
    record_peaks(true, ground.acc(t_next), t_next, hl);
    if (failure_check) check_failures(t_next);
    stop = stop || (rec.take_new_collapses() > 0 && on_collapse());
  } while (!stop && i + per <= steps && contact_free(hl));
  if (stop) rec.result().stopped = true;
  return i;
}

// The Newmark path's state from where the lumped stretch is.
void SearsRowRun::leave_stretch() {
  const double t = lumped->time();
  current_t = t;
  lumped->state(u, v, acc);
  if (!storeys.linear()) {
    lumped->storeys(lumped_storeys);
    storeys.set_state(lumped_storeys, u, v);
    r_next = storeys.correction();
  }
  if (p.track_energy) {
    double e[3];
    lumped->energies(e);
    e_input = e[0];
    e_damping = e[1];
    e_contact = e[2];
  }
  ground_at(t, gd, gv);
  F.setZero();
  F_next.setZero();
  F_prev = F;
  m_next = 1;
  h_prev = 0.0;
  loads(F_next, end);
}

SearsRowResult SearsRowRun::run() {
  long i = 0;
  const long per_lumped = stepping.lumped * stepping.ratio;
  while (i < steps) {
    if (lumped && p.contacts && i % per_lumped == 0 && i + per_lumped <= steps) {
      if (contact_free(stepping.lumped_s())) {
        i = lumped_stretch(i);
        if (rec.result().stopped) break;
        continue;
      }
      // Without a proved bound: steps kept where their own motion shows no contact near.
      if (located && i >= located_retry && located_open()) {
        const long from = i;
        i = located_stretch(i);
        if (rec.result().stopped) break;
        if (i > from) continue;
      }
    }
    const bool on_grid = event && i % stepping.ratio == 0 && i + stepping.ratio <= steps;
    const bool coarse = on_grid && contact_free(hc);
    if (!coarse && slabs.dormant_count() > 0) slabs.wake_all_dormant();
    if (!coarse) coarse_in_run = 0;
    if (on_grid && !coarse && p.contacts && model.sleeping_slabs) fall_asleep();
    if (p.track_energy) {
      u_prev = u;
      v_prev = v;
    }
    double h = hc;
    const double t_start = i * dt;  // as the step's start was computed (ag there: see add_energy)
    if (coarse) {
      i += stepping.ratio;
      coarse_step(i * dt);
      ++out.counts.coarse;
      m_next = 1;
      F_prev = F;
      h_prev = hc;
    } else {
      // A step through contacts (SearsRowRun::room says how far it may reach).
      const long m = fine_step(i);
      i += m;
      h = m * dt;
      modal_bound_valid = lumped_bound_valid = false;
      ++out.counts.fine;
      if (slabs.asleep_count() > 0 && i % stepping.ratio == 0) finish_sleep();
    }
    const double t_next = i * dt;
    current_t = t_next;
    RunRecorder::check_finite(u, t_next, "damped Sears model");
    if (p.track_energy) add_energy(h, t_start, t_next);  // before the ground moves on to t_next
    ground_at(t_next, gd, gv);
    const double* ag = ground.acc(t_next);
    record_sites(coarse, h, t_next);
    F = F_next;    // (crush_faces reads F_next)
    if (!plain) {  // crushing faces, the struck columns' shear (issue 36)
      if (!coarse && any_cap) crush_faces();
      for (int s = 0; s < ns && !slab_only; ++s) {
        const ContactSite& site = assembled.sites[s];
        if (site.struck_dof >= 0)
          rec.column_shear(s, column_shear_demand(site, storeys.shear(u, site.struck_dof), F(s)));
      }
    }
    record_peaks(coarse, ag, t_next, h);
    if (failure_check) check_failures(t_next);
    if (rec.keeps_history()) {
      Eigen::VectorXd shear(n);
      for (int k = 0; k < n; ++k) shear(k) = storeys.shear(u, k);
      rec.history(t_next, u, acc, ag, F, shear);
    }
    if (rec.take_new_collapses() > 0 && on_collapse()) break;
  }
  finish();
  return std::move(out);
}

void SearsRowRun::check_failures(double t) {
  for (int i = 0; i < n; ++i)
    rec.check_failed_storey(i, assembled.storeys[i], storeys.committed(i), t);
}

bool SearsRowRun::on_collapse() {
  std::vector<int> hold;
  const bool stop = rec.apply_collapse_policy(
      p.track_energy, [this] { return energy_now(); }, hold);
  for (int i : hold) {
    held_dofs.push_back(i);
    v(i) = 0.0;
    acc(i) = 0.0;
  }
  return stop;
}

EnergyBalance SearsRowRun::energy_now() const {
  EnergyBalance e;
  e.input = e_input;
  e.damping = e_damping;
  e.contact = e_contact - e_crushing;  // the crushing work is the crushing's (issue 36)
  e.crushing = e_crushing;
  e.kinetic = 0.5 * v.dot(assembled.M * v);
  e.strain = storeys.stored(u);
  Eigen::VectorXd dissipated(n);
  for (int k = 0; k < n; ++k) dissipated(k) = storeys.dissipated(u, k);
  e.hysteretic = dissipated.sum();
  return e;
}

void SearsRowRun::finish() {
  slabs.wake_all_dormant();
  for (auto& c : out.contacts) count_impacts(c, model.impact_force_fraction);
  const bool stopped = rec.result().stopped;
  rec.finish(stopped ? current_t : steps * dt, u, v);
  RowResult& r = rec.result();
  r.steps += out.counts.fine + out.counts.coarse;  // and the lumped stretches' own
  r.hysteretic_energy.resize(n);
  for (int k = 0; k < n; ++k) r.hysteretic_energy(k) = storeys.dissipated(u, k);
  for (int s = 0; s < ns && s < static_cast<int>(r.sites.size()); ++s) r.sites[s].crush = crush[s];
  if (p.track_energy) r.energy = rec.final_energy(energy_now());
  out.row = std::move(r);
}

// The step's work terms (Newmark average acceleration: u_i+1 - u_i = h (v_i + v_i+1) / 2 and
// M (v_i+1 - v_i) = h (p - C v - f) averaged over the step's ends, so that the kinetic energy
// changes by exactly the work of the averaged forces on the displacement increment):
// input -du^T M 1 (ag_i + ag_i+1) / 2, damping h v_avg^T C v_avg, contact
// sum_s (F_i + F_i+1) / 2 (du_L - du_R), u_L and u_R the sites' points (SitePoint: the force
// loads their DOFs with w_k F, so its work is F times the points' displacement increments).
void SearsRowRun::add_energy(double h, double t_start, double t_next) {
  const AssembledRow& a = assembled;
  const int m = ground_inputs(ground);
  ag_avg_.resize(m);
  mdu_.assign(m + 1, 0.0);
  // ag at the step's start where the step took it: at a record's last sample t_next - h may
  // round past it, where the record's acceleration drops to 0 (GroundMotion::at).
  const double* ag0 = ag_at(t_start);
  for (int c = 0; c < m; ++c) ag_avg_[c] = ag0[c];
  const double* ag1 = ag_at(t_next);
  for (int c = 0; c < m; ++c) ag_avg_[c] = 0.5 * (ag_avg_[c] + ag1[c]);
  for (int k = 0; k < n; ++k)
    mdu_[std::min(ground.channel(k), m)] += a.M(k, k) * (u(k) - u_prev(k));
  for (int c = 0; c < m; ++c) e_input -= ag_avg_[c] * mdu_[c];
  // The ground's relative motion does work on the contacts (issue 28): input and contact.
  ground_at(t_next, gd_next, gv_next);
  for (int k = 0; k < ns; ++k)
    if (ground.differs(k)) e_input += 0.5 * (F(k) + F_next(k)) * (gd_next[k] - gd[k]);
  const Eigen::VectorXd v_avg = 0.5 * (v + v_prev);
  e_damping += h * v_avg.dot(a.C * v_avg);
  if (storeys.tangent_damping()) e_damping += storeys.damper_work(u_prev, u);
  for (int k = 0; k < ns; ++k) {
    const SitePoint &l = left_point(k), &r = right_point(k);
    e_contact += 0.5 * (F(k) + F_next(k)) *
                 ((l.of(u.data()) - l.of(u_prev.data())) - (r.of(u.data()) - r.of(u_prev.data())) +
                  (gd_next[k] - gd[k]));
  }
}

}  // namespace pound::sears::detail

namespace pound::sears {

SearsRowResult solve_sears_row(const SearsRowProblem& p, const SearsRowModel& model) {
  return detail::SearsRowRun(p, model).run();
}

}  // namespace pound::sears
