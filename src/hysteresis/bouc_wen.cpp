#include "hysteresis/bouc_wen.hpp"

#include <algorithm>
#include <cmath>

namespace pound {
namespace {

// |z / uy|^n, with the common n = 2 and n = 1 without pow().
double ratio_power(double z, double uy, double n) {
  const double r = std::fabs(z / uy);
  if (n == 2.0) return r * r;
  if (n == 1.0) return r;
  return std::pow(r, n);
}

}  // namespace

double BoucWenStorey::slope(const StoreyParameters& p, double z, double sign) {
  // 1 - |z|^n (gamma + beta sgn(dd z)) with beta = gamma = 1 / (2 uy^n): loading (dd z > 0)
  // 1 - |z/uy|^n, unloading 1.
  return sign * z > 0.0 ? 1.0 - ratio_power(z, p.uy(), p.bw_n) : 1.0;
}

double BoucWenStorey::shear(const StoreyParameters& p, const StoreyState&, double d,
                            const double* x) const {
  return p.k0 * (p.b * d + (1.0 - p.b) * x[0]);
}

void BoucWenStorey::rates(const StoreyParameters& p, const StoreyState&, double, double dd,
                          const double* x, double* dxdt) const {
  const double z = x[0];
  const double dz = dd * slope(p, z, dd);
  dxdt[0] = dz;
  dxdt[1] = (1.0 - p.b) * p.k0 * z * (dd - dz);
}

double BoucWenStorey::dissipated(const StoreyParameters&, const StoreyState&, double,
                                 const double* x) const {
  return x[1];
}

double BoucWenStorey::stored(const StoreyParameters& p, const StoreyState&, double d,
                             const double* x) const {
  return 0.5 * p.k0 * (p.b * d * d + (1.0 - p.b) * x[0] * x[0]);
}

double BoucWenStorey::advance(const StoreyParameters& p, const StoreyState& committed, double d0,
                              double d1, StoreyState& trial) const {
  trial = committed;
  const double delta = d1 - d0;
  if (delta != 0.0) {
    const double sign = delta > 0.0 ? 1.0 : -1.0;
    const double max_sub = p.uy() / (50.0 * std::max(1.0, p.bw_n));
    const int m = std::max(1, static_cast<int>(std::ceil(std::fabs(delta) / max_sub)));
    const double h = delta / m, c = (1.0 - p.b) * p.k0;
    // dz/dd = slope(z), dE/dd = c z (1 - slope(z)) (energy per unit drift along the path).
    auto f = [&](double z, double& dz, double& de) {
      dz = slope(p, z, sign);
      de = c * z * (1.0 - dz);
    };
    double z = trial.x[0], e = trial.x[1];
    for (int i = 0; i < m; ++i) {  // classical Runge-Kutta in d
      double k1z, k1e, k2z, k2e, k3z, k3e, k4z, k4e;
      f(z, k1z, k1e);
      f(z + 0.5 * h * k1z, k2z, k2e);
      f(z + 0.5 * h * k2z, k3z, k3e);
      f(z + h * k3z, k4z, k4e);
      z += h / 6.0 * (k1z + 2.0 * k2z + 2.0 * k3z + k4z);
      e += h / 6.0 * (k1e + 2.0 * k2e + 2.0 * k3e + k4e);
    }
    trial.x[0] = z;
    trial.x[1] = e;
  }
  return shear(p, trial, d1, trial.x);
}

}  // namespace pound
