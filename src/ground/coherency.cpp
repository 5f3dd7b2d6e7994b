#include "ground/coherency.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/error.hpp"

namespace pound {
namespace {

struct ModelInfo {
  CoherencyModel model;
  const char* name;
  std::vector<const char*> parameters;  // names, in order
  std::vector<double> defaults;
  double fitted_min_separation = 0.0;  // [m]; 0: no floor
};

// SMART-1, on which Harichandran & Vanmarcke (1986) and Hao et al. (1989) fitted their models,
// has no two stations closer than about 100 m (issue 37).
constexpr double kSmart1MinSeparation = 100.0;  // [m]

const std::vector<ModelInfo>& models() {
  static const std::vector<ModelInfo> m = {
      {CoherencyModel::none, "none", {}, {}},
      {CoherencyModel::harichandran_vanmarcke_1986,
       "harichandran-vanmarcke-1986",
       {"A", "alpha", "k", "f0", "b"},
       {0.736, 0.147, 5210.0, 1.09, 2.78},
       kSmart1MinSeparation},
      {CoherencyModel::luco_wong_1986, "luco-wong-1986", {"alpha"}, {2.5e-4}},
      {CoherencyModel::hao_oliveira_penzien_1989,
       "hao-oliveira-penzien-1989",
       {"beta", "a", "b", "c"},
       {1.109e-4, 3.583e-3, -1.811e-5, 1.177e-4},
       kSmart1MinSeparation},
      {CoherencyModel::abrahamson_2007_soil, "abrahamson-2007-soil", {}, {}},
      {CoherencyModel::abrahamson_2007_rock, "abrahamson-2007-rock", {}, {}},
  };
  return m;
}

const ModelInfo& info(CoherencyModel model) {
  for (const ModelInfo& m : models())
    if (m.model == model) return m;
  return models().front();
}

std::string number(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", x);
  return b;
}

// Hao, Oliveira & Penzien (1989): alpha(f) = a / f + b f + c [s^2/m^0.5], f held within the
// fitted 0.05-10 Hz (0.314-62.83 rad/s).
constexpr double kHaoFMin = 0.05, kHaoFMax = 10.0;  // [Hz]
double hao_alpha(const std::vector<double>& p, double f) {
  const double fc = std::min(std::max(f, kHaoFMin), kHaoFMax);
  return p[1] / fc + p[2] * fc + p[3];
}

// Abrahamson (2007), EPRI 1015110, horizontal plane-wave coherency (docs/ground.md: the
// coefficients as code_aster's signal_correlation_utils.py, ABRA_SOLMOYEN and ABRA_ROCHER,
// has them). f [Hz], d > 0 [m]; the coefficients' d is held at kAbrahamsonDMax (the soil
// model's a2 = 15.8 - 0.044 d vanishes at 359 m), tanh(a3 d) takes d itself.
constexpr double kAbrahamsonDMax = 300.0;  // [m]
double abrahamson_2007(bool rock, double d, double f) {
  const double x = std::min(d, kAbrahamsonDMax), l = std::log(x + 1.0);
  const double a1 = 1.0, a3 = 0.4;  // a3 [1/m]
  double n1, n2, a2, fc;            // a2, fc [Hz]
  if (rock) {
    n1 = 3.8 - 0.04 * l + 0.0105 * (l - 3.6) * (l - 3.6);
    n2 = 16.4;
    a2 = 40.0;
    fc = 27.9 - 4.82 * l + 1.24 * (l - 3.6) * (l - 3.6);
  } else {
    n1 = 3.0;
    n2 = 15.0;
    a2 = 15.8 - 0.044 * x;
    fc = 14.3 - 2.35 * l;
  }
  const double ft = f * std::tanh(a3 * d);
  return 1.0 / std::sqrt((1.0 + std::pow(ft / (a1 * fc), n1)) * (1.0 + std::pow(ft / a2, n2)));
}

// Each parameter's range; the message names the parameter and what is valid.
void check_parameters(const ModelInfo& m, const std::vector<double>& p, const std::string& where) {
  const auto bad = [&](std::size_t i, const std::string& valid) {
    return InputError(where + ": coherency " + m.name + " parameter " + m.parameters[i] + " = " +
                      number(p[i]) + " is out of range; valid: " + valid);
  };
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!std::isfinite(p[i])) throw bad(i, "a finite number");
  switch (m.model) {
    case CoherencyModel::none:
    case CoherencyModel::abrahamson_2007_soil:
    case CoherencyModel::abrahamson_2007_rock:
      break;
    case CoherencyModel::harichandran_vanmarcke_1986:
      if (!(p[0] > 0.0 && p[0] <= 1.0)) throw bad(0, "0 < A <= 1");
      if (!(p[1] > 0.0)) throw bad(1, "alpha > 0");
      if (!(p[2] > 0.0)) throw bad(2, "k > 0 m");
      if (!(p[3] > 0.0)) throw bad(3, "f0 > 0 Hz");
      if (!(p[4] > 0.0)) throw bad(4, "b > 0");
      break;
    case CoherencyModel::luco_wong_1986:
      if (!(p[0] > 0.0)) throw bad(0, "alpha > 0 s/m");
      break;
    case CoherencyModel::hao_oliveira_penzien_1989: {
      if (!(p[0] >= 0.0)) throw bad(0, "beta >= 0 1/m");
      // alpha(f) >= 0 over 0.05-10 Hz: at both ends and at the interior minimum sqrt(a / b)
      // when a, b > 0 (alpha is convex there; otherwise monotone).
      std::vector<double> fs = {kHaoFMin, kHaoFMax};
      if (p[1] > 0.0 && p[2] > 0.0) fs.push_back(std::sqrt(p[1] / p[2]));
      for (double f : fs)
        if (hao_alpha(p, f) < 0.0)
          throw InputError(where + ": coherency " + m.name +
                           " parameters a, b, c = " + number(p[1]) + ", " + number(p[2]) + ", " +
                           number(p[3]) + " give alpha(f) = a/f + b f + c < 0 at f = " + number(f) +
                           " Hz; valid: alpha >= 0 over 0.05-10 Hz");
      break;
    }
  }
}

}  // namespace

