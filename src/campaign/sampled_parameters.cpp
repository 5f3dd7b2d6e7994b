#include "campaign/sampled_parameters.hpp"

#include <algorithm>
#include <map>

#include "campaign/sampled_foundation.hpp"
#include "contact/registry.hpp"
#include "core/error.hpp"
#include "hysteresis/registry.hpp"

namespace pound {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Ranges.
constexpr ValidRange kPositive{};
constexpr ValidRange kNonnegative{true};

// Checks against the study.
void check_model(const SampledParameter& p, const BuildingRow&, const Options& smp) {
  if (p.distribution.kind() != DistributionKind::discrete)
    throw smp.invalid(
        p.key, "valid: discrete(name: weight, ...) with names from " + every_contact_model_name());
  for (const auto& l : p.distribution.labels())
    if (!is_sears_model(l)) find_contact_model(l, smp.where(p.key));
}

void check_has_yield_shears(const SampledParameter& p, const BuildingRow& row, const Options& smp) {
  if (!row.buildings[static_cast<std::size_t>(p.building)].yield_shears.empty()) return;
  std::string inelastic;
  for (const auto& law : storey_laws())
    if (law.name != "elastic") inelastic += (inelastic.empty() ? "" : " or ") + law.name;
  const std::string b = "building" + std::to_string(p.building + 1);
  throw InputError(smp.where(p.key) + ": " + b +
                   " has no yield_shears; its strength can be sampled only when " + b +
                   ".yield_shears gives the storey yield shears (N), with an inelastic " + b +
                   ".hysteresis (" + inelastic + ")");
}

// The IMK parameters act only on an imk building.
void check_is_imk(const SampledParameter& p, const BuildingRow& row, const Options& smp) {
  const Building& b = row.buildings[static_cast<std::size_t>(p.building)];
  if (b.hysteresis == "imk") return;
  const std::string name = "building" + std::to_string(p.building + 1);
  throw InputError(smp.where(p.key) + ": " + name + ".hysteresis is '" + b.hysteresis +
                   "'; the deteriorating storey's parameters are sampled only with " + name +
                   ".hysteresis = imk");
}

// Sets one IMK parameter of every storey of building b.
template <std::vector<double> Building::*member>
void set_every_storey(SampleModel& m, int b, double v) {
  Building& bd = m.row.buildings[static_cast<std::size_t>(b)];
  (bd.*member).assign(bd.masses.size(), v);
}

// Scales every entry of v by f.
void scale(std::vector<double>& v, double f) {
  for (double& x : v) x *= f;
}

Building& building(SampleModel& m, int b) {
  return m.row.buildings[static_cast<std::size_t>(b)];
}

}  // namespace

const std::vector<SampledParameterSpec>& sampled_parameter_table() {
  using S = SampleModel;
  // The soil and foundation entries (issue 29) follow, from sampled_foundation.cpp.
  static const std::vector<SampledParameterSpec> table = with_foundation_parameters({
      {"e",
       "-",
       "coefficient of restitution (distribution)",
       SampleStage::direct,
       {false, -kInf, 1.0, true, "e must stay in (0, 1]; truncate at 1"},
       [](S& m, int, double v) { m.contact.params.e = v; },
       nullptr},
      {"k", "N/m or N/m^1.5", "contact stiffness (distribution)", SampleStage::direct, kPositive,
       [](S& m, int, double v) { m.contact.params.k = v; }, nullptr, true},
      // After the stiffness scales: the larger storey stiffness of the sample's row.
      {"k_factor", "-", "contact stiffness / larger storey stiffness (distribution)",
       SampleStage::after_row, kPositive,
       [](S& m, int, double v) {
         double kmax = 0;
         for (const auto& b : m.row.buildings)
           for (double k : b.stiffnesses) kmax = std::max(kmax, k);
         m.contact.params.k = v * kmax;
       },
       nullptr, true},
      {"gap", "m", "gap at every colliding floor of every pair (distribution)", SampleStage::direct,
       kNonnegative,
       [](S& m, int, double v) {
         for (auto& g : m.row.gaps) g.assign(g.size(), v);
       },
       nullptr},
      {"damping",
       "-",
       "damping ratio of every building (distribution)",
       SampleStage::direct,
       {true, -kInf, 1.0, false, "damping must stay below 1"},
       [](S& m, int, double v) {
         for (auto& b : m.row.buildings) b.damping_ratio = v;
       },
       nullptr},
      {kSampledContactModelKey,
       "",
       "contact model: discrete(name: weight, ...)",
       SampleStage::label,
       {},
       nullptr,
       check_model},
      {"chi",
       "-",
       "wave-speed factor of the damped Sears model (distribution)",
       SampleStage::sears,
       {false, -kInf, 1.0, true, "chi must stay in (0, 1]; truncate at 1"},
       [](S& m, int, double v) { m.sears.chi = v; },
       nullptr},
      {"D",
       "-",
       "fraction factor of the Sears flat contact (distribution)",
       SampleStage::sears,
       {false, 1.0, kInf, true, "D must be >= 1; truncate at 1"},
       [](S& m, int, double v) { m.sears.D = v; },
       nullptr},
      {"building#.mass_scale", "-", "factor on the building's floor masses (distribution)",
       SampleStage::direct, kPositive,
       [](S& m, int b, double v) { scale(building(m, b).masses, v); }, nullptr},
      {"building#.stiffness_scale", "-",
       "factor on the building's storey stiffnesses (distribution)", SampleStage::direct, kPositive,
       [](S& m, int b, double v) { scale(building(m, b).stiffnesses, v); }, nullptr},
      {"building#.strength_scale", "-",
       "factor on the building's storey yield shears (distribution; needs its yield_shears)",
       SampleStage::direct, kPositive,
       [](S& m, int b, double v) { scale(building(m, b).yield_shears, v); },
       check_has_yield_shears},
      // Modelling uncertainty of the deteriorating storeys (issue 23; docs/hysteresis.md).
      {"building#.plastic_drift_ratio", "-",
       "imk: theta_p of every storey of the building, yield to cap (distribution)",
       SampleStage::direct, kPositive, set_every_storey<&Building::plastic_drift_ratio>,
       check_is_imk},
      {"building#.post_cap_drift_ratio", "-",
       "imk: theta_pc of every storey of the building, cap to zero strength (distribution)",
       SampleStage::direct, kPositive, set_every_storey<&Building::post_cap_drift_ratio>,
       check_is_imk},
      {"building#.energy_capacity", "-",
       "imk: lambda of every storey of the building, E_t = lambda Fy uy (distribution)",
       SampleStage::direct, kPositive, set_every_storey<&Building::energy_capacity>, check_is_imk},
      // Wave passage (issue 28): needs the buildings' positions (ground_options.hpp).
      {"ground.apparent_velocity", "m/s",
       "apparent velocity of the wave along the row, from building 1 (distribution, > 0)",
       SampleStage::direct, kPositive, [](S& m, int, double v) { m.ground.apparent_velocity = v; },
       nullptr, false, true},
      {"hardening",
       "-",
       "post-yield stiffness ratio b = k_post / k0 of every storey of every building, in [0, 1) "
       "(distribution)",
       SampleStage::direct,
       {true, -kInf, 1.0, false,
        "hardening b = k_post / k0 must stay in [0, 1); truncate the distribution below 1"},
       [](S& m, int, double v) {
         for (auto& b : m.row.buildings) b.hardening.assign(b.masses.size(), v);
       },
       nullptr},
  });
  return table;
}

