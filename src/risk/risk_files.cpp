#include "risk/risk_files.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/h5.hpp"
#include "pound/version.hpp"

namespace pound {
namespace {

std::string fit_fields(const LognormalFit& f) {
  return std::string(to_string(f.status)) + "," + csv_number(f.finite() ? f.theta : NAN) + "," +
         csv_number(f.finite() ? f.beta : NAN);
}

std::string gaps_csv(const RiskReport& r) {
  std::string s =
      "pair,gap_m,analyses,pounding,status,theta_mps2,beta,maf_per_year,probability,"
      "probability_ci90_lo,probability_ci90_hi,theta_bound_lo_mps2,theta_bound_hi_mps2,"
      "maf_share_outside_campaign,pounding_collapsed\n";
  for (const auto& p : r.pairs)
    for (const auto& e : p.grid)
      s += std::to_string(p.pair + 1) + "," + csv_number(e.gap) + "," + std::to_string(e.analyses) +
           "," + std::to_string(e.pounding) + "," + fit_fields(e.fit) + "," + csv_number(e.maf) +
           "," + csv_number(e.probability) + "," + csv_number(e.probability_band.lo) + "," +
           csv_number(e.probability_band.hi) + "," +
           csv_number(e.fit.bracketed() ? e.fit.theta_lo : NAN) + "," +
           csv_number(e.fit.bracketed() ? e.fit.theta_hi : NAN) + "," +
           csv_number(e.outside_share) + "," + std::to_string(e.pounding_collapsed) + "\n";
  return s;
}

std::string rules_csv(const RiskReport& r) {
  std::string s =
      "pair,rule,gap_m,level,design_im_mps2,rho,pounding,status,theta_mps2,beta,maf_per_year,"
      "probability,ec8_case\n";
  for (const auto& p : r.pairs)
    for (const auto& k : p.rules)
      s += std::to_string(p.pair + 1) + "," + to_string(k.rule) + "," + csv_number(k.gap) + "," +
           std::to_string(k.level) + "," + csv_number(r.design_im) + "," + csv_number(p.rho) + "," +
           std::to_string(k.estimate.pounding) + "," + fit_fields(k.estimate.fit) + "," +
           csv_number(k.estimate.maf) + "," + csv_number(k.estimate.probability) + "," +
           (k.rule == SeparationRule::ec8 ? to_string(p.ec8_case) : "") + "\n";
  return s;
}

// The point probabilities in T years and the bootstrap bands of a damage limit (DamageRisk).
std::string damage_band_fields(const DamageRisk& d) {
  std::string s = csv_number(d.probability_pounding) + "," + csv_number(d.probability_free);
  for (const Interval& iv : {d.maf_pounding_band, d.maf_free_band, d.ratio_band,
                             d.probability_pounding_band, d.probability_free_band})
    s += "," + csv_number(iv.lo) + "," + csv_number(iv.hi);
  return s + "," + std::to_string(d.bootstrap_replicates) + "," +
         std::to_string(d.maf_pounding_band.finite) + "," + std::to_string(d.maf_free_band.finite);
}

std::string damage_csv(const CampaignData& c, const RiskReport& r) {
  std::string s =
      "building,building_name,edp,unit,limit,status_pounding,theta_pounding_mps2,beta_pounding,"
      "status_free,theta_free_mps2,beta_free,maf_pounding_per_year,maf_free_per_year,ratio,"
      "maf_share_outside_campaign_pounding,maf_share_outside_campaign_free,model,"
      "free_same_analyses,theta_free_same_mps2,beta_free_same,maf_pounding_kept_per_year,"
      "probability_pounding,probability_free,maf_pounding_ci90_lo_per_year,"
      "maf_pounding_ci90_hi_per_year,maf_free_ci90_lo_per_year,maf_free_ci90_hi_per_year,"
      "ratio_ci90_lo,ratio_ci90_hi,probability_pounding_ci90_lo,probability_pounding_ci90_hi,"
      "probability_free_ci90_lo,probability_free_ci90_hi,bootstrap_replicates,"
      "band_finite_pounding,band_finite_free\n";
  for (const auto& d : r.damage)
    s += std::to_string(d.building) + "," + c.building_name(d.building) + "," + to_string(d.edp) +
         "," + unit_of(d.edp) + "," + csv_number(d.limit) + "," + fit_fields(d.pounding) + "," +
         fit_fields(d.free) + "," + csv_number(d.maf_pounding) + "," + csv_number(d.maf_free) +
         "," + csv_number(d.ratio) + "," + csv_number(d.outside_pounding) + "," +
         csv_number(d.outside_free) + "," + (d.model.empty() ? "all" : d.model) + "," +
         (d.same_analyses ? "1" : "0") + "," +
         csv_number(d.free_same.finite() ? d.free_same.theta : NAN) + "," +
         csv_number(d.free_same.finite() ? d.free_same.beta : NAN) + "," +
         csv_number(d.maf_pounding_kept) + "," + damage_band_fields(d) + "\n";
  return s;
}

// A dataset of doubles of any rank.
void put(hid_t f, const std::string& name, const std::vector<double>& v, std::vector<hsize_t> dims,
         const std::string& units = "") {
  h5::ensure_group(f, name.substr(0, name.rfind('/')));
  const hid_t space = H5Screate_simple(int(dims.size()), dims.data(), nullptr);
  const hid_t ds =
      H5Dcreate2(f, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (ds < 0) throw InputError("HDF5: cannot create dataset " + name);
  const herr_t st =
      v.empty() ? 0 : H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  H5Dclose(ds);
  H5Sclose(space);
  if (st < 0) throw InputError("HDF5: writing " + name + " failed");
  if (!units.empty()) h5::attribute(f, name, "units", units);
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ",") + x;
  return s;
}

// /risk/damage: per limit its building, limit, rates, ratio, probabilities in T years, their
// bootstrap bands (NAME_lo, NAME_hi) and the replicates with a finite value.
void write_damage(hid_t id, const std::string& g, const RiskReport& r) {
  struct Column {
    const char* name;
    const char* units;
    double DamageRisk::*point;
    Interval DamageRisk::*band;
  };
  constexpr Column kColumns[] = {
      {"maf_pounding", "1/yr", &DamageRisk::maf_pounding, &DamageRisk::maf_pounding_band},
      {"maf_free", "1/yr", &DamageRisk::maf_free, &DamageRisk::maf_free_band},
      {"ratio", "-", &DamageRisk::ratio, &DamageRisk::ratio_band},
      {"probability_pounding", "-", &DamageRisk::probability_pounding,
       &DamageRisk::probability_pounding_band},
      {"probability_free", "-", &DamageRisk::probability_free, &DamageRisk::probability_free_band}};
  std::vector<double> b, lim, finite_p, finite_f;
  std::vector<std::string> edp, model;
  for (const auto& d : r.damage) {
    b.push_back(double(d.building));
    edp.push_back(to_string(d.edp));
    model.push_back(d.model.empty() ? "all" : d.model);
    lim.push_back(d.limit);
    finite_p.push_back(double(d.maf_pounding_band.finite));
    finite_f.push_back(double(d.maf_free_band.finite));
  }
  const hsize_t D = r.damage.size();
  put(id, g + "/building", b, {D}, "-");
  h5::attribute(id, g, "edp", joined(edp));
  h5::attribute(id, g, "model", joined(model));
  put(id, g + "/limit", lim, {D});
  for (const Column& col : kColumns) {
    std::vector<double> v, lo, hi;
    for (const auto& d : r.damage) {
      v.push_back(d.*col.point);
      lo.push_back((d.*col.band).lo);
      hi.push_back((d.*col.band).hi);
    }
    put(id, g + "/" + col.name, v, {D}, col.units);
    put(id, g + "/" + col.name + "_lo", lo, {D}, col.units);
    put(id, g + "/" + col.name + "_hi", hi, {D}, col.units);
  }
  put(id, g + "/band_finite_pounding", finite_p, {D}, "-");
  put(id, g + "/band_finite_free", finite_f, {D}, "-");
}

void write_h5(const std::string& path, const CampaignData& c, const HazardCurve& h,
              const RiskReport& r, const RiskRunInfo& info) {
  AtomicPath out(path);
  {
    h5::File f(out.temp());
    const hid_t id = f.id();
    const std::string g = "/risk";
    h5::ensure_group(id, g);
    h5::attribute(id, g, "input", info.input);
    h5::attribute(id, g, "hazard", h.source);
    h5::attribute(id, g, "config", info.config);
    h5::attribute(id, g, "engine_version", kVersion);
    h5::attribute(id, g, "git_revision", kGitRevision);
    h5::attribute(id, g, "intensity_measure", c.intensity_measure);
    h5::attribute(id, g, "years", info.settings.years);
    h5::attribute(id, g, "target_probability", info.settings.target_probability);
    h5::attribute(id, g, "design_im_mps2", r.design_im);
    h5::attribute(id, g, "design_im_source",
                  r.design_im_given ? "--design-im" : "the hazard's 475-year intensity");
    h5::attribute(id, g, "hazard_rule", h.extrapolation_rule());
    h5::attribute(id, g, "bootstrap_replicates", double(info.settings.bootstrap.replicates));
    h5::attribute(id, g, "bootstrap_seed", double(info.settings.bootstrap.seed));
    h5::attribute(id, g, "samples", double(r.samples));
    h5::attribute(id, g, "failed", double(r.failed));
    h5::attribute(id, g, "used", double(r.used));
    h5::attribute(id, g, "design", r.stripes ? "stripes" : "continuous");
    h5::attribute(id, g, "building_names", joined(c.building_names));
    h5::attribute(id, g, "notes", joined(r.notes));
    // The hazard curve: its points and the curve as used (log-log, extended beyond the ends).
    put(id, g + "/hazard/im", h.im, {h.im.size()}, "m/s^2");
    put(id, g + "/hazard/rate", h.rate, {h.rate.size()}, "1/yr");
    std::vector<double> cim, crate;
    const double lo = h.im.front() / 4, hi = h.im.back() * 2;
    for (int i = 0; i < 200; ++i) {
      cim.push_back(lo * std::pow(hi / lo, i / 199.0));
      crate.push_back(h.rate_at(cim.back()));
    }
    put(id, g + "/hazard/curve_im", cim, {cim.size()}, "m/s^2");
    put(id, g + "/hazard/curve_rate", crate, {crate.size()}, "1/yr");
    for (const auto& p : r.pairs) {
      const std::string pg = g + "/pair" + std::to_string(p.pair + 1);
      std::vector<double> gap, theta, beta, maf, prob, lo90, hi90, n, z, oim, on, oz;
      std::vector<std::string> status;
      for (const auto& e : p.grid) {
        gap.push_back(e.gap);
        theta.push_back(e.fit.finite() ? e.fit.theta : NAN);
        beta.push_back(e.fit.finite() ? e.fit.beta : NAN);
        maf.push_back(e.maf);
        prob.push_back(e.probability);
        lo90.push_back(e.probability_band.lo);
        hi90.push_back(e.probability_band.hi);
        n.push_back(double(e.analyses));
        z.push_back(double(e.pounding));
        status.push_back(to_string(e.fit.status));
        for (const auto& o : e.observed) on.push_back(double(o.n)), oz.push_back(double(o.z));
      }
      const std::size_t G = p.grid.size(), S = G ? p.grid[0].observed.size() : 0;
      for (std::size_t k = 0; k < S; ++k) oim.push_back(p.grid[0].observed[k].im);
      put(id, pg + "/gap", gap, {G}, "m");
      put(id, pg + "/theta", theta, {G}, "m/s^2");
      put(id, pg + "/beta", beta, {G}, "-");
      put(id, pg + "/maf", maf, {G}, "1/yr");
      put(id, pg + "/probability", prob, {G}, "-");
      put(id, pg + "/probability_lo", lo90, {G}, "-");
      put(id, pg + "/probability_hi", hi90, {G}, "-");
      put(id, pg + "/analyses", n, {G}, "-");
      put(id, pg + "/pounding", z, {G}, "-");
      put(id, pg + "/observed_im", oim, {S}, "m/s^2");
      put(id, pg + "/observed_n", on, {G, S}, "-");
      put(id, pg + "/observed_z", oz, {G, S}, "-");
      h5::attribute(id, pg, "status", joined(status));
      h5::attribute(id, pg, "gap_for_target_m", p.gap_for_target);
      h5::attribute(id, pg, "gap_for_target_status", to_string(p.target_status));
      h5::attribute(id, pg, "gap_band_lo_m", p.gap_band.lo);
      h5::attribute(id, pg, "gap_band_hi_m", p.gap_band.hi);
      h5::attribute(id, pg, "gap_band_finite", double(p.gap_band.finite));
      h5::attribute(id, pg, "rho", p.rho);
      h5::attribute(id, pg, "ec8_case", to_string(p.ec8_case));
      h5::attribute(id, pg, "rules_note", p.rules_note);
      std::vector<double> rg, rl, rp, rm;
      std::vector<std::string> names;
      for (const auto& k : p.rules) {
        names.push_back(to_string(k.rule));
        rg.push_back(k.gap);
        rl.push_back(double(k.level));
        rp.push_back(k.estimate.probability);
        rm.push_back(k.estimate.maf);
      }
      h5::attribute(id, pg, "rules", joined(names));
      put(id, pg + "/rule_gap", rg, {rg.size()}, "m");
      put(id, pg + "/rule_level", rl, {rl.size()}, "-");
      put(id, pg + "/rule_probability", rp, {rp.size()}, "-");
      put(id, pg + "/rule_maf", rm, {rm.size()}, "1/yr");
      put(id, pg + "/median_left", p.median_left, {p.median_left.size()}, "m");
      put(id, pg + "/median_right", p.median_right, {p.median_right.size()}, "m");
    }
    write_damage(id, g + "/damage", r);
    f.close();  // a failed write (disk full) is reported here, before the file is renamed
  }
  out.commit();
}

}  // namespace

std::vector<std::string> write_risk_files(const std::string& dir, const CampaignData& c,
                                          const HazardCurve& h, const RiskReport& r,
                                          const RiskRunInfo& info) {
  const std::vector<std::string> files = {dir + "/risk_gaps.csv", dir + "/code_rules.csv",
                                          dir + "/damage_maf.csv", dir + "/risk.h5"};
  write_text_file(files[0], gaps_csv(r));
  write_text_file(files[1], rules_csv(r));
  write_text_file(files[2], damage_csv(c, r));
  write_h5(files[3], c, h, r, info);
  return files;
}

}  // namespace pound
