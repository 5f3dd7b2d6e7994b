#include "solver/row_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "solver/dopri5.hpp"

namespace pound {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Cubic Hermite interpolant on theta in [0, 1] of a quantity with values g0, g1 and time
// derivatives d0, d1 over a step of length h.
struct Hermite {
  double g0, g1, m0, m1;  // m = h * derivative
  double at(double th) const {
    const double t2 = th * th, t3 = t2 * th;
    return (2 * t3 - 3 * t2 + 1) * g0 + (t3 - 2 * t2 + th) * m0 + (-2 * t3 + 3 * t2) * g1 +
           (t3 - t2) * m1;
  }
  // Interior stationary points in (0, 1): roots of the derivative (a quadratic).
  int stationary(double out[2]) const {
    const double a = 6 * g0 + 3 * m0 - 6 * g1 + 3 * m1;
    const double b = -6 * g0 - 4 * m0 + 6 * g1 - 2 * m1;
    const double c = m0;
    int n = 0;
    auto push = [&](double r) {
      if (r > 0.0 && r < 1.0) out[n++] = r;
    };
    if (std::fabs(a) < 1e-300) {
      if (std::fabs(b) > 1e-300) push(-c / b);
      return n;
    }
    const double disc = b * b - 4 * a * c;
    if (disc < 0) return 0;
    const double sq = std::sqrt(disc);
    const double q = -0.5 * (b + (b >= 0 ? sq : -sq));
    push(q / a);
    if (q != 0.0) push(c / q);
    if (n == 2 && out[0] > out[1]) std::swap(out[0], out[1]);
    return n;
  }
  double max_over_step() const {
    double s[2], m = std::max(g0, g1);
    const int n = stationary(s);
    for (int i = 0; i < n; ++i) m = std::max(m, at(s[i]));
    return m;
  }
  double min_over_step() const {
    double s[2], m = std::min(g0, g1);
    const int n = stationary(s);
    for (int i = 0; i < n; ++i) m = std::min(m, at(s[i]));
    return m;
  }
  double absmax_over_step() const {
    double s[2], m = std::max(std::fabs(g0), std::fabs(g1));
    const int n = stationary(s);
    for (int i = 0; i < n; ++i) m = std::max(m, std::fabs(at(s[i])));
    return m;
  }
  // Upper bound of |value| over the step: the basis functions of g0 and g1 are >= 0 and sum to
  // 1, those of m0 and m1, theta (1 - theta)^2 and theta^2 (theta - 1), are at most 4/27 in
  // magnitude. The factor 1 + 1e-12 covers the round-off of at().
  double absmax_bound() const {
    return (std::max(std::fabs(g0), std::fabs(g1)) + 4.0 / 27.0 * (std::fabs(m0) + std::fabs(m1))) *
           (1.0 + 1e-12);
  }
  // max(peak, absmax_over_step()), skipping the stationary points when the bound cannot
  // raise the peak.
  double raise_peak(double peak) const {
    return absmax_bound() <= peak ? peak : std::max(peak, absmax_over_step());
  }
};

class Solver {
 public:
  Solver(const RowProblem& p, const IntegratorSettings& s)
      : p_(p), s_(s), row_(*p.row), n_(row_.dofs()), ns_(static_cast<int>(row_.sites.size())) {
    pounding_ = !p.laws.empty();
    if (pounding_ && static_cast<int>(p.laws.size()) != ns_)
      throw std::logic_error("one contact law per site expected");
    active_.assign(ns_, false);
    v0_.assign(ns_, 0.0);
    below_.assign(n_, -1);
    for (std::size_t b = 0; b < row_.offset.size(); ++b) {
      const int o = row_.offset[b];
      const int end = b + 1 < row_.offset.size() ? row_.offset[b + 1] : n_;
      for (int i = o + 1; i < end; ++i) below_[i] = i - 1;
    }
    force_.setZero(ns_);
    work_.resize(2 * n_ + ns_);
    build_sparse_rows();
  }

