#include "risk/hazard_curve.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/options.hpp"
#include "io/utf8_bom.hpp"
#include "motion/ground_motion.hpp"

namespace pound {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r"), e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The two comma-separated fields of a line; false when there are not exactly two.
bool two_fields(const std::string& line, std::string* a, std::string* b) {
  const auto comma = line.find(',');
  if (comma == std::string::npos || line.find(',', comma + 1) != std::string::npos) return false;
  *a = trim(line.substr(0, comma));
  *b = trim(line.substr(comma + 1));
  return true;
}

// A point's value for a message: 10 significant digits (6.5e-07, not std::to_string's
// 0.000000), and nan / inf spelled out where a CSV field would be empty.
std::string shown(double x) {
  return std::isfinite(x) ? csv_number(x) : std::to_string(x);
}

// "name [unit]" -> name, unit; false without brackets.
bool name_and_unit(const std::string& field, std::string* name, std::string* unit) {
  const auto open = field.find('['), close = field.rfind(']');
  if (open == std::string::npos || close == std::string::npos || close < open) return false;
  *name = lower(trim(field.substr(0, open)));
  *unit = lower(trim(field.substr(open + 1, close - open - 1)));
  return true;
}

}  // namespace

HazardCurve make_hazard_curve(std::vector<double> im, std::vector<double> rate,
                              const std::string& measure, double period_s, const std::string& unit,
                              const std::string& source) {
  HazardCurve h;
  h.source = source;
  h.measure = measure;
  h.period_s = period_s;
  h.file_unit = unit;
  if (unit != "g" && unit != "m/s2")
    throw InputError(source + ": intensity unit '" + unit + "'; valid: g, m/s2");
  if (im.size() != rate.size() || im.size() < 2)
    throw InputError(source + ": " + std::to_string(im.size()) +
                     " hazard points; valid: at least two (intensity, rate) points");
  const double factor = unit == "g" ? kGravity : 1.0;
  for (std::size_t i = 0; i < im.size(); ++i) {
    const std::string at = source + ": point " + std::to_string(i + 1) + " (" + shown(im[i]) + " " +
                           unit + ", " + shown(rate[i]) + " /yr)";
    if (!(std::isfinite(im[i]) && im[i] > 0))
      throw InputError(at + ": the intensity must be a finite number > 0");
    if (!(std::isfinite(rate[i]) && rate[i] > 0))
      throw InputError(at +
                       ": the annual rate of exceedance must be a finite number > 0 "
                       "(drop points of rate 0; negative rates are not rates)");
    // A slope between two intensities a rounding apart would be ln(rate) / 1e-16: the curve
    // and its integrals would be round-off (found by fuzz_hazard).
    if (i > 0 && !(im[i] > im[i - 1] * (1.0 + 1e-6)))
      throw InputError(at +
                       ": the intensities must increase strictly from point to point, each by "
                       "more than 1e-6 of the previous one");
    if (i > 0 && !(rate[i] < rate[i - 1]))
      throw InputError(at +
                       ": the rate of exceedance must fall strictly as the intensity "
                       "rises (a hazard curve is decreasing)");
    h.im.push_back(im[i] * factor);
    h.rate.push_back(rate[i]);
  }
  return h;
}

HazardCurve read_hazard_curve(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the hazard curve file");
  std::string line, measure, unit;
  double period = 0.0;
  bool header = false;
  std::vector<double> im, rate;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (n == 1) strip_utf8_bom(line);  // as Windows editors save "UTF-8" files
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const std::string where = path + ":" + std::to_string(n);
    std::string a, b;
    if (!two_fields(t, &a, &b))
      throw InputError(where +
                       ": expected two comma-separated columns, intensity and annual "
                       "rate of exceedance");
    if (!header) {
      std::string name, rate_name, rate_unit;
      if (!name_and_unit(a, &name, &unit) || !name_and_unit(b, &rate_name, &rate_unit))
        throw InputError(where + ": header '" + t +
                         "'; valid: 'pga [g], annual_rate [1/yr]' "
                         "(measure pga or sa(T) with T in s; unit g or m/s2)");
      if (unit == "m/s^2") unit = "m/s2";
      if (unit != "g" && unit != "m/s2")
        throw InputError(where + ": intensity unit '" + unit + "'; valid: g, m/s2, m/s^2");
      if (rate_unit != "1/yr" && rate_unit != "1/year")
        throw InputError(where + ": rate unit '" + rate_unit + "'; valid: 1/yr, 1/year");
      if (name == "pga") {
        measure = "pga";
      } else if (name.rfind("sa(", 0) == 0 && name.back() == ')') {
        measure = "sa";
        period = parse_number(name.substr(3, name.size() - 4), where + ": period of " + name);
        if (!(period > 0)) throw InputError(where + ": the period of sa(T) must be > 0 s");
      } else {
        throw InputError(where + ": intensity measure '" + name + "'; valid: pga, sa(T)");
      }
      header = true;
      continue;
    }
    im.push_back(parse_number(a, where + ": intensity"));
    rate.push_back(parse_number(b, where + ": annual rate"));
  }
  if (!header)
    throw InputError(path +
                     ": no header line; valid: 'pga [g], annual_rate [1/yr]' then the "
                     "points");
  return make_hazard_curve(im, rate, measure, period, unit, path);
}

std::vector<HazardCurve::Segment> HazardCurve::segments() const {
  std::vector<Segment> s;
  const std::size_t n = im.size();
  auto line = [&](std::size_t i, double lo, double hi) {  // through points i and i + 1
    const double x0 = std::log(im[i]), x1 = std::log(im[i + 1]);
    const double b = (std::log(rate[i + 1]) - std::log(rate[i])) / (x1 - x0);
    return Segment{b, lo, hi, x0, std::log(rate[i])};
  };
  s.push_back(line(0, -kInf, std::log(im[0])));
  for (std::size_t i = 0; i + 1 < n; ++i)
    s.push_back(line(i, std::log(im[i]), std::log(im[i + 1])));
  s.push_back(line(n - 2, std::log(im[n - 1]), kInf));
  return s;
}

double HazardCurve::rate_at(double x) const {
  const double u = std::log(x);
  for (const auto& s : segments())
    if (u <= s.hi) return std::exp(s.ln_rate(u));
  return 0.0;
}

double HazardCurve::im_at_rate(double r) const {
  const double v = std::log(r);
  for (const auto& s : segments()) {
    const double u = s.x0 + (v - s.y0) / s.b;  // b < 0: the rate falls along the curve
    if (u <= s.hi) return std::exp(std::max(u, s.lo));
  }
  return kInf;
}

std::string HazardCurve::extrapolation_rule() const {
  std::ostringstream o;
  o << "log-log interpolation between the " << im.size()
    << " points; below the first and above the last point the power law of the end segment "
       "is extended (log-log extrapolation)";
  return o.str();
}

}  // namespace pound