bool SampledParameter::is_label() const {
  return spec && spec->stage == SampleStage::label;
}

std::vector<OptionSpec> sampled_option_specs() {
  std::vector<OptionSpec> specs;
  for (const auto& e : sampled_parameter_table()) specs.push_back({e.key, e.unit, "", e.help});
  return specs;
}

bool is_sampled(const Options& smp, const std::string& key) {
  if (!smp.given(key)) return false;
  std::string v = smp.get_string(key);
  v.erase(0, v.find_first_not_of(" \t"));
  v.erase(v.find_last_not_of(" \t") + 1);
  return v != "none";
}

std::vector<SampledParameter> read_sampled_parameters(const Options& opt, const BuildingRow& row) {
  const Options smp = opt.section("sample", sampled_option_specs());
  const int buildings = static_cast<int>(row.buildings.size());
  // A building the study does not have: the first key given under it is named.
  for (const auto& [number, key] : smp.numbered_sections("building"))
    if (number > buildings)
      throw InputError(smp.where(key) + ": the study has only " + std::to_string(buildings) +
                       (buildings == 1 ? " building (valid: building1)"
                                       : " buildings (valid: building1..building" +
                                             std::to_string(buildings) + ")"));

  // The given keys in sorted order (std::map), each with its entry and building.
  std::map<std::string, SampledParameter> given;
  for (const auto& e : sampled_parameter_table()) {
    const std::string pattern = e.key;
    const auto hash = pattern.find('#');
    if (hash == std::string::npos) {
      if (is_sampled(smp, pattern)) given[pattern] = {pattern, {}, &e, -1};
      continue;
    }
    for (int b = 1; b <= buildings; ++b) {
      const std::string k = pattern.substr(0, hash) + std::to_string(b) + pattern.substr(hash + 1);
      if (is_sampled(smp, k)) given[k] = {k, {}, &e, b - 1};
    }
  }

  std::vector<SampledParameter> out;
  for (auto& [k, p] : given) {
    p.distribution = Distribution::parse(smp.get_string(k), smp.where(k));
    if (!p.is_label()) {
      if (p.distribution.kind() == DistributionKind::discrete)
        p.distribution.lower();  // numeric check
      const double lo = p.distribution.lower(), hi = p.distribution.upper();
      const ValidRange& r = p.spec->range;
      if (!r.zero_allowed && !(lo > 0))
        throw smp.invalid(
            k, "its values must be > 0; truncate the distribution (e.g. normal(m, s, lo, hi))");
      if (r.zero_allowed && !(lo >= 0))
        throw smp.invalid(k, "its values must be >= 0; truncate the distribution");
      if (!(lo >= r.min) || !(r.max_inclusive ? hi <= r.max : hi < r.max))
        throw smp.invalid(k, r.message);
    }
    if (p.spec->check) p.spec->check(p, row, smp);
    out.push_back(std::move(p));
  }
  return out;
}

void apply_sampled(const std::vector<SampledParameter>& params, const std::vector<double>& values,
                   SampleModel& m) {
  for (const SampleStage stage : {SampleStage::direct, SampleStage::after_row, SampleStage::sears})
    for (std::size_t i = 0; i < params.size(); ++i)
      if (params[i].spec->stage == stage) params[i].spec->apply(m, params[i].building, values[i]);
}

}  // namespace pound
