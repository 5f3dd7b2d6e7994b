#include "motion/spectrum_table.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "io/period_table.hpp"
#include "motion/ground_motion.hpp"

namespace pound {

TableSpectrum::TableSpectrum(std::vector<double> periods, std::vector<double> sa, double damping,
                             std::string name)
    : damping_(damping), name_(std::move(name)) {
  if (periods.size() != sa.size() || periods.size() < 2)
    throw InputError(name_ + ": a spectrum table needs at least 2 (T, Sa) pairs");
  for (std::size_t i = 0; i < periods.size(); ++i) {
    if (!(periods[i] > 0.0) || (i > 0 && !(periods[i] > periods[i - 1])))
      throw InputError(name_ + ": periods must be > 0 and strictly increasing");
    if (!(sa[i] > 0.0)) throw InputError(name_ + ": spectral accelerations must be > 0");
    log_t_.push_back(std::log(periods[i]));
    log_sa_.push_back(std::log(sa[i]));
  }
  t_first_ = periods.front();
  t_last_ = periods.back();
}

double TableSpectrum::sa(double T) const {
  if (T <= t_first_) return std::exp(log_sa_.front());
  if (T >= t_last_) return std::exp(log_sa_.back());
  const double lt = std::log(T);
  const auto it = std::upper_bound(log_t_.begin(), log_t_.end(), lt);
  const std::size_t i = std::size_t(it - log_t_.begin()) - 1;
  const double f = (lt - log_t_[i]) / (log_t_[i + 1] - log_t_[i]);
  return std::exp(log_sa_[i] + f * (log_sa_[i + 1] - log_sa_[i]));
}

std::string TableSpectrum::describe() const {
  std::ostringstream s;
  s << "user table " << name_ << ": " << log_t_.size() << " points from " << t_first_ << " to "
    << t_last_ << " s, log-log interpolation, damping " << 100.0 * damping_ << " %";
  return s.str();
}

TableSpectrum read_spectrum_table(const std::string& path, double damping) {
  std::vector<double> t, sa;
  for (const PeriodTableRow& r :
       read_period_table(path, "the spectrum table", "'T Sa' (T in s, Sa in g)")) {
    if (!(r.value > 0.0)) throw InputError(r.where + ": Sa " + r.text + " g; valid: > 0");
    t.push_back(r.period);
    sa.push_back(r.value * kGravity);
  }
  if (t.size() < 2) throw InputError(path + ": fewer than 2 (T, Sa) pairs; give at least 2");
  return TableSpectrum(std::move(t), std::move(sa), damping, path);
}

}  // namespace pound
