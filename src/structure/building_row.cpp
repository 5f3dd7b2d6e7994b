#include "structure/building_row.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/error.hpp"
#include "hysteresis/registry.hpp"
#include "structure/building_on_base.hpp"
#include "structure/foundation.hpp"

namespace pound {

namespace {

// A building's name for messages and site descriptions; "building N" (N from 1) for a building
// built without one (a hand-built row, the Python API).
std::string label(const BuildingRow& row, int b) {
  const std::string& name = row.buildings[b].name;
  return name.empty() ? "building " + std::to_string(b + 1) : name;
}

}  // namespace

int colliding_levels(const BuildingRow& row, int pair) {
  return static_cast<int>(pair_sites(row.buildings[pair], row.buildings[pair + 1]).size());
}

std::string describe_site(const BuildingRow& row, const ContactSite& s) {
  const SiteGeometry& g = s.geometry;
  const std::string slab = label(row, s.pair + g.slab_side);
  const std::string hit = label(row, s.pair + 1 - g.slab_side);
  std::string out = slab + " floor " + std::to_string(g.slab_floor + 1) + " against " + hit;
  if (g.kind == SiteKind::slab)
    return out + " floor " + std::to_string(g.hit + 1) + " (slab to slab)";
  char xi[32];
  std::snprintf(xi, sizeof xi, "%.3f", g.xi);
  return out + " storey " + std::to_string(g.hit + 1) + " at xi " + xi + " (slab to column)";
}

ContactSite floor_site(const AssembledRow& a, int pair, int level, int dof_left, int dof_right,
                       double gap) {
  ContactSite s;
  s.pair = pair;
  s.level = level;
  s.gap = gap;
  s.dof_left = dof_left;
  s.dof_right = dof_right;
  s.left.add(dof_left, 1.0);
  s.right.add(dof_right, 1.0);
  s.geometry.slab_floor = s.geometry.hit = level;
  s.mass_left = 1.0 / a.inv_mass(dof_left);
  s.mass_right = 1.0 / a.inv_mass(dof_right);
  return s;
}

std::vector<std::string> describe_sites(const BuildingRow& row) {
  std::vector<std::string> out;
  for (std::size_t p = 0; p + 1 < row.buildings.size(); ++p) {
    const std::vector<SiteGeometry> g = pair_sites(row.buildings[p], row.buildings[p + 1]);
    const std::string pair = "pair " + std::to_string(p + 1);
    bool aligned = true;
    for (std::size_t k = 0; k < g.size(); ++k)
      aligned =
          aligned && g[k].kind == SiteKind::slab && g[k].slab_floor == int(k) && g[k].hit == int(k);
    if (aligned) {
      out.push_back(pair + " (" + label(row, int(p)) + " | " + label(row, int(p) + 1) + "): " +
                    (g.empty()       ? std::string("no contact site")
                     : g.size() == 1 ? std::string("floor 1 slab to slab")
                                     : "floors 1-" + std::to_string(g.size()) + " slab to slab"));
      continue;
    }
    for (std::size_t k = 0; k < g.size(); ++k) {
      ContactSite s;
      s.pair = static_cast<int>(p);
      s.geometry = g[k];
      out.push_back(pair + " site " + std::to_string(k + 1) + ": " + describe_site(row, s));
    }
  }
  return out;
}

namespace {

// The apparent mass of a point, 1 / sum(w^2 / m) [kg] (physics.md section 5b): a DOF without
// mass (inv_mass 0) adds nothing. A slab's is its floor mass, 1 / inv_mass, to the bit.
double apparent_mass(const SitePoint& pt, const AssembledRow& a) {
  double inv = 0.0;
  for (int k = 0; k < pt.count; ++k) inv += pt.weight[k] * pt.weight[k] * a.inv_mass(pt.dof[k]);
  return 1.0 / inv;
}

// The point of building b's columns in storey j at xi (SitePoint): floor j-1 (or the base's
// sway) with 1 - s, floor j with s, the base's rotation with h (xi - s).
SitePoint column_point(const Building& bd, const AssembledRow& a, int b, int j, double xi) {
  const double s = column_shape(xi);
  const int below = j > 0 ? a.offset[b] + j - 1 : a.sway[b];
  SitePoint pt;
  if (below >= 0) pt.add(below, 1.0 - s);
  pt.add(a.offset[b] + j, s);
  if (a.rot[b] >= 0) pt.add(a.rot[b], bd.storey_heights[j] * (xi - s));
  return pt;
}

ContactSite make_site(const BuildingRow& row, const AssembledRow& a, int p, int k,
                      const SiteGeometry& g) {
  ContactSite s;
  s.pair = p;
  s.level = k;
  s.geometry = g;
  s.gap = row.gaps.at(p).at(k);
  const int slab_b = p + g.slab_side, hit_b = p + 1 - g.slab_side;
  SitePoint slab;
  slab.add(a.offset[slab_b] + g.slab_floor, 1.0);
  SitePoint hit;
  if (g.kind == SiteKind::slab) {
    hit.add(a.offset[hit_b] + g.hit, 1.0);
  } else {
    const Building& bd = row.buildings[hit_b];
    hit = column_point(bd, a, hit_b, g.hit, g.xi);
    s.column_stiffness = column_point_stiffness(bd.stiffnesses[g.hit], bd.face_column_share, g.xi);
    s.struck_dof = a.offset[hit_b] + g.hit;
    s.face_share = bd.face_column_share;
    s.shape = column_shape(g.xi);
    s.struck_sign = g.slab_side == 0 ? 1.0 : -1.0;
    for (int q = 0; q < hit.count; ++q)
      if (a.massless[hit.dof[q]])
        throw InputError(label(row, hit_b) + ": a slab of " + label(row, slab_b) +
                         " strikes the columns of storey " + std::to_string(g.hit + 1) +
                         ", which stand on a massless foundation DOF: not modelled; give the "
                         "foundation a mass and rotary inertia (foundation_mass, "
                         "foundation_inertia)");
  }
  s.left = g.slab_side == 0 ? slab : hit;
  s.right = g.slab_side == 0 ? hit : slab;
  s.dof_left = a.offset[p] + (g.slab_side == 0 ? g.slab_floor : g.hit);
  s.dof_right = a.offset[p + 1] + (g.slab_side == 0 ? g.hit : g.slab_floor);
  s.mass_left = apparent_mass(s.left, a);
  s.mass_right = apparent_mass(s.right, a);
  return s;
}

}  // namespace

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
    const std::vector<SiteGeometry> g = pair_sites(row.buildings[p], row.buildings[p + 1]);
    const std::size_t given = p < static_cast<int>(row.gaps.size()) ? row.gaps[p].size() : 0;
    if (given != g.size())  // the study readers expand one gap to every site
      throw InputError("pair " + std::to_string(p + 1) + " (" + label(row, p) + " | " +
                       label(row, p + 1) + "): " + std::to_string(given) + " gaps for its " +
                       std::to_string(g.size()) +
                       " contact sites; valid: one gap per site, in the order pound simulate "
                       "lists them");
    for (std::size_t k = 0; k < g.size(); ++k)
      out.sites.push_back(make_site(row, out, p, static_cast<int>(k), g[k]));
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
