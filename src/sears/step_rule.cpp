#include "sears/step_rule.hpp"

#include <cmath>
#include <sstream>

#include "core/error.hpp"

namespace pound::sears {

StepLimits step_limits(double t_min, double t_c) {
  StepLimits s;
  s.auto_dt_s = std::fmin(t_min / kStepsPerShortestPeriod, t_c / kStepsPerContact);
  s.max_dt_s = std::fmin(t_min / kMinStepsPerShortestPeriod, t_c / kMinStepsPerContact);
  return s;
}

double choose_step(const StepLimits& limits, double dt_user) {
  if (!(dt_user > 0.0)) return limits.auto_dt_s;
  if (!std::isfinite(dt_user) || dt_user > limits.max_dt_s) {
    std::ostringstream m;
    m.precision(4);
    m << "damped Sears model: dt = " << dt_user << " s is too large; the largest allowed step is "
      << limits.max_dt_s << " s (half the shortest modal period retained or 1/20 of the contact "
      << "time scale; automatic step " << limits.auto_dt_s << " s)";
    throw InputError(m.str());
  }
  return dt_user;
}

}  // namespace pound::sears