  RowResult run();

 private:
  // Right-hand side: y = [u; v; J] with J the impulse per site (physics.md section 1):
  //   u' = v,  v' = -M^-1 (C v + K u) - 1 ag + M^-1 P,  J' = contact force per site.
  // M is diagonal; the products C v and K u use the bands or the compressed rows of
  // build_sparse_rows. Allocation-free.
  void rhs(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dy) {
    contact_forces(y);
    const double ag = p_.motion ? p_.motion->at(t) : 0.0;
    dy.resize(2 * n_ + ns_);
    const double* u = y.data();
    const double* v = u + n_;
    const double* im = row_.inv_mass.data();
    double* du = dy.data();
    double* dv = du + n_;
    for (int i = 0; i < n_; ++i) du[i] = v[i];
    if (tridiagonal_ && n_ > 1) {
      const double *kl = kl_.data(), *kd = kd_.data(), *ku = ku_.data();
      const double *cl = cl_.data(), *cd = cd_.data(), *cu = cu_.data();
      const int m = n_ - 1;
      dv[0] = -im[0] * (cd[0] * v[0] + cu[0] * v[1] + (kd[0] * u[0] + ku[0] * u[1])) - ag;
      for (int i = 1; i < m; ++i)
        dv[i] = -im[i] * (cl[i] * v[i - 1] + cd[i] * v[i] + cu[i] * v[i + 1] +
                          (kl[i] * u[i - 1] + kd[i] * u[i] + ku[i] * u[i + 1])) -
                ag;
      dv[m] = -im[m] * (cl[m] * v[m - 1] + cd[m] * v[m] + (kl[m] * u[m - 1] + kd[m] * u[m])) - ag;
    } else {
      for (int i = 0; i < n_; ++i) {
        double f = 0.0;
        for (int e = row_start_[i]; e < row_start_[i + 1]; ++e) {
          const int j = col_[e];
          f += c_val_[e] * v[j] + k_val_[e] * u[j];
        }
        dv[i] = -im[i] * f - ag;
      }
    }
    for (int i = 0; i < ns_; ++i) {
      const double f = force_(i);
      dv[n_ + i] = f;
      if (f == 0.0) continue;
      const auto& site = row_.sites[i];
      dv[site.dof_left] -= im[site.dof_left] * f;
      dv[site.dof_right] += im[site.dof_right] * f;
    }
  }

  // Storage of K and C for the products of rhs(). A shear building's K is tridiagonal
  // (Th. 3.6) and so is its Rayleigh damping C = a0 M + a1 K (Chopra 11.4.1); buildings do not
  // couple (block diagonal: the entries between one building's top floor and the next one's
  // first floor are zero). Then the three bands are kept (kl_(i) = K(i, i-1), kd_(i) = K(i, i),
  // ku_(i) = K(i, i+1), the same for C; zero outside the matrix). Otherwise (modal damping
  // gives a full C per building) compressed rows over the union of the nonzero patterns.
  // Either costs O(nonzeros) instead of O(n^2) and gives the dense products up to round-off.
  void build_sparse_rows() {
    tridiagonal_ = true;
    for (int i = 0; i < n_; ++i)
      for (int j = 0; j < n_; ++j)
        if (std::abs(i - j) > 1 && (row_.K(i, j) != 0.0 || row_.C(i, j) != 0.0))
          tridiagonal_ = false;
    auto band = [&](const Eigen::MatrixXd& A, int offset) {
      std::vector<double> b(n_, 0.0);
      for (int i = 0; i < n_; ++i)
        if (i + offset >= 0 && i + offset < n_) b[i] = A(i, i + offset);
      return b;
    };
    kl_ = band(row_.K, -1), kd_ = band(row_.K, 0), ku_ = band(row_.K, 1);
    cl_ = band(row_.C, -1), cd_ = band(row_.C, 0), cu_ = band(row_.C, 1);
    row_start_.assign(1, 0);
    for (int i = 0; i < n_; ++i) {
      for (int j = 0; j < n_; ++j) {
        if (row_.K(i, j) == 0.0 && row_.C(i, j) == 0.0) continue;
        col_.push_back(j);
        k_val_.push_back(row_.K(i, j));
        c_val_.push_back(row_.C(i, j));
      }
      row_start_.push_back(static_cast<int>(col_.size()));
    }
  }

