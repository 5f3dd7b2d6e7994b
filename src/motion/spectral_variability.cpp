#include "motion/spectral_variability.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "core/error.hpp"
#include "sampling/normal.hpp"

namespace pound {
namespace {

std::string key(const char* a, char sep, const char* b) {
  return std::string(a) + sep + b;
}

}  // namespace

std::string VariabilitySettings::describe() const {
  if (mode == Variability::none) return "none";
  return "spectral: sigma " + sigma.describe() + "; correlation " + to_string(correlation);
}

std::vector<OptionSpec> variability_option_specs(char sep) {
  return {
      {"variability", "", "none",
       "none (every motion matches the design spectrum) or spectral (each its own random target "
       "ln Sa = ln Sa_design + sigma eps)"},
      {key("sigma", sep, "lnsa"), "-", "",
       "spectral: constant standard deviation of ln Sa, >= 0 (instead of the sigma model)"},
      {key("sigma", sep, "table"), "", "",
       "spectral: file of lines 'T sigma' (s, -), linear in ln T (instead of the sigma model)"},
      {key("sigma", sep, "model"), "", "boore-atkinson-2008",
       "spectral: sigma(T) of a ground-motion model: boore-atkinson-2008 (Table 8, sigma_TU)"},
      {"correlation", "", "baker-jayaram-2008",
       "spectral: correlation of eps across periods: baker-jayaram-2008, none or full"},
  };
}

VariabilitySettings variability_from_options(const Options& o, char sep) {
  VariabilitySettings s;
  const std::string mode = o.get_string("variability");
  if (mode == "none")
    s.mode = Variability::none;
  else if (mode == "spectral")
    s.mode = Variability::spectral;
  else
    throw o.invalid("variability", "valid: none or spectral");
  const std::string k_lnsa = key("sigma", sep, "lnsa"), k_table = key("sigma", sep, "table"),
                    k_model = key("sigma", sep, "model");
  const int given = int(o.given(k_lnsa)) + int(o.given(k_table)) + int(o.given(k_model));
  if (given > 1)
    throw InputError(o.where(o.given(k_lnsa) ? k_lnsa : k_table) + ": give one of " + k_lnsa +
                     ", " + k_table + " and " + k_model + ", not several");
  if (o.given(k_lnsa)) {
    const double v = o.get_double(k_lnsa);
    if (!(v >= 0.0)) throw o.invalid(k_lnsa, "valid: a standard deviation of ln Sa >= 0");
    s.sigma = SigmaLnSa::constant(v);
  } else if (o.given(k_table)) {
    const std::string path = o.get_path(k_table);
    try {
      s.sigma = read_sigma_table(path);
    } catch (const InputError& e) {
      throw InputError(o.where(k_table) + ": " + e.what());
    }
  } else {
    s.sigma = sigma_model(o.get_string(k_model), o.where(k_model));
  }
  s.correlation = parse_spectral_correlation(o.get_string("correlation"), o.where("correlation"));
  return s;
}

TargetVariability::TargetVariability(VariabilitySettings settings, std::vector<double> periods)
    : settings_(std::move(settings)), periods_(std::move(periods)) {
  const std::size_t n = periods_.size();
  for (double t : periods_) sigma_.push_back(settings_.sigma(t));
  if (!enabled() || settings_.correlation != SpectralCorrelation::baker_jayaram_2008) return;
  Eigen::MatrixXd r(n, n);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t k = 0; k <= j; ++k)
      r(j, k) = r(k, j) = baker_jayaram_2008(periods_[j], periods_[k]);
  Eigen::MatrixXd f;
  const Eigen::LLT<Eigen::MatrixXd> llt(r);
  if (llt.info() == Eigen::Success) {
    f = llt.matrixL();
  } else {
    // Not numerically positive definite: the nearest positive semi-definite factor, rows
    // scaled back to unit variance.
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(r);
    if (es.info() != Eigen::Success)
      throw NumericalError("spectral variability: no factor of the correlation matrix");
    f = es.eigenvectors() * es.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
    for (Eigen::Index j = 0; j < f.rows(); ++j) f.row(j) /= f.row(j).norm();
  }
  lower_.resize(n * n);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t k = 0; k < n; ++k) lower_[j * n + k] = f(Eigen::Index(j), Eigen::Index(k));
}

std::vector<double> TargetVariability::epsilon(const CounterRng& rng, std::uint64_t index) const {
  const std::size_t n = periods_.size();
  std::vector<double> eps(n, 0.0);
  if (!enabled() || n == 0) return eps;
  switch (settings_.correlation) {
    case SpectralCorrelation::full: {
      const double z = normal_quantile(rng.uniform(index, 0));
      eps.assign(n, z);
      break;
    }
    case SpectralCorrelation::none:
      for (std::size_t j = 0; j < n; ++j) eps[j] = normal_quantile(rng.uniform(index, j));
      break;
    case SpectralCorrelation::baker_jayaram_2008: {
      std::vector<double> z(n);
      for (std::size_t j = 0; j < n; ++j) z[j] = normal_quantile(rng.uniform(index, j));
      // eps = L z (a full factor from the eigen fallback is used the same way).
      for (std::size_t j = 0; j < n; ++j) {
        double sum = 0.0;
        const double* row = &lower_[j * n];
        for (std::size_t k = 0; k < n; ++k) sum += row[k] * z[k];
        eps[j] = sum;
      }
      break;
    }
  }
  return eps;
}

std::vector<double> TargetVariability::ln_factor(const std::vector<double>& eps) const {
  std::vector<double> out(eps.size());
  for (std::size_t j = 0; j < eps.size(); ++j) out[j] = sigma_[j] * eps[j];
  return out;
}

}  // namespace pound
