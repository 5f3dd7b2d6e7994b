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
    if (site.column())
      throw InputError("damped Sears model: " + describe_site(row, site) +
                       " is slab to column, which the Sears path does not model yet (issue "
                       "36); use a lumped contact model, or align the floors");
    const int fl = floor_index(site.dof_left), fr = floor_index(site.dof_right);
    L.floors[fl].site_right = static_cast<int>(s);  // the left building's floor: its x = l end
    L.floors[fr].site_left = static_cast<int>(s);   // the right building's floor: its x = 0 end
    L.site_left_floor.push_back(fl);
    L.site_right_floor.push_back(fr);
    SlabContactLaw law;
    law.kind = model.contact;
    law.force_cap_N = model.force_cap_N;
    if (model.contact == ContactKind::flat) {
      if (!(model.D >= 1.0)) throw InputError("damped Sears model: D must be >= 1");
      const Slab left = floor_slab(row, model, site.pair, site.geometry.slab_floor);
      const Slab right = floor_slab(row, model, site.pair + 1, site.geometry.hit);
      law.stiffness = flat_contact_stiffness(left, right, model.D);  // Th. 8.1-8.2
    } else if (model.hertz_k > 0.0) {
      law.stiffness = model.hertz_k;
    } else {
      // Th. 7.2 from the faces' radii and the two slabs' materials.
      const auto& sl = model.slabs.at(site.pair);
      const auto& sr = model.slabs.at(site.pair + 1);
      law.stiffness = hertz_stiffness(sl.E_Pa, sl.poisson, model.hertz_radius_left, sr.E_Pa,
                                      sr.poisson, model.hertz_radius_right);
    }
    validate(law);
    L.laws.push_back(law);
  }
  return L;
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
    const auto flex_l = L.banks[fl].flexibility(level), flex_r = L.banks[fr].flexibility(level);
    // delta_s = w_right(left floor) - w_left(right floor); the left floor's right end carries
    // -F_s and its left end +F_t (t = its other site), the right floor's left end +F_s and its
    // right end -F_t'.
    S(s, s) += flex_l.same + flex_r.same;
    if (L.floors[fl].site_left >= 0) S(s, L.floors[fl].site_left) -= flex_l.cross;
    if (L.floors[fr].site_right >= 0) S(s, L.floors[fr].site_right) -= flex_r.cross;
  }
  return S;
}

}  // namespace pound::sears
