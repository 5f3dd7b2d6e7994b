#include "ground/station_set.hpp"

#include <cmath>
#include <limits>
#include <utility>

#include "core/error.hpp"
#include "ground/at_rest.hpp"
#include "ground/ground_trace.hpp"
#include "ground/wave_passage.hpp"
#include "motion/motion_processing.hpp"
#include "motion/response_spectrum.hpp"
#include "sampling/counter_rng.hpp"

namespace pound {
namespace {

constexpr long kMaxStations = 50;
constexpr double kHalfBand = 0.25;  // [Hz]

const char* const kStationKeys[] = {"stations",          "spacing",   "positions",
                                    "apparent-velocity", "coherency", "coherency-parameters"};

// The station coordinates [m] of --stations N --spacing D (station 1 at 0) or --positions.
std::vector<double> positions_from_options(const Options& o) {
  const bool n = o.given("stations"), d = o.given("spacing"), p = o.given("positions");
  if (p && (n || d))
    throw o.invalid("positions", "give --positions or --stations with --spacing, not both");
  if (n != d)
    throw o.invalid(n ? "stations" : "spacing",
                    "give --stations N and --spacing D (m) together, or --positions x1,x2,...");
  std::vector<double> x;
  if (p) {
    x = o.get_doubles("positions");
    if (x.empty() || long(x.size()) > kMaxStations)
      throw o.invalid("positions", "valid: 1 to " + std::to_string(kMaxStations) + " positions");
    for (std::size_t j = 1; j < x.size(); ++j)
      if (!(x[j] > x[j - 1]))
        throw o.invalid("positions", "valid: strictly increasing coordinates in m (position " +
                                         std::to_string(j + 1) + " is not above position " +
                                         std::to_string(j) + ")");
    return x;
  }
  const long count = o.get_int("stations");
  if (count < 1 || count > kMaxStations)
    throw o.invalid("stations", "valid: 1 to " + std::to_string(kMaxStations));
  const double spacing = o.get_double("spacing");
  if (!(spacing > 0.0)) throw o.invalid("spacing", "valid: a spacing > 0 m");
  for (long j = 0; j < count; ++j) x.push_back(spacing * double(j));
  return x;
}

// --apparent-velocity: a non-zero number or +-inf [m/s].
double velocity_from_options(const Options& o) {
  const double inf = std::numeric_limits<double>::infinity();
  if (!o.given("apparent-velocity")) return inf;
  const std::string text = o.get_string("apparent-velocity");
  if (text == "inf" || text == "+inf") return inf;
  if (text == "-inf") return -inf;
  const std::string valid =
      "valid: a non-zero velocity in m/s (negative: waves from the last station towards "
      "station 1) or inf (no delay)";
  double v = 0.0;
  try {
    v = parse_number(text, o.where("apparent-velocity"));
  } catch (const InputError&) {
    throw o.invalid("apparent-velocity", valid);
  }
  if (v == 0.0) throw o.invalid("apparent-velocity", valid);
  return v;
}

Coherency coherency_from_options(const Options& o) {
  if (o.given("coherency-parameters") && !o.given("coherency"))
    throw o.invalid("coherency-parameters",
                    "give --coherency MODEL too (" + coherency_model_names() + ")");
  if (!o.given("coherency")) return Coherency{};
  const std::vector<double> p = o.given("coherency-parameters")
                                    ? o.get_doubles("coherency-parameters")
                                    : std::vector<double>{};
  const std::string name = o.get_string("coherency");
  return make_coherency(
      name, p, o.where(o.given("coherency-parameters") ? "coherency-parameters" : "coherency"));
}

}  // namespace

std::vector<OptionSpec> station_set_option_specs() {
  std::vector<OptionSpec> specs = motion_set_option_specs();
  const std::vector<OptionSpec> own = {
      {"stations", "-", "",
       "stations along the row (issue 28; with --spacing): motion-NNN-sK.txt per station"},
      {"spacing", "m", "", "distance between neighbouring stations (station 1 at 0)"},
      {"positions", "m", "", "station coordinates x1,x2,... along the row, strictly increasing"},
      {"apparent-velocity", "m/s", "",
       "apparent velocity of the waves along the row, station 1 first (negative: from the last "
       "station; default inf: no delay)"},
      {"coherency", "", "",
       "lagged coherency between stations: " + coherency_model_names() + " (default none)"},
      {"coherency-parameters", "", "",
       "the model's parameters in its order, SI (default: the model's; docs/ground.md)"},
  };
  specs.insert(specs.end(), own.begin(), own.end());
  return specs;
}

StationSetRequest station_set_from_options(const Options& o) {
  StationSetRequest r;
  r.apparent_velocity = std::numeric_limits<double>::infinity();
  for (const char* k : kStationKeys) r.enabled = r.enabled || o.given(k);
  if (r.enabled && !o.given("stations") && !o.given("spacing") && !o.given("positions")) {
    const char* key = o.given("apparent-velocity") ? "apparent-velocity"
                      : o.given("coherency")       ? "coherency"
                                                   : "coherency-parameters";
    throw o.invalid(key, "give the stations too: --stations N --spacing D or --positions LIST");
  }
  if (r.enabled) {
    r.stations.positions = positions_from_options(o);
    r.apparent_velocity = velocity_from_options(o);
    r.stations.coherency = coherency_from_options(o);
    r.delays = arrival_delays(r.stations.positions, r.apparent_velocity);
  }
  r.motions = motion_set_from_options(o);
  return r;
}

std::vector<double> curve_frequencies(double dt) {
  const double top = std::min(10.0, 0.8 * 0.5 / dt - kHalfBand);
  std::vector<double> f;
  for (int i = 2; 0.25 * i <= top + 1e-12; ++i) f.push_back(0.25 * i);
  return f;
}

std::vector<double> report_frequencies(double dt) {
  std::vector<double> out;
  for (double f : {1.0, 2.0, 4.0, 6.0})
    if (f <= std::min(10.0, 0.8 * 0.5 / dt - kHalfBand) + 1e-12) out.push_back(f);
  return out;
}

StationSet generate_station_set(const StationSetRequest& request) {
  const MotionSetRequest& rq = request.motions;
  const DesignSpectrum& target = *rq.target;
  const SimqkeSettings& s = rq.settings;
  StationGenerator gen(target, rq.duration, s, request.stations);
  const std::size_t ns = request.stations.positions.size(), off = std::size_t(s.match_extend);
  StationSet out;
  out.periods = log_spaced_periods(s.match_t_min, s.match_t_max, s.match_periods);
  const std::size_t np = out.periods.size();
  out.design = target.sample(out.periods);
  const SpectrumCalculator calc(out.periods, target.damping(), s.dt);
  const TargetVariability var(rq.variability, gen.match_periods());
  out.variable = var.enabled();
  if (out.variable)
    out.sigma.assign(var.sigma().begin() + long(off), var.sigma().begin() + long(off + np));
  const CounterRng target_rng(std::uint64_t(rq.seed), stream_id(kTargetStream));
  out.mean.assign(ns * np, 0.0);
  out.geomean.assign(ns * np, 0.0);
  for (long i = 0; i < rq.count; ++i) {
    std::vector<GeneratedMotion> g;
    if (var.enabled()) {
      const std::vector<double> eps = var.epsilon(target_rng, std::uint64_t(i));
      g = gen.generate(std::uint64_t(rq.seed), std::uint64_t(i), var.ln_factor(eps));
      out.eps.insert(out.eps.end(), eps.begin() + long(off), eps.begin() + long(off + np));
    } else {
      g = gen.generate(std::uint64_t(rq.seed), std::uint64_t(i));
    }
    const std::vector<double> own(g.front().target_psa.begin() + long(off),
                                  g.front().target_psa.begin() + long(off + np));
    out.targets.insert(out.targets.end(), own.begin(), own.end());
    std::vector<GroundMotion> row;
    std::vector<MotionReport> reports;
    for (std::size_t j = 0; j < ns; ++j) row.push_back(delayed(g[j].motion, request.delays[j]));
    end_at_rest_where_they_differ(row);  // as a campaign's (at_rest.hpp)
    for (std::size_t j = 0; j < ns; ++j) {
      std::vector<double> psa;
      calc.compute_psa(row[j].accel, psa);
      MotionReport r;
      r.match = compare_spectra(psa, own);
      r.pga = row[j].pga();
      // The delayed record's end as the solvers integrate it (from rest one sample before the
      // record, ground_trace.hpp): 0 to round-off when the stations differ (at_rest.hpp).
      const GroundTrace trace(row[j]);
      trace.kinematics(trace.duration(), r.v_end, r.d_end);
      r.iterations = g[j].iterations;
      r.attempt = g[j].attempt;
      reports.push_back(r);
      for (std::size_t p = 0; p < np; ++p) {
        out.mean[j * np + p] += psa[p] / double(rq.count);
        out.geomean[j * np + p] += std::log(psa[p]) / double(rq.count);
      }
      out.psa.insert(out.psa.end(), psa.begin(), psa.end());
    }
    out.motions.push_back(std::move(row));
    out.reports.push_back(std::move(reports));
  }
  for (double& x : out.geomean) x = std::exp(x);
  out.coherency =
      achieved_coherency(out.motions, request.stations.positions, request.delays,
                         request.stations.coherency, curve_frequencies(s.dt), kHalfBand);
  return out;
}

}  // namespace pound