  // Contact force per site [N] into force_ (zero where no contact is active).
  void contact_forces(const Eigen::VectorXd& y) {
    for (int i = 0; i < ns_; ++i) {
      double f = 0.0;
      if (active_[i]) {
        const auto& site = row_.sites[i];
        const double d = gap_function(y, i);
        const double dd = y(n_ + site.dof_left) - y(n_ + site.dof_right);
        f = p_.laws[i]->force(d, dd, v0_[i]);
      }
      force_(i) = f;
    }
  }

  double gap_function(const Eigen::VectorXd& y, int i) const {
    const auto& s = row_.sites[i];
    return y(s.dof_left) - y(s.dof_right) - s.gap;  // physics.md section 1: delta_j
  }
  double gap_rate(const Eigen::VectorXd& y, int i) const {
    const auto& s = row_.sites[i];
    return y(n_ + s.dof_left) - y(n_ + s.dof_right);
  }
  Hermite site_hermite(int i, const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                       double h) const {
    return {gap_function(y0, i), gap_function(y1, i), h * gap_rate(y0, i), h * gap_rate(y1, i)};
  }

  double error_norm(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                    const Eigen::VectorXd& err) const {
    double sum = 0.0;
    const int m = 2 * n_;
    for (int i = 0; i < m; ++i) {
      const double sc = s_.atol + s_.rtol * std::max(std::fabs(y0(i)), std::fabs(y1(i)));
      const double r = err(i) / sc;
      sum += r * r;
    }
    return std::sqrt(sum / m);
  }

  void step(double t, double h, const Eigen::VectorXd& y, const Eigen::VectorXd& k1,
            Eigen::VectorXd& y1, Eigen::VectorXd& err, Eigen::VectorXd& k7) {
    auto f = [this](double tt, const Eigen::VectorXd& yy, Eigen::VectorXd& dy) { rhs(tt, yy, dy); };
    dopri5_step(f, t, h, y, k1, y1, err, work_);
    k7 = work_.k7;
  }

