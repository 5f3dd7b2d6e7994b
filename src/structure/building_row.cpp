#include "structure/building_row.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hysteresis/registry.hpp"
#include "structure/building_on_base.hpp"
#include "structure/foundation.hpp"

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
  const int nb = static_cast<int>(row.buildings.size());
  std::vector<BaseMatrices> bm;
  int n = 0;
  for (const auto& b : row.buildings) {
    out.offset.push_back(n);
    n += b.floors();
    bm.push_back(assemble_on_base(b));
  }
  out.floors = n;
  out.sway.assign(nb, -1);
  out.rot.assign(nb, -1);
  for (int b = 0; b < nb; ++b)
    if (bm[b].flexible) {
      out.sway[b] = n++;
      out.rot[b] = n++;
    }
  out.M = Eigen::MatrixXd::Zero(n, n);
  out.C = Eigen::MatrixXd::Zero(n, n);
  out.K = Eigen::MatrixXd::Zero(n, n);
  out.Kg = Eigen::MatrixXd::Zero(n, n);
  out.influence = Eigen::VectorXd::Ones(n);
  out.base_damping.assign(n, 0.0);
  out.building_of.assign(n, 0);
  out.storeys.resize(n);
  for (int b = 0; b < nb; ++b) {
    const Building& bd = row.buildings[b];
    const BaseMatrices& m = bm[b];
    const int o = out.offset[b], nf = bd.floors();
    // Local DOF l of the building (its floors, then sway and rotation) -> global DOF.
    auto at = [&](int l) { return l < nf ? o + l : (l == nf ? out.sway[b] : out.rot[b]); };
    for (int l = 0; l < m.dofs(); ++l) {
      out.building_of[at(l)] = b;
      out.influence(at(l)) = m.influence(l);
      for (int k = 0; k < m.dofs(); ++k) {
        out.M(at(l), at(k)) = m.M(l, k);
        out.C(at(l), at(k)) = m.C(l, k);
        out.K(at(l), at(k)) = bd.p_delta ? m.K0(l, k) - m.Kg(l, k) : m.K0(l, k);
        if (bd.p_delta) out.Kg(at(l), at(k)) = m.Kg(l, k);
      }
    }
    out.periods.push_back(m.periods);
    out.damping_ratios.push_back(m.damping_ratios);
    const StoreyLaw& law = find_storey_law(bd.hysteresis, bd.name);
    // Linear: the forces are K u and the damping C v with constant matrices.
    out.linear = out.linear && law.linear();
    const double a1 = m.rayleigh_a1;
    for (int j = 0; j < nf; ++j) {
      RowStorey& s = out.storeys[o + j];
      s.law = &law;
      s.p = bd.storey(j);
      s.below = j > 0 ? o + j - 1 : out.sway[b];
      s.above = j + 1 < nf ? o + j + 1 : -1;
      s.building = b;
      s.rot = out.rot[b];
      s.kg = bd.geometric_stiffness(j);
      if (bd.damping_stiffness == DampingStiffness::tangent) s.damping_a1 = a1;
    }
    if (!m.flexible) continue;
    // The base's sway and rotation, each on its foundation spring (a linear "storey").
    const StoreyLaw& elastic = find_storey_law("elastic", bd.name);
    const FoundationConstants f = foundation_constants(bd.foundation);
    for (int k = 0; k < 2; ++k) {
      RowStorey& s = out.storeys[k == 0 ? out.sway[b] : out.rot[b]];
      s.law = &elastic;
      s.p.k0 = k == 0 ? f.sway_stiffness : f.rocking_stiffness;
      s.building = b;
      s.above = k == 0 ? o : -1;
      s.foundation = true;
    }
    out.base_damping[out.sway[b]] = f.sway_damping;
    out.base_damping[out.rot[b]] = f.rocking_damping;
  }
  out.inv_mass = Eigen::VectorXd::Zero(n);
  out.massless.assign(n, 0);
  for (int i = 0; i < n; ++i) {
    if (out.M(i, i) > 0.0)
      out.inv_mass(i) = 1.0 / out.M(i, i);
    else
      out.massless[i] = 1;
  }
  for (int p = 0; p + 1 < nb; ++p) {
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

double step_period(const AssembledRow& a) {
  if (a.damping_ratios.size() != a.periods.size()) return shortest_period(a);
  double t = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < a.periods.size(); ++b) {
    const Eigen::VectorXd& p = a.periods[b];
    const Eigen::VectorXd& z = a.damping_ratios[b];
    for (int i = 0; i < p.size(); ++i)
      if (p(i) > 0.0 && std::isfinite(p(i)) && !(i < z.size() && z(i) >= 1.0))
        t = std::min(t, p(i));
  }
  return t;
}

}  // namespace pound
