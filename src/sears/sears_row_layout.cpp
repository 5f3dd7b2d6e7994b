#include "sears/sears_row_layout.hpp"

#include <string>

#include "core/error.hpp"
#include "sears/contact_stiffness.hpp"

namespace pound::sears {

Slab floor_slab(const BuildingRow& row, const SearsRowModel& model, int b, int j) {
  const FloorSlabProperties& p = model.slabs.at(b);
  auto pick = [j](const std::vector<double>& per_floor, double all) {
    return per_floor.empty() ? all : per_floor.at(static_cast<std::size_t>(j));
  };
  Slab s{pick(p.length_per_floor_m, p.length_m),
         pick(p.E_per_floor_Pa, p.E_Pa),
         pick(p.rho_per_floor_kg_m3, p.rho_kg_m3),
         p.poisson,
         row.buildings[b].masses[j],
         model.chi};
  const std::string what = "building " + std::to_string(b + 1) + " floor " + std::to_string(j + 1);
  validate(s, what.c_str());
  return s;
}

RowContactLayout make_layout(const BuildingRow& row, const AssembledRow& a,
                             const SearsRowModel& model) {
  if (model.slabs.size() != row.buildings.size())
    throw InputError("damped Sears model: " + std::to_string(model.slabs.size()) +
                     " slab descriptions for " + std::to_string(row.buildings.size()) +
                     " buildings; give one per building");
  if (model.modes < 1) throw InputError("damped Sears model: modes must be >= 1");
  if (!(model.xi_s >= 0.0 && model.xi_s < 1.0))
    throw InputError("damped Sears model: xi_s must be in [0, 1)");
  if (!(model.impact_force_fraction >= 0.0 && model.impact_force_fraction <= 1.0))
    throw InputError("damped Sears model: impact_force_fraction must be in [0, 1]");
  if (!(model.contact_step_tolerance >= 0.0 && model.contact_step_tolerance <= 0.1))
    throw InputError("damped Sears model: contact_step_tolerance must be 0 or in (0, 0.1]");
  RowContactLayout L;
  auto floor_index = [&](int dof) {
    for (std::size_t i = 0; i < L.floors.size(); ++i)
      if (L.floors[i].dof == dof) return static_cast<int>(i);
    CollidingFloor f;
    f.dof = dof;
    for (std::size_t b = 0; b < a.offset.size(); ++b)
      if (dof >= a.offset[b]) {
        f.building = static_cast<int>(b);
        f.floor = dof - a.offset[b] + 1;
      }
    L.floors.push_back(f);
    return static_cast<int>(L.floors.size()) - 1;
  };
  for (std::size_t s = 0; s < a.sites.size(); ++s) {
    const ContactSite& site = a.sites[s];
    const SiteGeometry& g = site.geometry;
    // The bars: both slabs at a slab site; at a column site the striking slab only (its right
    // end x = l when it belongs to the left building, its left end x = 0 otherwise).
    const bool left_bar = !site.column() || g.slab_side == 0;
    const bool right_bar = !site.column() || g.slab_side == 1;
    const int fl = left_bar ? floor_index(site.dof_left) : -1;
    const int fr = right_bar ? floor_index(site.dof_right) : -1;
    auto claim = [&](int& end) {  // one site per slab end
      if (end >= 0)
        throw InputError("damped Sears model: " + describe_site(row, site) +
                         " meets a slab end that another site already uses; storeys shorter "
                         "than the slabs' thickness are not modelled");
      end = static_cast<int>(s);
    };
    if (fl >= 0) claim(L.floors[fl].site_right);  // the left building's floor: its x = l end
    if (fr >= 0) claim(L.floors[fr].site_left);   // the right building's floor: its x = 0 end
    L.site_left_floor.push_back(fl);
    L.site_right_floor.push_back(fr);
    L.laws.push_back(site_law(row, model, site));
  }
  return L;
}

SlabContactLaw site_law(const BuildingRow& row, const SearsRowModel& model,
                        const ContactSite& site) {
  const SiteGeometry& g = site.geometry;
  SlabContactLaw law;
  law.kind = model.contact;
  law.force_cap_N = model.force_cap_N;
  if (model.contact == ContactKind::flat) {
    if (!(model.D >= 1.0)) throw InputError("damped Sears model: D must be >= 1");
    if (!site.column()) {
      const Slab left = floor_slab(row, model, site.pair, g.slab_floor);
      const Slab right = floor_slab(row, model, site.pair + 1, g.hit);
      law.stiffness = flat_contact_stiffness(left, right, model.D);  // Th. 8.1-8.2
    } else {  // Th. 8.2 for the striking slab alone; the column replaces the struck bar
      const Slab slab = floor_slab(row, model, site.pair + g.slab_side, g.slab_floor);
      law.stiffness = slab_axial_stiffness(slab.E_Pa, slab.area_m2(), slab.length_m, model.D);
    }
  } else if (model.hertz_k > 0.0) {
    law.stiffness = model.hertz_k;
  } else {
    // Th. 7.2 from the faces' radii and the two buildings' materials.
    const auto& sl = model.slabs.at(site.pair);
    const auto& sr = model.slabs.at(site.pair + 1);
    law.stiffness = hertz_stiffness(sl.E_Pa, sl.poisson, model.hertz_radius_left, sr.E_Pa,
                                    sr.poisson, model.hertz_radius_right);
  }
  // The struck columns in series (issue 36): delta = delta_c + F / k_col.
  if (site.column()) law.series_compliance_m_per_N = 1.0 / site.column_stiffness;
  validate(law);
  return law;
}

void build_banks(RowContactLayout& L, const BuildingRow& row, const SearsRowModel& model,
                 double dt) {
  L.banks.clear();
  for (const auto& f : L.floors)
    L.banks.emplace_back(floor_slab(row, model, f.building, f.floor - 1), model.modes, model.xi_s,
                         dt);
}

Eigen::MatrixXd modal_compliance(const RowContactLayout& L, int level) {
  const int ns = static_cast<int>(L.laws.size());
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(ns, ns);
  for (int s = 0; s < ns; ++s) {
    const int fl = L.site_left_floor[s], fr = L.site_right_floor[s];
    // delta_s = w_right(left floor) - w_left(right floor); the left floor's right end carries
    // -F_s and its left end +F_t (t = its other site), the right floor's left end +F_s and its
    // right end -F_t'. A column side (-1) has no bar: no modal part.
    if (fl >= 0 && fr >= 0) {  // (the sum in the order of the slab sites before issue 36)
      const auto flex_l = L.banks[fl].flexibility(level), flex_r = L.banks[fr].flexibility(level);
      S(s, s) += flex_l.same + flex_r.same;
    } else {
      S(s, s) += L.banks[fl >= 0 ? fl : fr].flexibility(level).same;
    }
    if (fl >= 0 && L.floors[fl].site_left >= 0)
      S(s, L.floors[fl].site_left) -= L.banks[fl].flexibility(level).cross;
    if (fr >= 0 && L.floors[fr].site_right >= 0)
      S(s, L.floors[fr].site_right) -= L.banks[fr].flexibility(level).cross;
  }
  return S;
}

}  // namespace pound::sears
