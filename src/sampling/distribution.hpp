#pragma once
// Distributions of sampled study parameters, each mapping a uniform u in (0, 1) to a value by
// its inverse CDF (so plain Monte Carlo and Latin hypercube share the same code). Written in
// study files as:
//   0.05                          fixed value (also fixed(0.05))
//   uniform(a, b)                 a <= x <= b
//   normal(mean, sd)
//   lognormal(median, beta)       ln x ~ N(ln median, beta^2)
//   normal(mean, sd, lo, hi)      truncated to [lo, hi]; likewise lognormal(median, beta, lo, hi)
//   discrete(v1: w1, v2: w2, ...) values (numbers or names) with weights (normalised)
#include <string>
#include <vector>

namespace pound {

enum class DistributionKind { fixed, uniform, normal, lognormal, discrete };

class Distribution {
 public:
  /// Parses the text; `where` (file:line: key) prefixes errors, which list the valid forms.
  static Distribution parse(const std::string& text, const std::string& where);

  DistributionKind kind() const { return kind_; }
  bool is_fixed() const { return kind_ == DistributionKind::fixed; }
  /// The value for a uniform u in (0, 1) (numeric distributions).
  double value(double u) const;
  /// The chosen label for a discrete distribution (numbers are returned as written).
  const std::string& label(double u) const;
  /// Index of the discrete outcome for u.
  std::size_t index(double u) const;
  const std::vector<std::string>& labels() const { return labels_; }
  std::string text() const { return text_; }
  /// The smallest and largest values the distribution can produce (numeric kinds; infinite
  /// for untruncated normal tails).
  double lower() const;
  double upper() const;

 private:
  DistributionKind kind_ = DistributionKind::fixed;
  double p1_ = 0,
         p2_ = 0;  // fixed: value; uniform: a, b; normal: mean, sd; lognormal: ln median, beta
  double plo_ = 0, phi_ = 1;  // CDF of the truncation bounds (1-plo..phi used for truncation)
  bool truncated_ = false;
  double lo_ = 0, hi_ = 0;
  std::vector<std::string> labels_;
  std::vector<double> cumulative_;  // discrete: cumulative normalised weights
  std::string text_;
};

}  // namespace pound