  // Earliest event in the accepted step (t0, y0) -> (t0 + h, y1): the site and an estimate
  // of theta. Returns -1 when none.
  int find_event(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1, double h,
                 double& theta) const {
    int best = -1;
    theta = 2.0;
    for (int i = 0; i < ns_; ++i) {
      const Hermite c = site_hermite(i, y0, y1, h);
      bool ev;
      if (!active_[i]) {
        if (c.g0 > 0.0)  // across within the location tolerance: only a renewed approach counts
          ev = c.m0 > 0.0 || c.g1 > c.g0;
        else
          ev = c.g1 > 0.0 || (c.m0 > 0.0 && c.max_over_step() > 0.0);
      } else {
        ev = c.g1 < 0.0 || (c.m0 < 0.0 && c.min_over_step() < 0.0);
      }
      if (!ev) continue;
      // First sign change of the cubic, scanned then bisected.
      const double sign = active_[i] ? -1.0 : 1.0;
      double lo = 0.0, th = 1.0;
      const int nscan = 32;
      for (int k = 1; k <= nscan; ++k) {
        const double x = double(k) / nscan;
        if (sign * c.at(x) > 0.0) {
          th = x;
          break;
        }
        lo = x;
      }
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + th);
        if (sign * c.at(mid) > 0.0)
          th = mid;
        else
          lo = mid;
      }
      if (th < theta) {
        theta = th;
        best = i;
      }
    }
    return best;
  }

  void update_peaks(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1, double h,
                    const Eigen::VectorXd& dy1);
  void record(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& dy);
  void apply_event(int site, double t, Eigen::VectorXd& y);
  void check_finite(double t, const Eigen::VectorXd& y) const {
    if (!y.allFinite())
      throw NumericalError("non-finite state at t = " + std::to_string(t) +
                           " s (the response diverged; check stiffness, masses and step)");
  }

  const RowProblem& p_;
  const IntegratorSettings& s_;
  const AssembledRow& row_;
  const int n_, ns_;
  bool pounding_ = false;
  std::vector<char> active_;  // contact active per site
  std::vector<double> v0_;    // approach velocity at the start of the current contact [m/s]
  std::vector<int> below_;    // DOF of the floor below, -1 for a first floor
  std::vector<double> last_event_t_;
  std::vector<int> chatter_;
  Eigen::VectorXd force_;                            // contact force per site [N]
  bool tridiagonal_ = false;                         // K and C tridiagonal (build_sparse_rows)
  std::vector<double> kl_, kd_, ku_, cl_, cd_, cu_;  // their bands [N/m], [N s/m]
  std::vector<int> row_start_, col_;   // compressed rows of K and C (build_sparse_rows)
  std::vector<double> k_val_, c_val_;  // their entries [N/m], [N s/m]
  Dopri5Work work_;
  RowResult r_;
};

void Solver::record(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& dy) {
  // Absolute acceleration u'' + ag = M^-1 (P - C v - K u): dy already holds u'' = that - ag.
  const double ag = p_.motion ? p_.motion->at(t) : 0.0;
  for (int i = 0; i < n_; ++i) {
    const double a = dy(n_ + i) + ag;
    r_.peak_abs_accel(i) = std::max(r_.peak_abs_accel(i), std::fabs(a));
  }
  contact_forces(y);
  for (int i = 0; i < ns_; ++i) {
    auto& sr = r_.sites[i];
    if (active_[i]) sr.peak_force = std::max(sr.peak_force, force_(i));
  }
  if (p_.record_history) {
    r_.history.t.push_back(t);
    r_.history.u.push_back(y.head(n_));
    r_.history.a_abs.push_back(dy.segment(n_, n_).array() + ag);
    r_.history.force.push_back(force_);
  }
}

void Solver::update_peaks(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1, double h,
                          const Eigen::VectorXd& dy1) {
  (void)dy1;
  // Displacement and drift extrema inside the step from the cubic Hermite interpolant
  // (fourth-order accurate, like the integrator's own error).
  for (int i = 0; i < n_; ++i) {
    const Hermite c{y0(i), y1(i), h * y0(n_ + i), h * y1(n_ + i)};
    r_.peak_disp(i) = c.raise_peak(r_.peak_disp(i));
    const int b = below_[i];
    Hermite d = c;
    if (b >= 0) {
      d.g0 -= y0(b);
      d.g1 -= y1(b);
      d.m0 -= h * y0(n_ + b);
      d.m1 -= h * y1(n_ + b);
    }
    r_.peak_drift(i) = d.raise_peak(r_.peak_drift(i));
  }
  for (int i = 0; i < ns_; ++i) {
    if (!active_[i]) continue;
    const Hermite c = site_hermite(i, y0, y1, h);
    r_.sites[i].peak_penetration = std::max(r_.sites[i].peak_penetration, c.max_over_step());
  }
}

