#include "motion/sigma_lnsa.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "io/period_table.hpp"

namespace pound {

SigmaLnSa SigmaLnSa::constant(double sigma) {
  if (!(sigma >= 0.0 && std::isfinite(sigma)))
    throw InputError("sigma of ln Sa: " + std::to_string(sigma) + "; valid: a finite number >= 0");
  SigmaLnSa s;
  s.log_t_ = {0.0};
  s.sigma_ = {sigma};
  std::ostringstream d;
  d << "constant sigma_lnsa = " << sigma;
  s.describe_ = d.str();
  return s;
}

SigmaLnSa SigmaLnSa::table(std::vector<double> periods, std::vector<double> sigmas,
                           std::string name) {
  if (periods.empty() || periods.size() != sigmas.size())
    throw InputError(name + ": a sigma table needs at least one (T, sigma) pair");
  SigmaLnSa s;
  for (std::size_t i = 0; i < periods.size(); ++i) {
    if (!(periods[i] > 0.0) || (i > 0 && !(periods[i] > periods[i - 1])))
      throw InputError(name + ": periods must be > 0 s and strictly increasing");
    if (!(sigmas[i] >= 0.0 && std::isfinite(sigmas[i])))
      throw InputError(name + ": sigma must be finite and >= 0");
    s.log_t_.push_back(std::log(periods[i]));
  }
  s.sigma_ = std::move(sigmas);
  std::ostringstream d;
  d << name << ": " << periods.size() << " points from " << periods.front() << " to "
    << periods.back() << " s, linear in ln T";
  s.describe_ = d.str();
  return s;
}

SigmaLnSa SigmaLnSa::boore_atkinson_2008() {
  // Boore & Atkinson (2008), Table 8: periods [s] and sigma_TU [-] (ln units), PGA and PGV
  // left out (PGA is T = 0, below the held first value).
  static const std::vector<double> t = {0.01, 0.02, 0.03, 0.05, 0.075, 0.1,  0.15,
                                        0.2,  0.25, 0.3,  0.4,  0.5,   0.75, 1.0,
                                        1.5,  2.0,  3.0,  4.0,  5.0,   7.5,  10.0};
  static const std::vector<double> s = {0.569, 0.569, 0.578, 0.589, 0.606, 0.608, 0.592,
                                        0.596, 0.592, 0.608, 0.603, 0.615, 0.649, 0.654,
                                        0.684, 0.702, 0.700, 0.702, 0.730, 0.781, 0.735};
  SigmaLnSa out = table(t, s, "Boore & Atkinson (2008) Table 8 sigma_TU");
  out.describe_ =
      "Boore & Atkinson (2008), Earthquake Spectra 24(1), Table 8, sigma_TU (total, fault type "
      "unspecified), 0.57-0.78 over 0.01-10 s, linear in ln T";
  return out;
}

double SigmaLnSa::operator()(double period) const {
  if (sigma_.size() == 1) return sigma_.front();
  if (!(period > 0.0)) return sigma_.front();
  const double lt = std::log(period);
  if (lt <= log_t_.front()) return sigma_.front();
  if (lt >= log_t_.back()) return sigma_.back();
  const auto it = std::upper_bound(log_t_.begin(), log_t_.end(), lt);
  const std::size_t i = std::size_t(it - log_t_.begin()) - 1;
  const double f = (lt - log_t_[i]) / (log_t_[i + 1] - log_t_[i]);
  return sigma_[i] + f * (sigma_[i + 1] - sigma_[i]);
}

SigmaLnSa read_sigma_table(const std::string& path) {
  std::vector<double> t, s;
  for (const PeriodTableRow& r :
       read_period_table(path, "the sigma table", "'T sigma' (T in s, sigma of ln Sa, -)")) {
    if (!(r.value >= 0.0)) throw InputError(r.where + ": sigma " + r.text + "; valid: >= 0");
    t.push_back(r.period);
    s.push_back(r.value);
  }
  if (t.empty()) throw InputError(path + ": no (T, sigma) line; give at least one");
  return SigmaLnSa::table(std::move(t), std::move(s), path);
}

SigmaLnSa sigma_model(const std::string& name, const std::string& where) {
  if (name == "boore-atkinson-2008") return SigmaLnSa::boore_atkinson_2008();
  throw InputError(where + ": unknown ground-motion model '" + name +
                   "'; valid: boore-atkinson-2008");
}

}  // namespace pound
