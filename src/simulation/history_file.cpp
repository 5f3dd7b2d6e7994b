#include "simulation/history_file.hpp"

#include <cmath>

#include "io/atomic_file.hpp"
#include "io/h5.hpp"
#include "pound/version.hpp"

namespace pound {
namespace {

void write_run(hid_t f, const std::string& group, const History& h) {
  const std::size_t steps = h.t.size();
  const std::size_t dofs = steps ? static_cast<std::size_t>(h.u[0].size()) : 0;
  const std::size_t sites = steps ? static_cast<std::size_t>(h.force[0].size()) : 0;
  std::vector<double> u(steps * dofs), a(steps * dofs), force(steps * sites), shear(steps * dofs);
  for (std::size_t s = 0; s < steps; ++s) {
    for (std::size_t i = 0; i < dofs; ++i) {
      u[s * dofs + i] = h.u[s](i);
      a[s * dofs + i] = h.a_abs[s](i);
      shear[s * dofs + i] = s < h.shear.size() ? h.shear[s](i) : std::nan("");
    }
    for (std::size_t i = 0; i < sites; ++i) force[s * sites + i] = h.force[s](i);
  }
  h5::write(f, group + "/time", h.t, steps, 0, "s");
  h5::write(f, group + "/displacement", u, steps, dofs, "m");
  h5::write(f, group + "/abs_acceleration", a, steps, dofs, "m/s^2");
  h5::write(f, group + "/contact_force", force, steps, sites, "N");
  // Shear of the storey below each floor (storey j joins floor j-1 and floor j): plotted
  // against the storey drift it gives the hysteresis loops.
  h5::write(f, group + "/storey_shear", shear, steps, dofs, "N");
}

}  // namespace

void write_histories(const std::string& path, const BuildingRow& row, const GroundMotion& motion,
                     const RowSimulation& sim, const std::string& config_text) {
  AtomicPath out(path);
  {
    h5::File f(out.temp());
    std::vector<int> dof_b, dof_f, site_p, site_f;
    for (std::size_t b = 0; b < row.buildings.size(); ++b)
      for (int j = 0; j < row.buildings[b].floors(); ++j) {
        dof_b.push_back(static_cast<int>(b));
        dof_f.push_back(j + 1);
      }
    for (const auto& s : sim.sites) {
      site_p.push_back(s.pair);
      site_f.push_back(s.floor);
    }
    h5::write(f.id(), "/row/dof_building", dof_b);
    h5::write(f.id(), "/row/dof_floor", dof_f);
    h5::write(f.id(), "/row/site_pair", site_p);
    h5::write(f.id(), "/row/site_floor", site_f);
    write_run(f.id(), "/pounding", sim.pounding.history);
    write_run(f.id(), "/free", sim.free.history);
    std::vector<double> t(motion.accel.size());
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = i * motion.dt;
    h5::write(f.id(), "/motion/time", t, t.size(), 0, "s");
    h5::write(f.id(), "/motion/acceleration", motion.accel, t.size(), 0, "m/s^2");
    h5::attribute(f.id(), "/", "config", config_text);
    h5::attribute(f.id(), "/", "engine_version", kVersion);
    h5::attribute(f.id(), "/", "git_revision", kGitRevision);
    f.close();
  }
  out.commit();
}

}  // namespace pound
