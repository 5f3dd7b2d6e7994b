#include "hysteresis/imk.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

namespace pound {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Branch kinds (StoreyState::branch = side x kind; imk.hpp). The numbers are OpenSees'
// IMKPeakOriented branch numbers.
enum Kind : int {
  kElastic = 0,
  kUnload = 1,
  kToLocal = 3,
  kToGlobal = 4,
  kPostYield = 5,
  kPostCap = 6,
  kResidual = 7,
};
constexpr int kFailed = 100;  // no side: no shear for ever

// One loading direction, in its own sign (drifts and shears positive toward it).
struct Side {
  double fy;        // yield strength Fy [N]
  double kp;        // post-yield stiffness Kp [N/m]
  double d_cap;     // capping point: drift [m]
  double f_cap;     // and shear [N]
  double d_global;  // global peak: the largest drift reached toward this side [m]
  double f_global;  // its shear, on the backbone [N]
  double d_local;   // last reversal point: drift [m]
  double f_local;   // and shear [N]
  double yielded;   // 1 once the side yielded (OpenSees' posYield_Flag / negYield_Flag), else 0
};

// The law's history, kept in StoreyState::history (branch and d_anchor are StoreyState's). Its
// first members, the current line (Line), are all the frequent calls read.
struct Line {
  double v_anchor;  // shear at StoreyState::d_anchor on the current line [N]
  double slope;     // of the current line [N/m]
  double d_end;     // end of the branch toward its side (+ for the elastic branch) [m]
  double d_back;    // elastic and unloading branches: their other end [m]
  double work;      // work of the shear from rest to d_anchor [J]
  double ku;        // unloading stiffness Ku [N/m]; 0 only in a state never touched
};
struct History {
  Line line;           // first: line_of() reads it alone
  double e_excursion;  // E_h at the start of the current excursion [J]
  Side side[2];        // [0] positive, [1] negative direction
};
static_assert(sizeof(History) == sizeof(double) * StoreyState::kHistory,
              "StoreyState::history holds the IMK history exactly");
static_assert(std::is_standard_layout<History>::value && std::is_trivially_copyable<History>::value,
              "copied with memcpy, the line first");

// The current line of a state some IMK call has touched (Line::ku > 0).
Line line_of(const StoreyState& s) {
  Line l;
  std::memcpy(&l, s.history, sizeof l);
  return l;
}

// The storey's constants from its parameters (imk.hpp).
struct Constants {
  double k0;   // initial stiffness [N/m]
  double uy0;  // initial yield drift Fy / k0 [m]
  double fr;   // residual strength Fr [N]
  double kpc;  // post-capping stiffness magnitude Fc / (theta_pc h) [N/m]
  double e_t;  // reference energy E_t = lambda Fy uy [J]
  double d_u;  // ultimate drift theta_u h [m]
  double c;    // energy exponent [-]
};

Constants constants_of(const StoreyParameters& p) {
  Constants k;
  k.k0 = p.k0;
  k.uy0 = p.Fy / p.k0;
  k.fr = p.residual_strength_ratio * p.Fy;
  k.kpc = p.cap_strength_ratio * p.Fy / (p.post_cap_drift_ratio * p.h);
  k.e_t = p.energy_capacity * p.Fy * k.uy0;
  k.d_u = p.ultimate_drift_ratio * p.h;
  k.c = p.energy_exponent;
  return k;
}

// beta = (E_i / (E_t - E_h))^c (Ibarra et al. 2005, eq. 4), E_i clipped below at 0. Returns
// false when the storey fails: the energy spent (E_t - E_h <= 0) or beta above 1.
bool deterioration(const Constants& k, double e_i, double e_h, double& beta) {
  const double remaining = k.e_t - e_h;
  if (!(remaining > 0.0)) return false;
  const double r = std::max(e_i, 0.0) / remaining;
  beta = k.c == 1.0 ? r : std::pow(r, k.c);
  return beta <= 1.0;
}

// Whether a monotone path toward dir (+1, -1) that ends at drift d1 leaves the branch whose end
// toward dir is `end` [m]: d1 past the end, or at it when the end is the ultimate drift theta_u h
// (d_u [m], dir end >= d_u). Reaching theta_u h is failure, as OpenSees' IMKPeakOriented fails
// the storey at a drift Ui >= Uu (its July 2020 code: ui >= Uu_pos; its September 2023 code:
// dU > 0 && Ui >= posUu_0), not only past it.
bool leaves(double d1, double end, int dir, double d_u) {
  const double beyond = dir * (d1 - end);
  return beyond > 0.0 || (beyond == 0.0 && dir * end >= d_u);
}

// A storey's IMK state, unpacked from StoreyState, with the rules of imk.hpp as transitions.
// Drifts and shears are actual ones unless named "side" values (primed in the comments).
class Imk {
 public:
  Imk(const StoreyParameters& p, const StoreyState& s)
      : k_(constants_of(p)), branch_(s.branch), d_anchor_(s.d_anchor) {
    std::memcpy(&h_, s.history, sizeof h_);
    if (h_.line.ku == 0.0) start(p);  // a state at rest that no IMK call has touched
  }
  void save(StoreyState& s) const {
    s.branch = branch_;
    s.d_anchor = d_anchor_;
    std::memcpy(s.history, &h_, sizeof h_);
  }

