#include "fragility/rank_correlation.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace pound {

std::vector<double> ranks(const std::vector<double>& x) {
  std::vector<std::size_t> order(x.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
  std::vector<double> r(x.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && x[order[j + 1]] == x[order[i]]) ++j;
    const double avg = 0.5 * double(i + j) + 1.0;
    for (std::size_t k = i; k <= j; ++k) r[order[k]] = avg;
    i = j + 1;
  }
  return r;
}

double pearson(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  if (n < 2 || y.size() != n) return std::numeric_limits<double>::quiet_NaN();
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / double(n);
  const double my = std::accumulate(y.begin(), y.end(), 0.0) / double(n);
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
  }
  const double scale = std::sqrt(sxx * syy);
  if (!(scale > 1e-14 * (sxx + syy))) return std::numeric_limits<double>::quiet_NaN();
  return sxy / scale;
}

double spearman(const std::vector<double>& x, const std::vector<double>& y) {
  return pearson(ranks(x), ranks(y));
}

double partial_rank_correlation(const std::vector<std::vector<double>>& columns,
                                const std::vector<double>& y, std::size_t j) {
  const std::size_t n = y.size(), p = columns.size();
  if (j >= p || n < p + 2) return std::numeric_limits<double>::quiet_NaN();
  Eigen::MatrixXd z(n, p);  // intercept and the other parameters' ranks
  z.col(0).setOnes();
  for (std::size_t c = 0, k = 1; c < p; ++c) {
    if (c == j) continue;
    const auto r = ranks(columns[c]);
    for (std::size_t i = 0; i < n; ++i) z(Eigen::Index(i), Eigen::Index(k)) = r[i];
    ++k;
  }
  auto residual = [&](const std::vector<double>& v) {
    const auto r = ranks(v);
    const Eigen::VectorXd b = Eigen::Map<const Eigen::VectorXd>(r.data(), Eigen::Index(n));
    const Eigen::VectorXd e = b - z * z.colPivHouseholderQr().solve(b);
    return std::vector<double>(e.data(), e.data() + n);
  };
  return pearson(residual(columns[j]), residual(y));
}

}  // namespace pound
