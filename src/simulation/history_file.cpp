#include "simulation/history_file.hpp"

#include "io/atomic_file.hpp"
#include "io/h5.hpp"
#include "pound/version.hpp"
#include "simulation/history_table.hpp"

namespace pound {
namespace {

void write_run(hid_t f, const std::string& group, const History& h, const HistoryLayout& l) {
  const HistoryTable t = history_table(h, l);
  h5::write(f, group + "/time", t.time, t.steps, 0, "s");
  h5::write(f, group + "/displacement", t.displacement, t.steps, t.dofs, "m");
  h5::write(f, group + "/abs_acceleration", t.abs_acceleration, t.steps, t.dofs, "m/s^2");
  h5::write(f, group + "/contact_force", t.contact_force, t.steps, t.sites, "N");
  // Shear of the storey below each floor (storey j joins floor j-1 and floor j): plotted
  // against the storey drift it gives the hysteresis loops.
  h5::write(f, group + "/storey_shear", t.storey_shear, t.steps, t.dofs, "N");
  // The storey's deformation (the drift the storey law sees; on a flexible foundation the chord
  // minus h theta) and each base's sway and rotation (0 on a fixed base).
  h5::write(f, group + "/storey_drift", t.storey_drift, t.steps, t.dofs, "m");
  h5::write(f, group + "/foundation_sway", t.foundation_sway, t.steps, t.buildings, "m");
  h5::write(f, group + "/foundation_rotation", t.foundation_rotation, t.steps, t.buildings, "rad");
}

}  // namespace

void write_histories(const std::string& path, const BuildingRow& row, const GroundMotion& motion,
                     const RowGround& ground, const RowSimulation& sim,
                     const std::string& config_text) {
  AtomicPath out(path);
  {
    h5::File f(out.temp());
    const HistoryLayout l = history_layout(row, sim);
    h5::write(f.id(), "/row/dof_building", l.dof_building);
    h5::write(f.id(), "/row/dof_floor", l.dof_floor);
    h5::write(f.id(), "/row/site_pair", l.site_pair);
    h5::write(f.id(), "/row/site_floor", l.site_floor);
    h5::write(f.id(), "/row/site_kind", l.site_kind);  // 0 slab to slab, 1 slab to column
    h5::write(f.id(), "/row/site_slab_building", l.site_slab_building);
    h5::write(f.id(), "/row/site_slab_floor", l.site_slab_floor);
    h5::write(f.id(), "/row/site_hit_building", l.site_hit_building);
    h5::write(f.id(), "/row/site_hit", l.site_hit);  // floor (slab) or storey (column)
    h5::write(f.id(), "/row/site_xi", l.site_xi, l.site_xi.size(), 0, "-");
    const std::size_t ns = l.site_xi.size();
    h5::write(f.id(), "/row/site_peak_column_shear", l.site_peak_column_shear, ns, 0, "N");
    h5::write(f.id(), "/row/site_peak_column_shear_free", l.site_peak_column_shear_free, ns, 0,
              "N");
    h5::write(f.id(), "/row/site_crush", l.site_crush, ns, 0, "m");
    write_run(f.id(), "/pounding", sim.pounding.history, l);
    write_run(f.id(), "/free", sim.free.history, l);
    std::vector<double> t(motion.accel.size());
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = i * motion.dt;
    h5::write(f.id(), "/motion/time", t, t.size(), 0, "s");
    h5::write(f.id(), "/motion/acceleration", motion.accel, t.size(), 0, "m/s^2");
    const GroundTable g = ground_table(ground);
    h5::write(f.id(), "/ground/time", g.time, g.samples, 0, "s");
    h5::write(f.id(), "/ground/acceleration", g.acceleration, g.samples, g.buildings, "m/s^2");
    h5::write(f.id(), "/ground/displacement", g.displacement, g.samples, g.buildings, "m");
    h5::attribute(f.id(), "/", "config", config_text);
    h5::attribute(f.id(), "/", "engine_version", kVersion);
    h5::attribute(f.id(), "/", "git_revision", kGitRevision);
    f.close();
  }
  out.commit();
}

}  // namespace pound
