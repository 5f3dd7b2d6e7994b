// pound impact: two free bodies colliding once through a chosen contact model.
#include <cmath>
#include <cstdio>
#include <iostream>

#include "app/commands.hpp"
#include "app/help.hpp"
#include "io/options.hpp"
#include "study/impact_run.hpp"

namespace pound::app {
namespace {

void print(const ImpactResult& r, bool json) {
  if (json) {
    std::cout << impact_json(r) << "\n";
    return;
  }
  std::printf("e_eff               %.9g\n", r.e_eff);
  std::printf("contact duration    %.9g s\n", r.contact_duration_s);
  std::printf("impulse             %.9g N s\n", r.impulse_Ns);
  std::printf("peak force          %.9g N\n", r.peak_force_N);
  std::printf("max penetration     %.9g m\n", r.max_penetration_m);
  std::printf("velocities after    %.9g, %.9g m/s\n", r.v1_after, r.v2_after);
  if (!std::isnan(r.internal_energy1_J))
    std::printf("internal energy     %.9g, %.9g J\n", r.internal_energy1_J, r.internal_energy2_J);
}

}  // namespace

int run_impact(int argc, const char* const* argv) {
  Options opt("impact", kImpactSummary, impact_option_specs());
  if (help_asked(opt, argc, argv)) return 0;
  print(impact_from_options(opt), opt.flag("json"));
  return 0;
}

}  // namespace pound::app
