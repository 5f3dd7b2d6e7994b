// Switching events of a run (solver/row_run.hpp): located by Illinois iteration on re-taken
// Dormand-Prince steps, then applied (docs/integration.md).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "solver/row_run.hpp"

namespace pound::detail {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

// The bracket of switch ev in the step of length hs from (t_, y_): from the step's ends, or, when
// the switch is back below zero at the end, from the interior point theta hs where the cubic
// crossed (false: the cubic overshot, no event). A switch across zero by round-off at the start
// but moving back is bracketed from its dip's deepest point.
bool RowRun::bracket_event(int ev, double theta, double hs, Bracket& br) {
  br = {0.0, switch_at(ev, y_, k1_).value, hs, switch_at(ev, y1_, k7_).value};
  if (br.fb <= 0.0) {
    // A switch rising and falling back inside the step: confirm the interior extremum.
    const double hc = theta * hs;
    step(t_, hc, y_, k1_, ytry_, etry_, ktry_);
    const double fc = switch_at(ev, ytry_, ktry_).value;
    if (!(fc > 0.0)) return false;  // false alarm: the cubic overshot
    br.b = hc;
    br.fb = fc;
  }
  if (br.fa >= 0.0 && switch_at(ev, y_, k1_).rate <= 0.0) {
    // At the step start the function is across zero by round-off (delta ~ 1e-19 m left by the
    // location of the previous event) but moving back: the event is the renewed crossing after
    // the dip, not one at t (which would switch off and on at one instant, over and over).
    // Bracket it from the dip's deepest point.
    const Hermite c = switches_.hermite(dyn_, ev, y_, y1_, k1_, k7_, hs);
    double st[2], deepest = 0.0, th_dip = -1.0;
    const int nst = c.stationary(st);
    for (int k = 0; k < nst; ++k)
      if (c.at(st[k]) < deepest) {
        deepest = c.at(st[k]);
        th_dip = st[k];
      }
    if (th_dip > 0.0 && th_dip * hs < br.b) {
      step(t_, th_dip * hs, y_, k1_, ytry_, etry_, ktry_);
      const double fd = switch_at(ev, ytry_, ktry_).value;
      if (fd < 0.0) {
        br.a = th_dip * hs;
        br.fa = fd;
      }
    }
  }
  return true;
}

// The step length to switch ev's crossing inside the bracket, with ytry_ (ktry_, etry_) the state
// there. The first try is `guess` (the interpolant's crossing); then Newton's step on the switch's
// rate at the last try when it falls inside the bracket, else Illinois (each try is a re-taken
// step). Newton stops for good once a try does not halve |f|: the rate is that of the motion, and
// a long re-taken step (through a contact) may not follow it closely enough.
double RowRun::refine_event(int ev, double guess, Bracket br) {
  // Storey switches land strictly across (a kink of the law must not be undone by round-off).
  const bool must_cross = ev >= ns_;
  double f_last = kNaN, hc = 0.0;
  bool newton = true;
  int side = 0;
  for (int it = 0; it < 100; ++it) {
    hc = guess;
    if (!(hc > br.a && hc < br.b)) hc = (br.a * br.fb - br.b * br.fa) / (br.fb - br.fa);
    if (!(hc > br.a && hc < br.b)) hc = 0.5 * (br.a + br.b);
    step(t_, hc, y_, k1_, ytry_, etry_, ktry_);
    const SwitchValue c = switch_at(ev, ytry_, ktry_);
    const double fc = c.value;
    // Newton aims at 0 (contacts) or half the tolerance across (storeys must cross).
    if (it > 0 && !(std::fabs(fc) <= 0.5 * f_last)) newton = false;
    f_last = std::fabs(fc);
    guess = newton && c.rate != 0.0 ? hc + ((must_cross ? 0.5e-15 : 0.0) - fc) / c.rate : kNaN;
    if (fc > 0.0) {
      br.b = hc;
      br.fb = fc;
      if (side == 1) br.fa *= 0.5;
      side = 1;
    } else {
      br.a = hc;
      br.fa = fc;
      if (side == -1) br.fb *= 0.5;
      side = -1;
    }
    // On the crossing to round-off, and moving across it: a grazing contact that opens at
    // delta ~ 1e-18 m has |delta| < 1e-15 m at its own start as well, where the faces still
    // approach; accepting that point as its end would close and reopen the contact at one
    // instant, over and over (found in a campaign: "impacts accumulate").
    if (std::fabs(fc) < 1e-15 && c.rate > 0.0 && (!must_cross || fc > 0.0)) return hc;
    if (br.b - br.a < 1e-13 * std::max(1.0, t_)) {
      // Bracket collapsed: land just across the crossing.
      if (fc <= 0.0) {
        hc = br.b;
        step(t_, hc, y_, k1_, ytry_, etry_, ktry_);
      }
      return hc;
    }
  }
  throw NumericalError("event location failed at t = " + std::to_string(t_));
}

// Locates switch ev in the step of length hs from (t_, y_) by Illinois iteration on re-taken
// steps (g(h') = the switching function after a step h'), advances to it and applies it.
RowRun::Located RowRun::locate(int ev, double theta, double hs, double en, bool trial_failed) {
  Bracket br;
  if (!bracket_event(ev, theta, hs, br)) return Located::none;
  // Already at or across the crossing at the step start: the event is at t.
  const double hc = br.fa >= 0.0 ? 0.0 : refine_event(ev, theta * hs, br);
  if (trial_failed) {
    // The step to the event replaces a rejected one: it must be re-taken (an event at t
    // itself rests on the rejected trial only), pass the error test, and its own (accurate)
    // interpolant must show no earlier event of another switch.
    if (!(hc > 0.0)) {
      reject(hs, en);
      return Located::retry;
    }
    const double enc = error_norm(y_, ytry_, etry_);
    if (!(enc <= 1.0)) {
      reject(hc, enc);
      return Located::retry;
    }
    double th2;
    const int ev2 = find_event(y_, ytry_, k1_, ktry_, hc, th2);
    if (ev2 >= 0 && ev2 != ev) {  // retry up to the earlier event
      retry(std::max(th2, 0.1) * hc);
      return Located::retry;
    }
  }
  if (hc > 0.0) {
    update_peaks(y_, ytry_, k1_, ktry_, hc);
    y_ = ytry_;
    t_ += hc;
    ++rec_.result().steps;
  }
  apply_event(ev, t_, y_);
  rhs(t_, y_, k1_);
  record(t_, y_, k1_);
  return Located::applied;
}

void RowRun::apply_event(int k, double t, Eigen::VectorXd& y) {
  ++rec_.result().events;
  if (k < ns_) {
    apply_contact_event(k, t, y);
    any_contact_ = true;
    return;
  }
  if (k >= switches_.first_crush()) {  // a crushing phase starts or ends
    switches_.apply_crush(dyn_, k, t, y);
    return;
  }
  switches_.apply_storey(dyn_, k, t, y);
  storey_changed(switches_.storey_dof(k));
  const int dof = switches_.storey_dof(k);
  rec_.check_failed_storey(dof, storeys_[dof], dyn_.storey[dof], t);
}

void RowRun::apply_contact_event(int i, double t, Eigen::VectorXd& y) {
  if (dyn_.active[i]) {
    if (dyn_.crushing[i]) {  // (not expected: the faces part only after unloading)
      dyn_.crush[i] = dyn_.indentation(y, i);
      dyn_.crushing[i] = 0;
    }
    dyn_.active[i] = false;
    rec_.contact_ended(i, t);
    return;
  }
  const double rate = dyn_.penetration_rate(y, i);
  const ContactLaw& law = *p_->laws[i];
  switches_.guard_chatter(i, t, [&] {
    const ContactSite& site = row_.sites[i];
    const SiteGeometry& g = site.geometry;
    std::string where = "pair " + std::to_string(site.pair + 1) + ", ";
    if (site.column())  // the striking slab and the struck storey, 1-based (issue 36)
      where += std::string(g.slab_side == 0 ? "left" : "right") + " building's floor " +
               std::to_string(g.slab_floor + 1) + " against the other's storey " +
               std::to_string(g.hit + 1) + " columns";
    else
      where += "floor " + std::to_string(g.slab_floor + 1) + " against floor " +
               std::to_string(g.hit + 1);
    return "contact site " + std::to_string(i + 1) + " (" + where + ")";
  });
  rec_.contact_started(i, t);
  if (!law.impulsive()) {
    dyn_.active[i] = true;
    dyn_.v0[i] = std::max(rate, 0.0);
    return;
  }
  // Stereomechanical impact (Goldsmith): velocity jump conserving momentum, separation
  // velocity e times the approach velocity.
  if (rate > 0.0) {
    // Along the site: the sides' apparent masses (a slab's is its floor mass), each DOF's
    // velocity changed by w_k J / m_k (J the impulse; SitePoint).
    const auto& s = row_.sites[i];
    const StateLayout& at = dyn_.layout();
    const double mL = s.mass_left, mR = s.mass_right;
    const double jump = (1.0 + law.restitution()) * rate;
    const double impulse = mL * mR / (mL + mR) * jump;
    const auto kinetic = [&] {
      double e = 0.0;
      for (const SitePoint* pt : {&s.left, &s.right})
        for (int k = 0; k < pt->count; ++k) {
          const int d = pt->dof[k];
          if (row_.inv_mass(d) != 0.0) e += 0.5 / row_.inv_mass(d) * std::pow(y(n_ + d), 2);
        }
      return e;
    };
    const double e_before = kinetic();
    for (int k = 0; k < s.left.count; ++k)
      y(n_ + s.left.dof[k]) -= s.left.weight[k] * impulse / (1.0 / row_.inv_mass(s.left.dof[k]));
    for (int k = 0; k < s.right.count; ++k)
      y(n_ + s.right.dof[k]) += s.right.weight[k] * impulse / (1.0 / row_.inv_mass(s.right.dof[k]));
    y(at.impulses + i) += impulse;
    if (track_)  // the kinetic energy the jump removes: mu v0^2 (1 - e^2) / 2
      y(at.energies + 2) += e_before - kinetic();
    rec_.result().sites[i].peak_force = kNaN;
  }
  rec_.contact_ended(i, t);
}

// A rejected step: the next try from t has length hn [s].
void RowRun::retry(double hn) {
  ++rec_.result().rejected;
  h_ = hn;
  if (h_ < 1e-14 * std::max(1.0, t_))
    throw NumericalError("step size underflow at t = " + std::to_string(t_) + " s");
}

// Rejected for its local error enf > 1, a step of length hf is retried shorter (elementary
// controller, HNW II.4 eq. 4.13, factor limited to [0.1, 0.9]).
void RowRun::reject(double hf, double enf) {
  if (!std::isfinite(enf)) enf = 1e10;
  retry(hf * std::max(0.1, 0.9 * std::pow(enf, -0.2)));
}

}  // namespace pound::detail