  bool failed() const { return branch_ == kFailed; }
  int side() const { return branch_ > 0 ? 1 : -1; }
  // The direction a branch's d_end lies in: its side, + for the elastic branch.
  int travel() const { return branch_ >= 0 ? 1 : -1; }
  int kind() const { return branch_ < 0 ? -branch_ : branch_; }
  // Elastic and unloading branches: the storey moves either way between two drift ends.
  bool two_ended() const { return kind() == kElastic || kind() == kUnload; }
  const History& history() const { return h_; }

  double shear(double d) const {
    return failed() ? 0.0 : h_.line.v_anchor + h_.line.slope * (d - d_anchor_);
  }
  // Work of the shear from rest to d along the path taken [J] (closed form on the line).
  double work(double d) const {
    return failed() ? h_.line.work
                    : h_.line.work + 0.5 * (h_.line.v_anchor + shear(d)) * (d - d_anchor_);
  }
  double stored(double d) const {
    const double v = shear(d);
    return failed() ? 0.0 : v * v / (2.0 * h_.line.ku);
  }
  double dissipated(double d) const { return work(d) - stored(d); }

  // The storey passes the end of its branch in direction `dir` (+1, -1): the corner's rule.
  void cross(int dir) {
    if (kind() == kElastic) {  // first yield, toward dir (imk.hpp: branch 0)
      const double x = dir * k_.uy0;
      enter_backbone(dir, k_.uy0, x, work(x));
      return;
    }
    const int s = side();
    if (kind() == kUnload) {
      const double x = dir == s ? h_.line.d_end : h_.line.d_back;
      const double w = work(x);
      if (dir == s) {  // back at the reversal point: on toward the global peak
        after_local(s, x, w);
      } else if (-s * unload_zero() >= k_.d_u) {  // theta_u reached before the shear is zero
        fail(x, w);
      } else {  // the shear crosses zero: a new excursion toward -s
        excursion(-s, x, w);
      }
      return;
    }
    const double x = h_.line.d_end, w = work(x);
    if (natural_end() >= k_.d_u) {  // the drift reaches theta_u h (see leaves())
      fail(x, w);
      return;
    }
    if (kind() == kToLocal)
      after_local(s, x, w);
    else  // to global, post-yield, post-capping: the backbone beyond the corner
      enter_backbone(s, s * x, x, w);
  }

  // The drift rate reverses at d on a loading branch (3-7): unloading (imk.hpp).
  void reverse(double d) {
    const int s = side();
    const double v = shear(d), w = work(d), vs = s * v, ds = s * d;
    if (!(vs > 0.0)) {  // at the zero crossing itself: an excursion the other way
      excursion(-s, d, w);
      return;
    }
    Side& sd = at(s);
    sd.d_local = ds;
    sd.f_local = vs;
    if (ds > sd.d_global) {
      sd.d_global = ds;
      sd.f_global = vs;
    }
    // beta_K with the energies less the elastic energy still stored (Ku before reduction).
    const double e_h = w - v * v / (2.0 * h_.line.ku);
    double beta = 0.0;
    if (!deterioration(k_, e_h - h_.e_excursion, e_h, beta) || !(beta < 1.0)) {
      fail(d, w);
      return;
    }
    h_.line.ku *= 1.0 - beta;
    set_line(s * kUnload, d, v, h_.line.ku, w);
  }

  // The drift of the current branch's end toward dir, when it has one [m] (else +-inf).
  double end_toward(int dir) const {
    if (failed()) return dir * kInf;
    if (two_ended())
      return dir > 0 ? std::max(h_.line.d_end, h_.line.d_back)
                     : std::min(h_.line.d_end, h_.line.d_back);
    return dir == side() ? h_.line.d_end : dir * kInf;
  }

