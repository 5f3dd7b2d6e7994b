#include "motion/envelope.hpp"

#include <cmath>
#include <sstream>

#include "core/error.hpp"

namespace pound {

Envelope::Envelope(const EnvelopeSettings& s, double duration) : s_(s), duration_(duration) {
  if (!(duration > 0.0)) throw InputError("envelope: the duration must be > 0 s");
  if (s_.rise < 0.0) s_.rise = 0.1 * duration;
  if (s_.strong_end < 0.0) s_.strong_end = 0.5 * duration;
  if (s.shape == EnvelopeShape::jennings) {
    if (!(s_.rise >= 0.0 && s_.strong_end > s_.rise && s_.strong_end < duration))
      throw InputError("envelope: Jennings times need 0 <= rise < strong-end < duration");
    if (s.decay < 0.0) throw InputError("envelope: decay must be >= 0 1/s");
    // Default decay: I(duration) = 0.05.
    decay_ = s.decay > 0.0 ? s.decay : -std::log(0.05) / (duration - s_.strong_end);
    strong_ = s_.strong_end - s_.rise;
  } else {
    if (!(s.epsilon > 0.0 && s.epsilon < 1.0 && s.eta > 0.0 && s.eta < 1.0))
      throw InputError("envelope: Saragoni-Hart needs 0 < epsilon < 1 and 0 < eta < 1");
    // Boore (2003) eq. 20 parameters.
    b_ = -s.epsilon * std::log(s.eta) / (1.0 + s.epsilon * (std::log(s.epsilon) - 1.0));
    c_ = b_ / s.epsilon;
    a_ = std::pow(std::exp(1.0) / s.epsilon, b_);
    // Strong phase: the time I(t) >= 0.5 (by sampling).
    int above = 0;
    for (int i = 0; i <= 1000; ++i)
      if ((*this)(duration * i / 1000.0) >= 0.5) ++above;
    strong_ = duration * above / 1000.0;
  }
}

double Envelope::operator()(double t) const {
  if (t <= 0.0) return 0.0;
  if (s_.shape == EnvelopeShape::jennings) {
    if (t < s_.rise) return (t / s_.rise) * (t / s_.rise);
    if (t <= s_.strong_end) return 1.0;
    return std::exp(-decay_ * (t - s_.strong_end));
  }
  const double x = t / duration_;
  return a_ * std::pow(x, b_) * std::exp(-c_ * x);
}

std::string Envelope::describe() const {
  std::ostringstream o;
  if (s_.shape == EnvelopeShape::jennings)
    o << "Jennings-Housner-Tsai trapezoidal-exponential envelope: rise to " << s_.rise
      << " s, strong to " << s_.strong_end << " s, decay " << decay_ << " 1/s";
  else
    o << "Saragoni-Hart envelope: peak at " << s_.epsilon << " tw, " << s_.eta
      << " at tw = " << duration_ << " s";
  return o.str();
}

}  // namespace pound
