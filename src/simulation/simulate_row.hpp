#pragma once
// One simulation of a row of buildings under one ground motion, run twice: with pounding and
// without (the same equations and steps with the contacts switched off), and the response
// measures of physics.md section 4. A pure function: the kernel of a Monte Carlo sample.
#include <limits>
#include <vector>

#include "ground/row_ground.hpp"
#include "motion/ground_motion.hpp"
#include "simulation/contact_spec.hpp"
#include "solver/integrator_settings.hpp"
#include "solver/row_result.hpp"
#include "structure/building_row.hpp"

namespace pound {

struct FloorResponse {
  int building = 0;                             ///< 0-based building index
  int floor = 0;                                ///< 1-based floor number
  double disp_pounding = 0.0, disp_free = 0.0;  ///< peak |u| [m]
  double disp_amplification = 0.0;              ///< disp_pounding / disp_free [-] (mu_max/u_max)
  double peak_drift_ratio_pounding = 0.0,
         peak_drift_ratio_free = 0.0;             ///< peak storey drift / height [-]
  double drift_amplification = 0.0;               ///< [-]
  double accel_pounding = 0.0, accel_free = 0.0;  ///< peak absolute acceleration [m/s^2]
  /// |storey drift| at the end of the run (record plus extra_time) / storey height [-]; NaN
  /// for a building that collapsed, and for every building of a run that stopped at a collapse
  double residual_drift_ratio_pounding = 0.0, residual_drift_ratio_free = 0.0;
  /// Ductility demand: peak storey drift / yield drift Fy / k0 [-]; NaN when the building has
  /// no yield shears.
  double ductility_pounding = 0.0, ductility_free = 0.0;
  /// Hysteretic energy dissipated by the storey below the floor [J].
  double hysteretic_energy_pounding = 0.0, hysteretic_energy_free = 0.0;
};

struct SiteResponse {
  int pair = 0;  ///< 0-based pair index (buildings pair and pair+1)
  /// 1-based site number within the pair (the floor level where floors align; the campaign
  /// file's level index).
  int floor = 0;
  ContactSite site;  ///< where and how the slabs meet (issue 36): kind, floors, xi, k_col
  int impacts = 0;
  double peak_force = 0.0;        ///< [N]
  double peak_penetration = 0.0;  ///< [m]
  double first_contact = -1.0;    ///< [s]
  /// The face's permanent indentation at the end of the pounding run (crushing at
  /// contact.force_cap; 0 without) [m] (SiteResult::crush).
  double crush = 0.0;
  /// Peak relative approach u_L - u_R of the two facing floors in the FREE run [m]: before its
  /// first contact a pounding run is the free run, so this is the smallest gap at this level
  /// that the motion would not close (SiteResult::peak_approach).
  double approach_free = 0.0;
  /// Column sites (issue 36): the peak shear demand on the struck face's columns with and
  /// without pounding (SiteResult::peak_column_shear) [N]; NaN at slab sites.
  double column_shear_pounding = std::numeric_limits<double>::quiet_NaN();
  double column_shear_free = std::numeric_limits<double>::quiet_NaN();
  /// That demand over the struck storey's column_shear_strength [-]; NaN without one.
  double column_shear_ratio_pounding = std::numeric_limits<double>::quiet_NaN();
  double column_shear_ratio_free = std::numeric_limits<double>::quiet_NaN();
};

struct RowSimulation {
  std::vector<FloorResponse> floors;
  std::vector<SiteResponse> sites;
  RowResult pounding, free;  ///< the raw runs (histories when requested)
  /// Per building: collapse in each run (issue 23; RowResult::collapse); empty without the
  /// check. The pounding run stops at its first collapse.
  std::vector<BuildingCollapse> collapse_pounding, collapse_free;
  /// Per pair p (buildings p and p+1): the peak relative ground displacement |ug_p - ug_p+1|
  /// over the run [m] (issue 28; 0 on one motion), which the gap must take up besides the
  /// buildings' own motion.
  std::vector<double> ground_relative;
  /// Per building: the largest column-shear ratio over its struck storeys with and without
  /// pounding (SiteResponse::column_shear_ratio_*) [-]; NaN where it has no strength or none of
  /// its storeys is struck (issue 36).
  std::vector<double> column_shear_ratio_pounding, column_shear_ratio_free;
};

struct RowSimulationOptions {
  double extra_time = 0.0;      ///< free vibration after the record ends [s]
  bool record_history = false;  ///< keep time histories of both runs
  bool track_energy = false;    ///< energy balance of both runs (RowResult::energy)
  /// A building whose storey drift ratio passes this (or whose storey fails under P-Delta) has
  /// collapsed (RowProblem::collapse_drift_ratio); infinite: no check [-].
  double collapse_drift_ratio = std::numeric_limits<double>::infinity();

  /// These settings in a run's problem (RowProblem, sears::SearsRowProblem) on `ground`: the
  /// ground and extra_time (the run lasts until the last building's record ends plus
  /// extra_time), histories, energy balance and collapse.
  template <class Problem>
  void apply_to(Problem& p, const RowGround& ground) const {
    p.ground = &ground;
    p.t_end = ground.duration() + extra_time;
    p.record_history = record_history;
    p.track_energy = track_energy;
    p.collapse_drift_ratio = collapse_drift_ratio;
  }
};

/// The response measures of physics.md section 4 from a free and a pounding run of the same
/// row (any contact model) on `ground` until t_end [s]: fills floors, sites and the pairs'
/// relative ground displacement.
RowSimulation summarize_runs(const BuildingRow& row, const RowGround& ground, double t_end,
                             RowResult free, RowResult pounding);

/// The row on `ground` (one motion per building, ground/row_ground.hpp) with and without
/// pounding, by the lumped solver.
RowSimulation simulate_row(const BuildingRow& row, const RowGround& ground,
                           const ContactSpec& contact, const IntegratorSettings& integ,
                           const RowSimulationOptions& opt = {});
/// The same with one motion under every building.
RowSimulation simulate_row(const BuildingRow& row, const GroundMotion& motion,
                           const ContactSpec& contact, const IntegratorSettings& integ,
                           const RowSimulationOptions& opt = {});

}  // namespace pound