 private:
  Side& at(int s) { return h_.side[s > 0 ? 0 : 1]; }
  const Side& at(int s) const { return h_.side[s > 0 ? 0 : 1]; }

  // The initial state: elastic, both backbones as given (imk.hpp; OpenSees' revertToStart).
  void start(const StoreyParameters& p) {
    const double fc = p.cap_strength_ratio * p.Fy;
    Side sd;
    sd.fy = p.Fy;
    sd.kp = (fc - p.Fy) / (p.plastic_drift_ratio * p.h);
    sd.d_cap = k_.uy0 + p.plastic_drift_ratio * p.h;
    sd.f_cap = fc;
    sd.d_global = sd.d_local = k_.uy0;  // the yield point before any excursion there
    sd.f_global = sd.f_local = p.Fy;
    sd.yielded = 0.0;
    h_.side[0] = h_.side[1] = sd;
    h_.line.ku = k_.k0;
    h_.e_excursion = 0.0;
    branch_ = kElastic;
    d_anchor_ = 0.0;
    h_.line.v_anchor = 0.0;
    h_.line.slope = k_.k0;
    h_.line.work = 0.0;
    h_.line.d_end = k_.uy0;
    h_.line.d_back = -k_.uy0;
  }

  // Where the post-capping line of side sd reaches Fr [m, side drift].
  double residual_drift(const Side& sd) const { return sd.d_cap + (sd.f_cap - k_.fr) / k_.kpc; }
  // The zero-shear end of the unloading line u0 [m].
  double unload_zero() const {
    const Side& sd = at(side());
    return side() * (sd.d_local - sd.f_local / h_.line.ku);
  }
  // The natural end of a loading branch, before theta_u [m, side drift].
  double natural_end() const {
    const Side& sd = at(side());
    switch (kind()) {
      case kToLocal:
        return sd.d_local;
      case kToGlobal:
        return sd.d_global;
      case kPostYield:
        return sd.d_cap;
      case kPostCap:
        return residual_drift(sd);
      default:
        return kInf;  // residual
    }
  }

  // The current line: shear v at drift d with this slope, work w from rest to d; its ends.
  void set_line(int branch, double d, double v, double slope, double w) {
    branch_ = branch;
    d_anchor_ = d;
    h_.line.v_anchor = v;
    h_.line.slope = slope;
    h_.line.work = w;
    h_.line.d_end = h_.line.d_back = 0.0;
    if (failed()) return;
    const int s = side();
    if (kind() == kUnload) {
      h_.line.d_end = s * at(s).d_local;  // back at the reversal point
      h_.line.d_back = unload_zero();     // the shear crosses zero
      if (-s * h_.line.d_back > k_.d_u) h_.line.d_back = -s * k_.d_u;
    } else {
      h_.line.d_end = s * std::min(natural_end(), k_.d_u);
    }
  }

  void fail(double d, double w) { set_line(kFailed, d, 0.0, 0.0, w); }

  // Side s's backbone beyond its global peak (OpenSees' branches 5-7), entered at side drift
  // xs (actual drift x) with work w: post-yield, post-capping or residual by where xs lies.
  void enter_backbone(int s, double xs, double x, double w) {
    Side& sd = at(s);
    sd.yielded = 1.0;
    if (xs >= k_.d_u) return fail(x, w);
    const double uy = sd.fy / k_.k0;
    if (xs < sd.d_cap)
      return set_line(s * kPostYield, x, s * (sd.fy + sd.kp * (xs - uy)), sd.kp, w);
    if (xs < residual_drift(sd))
      return set_line(s * kPostCap, x, s * (sd.f_cap - k_.kpc * (xs - sd.d_cap)), -k_.kpc, w);
    if (k_.fr > 0.0) return set_line(s * kResidual, x, s * k_.fr, 0.0, w);
    fail(x, w);  // the backbone reached zero shear
  }

  // At the last reversal point L of side s (drift x): on toward the global peak G.
  void after_local(int s, double x, double w) {
    const Side& sd = at(s);
    if (sd.d_local < sd.d_global)
      set_line(s * kToGlobal, x, s * sd.f_local,
               (sd.f_global - sd.f_local) / (sd.d_global - sd.d_local), w);
    else
      enter_backbone(s, s * x, x, w);
  }

