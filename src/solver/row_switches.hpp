#pragma once
// The switching events of a row (docs/integration.md): a switch is a function of the state that
// changes the equations where it rises through zero: a contact starting (delta) or ending
// (-delta), the kinks of a piecewise storey law (hysteresis/storey_law.hpp: yielding,
// unloading), and with a force cap a crushing phase starting (the law's force reaching the cap)
// or ending (the approach rate turning negative). Switches 0..ns-1 are the contact sites, then
// the storeys' switches, then (a capped pounding run only) one crushing switch per site. This
// finds the
// earliest switch in a step from the cubic Hermite interpolant of each switching function,
// applies a storey's switch, and guards against switches piling up at one instant. Kernel only.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "solver/hermite.hpp"
#include "solver/row_dynamics.hpp"

namespace pound {

class RowSwitches {
 public:
  RowSwitches(const AssembledRow& row, const std::vector<RowStorey>& storeys);

  int sites() const { return ns_; }
  int storey_switches() const { return static_cast<int>(sw_.size()); }
  bool any(const RowDynamics& dyn) const { return dyn.pounding() || !sw_.empty(); }

  /// Switch k at state y with derivative dy (it happens where the value rises through 0).
  SwitchValue value(const RowDynamics& dyn, int k, const Eigen::VectorXd& y,
                    const Eigen::VectorXd& dy) const {
    if (k < ns_) {
      const double sign = dyn.active[k] ? -1.0 : 1.0;
      return {sign * dyn.penetration(y, k), sign * dyn.penetration_rate(y, k)};
    }
    if (k >= first_crush()) return crush_value(dyn, k - first_crush(), y, dy);
    return storey_value(dyn, k, y, dy);
  }
  /// The id of site 0's crushing switch (site i's: first_crush() + i).
  int first_crush() const { return ns_ + static_cast<int>(sw_.size()); }
  /// Applies crushing switch k (k >= first_crush()) at state y: a crushing phase starts (the
  /// law's own penetration is held) or ends (the indentation grown in it is committed).
  void apply_crush(RowDynamics& dyn, int k, double t, const Eigen::VectorXd& y);
  /// Its cubic Hermite interpolant over a step of length h [s].
  Hermite hermite(const RowDynamics& dyn, int k, const Eigen::VectorXd& y0,
                  const Eigen::VectorXd& y1, const Eigen::VectorXd& dy0, const Eigen::VectorXd& dy1,
                  double h) const {
    const SwitchValue a = value(dyn, k, y0, dy0), b = value(dyn, k, y1, dy1);
    return {a.value, b.value, h * a.rate, h * b.rate};
  }
  /// Earliest switch in the step y0 -> y1 of length h [s]: its id and an estimate of the
  /// fraction theta of the step where it happens; -1 when none.
  /// `ignore` (null: none): per switch id, 1 where a switch is not to be reported (a crushing
  /// switch whose crossing proved a false alarm in this step).
  int find_event(const RowDynamics& dyn, const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                 const Eigen::VectorXd& dy0, const Eigen::VectorXd& dy1, double h, double& theta,
                 const std::vector<char>* ignore = nullptr) const;

  /// Applies storey switch k (k >= sites()) at state y: the law's new branch (the caller then
  /// updates what depends on it: RowRun::storey_changed); a chatter error names the storey.
  void apply_storey(RowDynamics& dyn, int k, double t, const Eigen::VectorXd& y);
  /// After storey `dof` changed branch: the drift interval in which its switches cannot fire.
  void storey_changed(int dof, const StoreyState& s);
  /// Throws when switch k piles up events at time t [s] (Zeno behaviour); what() names it
  /// (called then only).
  template <class What>
  void guard_chatter(int k, double t, What what) {
    if (t - last_event_t_[k] < 1e-9) {
      if (++chatter_[k] > 1000) throw_chatter(k, t, what());
    } else {
      chatter_[k] = 0;
    }
    last_event_t_[k] = t;
  }
  /// Forgets the instants of past events (a new run).
  void reset();
  /// The storey switch k's floor DOF.
  int storey_dof(int k) const { return sw_[k - ns_].dof; }

 private:
  struct StoreySwitch {
    int dof = 0;    // the storey below this floor DOF
    int local = 0;  // the law's switch index
  };
  SwitchValue storey_value(const RowDynamics& dyn, int k, const Eigen::VectorXd& y,
                           const Eigen::VectorXd& dy) const;
  SwitchValue crush_value(const RowDynamics& dyn, int i, const Eigen::VectorXd& y,
                          const Eigen::VectorXd& dy) const;
  // The bracket of the first sign change of the cubic c in [0, 1] (c is positive at its end or
  // inside): a scan then bisection; the upper end.
  static double first_crossing(const Hermite& c);
  [[noreturn]] void throw_chatter(int k, double t, const std::string& what) const;

  const AssembledRow& row_;
  const std::vector<RowStorey>& storeys_;
  const int ns_;
  std::vector<StoreySwitch> sw_;      // storey switches (ids ns_, ns_ + 1, ...)
  std::vector<double> last_event_t_;  // per switch id [s]
  std::vector<int> chatter_;          // per switch id
  // Per storey the drift interval in which its switches cannot fire [m].
  std::vector<char> has_safe_;
  std::vector<double> safe_lo_, safe_hi_;
};

}  // namespace pound
