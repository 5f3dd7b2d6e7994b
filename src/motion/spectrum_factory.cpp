#include "motion/spectrum_factory.hpp"

#include <cmath>

#include "motion/ground_motion.hpp"
#include "motion/spectrum_asce7.hpp"
#include "motion/spectrum_ec8.hpp"
#include "motion/spectrum_japan.hpp"
#include "motion/spectrum_nzs1170.hpp"
#include "motion/spectrum_table.hpp"

namespace pound {

std::vector<OptionSpec> design_spectrum_option_specs() {
  return {
      {"spectrum", "", "", "target design spectrum: ec8, nzs1170, asce7, japan or table"},
      {"damping", "-", "0.05", "damping ratio of the spectrum (EC8 eta, Japan Fh corrections)"},
      {"ec8-type", "", "1", "Eurocode 8 spectrum type: 1 or 2"},
      {"ground-type", "", "", "Eurocode 8 ground type: A, B, C, D or E"},
      {"ag", "g", "", "Eurocode 8 design ground acceleration on type A ground"},
      {"site-class", "", "", "NZS 1170.5 site subsoil class: A, B, C, D or E"},
      {"Z", "-", "", "NZS 1170.5 hazard factor Z (Table 3.3)"},
      {"R", "-", "", "NZS 1170.5 return period factor R (or give --return-period)"},
      {"return-period", "years", "", "NZS 1170.5 return period for R from Table 3.5"},
      {"N", "-", "1", "NZS 1170.5 near-fault factor N (or give --fault-distance)"},
      {"fault-distance", "km", "", "NZS 1170.5 distance to the nearest major fault for N(T,D)"},
      {"SDS", "g", "", "ASCE 7 design spectral acceleration at short periods"},
      {"SD1", "g", "", "ASCE 7 design spectral acceleration at 1 s"},
      {"TL", "s", "", "ASCE 7 long-period transition period"},
      {"japan-level", "", "2", "Japanese spectrum level: 1 (rare) or 2 (extremely rare)"},
      {"japan-soil", "", "bedrock", "Japanese spectrum site: bedrock, 1, 2 or 3 (ground type)"},
      {"japan-zone", "-", "1.0", "Japanese seismic zone factor Z (0.7 to 1.0)"},
      {"table", "", "", "spectrum table file: lines 'T Sa', T in s and Sa in g"},
  };
}

namespace {

int letter(const Options& o, const std::string& key) {
  const std::string s = o.get_string(key);
  if (s.size() != 1 || s[0] < 'A' || s[0] > 'E') throw o.invalid(key, "valid: A, B, C, D or E");
  return s[0] - 'A';
}

void require_5_percent(const Options& o, const std::string& code) {
  if (std::fabs(o.get_double("damping") - 0.05) > 1e-12)
    throw o.invalid("damping", code +
                                   " gives 5 % spectra without a damping correction; valid: "
                                   "0.05");
}

}  // namespace

std::unique_ptr<DesignSpectrum> make_design_spectrum(const Options& o) {
  const std::string name = o.get_string("spectrum");
  const double damping = o.get_double("damping");
  if (!(damping >= 0.0 && damping < 1.0)) throw o.invalid("damping", "valid: 0 <= damping < 1");
  if (name == "ec8") {
    const std::string t = o.get_string("ec8-type");
    if (t != "1" && t != "2") throw o.invalid("ec8-type", "valid: 1 or 2");
    return std::make_unique<Ec8Spectrum>(t == "1" ? Ec8Type::type1 : Ec8Type::type2,
                                         static_cast<Ec8Ground>(letter(o, "ground-type")),
                                         o.get_positive("ag") * kGravity, damping);
  }
  if (name == "nzs1170") {
    require_5_percent(o, "NZS 1170.5");
    double r = 0.0;
    if (o.given("R") && o.given("return-period"))
      throw o.invalid("R", "give R or return-period, not both");
    if (o.given("return-period")) {
      const long years = o.get_int("return-period");
      r = nzs_return_period_factor(int(years));
    } else {
      r = o.get_positive("R");
    }
    const double z = o.get_positive("Z");
    if (z * r > 0.7 + 1e-12) throw o.invalid("Z", "Z R must not exceed 0.7 (NZS 1170.5 3.1.1)");
    const double n = o.get_double("N");
    if (!(n >= 1.0)) throw o.invalid("N", "valid: N >= 1");
    const double d = o.given("fault-distance") ? o.get_nonnegative("fault-distance") : -1.0;
    return std::make_unique<Nzs1170Spectrum>(static_cast<NzsSiteClass>(letter(o, "site-class")), z,
                                             r, n, d);
  }
  if (name == "asce7") {
    require_5_percent(o, "ASCE 7");
    const double sds = o.get_positive("SDS"), sd1 = o.get_positive("SD1");
    const double tl = o.get_positive("TL");
    if (!(tl > sd1 / sds)) throw o.invalid("TL", "valid: TL > TS = SD1/SDS");
    return std::make_unique<Asce7Spectrum>(sds * kGravity, sd1 * kGravity, tl);
  }
  if (name == "japan") {
    const std::string lv = o.get_string("japan-level");
    if (lv != "1" && lv != "2") throw o.invalid("japan-level", "valid: 1 or 2");
    const std::string s = o.get_string("japan-soil");
    JapanSoil soil;
    if (s == "bedrock")
      soil = JapanSoil::bedrock;
    else if (s == "1")
      soil = JapanSoil::type1;
    else if (s == "2")
      soil = JapanSoil::type2;
    else if (s == "3")
      soil = JapanSoil::type3;
    else
      throw o.invalid("japan-soil", "valid: bedrock, 1, 2 or 3");
    const double zone = o.get_positive("japan-zone");
    if (zone > 1.0) throw o.invalid("japan-zone", "valid: 0 < Z <= 1");
    return std::make_unique<JapanSpectrum>(lv == "1" ? JapanLevel::level1 : JapanLevel::level2,
                                           soil, zone, damping);
  }
  if (name == "table")
    return std::make_unique<TableSpectrum>(read_spectrum_table(o.get_string("table"), damping));
  throw o.invalid("spectrum", "valid: ec8, nzs1170, asce7, japan, table");
}

}  // namespace pound