  // Side s's backbone at side drift xs (OpenSees' global-peak update).
  double backbone(const Side& sd, double xs) const {
    const double uy = sd.fy / k_.k0;
    if (xs < uy) return k_.k0 * xs;
    if (xs < sd.d_cap) return sd.fy + sd.kp * (xs - uy);
    return std::max(sd.f_cap - k_.kpc * (xs - sd.d_cap), k_.fr);
  }

  // A new excursion toward side n: the shear crosses zero at drift u0 with work w.
  void excursion(int n, double u0, double w) {
    const double e_h = w;  // no elastic energy stored at zero shear
    double beta = 0.0;
    if (!deterioration(k_, e_h - h_.e_excursion, e_h, beta)) return fail(u0, w);
    h_.e_excursion = e_h;
    Side& sd = at(n);
    if (sd.yielded != 0.0) {
      // Basic strength: Fy and Kp times (1 - beta), Fy not below Fr.
      sd.fy *= 1.0 - beta;
      sd.kp *= 1.0 - beta;
      if (sd.fy < k_.fr) {
        sd.fy = k_.fr;
        sd.kp = 0.0;
      }
      const double uy = sd.fy / k_.k0;
      // Post-capping: the line's zero-drift intercept times (1 - beta); the cap is where the
      // post-yield and post-capping lines meet.
      sd.d_cap =
          ((1.0 - beta) * (sd.f_cap + k_.kpc * sd.d_cap) - (sd.fy - sd.kp * uy)) / (sd.kp + k_.kpc);
      sd.f_cap = sd.fy + sd.kp * (sd.d_cap - uy);
      // Accelerated reloading: the global peak drift times (1 + beta), on the new backbone.
      sd.d_global *= 1.0 + beta;
      sd.f_global = backbone(sd, sd.d_global);
    }
    if (!(sd.f_global > 0.0)) return fail(u0, w);  // no strength left at the target
    const double x0 = n * u0;
    if (!(sd.d_global > x0)) return enter_backbone(n, x0, u0, w);  // G not ahead of u0
    const double k_global = sd.f_global / (sd.d_global - x0);
    // The last reversal point L first when it lies ahead of u0, below the global peak's shear
    // (strictly, as OpenSees' posFlocal < posFglobal: a tie, both on the residual plateau, aims
    // at G) and above the line from u0 to G (Klocal > Kglobal).
    if (x0 < sd.d_local && sd.f_local < sd.f_global && sd.f_local / (sd.d_local - x0) > k_global)
      set_line(n * kToLocal, u0, 0.0, sd.f_local / (sd.d_local - x0), w);
    else
      set_line(n * kToGlobal, u0, 0.0, k_global, w);
  }

  Constants k_;
  int branch_;
  double d_anchor_;
  History h_;
};

}  // namespace

// The frequent calls read the current line only (line_of); a state no IMK call has touched
// yet (all zero: the elastic branch from rest) goes through Imk, which starts it.

double ImkStorey::shear(const StoreyParameters& p, const StoreyState& s, double d,
                        const double*) const {
  if (s.branch == kFailed) return 0.0;
  const Line l = line_of(s);
  if (l.ku == 0.0) return Imk(p, s).shear(d);
  return l.v_anchor + l.slope * (d - s.d_anchor);
}

SwitchValue ImkStorey::switch_value(int i, const StoreyParameters& p, const StoreyState& s,
                                    double d, double dd, double ddd) const {
  if (s.branch == kFailed) return {};
  const Line l = line_of(s);
  if (l.ku == 0.0) {
    StoreyState started;
    Imk(p, s).save(started);
    return switch_value(i, p, started, d, dd, ddd);
  }
  const int kind = s.branch < 0 ? -s.branch : s.branch;
  const double side = s.branch >= 0 ? 1.0 : -1.0;  // + for the elastic branch
  if (kind == kElastic || kind == kUnload) {       // linear in the drift: the solver's interpolant
    if (i == 0) return {side * (d - l.d_end), side * dd};  // passing the end toward the side
    return {side * (l.d_back - d), -side * dd};            // passing the other end
  }
  if (i == 1) return {-side * dd, -side * ddd};  // the drift rate reverses: unloading
  if (!std::isfinite(l.d_end)) return {};
  return {side * (d - l.d_end), side * dd};  // the drift passes the branch's end
}

