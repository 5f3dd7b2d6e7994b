#pragma once
// Record-to-record variability of spectrum-compatible motions: each motion is matched to its
// own random target spectrum around the design spectrum,
//
//   ln Sa_i(T_j) = ln Sa_design(T_j) + sigma(T_j) eps_i(T_j),
//
// with eps_i a standard normal vector over the generator's matching periods T_j, correlated
// across periods by a SpectralCorrelation model (spectral_correlation.hpp) and sigma(T) from
// sigma_lnsa.hpp. The draws: z_j = Phi^-1(u_j), u_j = CounterRng(seed, stream_id(
// "motion.spectrum")).uniform(index, j) (the campaign's study seed and sample id, or the seed
// and motion number of `pound motion generate`), and eps = L z with L the lower Cholesky factor
// of the correlation matrix R_jk = rho(T_j, T_k) (one z for every period with `full`, eps = z
// with `none`). So a sample's target depends only on (seed, index), on any rank.
//
// L is computed once per period set (Eigen's LLT); a matrix that is not numerically positive
// definite (a very dense period grid) falls back to R = V diag(lambda) V^T with negative
// eigenvalues set to 0 and the rows of V diag(sqrt lambda) scaled to unit length, so every
// eps_j keeps unit variance. The Baker-Jayaram matrix of the default 110 matching periods
// (0.040-4.99 s) is positive definite (smallest eigenvalue 1.1e-3).
#include <cstdint>
#include <string>
#include <vector>

#include "io/options.hpp"
#include "motion/sigma_lnsa.hpp"
#include "motion/spectral_correlation.hpp"
#include "sampling/counter_rng.hpp"

namespace pound {

enum class Variability {
  none,      ///< every motion matches the design spectrum (the generator as before issue 12)
  spectral,  ///< every motion matches its own random target spectrum (above)
};

struct VariabilitySettings {
  Variability mode = Variability::none;
  SigmaLnSa sigma = SigmaLnSa::boore_atkinson_2008();
  SpectralCorrelation correlation = SpectralCorrelation::baker_jayaram_2008;
  /// One line: "none" or "spectral, sigma ..., correlation ...".
  std::string describe() const;
};

/// The stream of the target draws (counter_rng.hpp).
inline const char* const kTargetStream = "motion.spectrum";

/// Option declarations: variability, sigma<sep>lnsa, sigma<sep>table, sigma<sep>model,
/// correlation; `sep` is '_' in study files ([generator] sigma_lnsa) and '-' on the command
/// line of `pound motion generate` (--sigma-lnsa).
std::vector<OptionSpec> variability_option_specs(char sep);
/// The settings from those options. At most one of sigma_lnsa, sigma_table, sigma_model may be
/// given (none: sigma_model's default). Every given key is checked, also with variability
/// none: sigma < 0, an unreadable table or an unknown name is an InputError naming the key.
VariabilitySettings variability_from_options(const Options& options, char sep);

/// The random targets over one set of periods.
class TargetVariability {
 public:
  /// periods [s] > 0 (the generator's matching periods).
  TargetVariability(VariabilitySettings settings, std::vector<double> periods);

  bool enabled() const { return settings_.mode == Variability::spectral; }
  const VariabilitySettings& settings() const { return settings_; }
  const std::vector<double>& periods() const { return periods_; }
  /// sigma(T_j) [-].
  const std::vector<double>& sigma() const { return sigma_; }

  /// eps at the periods [-] for draw `index` of `rng` (the stream kTargetStream).
  std::vector<double> epsilon(const CounterRng& rng, std::uint64_t index) const;
  /// ln(Sa_target / Sa_design) = sigma_j eps_j [-] at the periods.
  std::vector<double> ln_factor(const std::vector<double>& eps) const;

 private:
  VariabilitySettings settings_;
  std::vector<double> periods_, sigma_;
  std::vector<double> lower_;  // n x n row-major lower factor (baker-jayaram-2008 only)
};

}  // namespace pound