double Coherency::operator()(double d, double f) const {
  const std::vector<double>& p = parameters;
  if (model == CoherencyModel::none || d <= 0.0) return 1.0;
  switch (model) {
    case CoherencyModel::harichandran_vanmarcke_1986: {
      // Harichandran & Vanmarcke (1986), their eq. for the SMART-1 fit (docs/ground.md).
      const double a = p[0], alpha = p[1], k = p[2], f0 = p[3], b = p[4];
      const double theta = k / std::sqrt(1.0 + std::pow(f / f0, b));
      const double c = 2.0 * d * (1.0 - a + alpha * a);
      return a * std::exp(-c / (alpha * theta)) + (1.0 - a) * std::exp(-c / theta);
    }
    case CoherencyModel::luco_wong_1986: {
      const double x = p[0] * 2.0 * M_PI * f * d;
      return std::exp(-x * x);
    }
    case CoherencyModel::hao_oliveira_penzien_1989:
      return std::exp(-p[0] * d) * std::exp(-hao_alpha(p, f) * std::sqrt(d) * f * f);
    case CoherencyModel::abrahamson_2007_soil:
    case CoherencyModel::abrahamson_2007_rock:
      return abrahamson_2007(model == CoherencyModel::abrahamson_2007_rock, d, f);
    case CoherencyModel::none:
      break;
  }
  return 1.0;
}

std::string Coherency::name() const {
  return info(model).name;
}

std::string Coherency::describe() const {
  const ModelInfo& m = info(model);
  std::string out = m.name;
  if (m.model == CoherencyModel::none) return out + " (fully coherent)";
  if (m.parameters.empty()) return out + " (plane-wave coherency, EPRI 1015110)";
  static const std::vector<std::vector<const char*>> units = {
      {}, {"", "", " m", " Hz", ""}, {" s/m"}, {" 1/m", " s/m^0.5", " s^3/m^0.5", " s^2/m^0.5"}, {},
      {}};
  const std::vector<const char*>& u = units[std::size_t(m.model)];
  for (std::size_t i = 0; i < m.parameters.size(); ++i)
    out += std::string(i ? ", " : ": ") + m.parameters[i] + " = " + number(parameters[i]) + u[i];
  return out;
}

double Coherency::fitted_min_separation() const {
  return info(model).fitted_min_separation;
}

std::string fitted_range_note(const Coherency& c, double smallest_separation) {
  const double dmin = c.fitted_min_separation();
  if (!(smallest_separation < dmin)) return {};
  const double g0 = c(smallest_separation, 0.0);
  char b[400];
  std::snprintf(b, sizeof b,
                "coherency %s was fitted at separations of %g m and more; at %g m its coherency "
                "at zero frequency is %.3f, which leaves sqrt(2 (1 - %.3f)) = %.1f %% of the "
                "ground displacement independent at the two stations (abrahamson-2007-soil and "
                "-rock tend to 1 there)",
                c.name().c_str(), dmin, smallest_separation, g0, g0,
                100.0 * std::sqrt(2.0 * (1.0 - g0)));
  return b;
}

double smallest_separation(const std::vector<double>& positions) {
  std::vector<double> x = positions;
  std::sort(x.begin(), x.end());
  double out = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < x.size(); ++i) out = std::min(out, x[i] - x[i - 1]);
  return out;
}

std::string coherency_model_names() {
  std::string out;
  for (const ModelInfo& m : models()) out += std::string(out.empty() ? "" : ", ") + m.name;
  return out;
}

Coherency make_coherency(const std::string& name, const std::vector<double>& parameters,
                         const std::string& where) {
  for (const ModelInfo& m : models()) {
    if (name != m.name) continue;
    Coherency c;
    c.model = m.model;
    c.parameters = parameters.empty() ? m.defaults : parameters;
    if (m.defaults.empty() && !parameters.empty()) {
      std::string takers;
      for (const ModelInfo& t : models())
        if (!t.defaults.empty()) takers += std::string(takers.empty() ? "" : ", ") + t.name;
      throw InputError(where + ": coherency " + m.name + " takes no parameters, not " +
                       std::to_string(parameters.size()) + "; valid: no parameters, or a model " +
                       "that takes them: " + takers);
    }
    if (c.parameters.size() != m.defaults.size()) {
      std::string names;
      for (const char* p : m.parameters) names += std::string(names.empty() ? "" : ", ") + p;
      throw InputError(where + ": coherency " + m.name + " takes " +
                       std::to_string(m.defaults.size()) + " parameters" +
                       (names.empty() ? "" : " (" + names + ")") + ", not " +
                       std::to_string(parameters.size()));
    }
    check_parameters(m, c.parameters, where);
    return c;
  }
  throw InputError(where + ": unknown coherency model '" + name +
                   "'; valid: " + coherency_model_names());
}

}  // namespace pound
