#include "structure/building_row.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hysteresis/registry.hpp"

namespace pound {

int colliding_levels(const BuildingRow& row, int pair) {
  return std::min(row.buildings[pair].floors(), row.buildings[pair + 1].floors());
}

std::vector<RowStorey> elastic_storeys(const AssembledRow& a) {
  const StoreyLaw& law = find_storey_law("elastic", "elastic_storeys");
  const int n = a.dofs(), nb = static_cast<int>(a.offset.size());
  std::vector<RowStorey> out(static_cast<std::size_t>(n));
  for (int b = 0; b < nb; ++b) {
    const int o = a.offset[b], end = b + 1 < nb ? a.offset[b + 1] : n;
    for (int i = o; i < end; ++i) {
      RowStorey& s = out[static_cast<std::size_t>(i)];
      s.law = &law;
      s.below = i > o ? i - 1 : -1;
      s.above = i + 1 < end ? i + 1 : -1;
      s.building = b;
      s.p.k0 = a.K(i, i) + (s.above >= 0 ? a.K(i, s.above) : 0.0);
    }
  }
  return out;
}

AssembledRow assemble(const BuildingRow& row) {
  AssembledRow out;
  int n = 0;
  for (const auto& b : row.buildings) {
    out.offset.push_back(n);
    n += b.floors();
  }
  out.M = Eigen::MatrixXd::Zero(n, n);
  out.C = Eigen::MatrixXd::Zero(n, n);
  out.K = Eigen::MatrixXd::Zero(n, n);
  out.Kg = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t b = 0; b < row.buildings.size(); ++b) {
    const Building& bd = row.buildings[b];
    const auto m = assemble(bd);
    const int o = out.offset[b], nb = bd.floors();
    out.M.block(o, o, nb, nb) = m.M;
    out.C.block(o, o, nb, nb) = m.C;
    if (bd.p_delta) {
      out.K.block(o, o, nb, nb) = m.K - m.Kg;
      out.Kg.block(o, o, nb, nb) = m.Kg;
    } else {
      out.K.block(o, o, nb, nb) = m.K;
    }
    out.periods.push_back(m.periods);
    const StoreyLaw& law = find_storey_law(bd.hysteresis, bd.name);
    // Linear: the forces are K u and the damping C v with constant matrices.
    out.linear = out.linear && law.linear();
    for (int j = 0; j < nb; ++j) {
      RowStorey s;
      s.law = &law;
      s.p = bd.storey(j);
      s.below = j > 0 ? o + j - 1 : -1;
      s.above = j + 1 < nb ? o + j + 1 : -1;
      s.building = static_cast<int>(b);
      s.kg = bd.geometric_stiffness(j);
      if (bd.damping_stiffness == DampingStiffness::tangent) s.damping_a1 = m.rayleigh_a1;
      out.storeys.push_back(s);
    }
  }
  out.inv_mass = out.M.diagonal().cwiseInverse();
  for (int p = 0; p + 1 < static_cast<int>(row.buildings.size()); ++p) {
    for (int j = 0; j < colliding_levels(row, p); ++j) {
      ContactSite s;
      s.pair = p;
      s.level = j;
      s.dof_left = out.offset[p] + j;
      s.dof_right = out.offset[p + 1] + j;
      s.gap = row.gaps.at(p).at(j);
      out.sites.push_back(s);
    }
  }
  return out;
}

double shortest_period(const AssembledRow& a) {
  double t = std::numeric_limits<double>::infinity();
  for (const auto& p : a.periods)
    for (int i = 0; i < p.size(); ++i)
      if (p(i) > 0.0 && std::isfinite(p(i))) t = std::min(t, p(i));
  return t;
}

}  // namespace pound
