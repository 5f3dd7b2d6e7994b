// pound motion generate: spectrum-compatible motions (SIMQKE) into a folder; with stations
// (--stations/--positions, issue 28) motion_stations.cpp writes the station set.
//   pound motion generate --spectrum ... --count N --duration S --dt DT --seed K --out DIR
//       [--variability spectral --sigma-lnsa S | --sigma-table F | --sigma-model M
//        --correlation baker-jayaram-2008|none|full]
// Writes motion-NNN.txt and target-NNN.txt per motion and motions.h5, each whole or not at
// all, then prints how each motion matches its target (a table, or --json).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/help.hpp"
#include "app/motion_stations.hpp"
#include "app/motion_text_files.hpp"
#include "core/error.hpp"
#include "ground/station_set.hpp"
#include "io/atomic_file.hpp"
#include "io/h5.hpp"
#include "io/json.hpp"
#include "io/options.hpp"
#include "motion/motion_set.hpp"
#include "pound/version.hpp"

namespace pound::app {
namespace {

// Every motion's text file and its own target, each whole or not at all: DIR/motion-NNN.txt,
// DIR/target-NNN.txt. Returns the motion files' paths.
std::vector<std::string> write_text_files(const MotionSet& g, const MotionSetRequest& rq,
                                          const std::string& dir) {
  std::string header = "# pound motion generate (" + std::string(kVersion) + " " + kGitRevision +
                       ")\n# target: " + rq.target->describe() + "\n";
  if (g.variable) header += "# variability: " + rq.variability.describe() + "\n";
  std::vector<std::string> files;
  const std::size_t np = g.periods.size();
  for (std::size_t i = 0; i < g.motions.size(); ++i) {
    char number[24];
    std::snprintf(number, sizeof number, "%03zu", i);
    const std::string motion_name = std::string("motion-") + number + ".txt";
    files.push_back((std::filesystem::path(dir) / motion_name).string());
    const std::string id =
        "# seed: " + std::to_string(rq.seed) + ", index: " + std::to_string(i) + "\n";
    write_text(files.back(), g.motions[i], header + id);
    const std::vector<double> own(g.targets.begin() + long(i * np),
                                  g.targets.begin() + long((i + 1) * np));
    write_target((std::filesystem::path(dir) / (std::string("target-") + number + ".txt")).string(),
                 g.periods, own,
                 header + id + "# the spectrum " + motion_name + " was matched to\n");
  }
  return files;
}

// One HDF5 file with every motion, its spectrum and the target: DIR/motions.h5.
void write_motions_file(const std::string& dir, const MotionSet& g, double dt,
                        const DesignSpectrum& target, const VariabilitySettings& variability,
                        long seed, const Options& o) {
  const std::string h5path = (std::filesystem::path(dir) / "motions.h5").string();
  AtomicPath out(h5path);
  {
    h5::File f(out.temp());
    const std::size_t n = g.motions.front().accel.size(), np = g.periods.size();
    std::vector<double> acc, t(n), pga, vend, dend;
    std::vector<int> iters;
    for (std::size_t i = 0; i < n; ++i) t[i] = dt * double(i);
    for (std::size_t i = 0; i < g.motions.size(); ++i) {
      acc.insert(acc.end(), g.motions[i].accel.begin(), g.motions[i].accel.end());
      iters.push_back(g.reports[i].iterations);
      pga.push_back(g.reports[i].pga);
      vend.push_back(g.reports[i].v_end);
      dend.push_back(g.reports[i].d_end);
    }
    h5::write(f.id(), "/motions/time", t, n, 0, "s");
    h5::write(f.id(), "/motions/acceleration", acc, g.motions.size(), n, "m/s^2");
    h5::write(f.id(), "/motions/psa", g.psa, g.motions.size(), np, "m/s^2");
    h5::write(f.id(), "/motions/pga", pga, pga.size(), 0, "m/s^2");
    h5::write(f.id(), "/motions/final_velocity", vend, vend.size(), 0, "m/s");
    h5::write(f.id(), "/motions/final_displacement", dend, dend.size(), 0, "m");
    h5::write(f.id(), "/motions/iterations", iters);
    h5::write(f.id(), "/target/period", g.periods, np, 0, "s");
    h5::write(f.id(), "/target/psa", g.design, g.design.size(), 0, "m/s^2");
    h5::write(f.id(), "/target/mean_psa", g.mean, g.mean.size(), 0, "m/s^2");
    h5::write(f.id(), "/target/geomean_psa", g.geomean, g.geomean.size(), 0, "m/s^2");
    h5::write(f.id(), "/motions/target_psa", g.targets, g.motions.size(), np, "m/s^2");
    if (g.variable) {
      h5::write(f.id(), "/motions/epsilon", g.eps, g.motions.size(), np, "-");
      h5::write(f.id(), "/target/sigma_lnsa", g.sigma, g.sigma.size(), 0, "-");
    }
    h5::attribute(f.id(), "/", "variability", variability.describe());
    h5::attribute(f.id(), "/", "design_pga_mps2", target.sa(0.0));
    h5::attribute(f.id(), "/", "target", target.describe());
    h5::attribute(f.id(), "/", "damping", target.damping());
    h5::attribute(f.id(), "/", "seed", double(seed));
    h5::attribute(f.id(), "/", "config", o.resolved_text());
    h5::attribute(f.id(), "/", "engine_version", kVersion);
    h5::attribute(f.id(), "/", "git_revision", kGitRevision);
    f.close();
  }
  out.commit();
}

void field_ratios(JsonWriter& w, const char* key, const SpectrumMatch& m) {
  w.key(key)
      .begin_object()
      .field("min_ratio", m.min_ratio)
      .field("max_ratio", m.max_ratio)
      .field("mean_ratio", m.mean_ratio)
      .end_object();
}

void print_json(const MotionSet& g, const std::vector<std::string>& files,
                const DesignSpectrum& target, const VariabilitySettings& variability,
                const std::string& dir) {
  JsonWriter w;
  w.begin_object().field("target", target.describe()).field("out", dir);
  w.field("variability", variability.describe());
  w.key("motions").begin_array();
  for (std::size_t i = 0; i < g.reports.size(); ++i) {
    const MotionReport& r = g.reports[i];
    w.begin_object()
        .field("file", files[i])
        .field("min_ratio", r.match.min_ratio)
        .field("max_ratio", r.match.max_ratio)
        .field("mean_ratio", r.match.mean_ratio)
        .field("pga_g", r.pga / kGravity)
        .field("final_velocity_mps", r.v_end)
        .field("final_displacement_m", r.d_end)
        .field("iterations", r.iterations)
        .field("phase_set", r.attempt)
        .end_object();
  }
  w.end_array();
  field_ratios(w, "mean", compare_spectra(g.mean, g.design));
  field_ratios(w, "geometric_mean", compare_spectra(g.geomean, g.design));
  w.end_object();
  std::cout << w.str() << "\n";
}

void print_table(const MotionSet& g, const DesignSpectrum& target,
                 const VariabilitySettings& variability, const SimqkeSettings& s, double duration,
                 const std::string& dir) {
  std::printf("# target: %s\n# %zu motions of %g s at %g s into %s (motion-NNN.txt, motions.h5)\n",
              target.describe().c_str(), g.motions.size(), duration, s.dt, dir.c_str());
  if (g.variable)
    std::printf(
        "# variability: %s\n# each motion against its own target (target-NNN.txt); "
        "mean and geomean of the motions against the design spectrum\n",
        variability.describe().c_str());
  std::printf("# computed / target over %d periods %g-%g s\n", s.match_periods, s.match_t_min,
              s.match_t_max);
  std::printf("%-8s %7s %7s %7s %8s %12s %12s %5s\n", "motion", "min", "max", "mean", "PGA [g]",
              "v_end [m/s]", "d_end [m]", "iter");
  for (std::size_t i = 0; i < g.reports.size(); ++i) {
    const MotionReport& r = g.reports[i];
    std::printf("%-8zu %7.3f %7.3f %7.3f %8.4f %12.3e %12.3e %5d\n", i, r.match.min_ratio,
                r.match.max_ratio, r.match.mean_ratio, r.pga / kGravity, r.v_end, r.d_end,
                r.iterations);
  }
  const SpectrumMatch mean_match = compare_spectra(g.mean, g.design);
  std::printf("%-8s %7.3f %7.3f %7.3f\n", "mean", mean_match.min_ratio, mean_match.max_ratio,
              mean_match.mean_ratio);
  if (g.variable) {
    const SpectrumMatch geomean_match = compare_spectra(g.geomean, g.design);
    std::printf("%-8s %7.3f %7.3f %7.3f\n", "geomean", geomean_match.min_ratio,
                geomean_match.max_ratio, geomean_match.mean_ratio);
  }
}

}  // namespace

int run_motion_generate(int argc, const char* const* argv) {
  Options o("motion generate", "Spectrum-compatible motions (Gasparini & Vanmarcke 1976).",
            station_set_option_specs());
  if (help_asked(o, argc, argv)) return 0;
  const StationSetRequest srq = station_set_from_options(o);
  const MotionSetRequest& rq = srq.motions;
  const std::string dir = o.get_string("out");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw InputError(o.where("out") + ": cannot create folder '" + dir + "': " + ec.message());
  if (srq.enabled) return run_station_set(o, srq, dir);
  const MotionSet g = generate_motion_set(rq);
  const std::vector<std::string> files = write_text_files(g, rq, dir);
  write_motions_file(dir, g, rq.settings.dt, *rq.target, rq.variability, rq.seed, o);
  if (o.flag("json"))
    print_json(g, files, *rq.target, rq.variability, dir);
  else
    print_table(g, *rq.target, rq.variability, rq.settings, rq.duration, dir);
  return 0;
}

}  // namespace pound::app
