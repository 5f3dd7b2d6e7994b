#include "study/ground_options.hpp"

#include <algorithm>
#include <cmath>

#include "core/format.hpp"
#include "ground/at_rest.hpp"
#include "ground/wave_passage.hpp"

namespace pound {

bool GroundSpec::positions_matter() const {
  return std::isfinite(apparent_velocity) || coherency.model != CoherencyModel::none;
}

std::vector<double> GroundSpec::delays() const {
  std::vector<double> d(motion_files.size(), 0.0);
  if (!std::isfinite(apparent_velocity) || positions.empty()) return d;
  d = arrival_delays(positions, apparent_velocity);
  for (std::size_t b = 0; b < d.size() && b < motion_files.size(); ++b)
    if (!motion_files[b].empty()) d[b] = 0.0;  // its own record, recorded where it stands
  return d;
}

std::vector<OptionSpec> ground_option_specs() {
  return {
      {"building#.position", "m", "",
       "base centre of the building along the row (building 1 leftmost; default side by side: "
       "half of each slab_length plus the gap at floor 1 between the centres)"},
      {"building#.motion_file", "", "",
       "the building's own record (read with the [motion] keys' units, format and dt; its dt "
       "must be the study's)"},
      {"ground.apparent_velocity", "m/s", "inf",
       "wave passage along the row, from building 1 towards the last (negative: back); inf: "
       "every building's motion arrives at once"},
      {"ground.coherency", "", "none",
       "lagged coherency of generated motions: " + coherency_model_names()},
      {"ground.coherency_parameters", "", "",
       "the coherency model's parameters in its order, SI (default: the model's; docs/ground.md)"},
  };
}

namespace {

std::string format_position(double x) {
  return format_number(x, "%.6g");
}

// [ground] apparent_velocity: a nonzero number or +-inf.
double read_velocity(const Options& opt) {
  const std::string key = "ground.apparent_velocity";
  std::string t = opt.get_string(key);
  t.erase(0, t.find_first_not_of(" \t"));
  t.erase(t.find_last_not_of(" \t") + 1);
  std::string lower = t;
  std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
  const double inf = std::numeric_limits<double>::infinity();
  if (lower == "inf" || lower == "+inf" || lower == "infinity") return inf;
  if (lower == "-inf" || lower == "-infinity") return -inf;
  const std::string valid =
      "valid: an apparent velocity in m/s, not 0 (negative: the wave travels from the last "
      "building towards building 1), or inf (no wave passage)";
  double v = 0.0;
  try {
    v = parse_number(t, opt.where(key));
  } catch (const InputError&) {
    throw opt.invalid(key, valid);
  }
  if (v == 0.0) throw opt.invalid(key, valid);
  return v;
}

// The first slab length of building b (1-based), or NaN when not given.
double slab_length(const Options& opt, int b) {
  const std::string key = "building" + std::to_string(b) + ".slab_length";
  if (!opt.given(key)) return std::nan("");
  const double l = opt.get_doubles(key).front();
  return l > 0.0 ? l : std::nan("");  // the Sears reader names a bad value
}

void read_positions(const Options& opt, const BuildingRow& row, bool matter, GroundSpec& g) {
  const int nb = static_cast<int>(row.buildings.size());
  std::vector<double> x(nb, std::nan("")), len(nb);
  for (int b = 1; b <= nb; ++b) {
    len[b - 1] = slab_length(opt, b);
    const std::string key = "building" + std::to_string(b) + ".position";
    if (opt.given(key)) x[b - 1] = opt.get_double(key);
  }
  // Side by side where not given: building 1 at 0, each next centre half of each slab length
  // plus the gap at floor 1 further.
  for (int b = 0; b < nb; ++b) {
    if (!std::isnan(x[b])) continue;
    if (b == 0) {
      if (!std::isnan(len[0])) x[0] = 0.0;
      continue;
    }
    if (!std::isnan(x[b - 1]) && !std::isnan(len[b - 1]) && !std::isnan(len[b]))
      x[b] = x[b - 1] + 0.5 * len[b - 1] + row.gaps[b - 1].front() + 0.5 * len[b];
  }
  for (int b = 0; b < nb; ++b) {
    const std::string key = "building" + std::to_string(b + 1) + ".position";
    if (std::isnan(x[b])) {
      if (!matter) return;  // positions do not enter: none are kept
      throw InputError(opt.where(key) +
                       ": missing; wave passage and coherency need each building's position "
                       "along the row in m (or every building's slab_length, for side by side)");
    }
    if (b > 0 && !(x[b] > x[b - 1]))
      throw opt.invalid(key, "positions increase along the row (building " + std::to_string(b) +
                                 " is at " + format_position(x[b - 1]) + " m)");
    if (b > 0 && !std::isnan(len[b]) && !std::isnan(len[b - 1]) &&
        x[b] - 0.5 * len[b] < x[b - 1] + 0.5 * len[b - 1] - 1e-9 * std::fabs(x[b]))
      throw opt.invalid(
          key, "a position at least " + format_position(x[b - 1] + 0.5 * (len[b - 1] + len[b])) +
                   " m (building " + std::to_string(b + 1) + " overlaps building " +
                   std::to_string(b) + ": slab lengths " + format_position(len[b - 1]) + " and " +
                   format_position(len[b]) + " m)");
  }
  g.positions = x;
}

}  // namespace

GroundSpec ground_from_options(const Options& opt, const BuildingRow& row, bool sampled_velocity) {
  GroundSpec g;
  g.apparent_velocity = read_velocity(opt);
  std::vector<double> params;
  if (opt.given("ground.coherency_parameters"))
    params = opt.get_doubles("ground.coherency_parameters");
  g.coherency = make_coherency(
      opt.get_string("ground.coherency"), params,
      opt.where(opt.given("ground.coherency_parameters") ? "ground.coherency_parameters"
                                                         : "ground.coherency"));
  const int nb = static_cast<int>(row.buildings.size());
  for (int b = 1; b <= nb; ++b) {
    const std::string key = "building" + std::to_string(b) + ".motion_file";
    g.motion_files.push_back(opt.given(key) ? opt.get_path(key) : "");
  }
  read_positions(opt, row, g.positions_matter() || sampled_velocity, g);
  return g;
}

void refuse_coherency_with_records(const Options& opt, const GroundSpec& g) {
  if (g.coherency.model == CoherencyModel::none) return;
  throw opt.invalid("ground.coherency",
                    "none with recorded motions: coherency loss needs new motions (generated, "
                    "motion.source = generated in a campaign); a record under several buildings "
                    "gets wave passage only (ground.apparent_velocity)");
}

RowGround row_ground(const GroundSpec& g, const GroundMotion& reference,
                     const std::vector<GroundMotion>& own, bool generated) {
  const std::vector<double> delay = g.delays();
  std::vector<GroundMotion> motions;
  for (std::size_t b = 0; b < delay.size(); ++b) {
    const GroundMotion& m = b < own.size() && !own[b].accel.empty() ? own[b] : reference;
    motions.push_back(delay[b] > 0.0 ? delayed(m, delay[b]) : m);
  }
  if (generated) end_at_rest_where_they_differ(motions);
  return RowGround::per_building(motions);
}

}  // namespace pound