void Solver::apply_event(int i, double t, Eigen::VectorXd& y) {
  auto& sr = r_.sites[i];
  ++r_.events;
  if (!active_[i]) {
    const double rate = gap_rate(y, i);
    const ContactLaw& law = *p_.laws[i];
    // Chatter guard: instantaneous impacts piling up at one instant (Zeno behaviour).
    if (t - last_event_t_[i] < 1e-9) {
      if (++chatter_[i] > 1000)
        throw NumericalError("contact site " + std::to_string(i) + " (pair " +
                             std::to_string(row_.sites[i].pair + 1) + ", floor " +
                             std::to_string(row_.sites[i].level + 1) +
                             "): impacts accumulate at t = " + std::to_string(t) +
                             " s (chatter); use a force-based contact model");
    } else {
      chatter_[i] = 0;
    }
    last_event_t_[i] = t;
    if (sr.first_contact < 0) sr.first_contact = t;
    ++sr.impacts;
    if (law.impulsive()) {
      // Stereomechanical impact (Goldsmith): velocity jump conserving momentum, separation
      // velocity e times the approach velocity.
      if (rate > 0.0) {
        const auto& s = row_.sites[i];
        const double mL = 1.0 / row_.inv_mass(s.dof_left), mR = 1.0 / row_.inv_mass(s.dof_right);
        const double jump = (1.0 + law.restitution()) * rate;
        const double impulse = mL * mR / (mL + mR) * jump;
        y(n_ + s.dof_left) -= impulse / mL;
        y(n_ + s.dof_right) += impulse / mR;
        y(2 * n_ + i) += impulse;
        sr.peak_force = kNaN;
      }
      sr.last_separation = t;
    } else {
      active_[i] = true;
      v0_[i] = std::max(rate, 0.0);
    }
  } else {
    active_[i] = false;
    sr.last_separation = t;
  }
}

