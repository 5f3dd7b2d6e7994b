#include "study/impact_run.hpp"

#include "contact/registry.hpp"
#include "io/json.hpp"
#include "sears/sears_impact.hpp"
#include "sears/sears_options.hpp"
#include "solver/free_impact.hpp"

namespace pound {

const char* const kImpactSummary = "Two free bodies (no springs, no ground motion) colliding once.";

std::vector<OptionSpec> impact_option_specs() {
  std::vector<OptionSpec> specs = {
      {"model", "", "hc-linear", "contact model: " + every_contact_model_name()},
      {"e", "-", "0.65", "coefficient of restitution, in (0, 1]"},
      {"k", "N/m or N/m^1.5", "", "contact stiffness (N/m linear laws, N/m^1.5 Hertz laws)"},
      {"m1", "kg", "1", "mass of body 1 (moving towards body 2)"},
      {"m2", "kg", "1", "mass of body 2 (at rest)"},
      {"v0", "m/s", "1", "approach velocity"},
      {"dt", "s", "", "fixed integration step (default: adaptive steps)"},
      {"rtol", "-", "1e-10", "relative tolerance of the adaptive steps"},
      {"v0-min", "m/s", "1e-9", "smallest approach velocity used by v0-scaled damping"},
      {"json", "", "", "print one JSON object", true},
  };
  const auto sears_specs = sears::sears_impact_option_specs();
  specs.insert(specs.end(), sears_specs.begin(), sears_specs.end());
  return specs;
}

ImpactResult impact_from_options(const Options& opt) {
  const std::string model = opt.get_string("model");
  FreeImpactSpec spec;
  spec.m1 = opt.get_positive("m1");
  spec.m2 = opt.get_positive("m2");
  spec.v0 = opt.get_positive("v0");
  if (is_sears_model(model)) {
    // Damped Sears model: two free bars (docs/sears.md).
    const auto s = sears::sears_impact_spec_from(opt, spec.m1, spec.m2, spec.v0);
    return sears::simulate_sears_impact(s);
  }
  const auto& info = find_contact_model(model, opt.where("model"));
  ContactParameters p;
  p.e = opt.get_double("e");
  if (!(p.e > 0 && p.e <= 1)) throw opt.invalid("e", "valid: e in (0, 1]");
  if (!info.stiffness_unit.empty()) {
    if (!opt.has("k"))
      throw InputError(opt.where("k") + ": missing; model '" + model +
                       "' needs a contact stiffness --k [" + info.stiffness_unit + "]");
    p.k = opt.get_positive("k");
  }
  p.m1 = spec.m1;
  p.m2 = spec.m2;
  p.v0_min = opt.get_positive("v0-min");
  IntegratorSettings integ;
  integ.rtol = opt.get_positive("rtol");
  integ.atol = 1e-16;
  if (opt.given("dt")) {
    integ.control = StepControl::fixed;
    integ.dt = opt.get_positive("dt");
  }
  const auto law = info.make(p);
  return simulate_free_impact(*law, spec, integ);
}

std::string impact_json(const ImpactResult& r) {
  JsonWriter w;
  w.begin_object()
      .field("e_eff", r.e_eff)
      .field("contact_duration_s", r.contact_duration_s)
      .field("impulse_Ns", r.impulse_Ns)
      .field("peak_force_N", r.peak_force_N)
      .field("max_penetration_m", r.max_penetration_m)
      .field("v1_after", r.v1_after)
      .field("v2_after", r.v2_after)
      .field("contact_phases", r.contact_phases)
      .field("internal_energy1_J", r.internal_energy1_J)
      .field("internal_energy2_J", r.internal_energy2_J)
      .end_object();
  return w.str();
}

}  // namespace pound
