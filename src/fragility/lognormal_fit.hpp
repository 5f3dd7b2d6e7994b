#pragma once
// Lognormal fragility functions fitted by maximum likelihood (Baker 2015, "Efficient analytical
// fragility function fitting using dynamic structural analysis", Earthquake Spectra 31(1)):
//
//   P(EDP > limit | IM = x) = Phi( ln(x / theta) / beta )                       (Baker eq. 1)
//
// from observations (x_j, n_j, z_j): z_j of n_j analyses at intensity x_j exceed the limit.
// The binomial log-likelihood (Baker eq. 11, constant dropped)
//
//   l = sum_j z_j ln Phi(eta_j) + (n_j - z_j) ln Phi(-eta_j),   eta_j = a + b ln x_j
//
// is maximised in the probit parameters (a, b), where it is globally concave (Pratt 1981), so
// Newton's method with a backtracking line search converges from any start whenever a finite
// maximum exists; then theta = exp(-a / b), beta = 1 / b. ln Phi and the inverse Mills ratio
// phi/Phi are evaluated through erfc with an asymptotic series in the far lower tail, so counts
// far out in either tail do not underflow to log(0).
//
// A finite estimate does not exist when all or none of the analyses exceed, when the outcomes
// are separated by intensity (every exceedance at a higher intensity than every
// non-exceedance: beta -> 0), when fewer than two distinct intensities carry data, or when the
// maximum has b <= 0 (exceedance falling with intensity). Those cases are reported by `status`,
// never as numbers. Observations with n = 1 give the per-sample (Bernoulli) fit used when the
// intensities are continuous (sampled scale factors).
#include <string>
#include <vector>

namespace pound {

/// z of n analyses at intensity `im` exceed the limit.
struct Observation {
  double im = 0.0;  ///< intensity measure [m/s^2] (any positive unit; theta comes out in it)
  long n = 0;       ///< analyses [-]
  long z = 0;       ///< exceedances [-], 0 <= z <= n
};

enum class FitStatus {
  ok,                ///< finite maximum-likelihood estimate
  no_data,           ///< no analyses
  none_exceed,       ///< z = 0 everywhere: theta beyond every intensity
  all_exceed,        ///< z = n everywhere: theta below every intensity
  separated,         ///< outcomes split by intensity: beta -> 0, theta in a gap
  single_intensity,  ///< one distinct intensity: theta and beta not identifiable
  not_increasing,    ///< the maximum has exceedance falling with intensity
  no_convergence     ///< Newton did not converge (should not happen: concave likelihood)
};
const char* to_string(FitStatus s);

struct LognormalFit {
  FitStatus status = FitStatus::no_data;
  double theta = 0.0;   ///< median capacity [unit of im]
  double beta = 0.0;    ///< logarithmic standard deviation [-]
  double loglik = 0.0;  ///< maximised log-likelihood (binomial constant dropped)
  int iterations = 0;   ///< Newton iterations
  /// Asymptotic covariance of (ln theta, beta) from the inverse observed information
  /// (delta method from (a, b)): var_ln_theta, cov, var_beta.
  double var_ln_theta = 0.0, cov_ln_theta_beta = 0.0, var_beta = 0.0;
  /// Without a finite estimate (none_exceed, all_exceed, separated), where the data put theta
  /// [unit of im]: theta_lo is the highest intensity at which no analysis exceeds (0 when there
  /// is none), theta_hi the lowest at which all exceed (inf when there is none). For complete
  /// separation this is the gap in which the likelihood tends to its supremum as beta -> 0;
  /// with one stripe holding both outcomes (quasi-complete) it is the stripes either side.
  double theta_lo = 0.0, theta_hi = 0.0;
  bool finite() const { return status == FitStatus::ok; }
  /// True when theta_lo and theta_hi bound theta (none_exceed, all_exceed, separated).
  bool bracketed() const {
    return status == FitStatus::none_exceed || status == FitStatus::all_exceed ||
           status == FitStatus::separated;
  }
  /// P(EDP > limit | IM = x); NaN without a finite estimate.
  double probability(double im) const;
};

/// Maximum-likelihood fit of the lognormal fragility function to the observations.
LognormalFit fit_lognormal(const std::vector<Observation>& obs);

/// ln Phi(x), accurate in both tails (erfc, asymptotic series below x = -30).
double log_normal_cdf(double x);
/// phi(x) / Phi(x) (inverse Mills ratio), accurate for large negative x.
double normal_mills(double x);

}  // namespace pound