RowResult Solver::run() {
  const int N = 2 * n_ + ns_;
  r_.peak_disp.setZero(n_);
  r_.peak_drift.setZero(n_);
  r_.peak_abs_accel.setZero(n_);
  r_.sites.assign(ns_, SiteResult{});
  last_event_t_.assign(ns_, -1.0);
  chatter_.assign(ns_, 0);

  Eigen::VectorXd y = Eigen::VectorXd::Zero(N), y1(N), err(N), k1(N), k7(N), ytry(N), etry(N),
                  ktry(N);
  if (p_.u0.size()) y.head(n_) = p_.u0;
  if (p_.v0.size()) y.segment(n_, n_) = p_.v0;

  // Step limits.
  double tmin_period = std::numeric_limits<double>::infinity();
  for (const auto& per : row_.periods)
    for (int i = 0; i < per.size(); ++i)
      if (per(i) > 0) tmin_period = std::min(tmin_period, per(i));
  double h_max = s_.h_max > 0 ? s_.h_max : tmin_period / 20.0;
  const double rec_dt = p_.motion ? p_.motion->dt : 0.0;
  if (s_.h_max <= 0 && rec_dt > 0) h_max = std::min(h_max, rec_dt);
  if (!std::isfinite(h_max)) h_max = std::max(p_.t_end, 1e-6);
  const bool fixed = s_.control == StepControl::fixed;
  if (fixed && !(s_.dt > 0)) throw InputError("fixed-step integration needs dt > 0");
  double h = fixed ? s_.dt : std::min(h_max, 1e-4);

  double t = 0.0;
  // Contacts already closed at t = 0 (a negative gap or initial overlap) start at once.
  for (int i = 0; i < ns_ && pounding_; ++i)
    if (gap_function(y, i) > 0.0) apply_event(i, t, y);
  rhs(t, y, k1);
  record(t, y, k1);

  long grid = 0;  // fixed-step grid index
  long next_sample = 1;
  const double t_end = p_.t_end;
  bool any_contact = false;
  while (t < t_end * (1 - 1e-14)) {
    if (r_.steps + r_.rejected > s_.max_steps)
      throw NumericalError("more than " + std::to_string(s_.max_steps) +
                           " steps by t = " + std::to_string(t) + " s");
    // The step ends at the next record sample, grid point or the end.
    double t_stop = t_end;
    if (rec_dt > 0) {
      while (next_sample * rec_dt <= t * (1 + 1e-14) + 1e-15) ++next_sample;
      t_stop = std::min(t_stop, next_sample * rec_dt);
    }
    if (fixed) {
      while ((grid + 1) * s_.dt <= t * (1 + 1e-14) + 1e-15) ++grid;
      t_stop = std::min(t_stop, (grid + 1) * s_.dt);
    }
    double hs = fixed ? t_stop - t : std::min(h, t_stop - t);
    if (t + hs > t_stop * (1 - 1e-14)) hs = t_stop - t;
    step(t, hs, y, k1, y1, err, k7);
    double en = 0.0;
    // A rejected step: the next try from t has length hn [s].
    auto retry = [&](double hn) {
      ++r_.rejected;
      h = hn;
      if (h < 1e-14 * std::max(1.0, t))
        throw NumericalError("step size underflow at t = " + std::to_string(t) + " s");
    };
    // Rejected for its local error enf > 1, a step of length hf is retried shorter (elementary
    // controller, HNW II.4 eq. 4.13, factor limited to [0.1, 0.9]).
    auto reject = [&](double hf, double enf) {
      if (!std::isfinite(enf)) enf = 1e10;
      retry(hf * std::max(0.1, 0.9 * std::pow(enf, -0.2)));
    };
    bool trial_failed = false;
    if (!fixed) {
      en = error_norm(y, y1, err);
      trial_failed = !(en <= 1.0);
    }
    double theta;
    int ev = -1;
    if (trial_failed) {
      // A contact starting or ending inside the step puts a kink of the contact force (a jump
      // of its derivative) into it: there the error estimate falls only like h^2, not h^5, and
      // the controller would creep up on the event through many rejected steps. When the
      // trial's interpolant shows an event, it is located at once on re-taken steps (below),
      // which must then pass the error test; otherwise the step is rejected as usual.
      if (pounding_ && y1.allFinite()) ev = find_event(y, y1, hs, theta);
      if (ev < 0) {
        reject(hs, en);
        continue;
      }
    } else {
      check_finite(t + hs, y1);
      if (pounding_) ev = find_event(y, y1, hs, theta);
    }
    if (ev >= 0) {
      // Illinois iteration on the step length: g(h') = delta of site ev after a step h'.
      const double sign = active_[ev] ? -1.0 : 1.0;
      double a = 0.0, fa = sign * gap_function(y, ev);
      double b = hs, fb = sign * gap_function(y1, ev);
      double hc = theta * hs;
      bool found = false;
      int side = 0;
      if (fb <= 0.0) {
        // A contact opening and closing inside the step: confirm the interior extremum.
        step(t, hc, y, k1, ytry, etry, ktry);
        const double fc = sign * gap_function(ytry, ev);
        if (fc > 0.0) {
          b = hc;
          fb = fc;
        } else {
          b = -1.0;  // false alarm: the cubic overshot; accept the step as it is
        }
      }
      if (b > 0.0 && fa >= 0.0 && sign * gap_rate(y, ev) <= 0.0) {
        // At the step start the faces are across by round-off (delta ~ 1e-19 m left by the
        // location of the previous event) but moving back: the event is the renewed crossing
        // after the dip, not one at t (which would switch the contact off and on at one
        // instant, over and over). Bracket it from the dip's deepest point.
        const Hermite c = site_hermite(ev, y, y1, hs);
        double st[2], deepest = 0.0, th_dip = -1.0;
        const int nst = c.stationary(st);
        for (int k = 0; k < nst; ++k)
          if (sign * c.at(st[k]) < deepest) {
            deepest = sign * c.at(st[k]);
            th_dip = st[k];
          }
        if (th_dip > 0.0 && th_dip * hs < b) {
          step(t, th_dip * hs, y, k1, ytry, etry, ktry);
          const double fd = sign * gap_function(ytry, ev);
          if (fd < 0.0) {
            a = th_dip * hs;
            fa = fd;
          }
        }
      }
      if (b > 0.0) {
        if (fa >= 0.0) {  // already at or across the crossing at the step start: event at t
          hc = 0.0;
          found = true;
        }
        for (int it = 0; it < 100 && !found; ++it) {
          hc = (a * fb - b * fa) / (fb - fa);
          if (!(hc > a && hc < b)) hc = 0.5 * (a + b);
          step(t, hc, y, k1, ytry, etry, ktry);
          const double fc = sign * gap_function(ytry, ev);
          if (fc > 0.0) {
            b = hc;
            fb = fc;
            if (side == 1) fa *= 0.5;
            side = 1;
          } else {
            a = hc;
            fa = fc;
            if (side == -1) fb *= 0.5;
            side = -1;
          }
          // On the crossing to round-off, and moving across it: a grazing contact that opens
          // at delta ~ 1e-18 m has |delta| < 1e-15 m at its own start as well, where the faces
          // still approach; accepting that point as its end would close and reopen the contact
          // at one instant, over and over (found in a campaign: "impacts accumulate").
          if (std::fabs(fc) < 1e-15 && sign * gap_rate(ytry, ev) > 0.0) {
            found = true;
          } else if (b - a < 1e-13 * std::max(1.0, t)) {
            // Bracket collapsed: land just across the crossing.
            if (fc <= 0.0) {
              hc = b;
              step(t, hc, y, k1, ytry, etry, ktry);
            }
            found = true;
          }
        }
        if (!found)
          throw NumericalError("contact event location failed at t = " + std::to_string(t));
        if (trial_failed) {
          // The step to the event replaces a rejected one: it must be re-taken (an event at
          // t itself rests on the rejected trial only), pass the error test, and its own
          // (accurate) interpolant must show no earlier event of another site.
          if (!(hc > 0.0)) {
            reject(hs, en);
            continue;
          }
          const double enc = error_norm(y, ytry, etry);
          if (!(enc <= 1.0)) {
            reject(hc, enc);
            continue;
          }
          double th2;
          const int ev2 = find_event(y, ytry, hc, th2);
          if (ev2 >= 0 && ev2 != ev) {  // retry up to the earlier event
            retry(std::max(th2, 0.1) * hc);
            continue;
          }
        }
        if (hc > 0.0) {
          update_peaks(y, ytry, hc, ktry);
          y = ytry;
          t += hc;
          ++r_.steps;
        }
        apply_event(ev, t, y);
        any_contact = true;
        rhs(t, y, k1);
        record(t, y, k1);
        if (p_.stop_after_separation && any_contact) {
          bool all_open = true;
          for (int i = 0; i < ns_; ++i) all_open = all_open && !active_[i] && gap_rate(y, i) < 0.0;
          if (all_open) break;
        }
        continue;
      }
      if (trial_failed) {  // false alarm on a rejected trial
        reject(hs, en);
        continue;
      }
    }
    update_peaks(y, y1, hs, k7);
    y = y1;
    k1 = k7;
    t += hs;
    if (t_stop - t < 1e-14 * std::max(1.0, t)) t = t_stop;
    ++r_.steps;
    record(t, y, k1);
    if (!fixed) {
      const double fac = en > 0 ? std::min(5.0, std::max(0.2, 0.9 * std::pow(en, -0.2))) : 5.0;
      double hn = hs * fac;
      if (hs < h) hn = std::max(hn, h);  // the step was cut short by a sample or the end
      h = std::min(h_max, hn);
    }
  }
  r_.u_end = y.head(n_);
  r_.v_end = y.segment(n_, n_);
  r_.t_end = t;
  for (int i = 0; i < ns_; ++i) r_.sites[i].impulse = y(2 * n_ + i);
  return r_;
}

}  // namespace

RowResult solve(const RowProblem& p, const IntegratorSettings& s) {
  Solver solver(p, s);
  return solver.run();
}

}  // namespace pound
