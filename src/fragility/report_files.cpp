#include "fragility/report_files.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/h5.hpp"
#include "pound/version.hpp"

namespace pound {
namespace {

// The model column: "all" for the pooled curves.
std::string model_label(const std::string& m) {
  return m.empty() ? "all" : m;
}

std::string curves_csv(const CampaignData& c, const FragilityReport& r) {
  std::string s =
      "building,building_name,edp,unit,limit,pounding,status,theta_mps2,beta,"
      "theta_ci90_lo,theta_ci90_hi,beta_ci90_lo,beta_ci90_hi,theta_asym90_lo,theta_asym90_hi,"
      "beta_asym90_lo,beta_asym90_hi,bootstrap_finite,analyses,exceedances,theta_bound_lo_mps2,"
      "theta_bound_hi_mps2,left_out,model\n";
  for (const auto& k : r.curves) {
    long n = 0, z = 0;
    for (const auto& o : k.observed) n += o.n, z += o.z;
    const bool f = k.fit.finite();
    s += std::to_string(k.building) + "," + c.building_name(k.building) + "," + to_string(k.edp) +
         "," + unit_of(k.edp) + "," + csv_number(k.limit) + "," + (k.pounding ? "true" : "false") +
         "," + to_string(k.fit.status) + "," + csv_number(f ? k.fit.theta : NAN) + "," +
         csv_number(f ? k.fit.beta : NAN) + "," + csv_number(f ? k.theta_ci.lo : NAN) + "," +
         csv_number(f ? k.theta_ci.hi : NAN) + "," + csv_number(f ? k.beta_ci.lo : NAN) + "," +
         csv_number(f ? k.beta_ci.hi : NAN) + "," + csv_number(k.theta_asym_lo) + "," +
         csv_number(k.theta_asym_hi) + "," + csv_number(k.beta_asym_lo) + "," +
         csv_number(k.beta_asym_hi) + "," + std::to_string(k.theta_ci.finite) + "," +
         std::to_string(n) + "," + std::to_string(z) + "," +
         csv_number(k.fit.bracketed() ? k.fit.theta_lo : NAN) + "," +
         csv_number(k.fit.bracketed() ? k.fit.theta_hi : NAN) + "," + std::to_string(k.left_out) +
         "," + model_label(k.model) + "\n";
  }
  return s;
}

std::string shift_csv(const CampaignData& c, const FragilityReport& r) {
  std::string s =
      "building,building_name,edp,unit,limit,ratio,ratio_ci90_lo,ratio_ci90_hi,model,"
      "theta_pounding_mps2,theta_free_mps2,free_same_analyses,beta_free\n";
  for (const auto& k : r.shifts)
    s += std::to_string(k.building) + "," + c.building_name(k.building) + "," + to_string(k.edp) +
         "," + unit_of(k.edp) + "," + csv_number(k.limit) + "," + csv_number(k.ratio) + "," +
         csv_number(k.ci.lo) + "," + csv_number(k.ci.hi) + "," + model_label(k.model) + "," +
         csv_number(k.theta_pounding) + "," + csv_number(k.theta_free) + "," +
         (k.same_analyses ? "1" : "0") + "," +
         csv_number(k.free_same.finite() ? k.free_same.beta : NAN) + "\n";
  return s;
}

std::string observations_csv(const FragilityReport& r) {
  std::string s = std::string("building,edp,limit,") + (r.stripes ? "stripe" : "bin") +
                  ",im_mps2,n,exceed_pounding,exceed_free,model,n_free\n";
  for (std::size_t k = 0; k < r.curves.size(); ++k) {
    const auto& p = r.curves[k];
    if (!p.pounding) continue;
    const bool paired = k + 1 < r.curves.size() && !r.curves[k + 1].pounding;
    for (std::size_t j = 0; j < p.observed.size(); ++j)
      s += std::to_string(p.building) + "," + to_string(p.edp) + "," + csv_number(p.limit) + "," +
           std::to_string(j) + "," + csv_number(p.observed[j].im) + "," +
           std::to_string(p.observed[j].n) + "," + std::to_string(p.observed[j].z) + "," +
           (paired ? std::to_string(r.curves[k + 1].observed[j].z) : "") + "," +
           model_label(p.model) + "," +
           (paired ? std::to_string(r.curves[k + 1].observed[j].n) : "") + "\n";
  }
  return s;
}

std::string sensitivity_csv(const CampaignData& c, const FragilityReport& r) {
  std::string s = "building,building_name,response,rank,parameter,spearman,prcc,samples\n";
  std::string last;
  int rank = 0;
  for (const auto& k : r.sensitivity) {
    const std::string group = std::to_string(k.building) + k.response;
    rank = group == last ? rank + 1 : 1;
    last = group;
    s += std::to_string(k.building) + "," + c.building_name(k.building) + "," + k.response + "," +
         std::to_string(rank) + "," + k.parameter + "," + csv_number(k.spearman) + "," +
         csv_number(k.prcc) + "," + std::to_string(k.samples) + "\n";
  }
  return s;
}

void write_h5(const std::string& path, const CampaignData& c, const FragilityReport& r,
              const FragilityRunInfo& info) {
  AtomicPath out(path);
  {
    h5::File f(out.temp());
    const hid_t id = f.id();
    h5::ensure_group(id, "/fragility");
    h5::attribute(id, "/fragility", "input", info.input);
    h5::attribute(id, "/fragility", "config", info.config);
    h5::attribute(id, "/fragility", "engine_version", kVersion);
    h5::attribute(id, "/fragility", "git_revision", kGitRevision);
    h5::attribute(id, "/fragility", "bootstrap_seed", info.seed);
    h5::attribute(id, "/fragility", "bootstrap_replicates", double(info.replicates));
    h5::attribute(id, "/fragility", "samples", double(r.samples));
    h5::attribute(id, "/fragility", "failed", double(r.failed));
    h5::attribute(id, "/fragility", "used", double(r.used));
    h5::attribute(id, "/fragility", "design", r.stripes ? "stripes" : "continuous");
    h5::attribute(id, "/fragility", "intensity_measure", c.intensity_measure);
    h5::attribute(id, "/fragility", "im_period_s", c.im_period);
    std::string names;
    for (const auto& n : c.building_names) names += (names.empty() ? "" : ", ") + n;
    h5::attribute(id, "/fragility", "building_names", names);
    h5::write(id, "/fragility/grid_im", r.grid, r.grid.size(), 0, "m/s^2");
    for (std::size_t k = 0; k < r.curves.size(); ++k) {
      const auto& cv = r.curves[k];
      char g[48];
      std::snprintf(g, sizeof g, "/fragility/curve%03zu", k);
      h5::ensure_group(id, g);
      h5::attribute(id, g, "model", model_label(cv.model));
      h5::attribute(id, g, "building", double(cv.building));
      h5::attribute(id, g, "edp", to_string(cv.edp));
      h5::attribute(id, g, "limit", cv.limit);
      h5::attribute(id, g, "limit_units", unit_of(cv.edp));
      h5::attribute(id, g, "pounding", cv.pounding ? "true" : "false");
      h5::attribute(id, g, "left_out", double(cv.left_out));
      h5::attribute(id, g, "status", to_string(cv.fit.status));
      const bool fin = cv.fit.finite();
      h5::attribute(id, g, "theta", fin ? cv.fit.theta : NAN);
      h5::attribute(id, g, "beta", fin ? cv.fit.beta : NAN);
      h5::attribute(id, g, "theta_ci90_lo", fin ? cv.theta_ci.lo : NAN);
      h5::attribute(id, g, "theta_ci90_hi", fin ? cv.theta_ci.hi : NAN);
      h5::attribute(id, g, "beta_ci90_lo", fin ? cv.beta_ci.lo : NAN);
      h5::attribute(id, g, "beta_ci90_hi", fin ? cv.beta_ci.hi : NAN);
      // Without a finite estimate: the interval the data put theta in (inf: unbounded above).
      h5::attribute(id, g, "theta_bound_lo", cv.fit.bracketed() ? cv.fit.theta_lo : NAN);
      h5::attribute(id, g, "theta_bound_hi", cv.fit.bracketed() ? cv.fit.theta_hi : NAN);
      std::vector<double> im, n, z, p;
      for (const auto& o : cv.observed)
        im.push_back(o.im), n.push_back(double(o.n)), z.push_back(double(o.z));
      for (double x : r.grid) p.push_back(cv.fit.probability(x));
      const std::string base(g);
      h5::write(id, base + "/observed_im", im, im.size(), 0, "m/s^2");
      h5::write(id, base + "/observed_n", n, n.size(), 0, "-");
      h5::write(id, base + "/observed_z", z, z.size(), 0, "-");
      h5::write(id, base + "/probability", p, p.size(), 0, "-");
      h5::write(id, base + "/band_lo", cv.band_lo, cv.band_lo.size(), 0, "-");
      h5::write(id, base + "/band_hi", cv.band_hi, cv.band_hi.size(), 0, "-");
    }
    f.close();
  }
  out.commit();
}

}  // namespace

std::vector<std::string> write_fragility_files(const std::string& dir, const CampaignData& c,
                                               const FragilityReport& r,
                                               const FragilityRunInfo& info) {
  const std::string d = dir.empty() || dir.back() == '/' ? dir : dir + "/";
  const std::vector<std::string> paths = {d + "curves.csv", d + "shift.csv", d + "observations.csv",
                                          d + "sensitivity.csv", d + "fragility.h5"};
  write_text_file(paths[0], curves_csv(c, r));
  write_text_file(paths[1], shift_csv(c, r));
  write_text_file(paths[2], observations_csv(r));
  write_text_file(paths[3], sensitivity_csv(c, r));
  write_h5(paths[4], c, r, info);
  return paths;
}

}  // namespace pound
