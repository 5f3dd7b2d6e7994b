#include "solver/free_impact.hpp"

#include <cmath>

#include "core/error.hpp"
#include "solver/row_solver.hpp"

namespace pound {

ImpactResult simulate_free_impact(const ContactLaw& law, const FreeImpactSpec& spec,
                                  const IntegratorSettings& integ) {
  // Two one-floor "buildings" without storey springs: free bodies touching at t = 0.
  AssembledRow row;
  row.M = Eigen::Vector2d(spec.m1, spec.m2).asDiagonal();
  row.C = Eigen::MatrixXd::Zero(2, 2);
  row.K = Eigen::MatrixXd::Zero(2, 2);
  row.inv_mass = row.M.diagonal().cwiseInverse();
  row.offset = {0, 1};
  row.sites = {floor_site(row, 0, 0, 0, 1, 0.0)};

  RowProblem p;
  p.row = &row;
  p.laws = {&law};
  p.u0 = Eigen::Vector2d::Zero();
  p.v0 = Eigen::Vector2d(spec.v0, 0.0);
  p.stop_after_separation = true;
  // A bound on the time: generous multiples of any contact time scale are reached only if
  // the bodies never separate (e.g. a model that sticks).
  p.t_end = 1e6;
  IntegratorSettings s = integ;
  // No modal period limits the step; the first step is small and the controller grows it.
  if (s.h_max <= 0) s.h_max = 1e-2;
  const RowResult r = solve(p, s);
  if (r.t_end >= p.t_end * 0.999)
    throw NumericalError("the bodies did not separate (the contact model sticks)");

  ImpactResult out;
  const SiteResult& sr = r.sites[0];
  out.v1_after = r.v_end(0);
  out.v2_after = r.v_end(1);
  out.e_eff = (out.v2_after - out.v1_after) / spec.v0;
  out.contact_duration_s = law.impulsive() ? 0.0 : sr.last_separation - sr.first_contact;
  out.impulse_Ns = sr.impulse;
  out.peak_force_N = sr.peak_force;
  out.max_penetration_m = sr.peak_penetration;
  out.contact_phases = sr.impacts;
  return out;
}

}  // namespace pound
