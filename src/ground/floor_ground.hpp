#pragma once
// The ground as the floors and contact sites of an assembled row meet it (issue 28): the channel
// under every floor DOF (its building's, ground/row_ground.hpp), the ground acceleration under
// every floor at an instant, and per contact site whether its two buildings stand on different
// channels, with their relative ground displacement and velocity. Both solvers use it; a site
// whose buildings share a channel has no relative ground motion, so that a row on uniform ground
// computes what it did before. Kernel only: no files, no printing.
#include <limits>
#include <utility>
#include <vector>

#include "ground/row_ground.hpp"
#include "structure/building_row.hpp"

namespace pound {

class FloorGround {
 public:
  /// For the row `a` on `ground` (null: no ground; it must have the row's buildings, kept by the
  /// caller).
  FloorGround(const AssembledRow& a, const RowGround* ground);

  const RowGround* ground() const { return ground_; }
  /// The ground's channels (0 without ground).
  int channels() const { return channels_; }
  /// The channel under floor DOF i; channels() for a floor on no ground (acceleration 0).
  int channel(int i) const { return dof_channel_[i]; }

  /// Each channel's acceleration at t [m/s^2], and 0 at index channels() (valid until the next
  /// call of either).
  const double* channel_acc(double t) {
    if (t != acc_t_) {  // (the solvers ask again at the same t: the same numbers)
      for (int c = 0; c < channels_; ++c) agc_[c] = ground_->trace(c).acc(t);
      acc_t_ = t;
    }
    return agc_.data();
  }
  /// The channels' accelerations of the last channel_acc() or acc() call [m/s^2] (the same
  /// numbers without evaluating the traces again, for a caller at the same t).
  const double* last_channel_acc() const { return agc_.data(); }
  /// The ground acceleration under every floor DOF at t [m/s^2].
  const double* acc(double t) {
    channel_acc(t);
    for (std::size_t i = 0; i < ag_.size(); ++i) ag_[i] = agc_[dof_channel_[i]];
    return ag_.data();
  }

  /// Whether contact site s joins buildings on different channels; their channels.
  bool differs(int s) const { return site_channels_[s].first != site_channels_[s].second; }
  const std::pair<int, int>& site_channels(int s) const { return site_channels_[s]; }
  /// The site's relative ground displacement ug_L - ug_R [m] and velocity vg_L - vg_R [m/s] at
  /// t [s] (0 where it does not differ).
  void relative(int s, double t, double& du, double& dv) const;
  /// relative() of every site at t into du[s], dv[s] (as many as sites), each channel that a
  /// differing site meets evaluated once (the same numbers: a row's sites mostly share a pair
  /// of channels), and not again where the last call had the same t.
  void relative_all(double t, double* du, double* dv);

 private:
  const RowGround* ground_ = nullptr;
  int channels_ = 0;
  std::vector<int> dof_channel_;
  std::vector<std::pair<int, int>> site_channels_;
  std::vector<double> agc_, ag_;
  std::vector<int> used_;        // the channels that differing sites meet
  std::vector<double> vg_, ug_;  // relative_all's channel velocities [m/s], displacements [m]
  // The t of agc_ and of vg_, ug_ [s] (NaN: none yet; the ground does not change in a run).
  double acc_t_ = std::numeric_limits<double>::quiet_NaN();
  double kin_t_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace pound
