#include "study/row_options.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "contact/registry.hpp"
#include "contact/restitution.hpp"
#include "core/format.hpp"
#include "hysteresis/registry.hpp"
#include "motion/motion_processing.hpp"
#include "motion/motion_reader.hpp"
#include "study/foundation_options.hpp"
#include "study/ground_options.hpp"

namespace pound {

namespace {

// A default of StoreyParameters as the option's default text (one source for both).
std::string default_text(double x) {
  return format_number(x, "%g");
}

}  // namespace

std::vector<OptionSpec> storey_law_option_specs(const std::string& prefix) {
  const StoreyParameters d;
  const std::string list = prefix.empty() ? "" : " (one value or a list)";
  return {
      {prefix + "hardening", "-", default_text(d.b),
       "post-yield stiffness ratio b = k_post / k0 in [0, 1)" + list},
      {prefix + "bw_n", "-", default_text(d.bw_n), "Bouc-Wen sharpness n > 0" + list},
      {prefix + "cap_strength_ratio", "-", default_text(d.cap_strength_ratio),
       "imk: cap strength over yield strength Fc / Fy >= 1" + list},
      {prefix + "plastic_drift_ratio", "-", default_text(d.plastic_drift_ratio),
       "imk: drift ratio theta_p > 0 from yield to the cap" + list},
      {prefix + "post_cap_drift_ratio", "-", default_text(d.post_cap_drift_ratio),
       "imk: drift ratio theta_pc > 0 from the cap to zero strength" + list},
      {prefix + "ultimate_drift_ratio", "-", "",
       "imk: drift ratio theta_u beyond which the storey has no strength, not below the cap "
       "drift ratio uy / h + theta_p" +
           list + " (default: none)"},
      {prefix + "residual_strength_ratio", "-", default_text(d.residual_strength_ratio),
       "imk: residual strength over yield strength Fr / Fy in [0, 1)" + list},
      {prefix + "energy_capacity", "-", default_text(d.energy_capacity),
       "imk: lambda > 0 of the reference energy E_t = lambda Fy uy of cyclic deterioration" + list},
      {prefix + "energy_exponent", "-", default_text(d.energy_exponent),
       "imk: exponent c > 0 of cyclic deterioration" + list},
  };
}

std::vector<OptionSpec> row_option_specs() {
  auto specs = row_option_specs_without_laws();
  const auto laws = storey_law_option_specs("building#.");
  // After building#.yield_shears, where hardening and bw_n always stood.
  auto at = std::find_if(specs.begin(), specs.end(),
                         [](const OptionSpec& o) { return o.key == "building#.yield_shears"; });
  specs.insert(at + 1, laws.begin(), laws.end());
  // The ground under each building (issue 28), after the gaps.
  const auto ground = ground_option_specs();
  at = std::find_if(specs.begin(), specs.end(),
                    [](const OptionSpec& o) { return o.key == "pair#.gap"; });
  specs.insert(at + 1, ground.begin(), ground.end());
  // Each building's foundation (issue 29), after the ground under it.
  const auto foundation = foundation_option_specs();
  at = std::find_if(specs.begin(), specs.end(),
                    [](const OptionSpec& o) { return o.key == "ground.coherency_parameters"; });
  specs.insert(at + 1, foundation.begin(), foundation.end());
  return specs;
}

std::vector<OptionSpec> row_option_specs_without_laws() {
  return {
      {"building#.name", "", "", "label of the building"},
      {"building#.masses", "kg", "", "floor masses, floor 1 first (list)"},
      {"building#.stiffnesses", "N/m", "", "storey stiffnesses, storey 1 first (list)"},
      {"building#.storey_heights", "m", "3.0",
       "storey heights for drift ratios (one value for all storeys, or a list)"},
      {"building#.base_elevation", "m", "0",
       "level of the base against the row's datum (a street on a slope); floors stand at it "
       "plus the storey heights, and slabs meet what stands at their height"},
      {"building#.slab_thickness", "m", "0.2",
       "slab thickness, > 0: slabs within (t1 + t2) / 2 of a neighbour's floor meet it slab to "
       "slab, others strike the neighbour's columns"},
      {"building#.face_column_share", "-", "0.5",
       "share of a storey's stiffness in the columns of the face a neighbour's slab can strike, "
       "in (0, 1]"},
      {"building#.column_shear_strength", "N", "",
       "shear strength of the struck face's columns together (one value for all storeys, or a "
       "list): the demand over it is the column_shear limit state"},
      {"building#.damping", "-", "0.05", "inherent damping ratio, in [0, 1)"},
      {"building#.damping_type", "", "rayleigh",
       "rayleigh (ratio on modes 1 and 2) or modal (ratio on every mode)"},
      {"building#.hysteresis", "", "elastic", "storey law: " + storey_law_names()},
      {"building#.yield_shears", "N", "",
       "storey yield shears Fy > 0 (one value for all storeys, or a list); required by the "
       "inelastic laws"},
      {"building#.p_delta", "", "false",
       "P-Delta: the gravity load P_i of the floors at and above storey i adds -P_i d_i / h_i "
       "to its shear (true/false)"},
      {"building#.gravity_loads", "N", "",
       "gravity load per floor for P-Delta (one value for all floors, or a list; default m g)"},
      {"building#.damping_stiffness", "", "initial",
       "stiffness of the stiffness-proportional Rayleigh damping: initial (k0) or tangent (each "
       "storey's current tangent stiffness, at least 0; Charney 2008)"},
      {"pair#.gap", "m", "0",
       "at-rest gap between building # and #+1 (one value, or one per colliding floor)"},
      {"contact.model", "", "lve", "contact model: " + contact_model_names()},
      {"contact.e", "-", "0.65", "coefficient of restitution, in (0, 1]"},
      {"contact.k", "N/m or N/m^1.5", "",
       "contact stiffness (N/m for linear laws, N/m^1.5 for Hertz laws)"},
      {"contact.k_factor", "-", "",
       "contact stiffness as a multiple of the larger storey stiffness (when k is not given)"},
      {"contact.v0_min", "m/s", "0.001",
       "smallest approach velocity used by v0-scaled damping (Hertzdamp, Ye, Hunt-Crossley)"},
      {"contact.xi_relation", "", "exact",
       "MLVe damping-restitution relation: exact or published (Mahmoud & Jankowski 2011)"},
      {"contact.force_cap", "N", "",
       "cap on the contact force, > 0 (default none): above it the face crushes (the force stays "
       "at the cap, a permanent indentation grows and widens the gap); every lumped law but "
       "stereomechanical"},
      {"motion.file", "", "", "ground-motion record (.AT2, one/two columns, or fixed width)"},
      {"motion.format", "", "automatic", "automatic, at2, columns or fixed-width"},
      {"motion.units", "", "",
       "units of the record values when the file does not state "
       "them: g, m/s2 or cm/s2"},
      {"motion.dt", "s", "", "sample spacing of a one-column record without a header"},
      {"motion.scale", "-", "1", "factor applied to the record"},
      {"motion.duration", "s", "", "use only the first seconds of the record"},
      {"motion.baseline", "", "false", "baseline-correct the record (true/false)"},
      {"motion.check_pga", "", "true",
       "refuse a record whose peak acceleration is above 10 g or below 1e-6 g (wrong units or "
       "values); false accepts it (true/false)"},
      {"integrator", "", "",
       "shorthand: event (adaptive steps, fine only through contacts) or fixed (with --dt)"},
      {"dt", "s", "", "shorthand for the fixed step (integrator.dt, sears.dt)"},
      {"integrator.control", "", "adaptive",
       "adaptive (error-controlled Dormand-Prince 5(4); also 'event') or fixed"},
      {"integrator.rtol", "-", "1e-8", "relative local-error tolerance"},
      {"integrator.atol", "m", "1e-10", "absolute local-error tolerance (m and m/s)"},
      {"integrator.dt", "s", "", "step of the fixed-step integrator"},
      {"integrator.h_max", "s", "", "largest adaptive step (default min(record dt, T_min/20))"},
      {"integrator.free_steps", "", "exact",
       "lumped rows between contacts and yield events: exact (the linear system's exact step "
       "on the h_max grid) or dopri5 (adaptive Dormand-Prince throughout)"},
      {"simulation.extra_time", "s", "0", "free vibration simulated after the record ends"},
      {"simulation.collapse_drift_ratio", "-", "0.1",
       "a building whose storey drift ratio passes this has collapsed: the run stops there "
       "(pounding run) or the building stops (free run)"},
  };
}

namespace {

bool parse_bool(const Options& opt, const std::string& key) {
  const std::string v = opt.get_string(key);
  if (v == "true" || v == "yes" || v == "1" || v == "on") return true;
  if (v == "false" || v == "no" || v == "0" || v == "off") return false;
  throw opt.invalid(key, "valid: true or false");
}

// One value for every storey or one per storey; `valid` checks a value.
template <class Valid>
std::vector<double> storey_list(const Options& opt, const std::string& key, std::size_t n,
                                const std::string& what, Valid valid) {
  return opt.get_per_floor(key, n, what, valid);
}

std::vector<double> positive_list(const Options& opt, const std::string& key, std::size_t n,
                                  const std::string& what) {
  return storey_list(opt, key, n, what + " must be > 0", [](double x) { return x > 0; });
}

// [buildingN] hysteresis, yield_shears and the storey-law keys.
void read_hysteresis(const Options& opt, const std::string& pre, Building& bd) {
  const std::size_t n = bd.masses.size();
  bd.hysteresis = opt.get_string(pre + "hysteresis");
  find_storey_law(bd.hysteresis, opt.where(pre + "hysteresis"));
  if (opt.given(pre + "yield_shears"))
    bd.yield_shears = positive_list(opt, pre + "yield_shears", n, "every storey yield shear");
  else if (bd.inelastic())
    throw InputError(opt.where(pre + "yield_shears") + ": missing; hysteresis '" + bd.hysteresis +
                     "' needs the storey yield shears Fy > 0 in N (one value or one per storey)");
  read_storey_law_keys(opt, pre, bd);
}

}  // namespace

void read_storey_law_keys(const Options& opt, const std::string& pre, Building& bd) {
  const std::size_t n = bd.masses.size();
  bd.hardening = storey_list(opt, pre + "hardening", n, "valid: b = k_post / k0 in [0, 1)",
                             [](double x) { return x >= 0 && x < 1; });
  bd.bw_n = storey_list(opt, pre + "bw_n", n, "valid: a Bouc-Wen exponent n > 0",
                        [](double x) { return x > 0; });
  bd.cap_strength_ratio =
      storey_list(opt, pre + "cap_strength_ratio", n, "valid: a cap strength ratio Fc / Fy >= 1",
                  [](double x) { return x >= 1; });
  auto positive = [&](const char* key, const std::string& what) {
    return storey_list(opt, pre + key, n, "valid: " + what + " > 0",
                       [](double x) { return x > 0; });
  };
  bd.plastic_drift_ratio = positive("plastic_drift_ratio", "a plastic drift ratio theta_p");
  bd.post_cap_drift_ratio = positive("post_cap_drift_ratio", "a post-capping drift ratio theta_pc");
  bd.residual_strength_ratio = storey_list(opt, pre + "residual_strength_ratio", n,
                                           "valid: a residual strength ratio Fr / Fy in [0, 1)",
                                           [](double x) { return x >= 0 && x < 1; });
  bd.energy_capacity = positive("energy_capacity", "an energy capacity lambda");
  bd.energy_exponent = positive("energy_exponent", "an energy exponent c");
  bd.ultimate_drift_ratio.clear();
  const std::string u = pre + "ultimate_drift_ratio";
  if (!opt.given(u)) return;
  bd.ultimate_drift_ratio = positive("ultimate_drift_ratio", "an ultimate drift ratio theta_u");
  if (bd.hysteresis != "imk") return;
  for (std::size_t j = 0; j < n; ++j) {
    const StoreyParameters p = bd.storey(static_cast<int>(j));
    const double cap = p.uy() / p.h + p.plastic_drift_ratio;
    if (!(p.ultimate_drift_ratio >= cap)) {
      char b[200];
      std::snprintf(b, sizeof b,
                    "valid: theta_u not below the cap drift ratio uy / h + theta_p = %.6g of "
                    "storey %zu (uy = Fy / k0)",
                    cap, j + 1);
      throw opt.invalid(u, b);
    }
  }
}

namespace {

// [buildingN] p_delta, gravity_loads, damping_stiffness.
void read_gravity(const Options& opt, const std::string& pre, Building& bd) {
  bd.p_delta = parse_bool(opt, pre + "p_delta");
  if (opt.given(pre + "gravity_loads"))
    bd.gravity_loads = storey_list(opt, pre + "gravity_loads", bd.masses.size(),
                                   "valid: gravity loads > 0 N", [](double x) { return x > 0; });
  const std::string ds = opt.get_string(pre + "damping_stiffness");
  if (ds == "initial")
    bd.damping_stiffness = DampingStiffness::initial;
  else if (ds == "tangent")
    bd.damping_stiffness = DampingStiffness::tangent;
  else
    throw opt.invalid(pre + "damping_stiffness", "valid: initial or tangent");
}

// "building1..building3", or "building1" for one.
std::string numbered_range(const std::string& prefix, long hi) {
  return prefix + "1" + (hi > 1 ? ".." + prefix + std::to_string(hi) : "");
}

// The count of the numbered sections given without a gap from 1 (buildings 1, 2, 3: 3). A
// section past a gap (building5 without building4, building2000000000000) is an error naming
// its key; found from the keys given, in time independent of the number.
int consecutive_buildings(const Options& opt) {
  long n = 0;
  for (const auto& [number, key] : opt.numbered_sections("building")) {
    if (number != n + 1) {
      const std::string next = "building" + std::to_string(n + 1);
      throw InputError(opt.where(key) + ": " +
                       (n == 0
                            ? "there is no building1"
                            : "the row has " + numbered_range("building", n) + " and no " + next) +
                       " (" + next +
                       ".masses is missing; buildings are numbered 1, 2, 3, ... without gaps), "
                       "so valid: " +
                       numbered_range("building", n + 1));
    }
    ++n;
  }
  return static_cast<int>(n);
}

// Where the building's slabs stand (issue 36): its base's level, the slabs' thickness and the
// share of a storey's stiffness in the face's columns.
void read_elevations(const Options& opt, const std::string& pre, Building& bd) {
  bd.base_elevation = opt.get_double(pre + "base_elevation");
  if (!std::isfinite(bd.base_elevation))
    throw opt.invalid(pre + "base_elevation", "valid: a finite level in m");
  bd.slab_thickness = opt.get_double(pre + "slab_thickness");
  if (!(bd.slab_thickness > 0.0 && std::isfinite(bd.slab_thickness)))
    throw opt.invalid(pre + "slab_thickness", "valid: a finite thickness > 0 m");
  bd.face_column_share = opt.get_double(pre + "face_column_share");
  if (!(bd.face_column_share > 0.0 && bd.face_column_share <= 1.0))
    throw opt.invalid(pre + "face_column_share", "valid: a share in (0, 1]");
}

}  // namespace

BuildingRow row_from_options(const Options& opt) {
  BuildingRow row;
  const int nb = consecutive_buildings(opt);
  if (nb == 0)
    throw InputError((opt.config_path().empty() ? std::string("command line") : opt.config_path()) +
                     ": no buildings; give [building1] masses = ... and stiffnesses = ...");
  for (int b = 1; b <= nb; ++b) {
    const std::string pre = "building" + std::to_string(b) + ".";
    Building bd;
    bd.name =
        opt.given(pre + "name") ? opt.get_string(pre + "name") : "building" + std::to_string(b);
    // Result files list the names joined by commas (building_names).
    if (bd.name.find_first_not_of(" \t") == std::string::npos ||
        bd.name.find(',') != std::string::npos)
      throw opt.invalid(pre + "name", "valid: a non-empty label without commas");
    const auto masses = opt.get_doubles(pre + "masses");
    for (double m : masses)
      if (!(m > 0)) throw opt.invalid(pre + "masses", "every floor mass must be > 0 kg");
    bd.masses = masses;
    bd.stiffnesses =
        positive_list(opt, pre + "stiffnesses", masses.size(), "every storey stiffness");
    bd.storey_heights =
        positive_list(opt, pre + "storey_heights", masses.size(), "every storey height");
    read_elevations(opt, pre, bd);
    if (opt.given(pre + "column_shear_strength"))
      bd.column_shear_strength = positive_list(opt, pre + "column_shear_strength", masses.size(),
                                               "every column shear strength");
    bd.damping_ratio = opt.get_double(pre + "damping");
    if (!(bd.damping_ratio >= 0 && bd.damping_ratio < 1))
      throw opt.invalid(pre + "damping", "valid: a damping ratio in [0, 1)");
    const std::string dt = opt.get_string(pre + "damping_type");
    if (dt == "rayleigh")
      bd.damping = DampingKind::rayleigh;
    else if (dt == "modal")
      bd.damping = DampingKind::modal;
    else
      throw opt.invalid(pre + "damping_type", "valid: rayleigh or modal");
    read_hysteresis(opt, pre, bd);
    read_gravity(opt, pre, bd);
    bd.foundation = foundation_from_options(opt, pre, masses.size());
    validate_gravity(bd, opt.where(pre + (bd.p_delta ? "p_delta" : "damping_stiffness")));
    validate(bd, opt.where(pre + "masses"));
    row.buildings.push_back(bd);
  }
  for (int p = 1; p < nb; ++p) {
    const std::string key = "pair" + std::to_string(p) + ".gap";
    const auto levels = static_cast<std::size_t>(colliding_levels(row, p - 1));
    std::vector<double> g = opt.get_doubles(key);
    if (g.size() == 1) g.assign(levels, g[0]);
    if (g.size() != levels)
      throw opt.invalid(key, "expected one gap or " + std::to_string(levels) +
                                 " (one per contact site, in the order pound simulate --json "
                                 "lists them), in m");
    for (double x : g)
      if (!(x >= 0)) throw opt.invalid(key, "gaps must be >= 0 m");
    row.gaps.push_back(g);
  }
  // A pair past the last (pair5 of three buildings, pair999999999): its key is named, from the
  // keys given (a loop up to its number took minutes, and a number held at 10^9 went unseen).
  for (const auto& [p, key] : opt.numbered_sections("pair"))
    if (p >= nb)
      throw opt.invalid(key, nb == 1
                                 ? std::string("there is only 1 building, so no pair")
                                 : "there are only " + std::to_string(nb) +
                                       " buildings, so valid: " + numbered_range("pair", nb - 1));
  return row;
}

bool ContactUse::sears() const {
  return std::any_of(models.begin(), models.end(), is_sears_model);
}

bool ContactUse::lumped() const {
  return std::any_of(models.begin(), models.end(),
                     [](const std::string& m) { return !is_sears_model(m); });
}

ContactUse single_model_use(const Options& opt) {
  ContactUse use;
  use.models.push_back(opt.get_string("contact.model"));
  return use;
}

ContactSpec contact_from_options(const Options& opt, const BuildingRow& row,
                                 const ContactUse& use) {
  ContactSpec c;
  c.model = opt.get_string("contact.model");
  if (!is_sears_model(c.model)) find_contact_model(c.model, opt.where("contact.model"));
  c.params.e = opt.get_double("contact.e");
  if (!(c.params.e > 0 && c.params.e <= 1)) throw opt.invalid("contact.e", "valid: e in (0, 1]");
  c.params.v0_min = opt.get_positive("contact.v0_min");
  c.params.xi_relation = opt.get_string("contact.xi_relation");
  if (c.params.xi_relation != "exact" && c.params.xi_relation != "published")
    throw opt.invalid("contact.xi_relation", "valid: exact or published");
  if (opt.given("contact.force_cap")) {
    c.force_cap = opt.get_positive("contact.force_cap");
    // Crushing needs a force history: the stereomechanical jump has none.
    for (const auto& m : use.models)
      if (!is_sears_model(m) &&
          find_contact_model(m, opt.where("contact.model")).stiffness_unit.empty())
        throw opt.invalid("contact.force_cap",
                          "valid only with a model that has a force history; contact.model '" + m +
                              "' is an instantaneous impact, with no force to cap");
  }
  // The stiffness: of the first model of `use` that has one (the lumped models share k).
  const ContactModelInfo* needs_k = nullptr;
  for (const auto& m : use.models)
    if (!is_sears_model(m) && !needs_k) {
      const auto& info = find_contact_model(m, opt.where("contact.model"));
      if (!info.stiffness_unit.empty()) needs_k = &info;
    }
  if (opt.given("contact.k")) {
    c.params.k = opt.get_positive("contact.k");
  } else if (opt.given("contact.k_factor")) {
    double kmax = 0;
    for (const auto& b : row.buildings)
      for (double k : b.stiffnesses) kmax = std::max(kmax, k);
    c.params.k = opt.get_positive("contact.k_factor") * kmax;
  } else if (needs_k && !use.k_sampled && row.buildings.size() >= 2) {
    // One building: no pair, no contact; the law is never called, so k is not asked for.
    const std::string model = use.models.size() == 1 ? use.models[0] : needs_k->name;
    throw InputError(opt.where("contact.k") + ": missing; model '" + model +
                     "' needs a contact stiffness k [" + needs_k->stiffness_unit +
                     "] or k_factor (a multiple of the larger storey stiffness, commonly 20-100)" +
                     (use.k_alternative.empty() ? "" : " or " + use.k_alternative));
  }
  return c;
}

IntegratorSettings integrator_from_options(const Options& opt) {
  IntegratorSettings s;
  const std::string key = opt.given("integrator") ? "integrator" : "integrator.control";
  const std::string c = opt.get_string(key);
  if (c == "adaptive" || c == "event")
    s.control = StepControl::adaptive;
  else if (c == "fixed")
    s.control = StepControl::fixed;
  else
    throw opt.invalid(key, "valid: event (adaptive) or fixed");
  s.rtol = opt.get_positive("integrator.rtol");
  s.atol = opt.get_positive("integrator.atol");
  const std::string dt_key = opt.given("dt") ? "dt" : "integrator.dt";
  if (opt.given(dt_key)) s.dt = opt.get_positive(dt_key);
  if (s.control == StepControl::fixed && !(s.dt > 0))
    throw opt.invalid(dt_key, "fixed-step integration needs a step dt > 0 s (--dt)");
  if (opt.given("integrator.h_max")) s.h_max = opt.get_positive("integrator.h_max");
  const std::string free_steps = opt.get_string("integrator.free_steps");
  if (free_steps == "exact")
    s.exact_free = true;
  else if (free_steps == "dopri5")
    s.exact_free = false;
  else
    throw opt.invalid("integrator.free_steps", "valid: exact or dopri5");
  return s;
}

RowSimulationOptions simulation_from_options(const Options& opt) {
  RowSimulationOptions o;
  o.extra_time = opt.get_nonnegative("simulation.extra_time");
  o.collapse_drift_ratio = opt.get_positive("simulation.collapse_drift_ratio");
  return o;
}

MotionFileSpec motion_file_spec(const Options& opt, const std::string& path) {
  MotionFileSpec spec;
  spec.path = path;
  spec.format = parse_motion_format(opt.get_string("motion.format"), opt.where("motion.format"));
  if (opt.given("motion.units"))
    spec.units = parse_accel_units(opt.get_string("motion.units"), opt.where("motion.units"));
  if (opt.given("motion.dt")) spec.dt = opt.get_positive("motion.dt");
  spec.check_pga = parse_bool(opt, "motion.check_pga");
  return spec;
}

GroundMotion motion_from_options(const Options& opt) {
  return process_record(opt, read_motion(motion_file_spec(opt, opt.get_path("motion.file"))));
}

GroundMotion record_from_values(const Options& opt, const std::string& name, double dt,
                                std::vector<double> accel, const std::string& check_pga_key) {
  const bool check = parse_bool(opt, "motion.check_pga");
  return process_record(opt, motion_from_values(name, dt, std::move(accel), check, check_pga_key));
}

GroundMotion process_record(const Options& opt, GroundMotion g) {
  if (opt.given("motion.duration")) g = truncate(g, opt.get_positive("motion.duration"));
  const double s = opt.get_double("motion.scale");
  if (!(s > 0)) throw opt.invalid("motion.scale", "valid: a factor > 0");
  if (s != 1.0) g = scale(g, s);
  if (parse_bool(opt, "motion.baseline")) g = baseline_correct(g);
  return g;
}

}  // namespace pound
