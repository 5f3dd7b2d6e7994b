// pound motion generate --stations/--positions: the files and the report of a station set.
#include "app/motion_stations.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "app/motion_text_files.hpp"
#include "ground/coherency.hpp"
#include "io/atomic_file.hpp"
#include "io/h5.hpp"
#include "io/json.hpp"
#include "pound/version.hpp"

namespace pound::app {
namespace {

std::string number(double x, const char* format = "%g") {
  char b[40];
  std::snprintf(b, sizeof b, format, x);
  return b;
}

// Motion i, station j: DIR/motion-NNN-sK.txt (K = j + 1); the motion's target DIR/target-NNN.txt.
std::vector<std::vector<std::string>> write_text_files(const StationSet& g,
                                                       const StationSetRequest& rq,
                                                       const std::string& dir) {
  const MotionSetRequest& m = rq.motions;
  std::string header = "# pound motion generate (" + std::string(kVersion) + " " + kGitRevision +
                       ")\n# target: " + m.target->describe() + "\n";
  if (g.variable) header += "# variability: " + m.variability.describe() + "\n";
  header += "# coherency: " + rq.stations.coherency.describe() +
            "\n# apparent velocity: " + number(rq.apparent_velocity) + " m/s\n";
  std::vector<std::vector<std::string>> files(g.motions.size());
  const std::size_t np = g.periods.size();
  for (std::size_t i = 0; i < g.motions.size(); ++i) {
    char number_text[24];
    std::snprintf(number_text, sizeof number_text, "%03zu", i);
    const std::string id =
        "# seed: " + std::to_string(m.seed) + ", index: " + std::to_string(i) + "\n";
    for (std::size_t j = 0; j < g.motions[i].size(); ++j) {
      const std::string name =
          std::string("motion-") + number_text + "-s" + std::to_string(j + 1) + ".txt";
      files[i].push_back((std::filesystem::path(dir) / name).string());
      const std::string station = "# station " + std::to_string(j + 1) + " of " +
                                  std::to_string(g.motions[i].size()) + " at " +
                                  number(rq.stations.positions[j]) + " m, delayed by " +
                                  number(rq.delays[j]) + " s\n";
      write_text(files[i].back(), g.motions[i][j], header + id + station);
    }
    const std::vector<double> own(g.targets.begin() + long(i * np),
                                  g.targets.begin() + long((i + 1) * np));
    write_target(
        (std::filesystem::path(dir) / (std::string("target-") + number_text + ".txt")).string(),
        g.periods, own,
        header + id + "# the spectrum every station of motion-" + number_text +
            "-sK.txt was matched to\n");
  }
  return files;
}

// /coherency: the set's lags and lagged coherency beside the model's, every pair.
void write_coherency(hid_t f, const StationSet& g) {
  const AchievedCoherency& c = g.coherency;
  const std::size_t np = c.pairs.size(), nf = c.frequencies.size();
  std::vector<int> pair;
  std::vector<double> sep, lag, model_lag, model, achieved;
  for (const PairCoherency& p : c.pairs) {
    pair.push_back(p.j + 1);
    pair.push_back(p.k + 1);
    sep.push_back(p.separation);
    lag.push_back(p.lag);
    model_lag.push_back(p.model_lag);
    model.insert(model.end(), p.model.begin(), p.model.end());
    achieved.insert(achieved.end(), p.achieved.begin(), p.achieved.end());
  }
  h5::write(f, "/coherency/frequency", c.frequencies, nf, 0, "Hz");
  h5::write_array(f, "/coherency/pair", pair, {np, 2});
  h5::write(f, "/coherency/separation", sep, np, 0, "m");
  h5::write(f, "/coherency/lag", lag, np, 0, "s");
  h5::write(f, "/coherency/model_lag", model_lag, np, 0, "s");
  h5::write_array(f, "/coherency/model", model, {np, nf}, "-");
  h5::write_array(f, "/coherency/achieved", achieved, {np, nf}, "-");
  h5::attribute(f, "/coherency", "half_band_hz", c.half_band);
}

// DIR/motions.h5 with the station dimension (docs/motions.md, "Stations").
void write_motions_file(const std::string& dir, const StationSet& g, const StationSetRequest& rq,
                        const Options& o) {
  const MotionSetRequest& m = rq.motions;
  const std::size_t nm = g.motions.size(), ns = rq.stations.positions.size(), np = g.periods.size();
  std::size_t n = 0;
  for (const auto& row : g.motions)
    for (const GroundMotion& x : row) n = std::max(n, x.accel.size());
  AtomicPath out((std::filesystem::path(dir) / "motions.h5").string());
  {
    h5::File f(out.temp());
    std::vector<double> acc(nm * ns * n, 0.0), t(n), pga, vend, dend;
    std::vector<int> iters;
    for (std::size_t i = 0; i < n; ++i) t[i] = m.settings.dt * double(i);
    for (std::size_t i = 0; i < nm; ++i)
      for (std::size_t j = 0; j < ns; ++j) {
        const std::vector<double>& a = g.motions[i][j].accel;
        std::copy(a.begin(), a.end(), acc.begin() + long((i * ns + j) * n));
        const MotionReport& r = g.reports[i][j];
        pga.push_back(r.pga);
        vend.push_back(r.v_end);
        dend.push_back(r.d_end);
        iters.push_back(r.iterations);
      }
    h5::write(f.id(), "/motions/time", t, n, 0, "s");
    h5::write_array(f.id(), "/motions/acceleration", acc, {nm, ns, n}, "m/s^2");
    h5::write_array(f.id(), "/motions/psa", g.psa, {nm, ns, np}, "m/s^2");
    h5::write_array(f.id(), "/motions/pga", pga, {nm, ns}, "m/s^2");
    h5::write_array(f.id(), "/motions/final_velocity", vend, {nm, ns}, "m/s");
    h5::write_array(f.id(), "/motions/final_displacement", dend, {nm, ns}, "m");
    h5::write_array(f.id(), "/motions/iterations", iters, {nm, ns});
    h5::write(f.id(), "/motions/target_psa", g.targets, nm, np, "m/s^2");
    h5::write(f.id(), "/target/period", g.periods, np, 0, "s");
    h5::write(f.id(), "/target/psa", g.design, np, 0, "m/s^2");
    h5::write(f.id(), "/target/mean_psa", g.mean, ns, np, "m/s^2");
    h5::write(f.id(), "/target/geomean_psa", g.geomean, ns, np, "m/s^2");
    if (g.variable) {
      h5::write(f.id(), "/motions/epsilon", g.eps, nm, np, "-");
      h5::write(f.id(), "/target/sigma_lnsa", g.sigma, g.sigma.size(), 0, "-");
    }
    h5::write(f.id(), "/stations/position", rq.stations.positions, ns, 0, "m");
    h5::write(f.id(), "/stations/delay", rq.delays, ns, 0, "s");
    write_coherency(f.id(), g);
    h5::attribute(f.id(), "/", "stations", double(ns));
    h5::attribute(f.id(), "/", "apparent_velocity_mps", rq.apparent_velocity);
    h5::attribute(f.id(), "/", "coherency", rq.stations.coherency.describe());
    h5::attribute(f.id(), "/", "variability", m.variability.describe());
    h5::attribute(f.id(), "/", "design_pga_mps2", m.target->sa(0.0));
    h5::attribute(f.id(), "/", "target", m.target->describe());
    h5::attribute(f.id(), "/", "damping", m.target->damping());
    h5::attribute(f.id(), "/", "seed", double(m.seed));
    h5::attribute(f.id(), "/", "config", o.resolved_text());
    h5::attribute(f.id(), "/", "engine_version", kVersion);
    h5::attribute(f.id(), "/", "git_revision", kGitRevision);
    f.close();
  }
  out.commit();
}

// Indices of the report frequencies among the set's curve frequencies.
std::vector<std::size_t> report_columns(const StationSet& g, double dt) {
  std::vector<std::size_t> cols;
  for (double f : report_frequencies(dt))
    for (std::size_t k = 0; k < g.coherency.frequencies.size(); ++k)
      if (std::fabs(g.coherency.frequencies[k] - f) < 1e-9) cols.push_back(k);
  return cols;
}

void json_match(JsonWriter& w, const SpectrumMatch& m) {
  w.field("min_ratio", m.min_ratio).field("max_ratio", m.max_ratio);
  w.field("mean_ratio", m.mean_ratio);
}

void print_json(const StationSet& g, const std::vector<std::vector<std::string>>& files,
                const StationSetRequest& rq, const std::string& dir) {
  const MotionSetRequest& m = rq.motions;
  const std::size_t ns = rq.stations.positions.size(), np = g.periods.size();
  JsonWriter w;
  w.begin_object().field("target", m.target->describe()).field("out", dir);
  w.field("variability", m.variability.describe());
  w.field("coherency_model", rq.stations.coherency.describe());
  w.field("apparent_velocity_mps", rq.apparent_velocity);  // null when infinite
  w.key("stations").begin_array();
  for (std::size_t j = 0; j < ns; ++j)
    w.begin_object()
        .field("station", int(j + 1))
        .field("position_m", rq.stations.positions[j])
        .field("delay_s", rq.delays[j])
        .end_object();
  w.end_array().key("motions").begin_array();
  for (std::size_t i = 0; i < g.reports.size(); ++i) {
    w.begin_object().field("index", long(i)).key("stations").begin_array();
    for (std::size_t j = 0; j < ns; ++j) {
      const MotionReport& r = g.reports[i][j];
      w.begin_object().field("station", int(j + 1)).field("file", files[i][j]);
      json_match(w, r.match);
      w.field("pga_g", r.pga / kGravity)
          .field("final_velocity_mps", r.v_end)
          .field("final_displacement_m", r.d_end)
          .field("iterations", r.iterations)
          .field("phase_set", r.attempt)
          .end_object();
    }
    w.end_array().end_object();
  }
  w.end_array();
  for (const char* key : {"mean", "geometric_mean"}) {
    const std::vector<double>& v = std::string(key) == "mean" ? g.mean : g.geomean;
    w.key(key).begin_array();
    for (std::size_t j = 0; j < ns; ++j) {
      const std::vector<double> row(v.begin() + long(j * np), v.begin() + long((j + 1) * np));
      w.begin_object().field("station", int(j + 1));
      json_match(w, compare_spectra(row, g.design));
      w.end_object();
    }
    w.end_array();
  }
  const std::vector<std::size_t> cols = report_columns(g, m.settings.dt);
  w.key("coherency").begin_object().field("half_band_hz", g.coherency.half_band);
  w.key("frequencies_hz").begin_array();
  for (std::size_t k : cols) w.value(g.coherency.frequencies[k]);
  w.end_array().key("pairs").begin_array();
  for (const PairCoherency& p : g.coherency.pairs) {
    w.begin_object().key("stations").begin_array().value(p.j + 1).value(p.k + 1).end_array();
    w.field("separation_m", p.separation).field("model_lag_s", p.model_lag).field("lag_s", p.lag);
    for (const char* key : {"model", "achieved"}) {
      w.key(key).begin_array();
      for (std::size_t k : cols) w.value(std::string(key) == "model" ? p.model[k] : p.achieved[k]);
      w.end_array();
    }
    w.end_object();
  }
  w.end_array().end_object().end_object();
  std::cout << w.str() << "\n";
}

void print_coherency_table(const StationSet& g, double dt) {
  const std::vector<std::size_t> cols = report_columns(g, dt);
  std::printf("# lag and lagged coherency of the set (+- %g Hz), model / achieved\n",
              g.coherency.half_band);
  std::printf("%-6s %8s %17s", "pair", "d [m]", "lag [s]");
  for (std::size_t k : cols) std::printf("      %4g Hz", g.coherency.frequencies[k]);
  std::printf("\n");
  for (const PairCoherency& p : g.coherency.pairs) {
    std::printf("%-6s %8.1f %8.4f/%8.4f",
                (std::to_string(p.j + 1) + "-" + std::to_string(p.k + 1)).c_str(), p.separation,
                p.model_lag, p.lag);
    for (std::size_t k : cols) std::printf("  %5.3f/%5.3f", p.model[k], p.achieved[k]);
    std::printf("\n");
  }
}

void print_table(const StationSet& g, const StationSetRequest& rq, const std::string& dir) {
  const MotionSetRequest& m = rq.motions;
  const SimqkeSettings& s = m.settings;
  const std::size_t ns = rq.stations.positions.size(), np = g.periods.size();
  std::printf(
      "# target: %s\n# %zu motions x %zu stations of %g s at %g s into %s "
      "(motion-NNN-sK.txt, motions.h5)\n",
      m.target->describe().c_str(), g.motions.size(), ns, m.duration, s.dt, dir.c_str());
  std::printf("# coherency: %s; apparent velocity %g m/s\n",
              rq.stations.coherency.describe().c_str(), rq.apparent_velocity);
  if (g.variable) std::printf("# variability: %s\n", m.variability.describe().c_str());
  std::printf("# computed / target over %d periods %g-%g s\n", s.match_periods, s.match_t_min,
              s.match_t_max);
  std::printf("%-8s %7s %7s %7s %7s %8s %12s %12s %5s\n", "motion", "station", "min", "max", "mean",
              "PGA [g]", "v_end [m/s]", "d_end [m]", "iter");
  for (std::size_t i = 0; i < g.reports.size(); ++i)
    for (std::size_t j = 0; j < ns; ++j) {
      const MotionReport& r = g.reports[i][j];
      std::printf("%-8zu %7zu %7.3f %7.3f %7.3f %8.4f %12.3e %12.3e %5d\n", i, j + 1,
                  r.match.min_ratio, r.match.max_ratio, r.match.mean_ratio, r.pga / kGravity,
                  r.v_end, r.d_end, r.iterations);
    }
  for (std::size_t j = 0; j < ns; ++j) {
    const std::vector<double> row(g.mean.begin() + long(j * np),
                                  g.mean.begin() + long((j + 1) * np));
    const SpectrumMatch mm = compare_spectra(row, g.design);
    std::printf("%-8s %7zu %7.3f %7.3f %7.3f\n", "mean", j + 1, mm.min_ratio, mm.max_ratio,
                mm.mean_ratio);
  }
  if (ns > 1) print_coherency_table(g, s.dt);
}

}  // namespace

int run_station_set(const Options& o, const StationSetRequest& request, const std::string& dir) {
  const std::string note = fitted_range_note(request.stations.coherency,
                                             smallest_separation(request.stations.positions));
  if (!note.empty()) std::fprintf(stderr, "pound motion generate: note: %s\n", note.c_str());
  const StationSet g = generate_station_set(request);
  const auto files = write_text_files(g, request, dir);
  write_motions_file(dir, g, request, o);
  if (o.flag("json"))
    print_json(g, files, request, dir);
  else
    print_table(g, request, dir);
  return 0;
}

}  // namespace pound::app
