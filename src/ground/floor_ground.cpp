#include "ground/floor_ground.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace pound {

FloorGround::FloorGround(const AssembledRow& a, const RowGround* ground) : ground_(ground) {
  const int n = a.dofs(), nb = static_cast<int>(a.offset.size());
  channels_ = ground_ ? ground_->channels() : 0;
  if (ground_ && ground_->buildings() != nb)
    throw std::logic_error("the ground has " + std::to_string(ground_->buildings()) +
                           " buildings, the row " + std::to_string(nb));
  agc_.assign(channels_ + 1, 0.0);  // agc_[channels_] stays 0: floors on no ground
  ag_.assign(n, 0.0);
  dof_channel_.assign(n, channels_);
  const int floors = a.floors > 0 ? a.floors : n;  // (a row built by hand has floors only)
  for (int b = 0; b < nb && ground_; ++b) {
    const int end = b + 1 < nb ? a.offset[b + 1] : floors;
    for (int i = a.offset[b]; i < end; ++i) dof_channel_[i] = ground_->channel(b);
  }
  // A flexible foundation's sway moves with its building's ground; its rotation takes none
  // (AssembledRow::influence).
  for (int i = floors; i < n && ground_; ++i)
    if (a.influence.size() == n && a.influence(i) != 0.0)
      dof_channel_[i] = ground_->channel(a.building_of[i]);
  for (const auto& s : a.sites)
    site_channels_.emplace_back(dof_channel_[s.dof_left], dof_channel_[s.dof_right]);
  for (const auto& [l, r] : site_channels_)
    if (l != r)
      for (const int c : {l, r})
        if (std::find(used_.begin(), used_.end(), c) == used_.end()) used_.push_back(c);
  vg_.assign(channels_ + 1, 0.0);
  ug_.assign(channels_ + 1, 0.0);
}

void FloorGround::relative(int s, double t, double& du, double& dv) const {
  du = dv = 0.0;
  if (!differs(s)) return;
  double vl, ul, vr, ur;
  ground_->trace(site_channels_[s].first).kinematics(t, vl, ul);
  ground_->trace(site_channels_[s].second).kinematics(t, vr, ur);
  du = ul - ur;
  dv = vl - vr;
}

void FloorGround::relative_all(double t, double* du, double* dv) {
  if (t != kin_t_) {  // (the damped Sears path asks again at a step's end: the same numbers)
    for (const int c : used_) ground_->trace(c).kinematics(t, vg_[c], ug_[c]);
    kin_t_ = t;
  }
  for (std::size_t s = 0; s < site_channels_.size(); ++s) {
    const auto& [l, r] = site_channels_[s];
    du[s] = l == r ? 0.0 : ug_[l] - ug_[r];
    dv[s] = l == r ? 0.0 : vg_[l] - vg_[r];
  }
}

}  // namespace pound
