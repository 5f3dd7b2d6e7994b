#include "ground/coherency.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"

namespace pound {
namespace {

struct ModelInfo {
  CoherencyModel model;
  const char* name;
  std::vector<const char*> parameters;  // names, in order
  std::vector<double> defaults;
};

const std::vector<ModelInfo>& models() {
  static const std::vector<ModelInfo> m = {
      {CoherencyModel::none, "none", {}, {}},
      {CoherencyModel::harichandran_vanmarcke_1986,
       "harichandran-vanmarcke-1986",
       {"A", "alpha", "k", "f0", "b"},
       {0.736, 0.147, 5210.0, 1.09, 2.78}},
      {CoherencyModel::luco_wong_1986, "luco-wong-1986", {"alpha"}, {2.5e-4}},
      {CoherencyModel::hao_oliveira_penzien_1989,
       "hao-oliveira-penzien-1989",
       {"beta", "a", "b", "c"},
       {1.109e-4, 3.583e-3, -1.811e-5, 1.177e-4}},
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
  static const std::vector<std::vector<const char*>> units = {
      {}, {"", "", " m", " Hz", ""}, {" s/m"}, {" 1/m", " s/m^0.5", " s^3/m^0.5", " s^2/m^0.5"}};
  const std::vector<const char*>& u = units[std::size_t(m.model)];
  for (std::size_t i = 0; i < m.parameters.size(); ++i)
    out += std::string(i ? ", " : ": ") + m.parameters[i] + " = " + number(parameters[i]) + u[i];
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