void ImkStorey::on_switch(int i, const StoreyParameters& p, StoreyState& s, double d,
                          const double*) const {
  Imk m(p, s);
  if (m.failed()) return;
  if (m.two_ended()) {
    m.cross(i == 0 ? m.travel() : -m.travel());
  } else if (i == 1) {
    m.reverse(d);
  } else {
    m.cross(m.side());
  }
  m.save(s);
}

bool ImkStorey::branch_line(const StoreyParameters& p, const StoreyState& s, double& slope,
                            double& offset) const {
  if (s.branch == kFailed) {
    slope = offset = 0.0;
    return true;
  }
  if (const Line l = line_of(s); l.ku != 0.0) {  // the current line (Imk::shear(0), no Imk)
    slope = l.slope;
    offset = l.v_anchor + l.slope * (0.0 - s.d_anchor);
    return true;
  }
  const Imk m(p, s);
  if (m.failed()) {
    slope = offset = 0.0;
  } else {
    slope = m.history().line.slope;
    offset = m.shear(0.0);
  }
  return true;
}

bool ImkStorey::safe_drift(const StoreyParameters& p, const StoreyState& s, double& lo,
                           double& hi) const {
  if (s.branch != kFailed) {
    if (const Line l = line_of(s); l.ku != 0.0) {  // the current line, no Imk
      const int kind = s.branch < 0 ? -s.branch : s.branch;
      if (kind != kElastic && kind != kUnload) return false;  // see below
      lo = std::min(l.d_end, l.d_back);
      hi = std::max(l.d_end, l.d_back);
      return true;
    }
  }
  const Imk m(p, s);
  if (m.failed()) {  // no switch ever: anywhere (finite, for the solver's round-off margin)
    lo = -1e30;
    hi = 1e30;
    return true;
  }
  if (!m.two_ended()) return false;  // the unloading switch acts on the drift rate
  lo = std::min(m.history().line.d_end, m.history().line.d_back);
  hi = std::max(m.history().line.d_end, m.history().line.d_back);
  return true;
}

double ImkStorey::dissipated(const StoreyParameters& p, const StoreyState& s, double d,
                             const double*) const {
  return Imk(p, s).dissipated(d);
}

double ImkStorey::stored(const StoreyParameters& p, const StoreyState& s, double d,
                         const double*) const {
  if (s.branch == kFailed) return 0.0;
  const Line l = line_of(s);
  if (l.ku == 0.0) return Imk(p, s).stored(d);
  const double v = l.v_anchor + l.slope * (d - s.d_anchor);
  return v * v / (2.0 * l.ku);
}

double ImkStorey::advance(const StoreyParameters& p, const StoreyState& committed, double d0,
                          double d1, StoreyState& trial) const {
  const int dir = d1 > d0 ? 1 : (d1 < d0 ? -1 : 0);
  if (committed.branch == kFailed || dir == 0) {
    trial = committed;
    return shear(p, committed, d1, nullptr);
  }
  const double d_u = p.ultimate_drift_ratio * p.h;
  const Line l = line_of(committed);
  if (l.ku != 0.0) {  // d1 on the current branch: nothing changes (most Newmark passes)
    const int kind = committed.branch < 0 ? -committed.branch : committed.branch;
    const int side = committed.branch >= 0 ? 1 : -1;
    const bool two_ended = kind == kElastic || kind == kUnload;
    const double end = !two_ended ? l.d_end : (dir == side ? l.d_end : l.d_back);
    if ((two_ended || dir == side) && !leaves(d1, end, dir, d_u)) {
      trial = committed;
      return l.v_anchor + l.slope * (d1 - committed.d_anchor);
    }
  }
  // Every corner between d0 and d1 in order; a loading branch met against the path's direction
  // reverses at d0 (OpenSees: the shear and the step of opposite signs).
  Imk m(p, committed);
  double d = d0;
  for (int corner = 0; !m.failed() && corner < 1000; ++corner) {
    if (!m.two_ended() && m.side() != dir) {
      m.reverse(d);
      continue;
    }
    const double end = m.end_toward(dir);
    if (!leaves(d1, end, dir, d_u)) break;  // d1 lies on the current branch
    m.cross(dir);
    d = end;
  }
  trial = committed;
  m.save(trial);
  return m.shear(d1);
}

bool ImkStorey::failed(const StoreyParameters&, const StoreyState& s) const {
  return s.branch == kFailed;
}

double ImkStorey::unloading_stiffness(const StoreyParameters& p, const StoreyState& s) {
  return Imk(p, s).history().line.ku;
}

}  // namespace pound
