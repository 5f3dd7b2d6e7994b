#pragma once
// The ground under every building of a row (issue 28): one GroundTrace per distinct motion (a
// channel) and, per building, the channel it stands on. Buildings on the same motion share a
// channel, so a row on uniform ground has one channel, and the solvers do for it exactly what
// they did before the ground became per building. Every channel has the same sample spacing and
// starts at t = 0 (a delayed motion begins with its leading zeros, ground/wave_passage.hpp), so
// the solvers' steps end on one grid that holds every channel's samples. Kernel only.
#include <vector>

#include "ground/ground_trace.hpp"
#include "motion/ground_motion.hpp"

namespace pound {

class RowGround {
 public:
  RowGround() = default;
  /// One motion under every one of `buildings` buildings (one channel).
  static RowGround uniform(const GroundMotion& motion, int buildings);
  /// Building b on motions[b]; motions equal bit for bit (spacing and values) share a channel.
  /// Throws std::invalid_argument when the spacings differ (the study readers refuse that first).
  static RowGround per_building(const std::vector<GroundMotion>& motions);

  int buildings() const { return static_cast<int>(channel_of_.size()); }
  int channels() const { return static_cast<int>(traces_.size()); }
  /// The channel building b (0-based) stands on.
  int channel(int building) const { return channel_of_[building]; }
  const GroundTrace& trace(int channel) const { return traces_[channel]; }
  const GroundTrace& under(int building) const { return traces_[channel_of_[building]]; }
  /// The common sample spacing [s].
  double dt() const { return traces_.empty() ? 0.0 : traces_.front().dt(); }
  /// The last sample of the longest channel [s]: the runs last until then plus extra_time.
  double duration() const;
  /// The largest |ag| of any channel [m/s^2].
  double pga() const;
  /// Every channel's motion times `factor` [-] (a campaign's stripe scales the whole ground).
  RowGround scaled(double factor) const;

  /// The largest |ug_a(t) - ug_b(t)| over 0 <= t <= t_end [s] of buildings a and b [m]: the
  /// relative ground displacement that the pair's gap must also take up (exact: each sample
  /// interval's difference is a cubic, its extrema found from its quadratic rate; linear after
  /// the records). 0 when they stand on the same channel.
  double peak_relative_displacement(int a, int b, double t_end) const;

 private:
  std::vector<GroundTrace> traces_;
  std::vector<int> channel_of_;
};

}  // namespace pound
