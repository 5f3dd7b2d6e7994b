#include "motion/simqke.hpp"

#include <Random123/philox.h>
#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "motion/fftw_support.hpp"
#include "motion/motion_processing.hpp"
#include "motion/response_spectrum.hpp"

namespace pound {
double philox_uniform(std::uint64_t seed, std::uint64_t index, std::uint32_t i,
                      std::uint32_t stream) {
  using Rng = r123::Philox4x32;
  const Rng::key_type key = {
      {static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)}};
  const Rng::ctr_type ctr = {
      {i, stream, static_cast<std::uint32_t>(index), static_cast<std::uint32_t>(index >> 32)}};
  const Rng::ctr_type r = Rng()(ctr, key);
  // 27 + 26 bits -> [0, 1) with 53-bit resolution (the usual two-word construction).
  const double hi = double(r[0] >> 5), lo = double(r[1] >> 6);
  return (hi * 67108864.0 + lo) / 9007199254740992.0;
}

void simqke_phasors(std::uint64_t seed, std::uint64_t index, std::uint32_t stream,
                    const std::vector<double>& amplitude, std::vector<double>& re,
                    std::vector<double>& im) {
  re.resize(amplitude.size());
  im.resize(amplitude.size());
  for (std::size_t k = 0; k < amplitude.size(); ++k) {
    // A bin without amplitude needs no phase (its term is zero either way); each phase
    // depends on its own bin's counter only.
    if (amplitude[k] == 0.0) {
      re[k] = 1.0;
      im[k] = 0.0;
      continue;
    }
    const double u = philox_uniform(seed, index, std::uint32_t(k), stream);
    re[k] = std::cos(2.0 * M_PI * u);
    im[k] = std::sin(2.0 * M_PI * u);
  }
}

std::vector<double> simqke_match_periods(const SimqkeSettings& s) {
  const std::vector<double> core =
      log_spaced_periods(s.match_t_min, s.match_t_max, s.match_periods);
  const double r = core[1] / core[0];
  std::vector<double> out;
  for (int i = s.match_extend; i > 0; --i) out.push_back(core.front() / std::pow(r, i));
  out.insert(out.end(), core.begin(), core.end());
  for (int i = 1; i <= s.match_extend; ++i) out.push_back(core.back() * std::pow(r, i));
  return out;
}

SpectrumMatch compare_spectra(const std::vector<double>& computed,
                              const std::vector<double>& target) {
  SpectrumMatch m;
  if (computed.empty() || computed.size() != target.size()) return m;
  m.min_ratio = 1e300;
  m.max_ratio = 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < computed.size(); ++i) {
    const double r = computed[i] / target[i];
    m.min_ratio = std::min(m.min_ratio, r);
    m.max_ratio = std::max(m.max_ratio, r);
    sum += r;
  }
  m.mean_ratio = sum / double(computed.size());
  return m;
}

struct SimqkeGenerator::Impl {
  SimqkeSettings settings;
  double duration = 0.0;
  std::size_t n = 0, nfft = 0, nbins = 0;
  std::vector<double> envelope;    // I(t_i), i < n
  std::vector<double> amp0;        // first-guess A_k
  std::vector<double> target_psa;  // at the matching periods [m/s^2]
  std::vector<std::size_t> bin_j;  // matching-period interval of bin k
  std::vector<double> bin_w;       // weight of j + 1 in log period
  std::unique_ptr<SpectrumCalculator> spectra;
  double damping = 0.05;  // of the target [-]
  // The coarse spectrum of SimqkeStart::coarse_stride (made at its first use): its stride [-],
  // its periods' indices among the matching periods, ascending, the last one included.
  int coarse_stride = 0;
  std::unique_ptr<SpectrumCalculator> coarse;
  std::vector<std::size_t> coarse_at;
  std::unique_ptr<BaselineCorrector> baseline;
  std::vector<double> held_pow;  // ratio_j^relaxation of the current iteration
  double* real = nullptr;        // nfft reals
  fftw_complex* spec = nullptr;  // nbins complex
  fftw_plan c2r = nullptr, r2c = nullptr;

  ~Impl() {
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    if (c2r) fftw_destroy_plan(c2r);
    if (r2c) fftw_destroy_plan(r2c);
    if (real) fftw_free(real);
    if (spec) fftw_free(spec);
  }

  void make_coarse(int stride) {
    if (coarse_stride == stride) return;
    const std::vector<double>& all = spectra->periods();
    std::vector<double> periods;
    coarse_at.clear();
    for (std::size_t j = 0; j < all.size(); j += std::size_t(stride)) coarse_at.push_back(j);
    if (coarse_at.back() + 1 != all.size()) coarse_at.push_back(all.size() - 1);
    for (std::size_t j : coarse_at) periods.push_back(all[j]);
    coarse = std::make_unique<SpectrumCalculator>(periods, damping, settings.dt);
    coarse_stride = stride;
  }

  // The coarse spectrum of `accel` at every matching period [m/s^2]: computed at coarse_at,
  // between them ref_j exp(e_j), e = ln(psa / ref) linear in the index (the matching periods are
  // evenly spaced in ln T) from the two computed neighbours; ref is a full spectrum (an earlier
  // iteration's), whose period-to-period structure the correction keeps.
  void coarse_psa(const std::vector<double>& accel, const std::vector<double>& ref,
                  std::vector<double>& part, std::vector<double>& psa) const {
    coarse->compute_psa(accel, part);
    psa.resize(ref.size());
    double e0 = 0.0;  // ln(psa / ref) at the interval's lower computed period (one log each)
    for (std::size_t c = 0; c < coarse_at.size(); ++c) {
      const std::size_t hi = coarse_at[c];
      psa[hi] = part[c];
      const double e1 = std::log(part[c] / ref[hi]);
      if (c > 0) {
        const std::size_t lo = coarse_at[c - 1];
        for (std::size_t j = lo + 1; j < hi; ++j)
          psa[j] = ref[j] * std::exp(e0 + (e1 - e0) * double(j - lo) / double(hi - lo));
      }
      e0 = e1;
    }
  }

  // Ratio target / computed at bin k, interpolated in log period.
  double bin_ratio(const std::vector<double>& ratio, std::size_t k) const {
    const std::size_t j = bin_j[k];
    return ratio[j] + bin_w[k] * (ratio[std::min(j + 1, ratio.size() - 1)] - ratio[j]);
  }

  // The enveloped, baseline-corrected motion for amplitudes amp and phasors (re, im).
  void synthesise(const std::vector<double>& amp, const std::vector<double>& re,
                  const std::vector<double>& im, GroundMotion& m) {
    for (std::size_t k = 0; k < nbins; ++k) {
      spec[k][0] = 0.5 * amp[k] * re[k];
      spec[k][1] = 0.5 * amp[k] * im[k];
    }
    fftw_execute(c2r);  // real_j = sum_k A_k cos(w_k t_j + phi_k); destroys spec
    m.dt = settings.dt;
    m.accel.resize(n);
    for (std::size_t i = 0; i < n; ++i) m.accel[i] = real[i] * envelope[i];
    baseline->apply(m.accel);
  }

  // The motion with its Fourier amplitudes (zero-padded to nfft) multiplied by the ratio,
  // phases kept, then baseline-corrected (in place). A bin at a matching period or outside
  // their range (weight 0) takes ratio_j itself, whose power is computed once per iteration.
  void correct(GroundMotion& m, const std::vector<double>& ratio) {
    std::copy(m.accel.begin(), m.accel.end(), real);
    std::fill(real + n, real + nfft, 0.0);
    fftw_execute(r2c);
    held_pow.resize(ratio.size());
    for (std::size_t j = 0; j < ratio.size(); ++j)
      held_pow[j] = std::pow(ratio[j], settings.relaxation);
    spec[0][0] = spec[0][1] = 0.0;
    for (std::size_t k = 1; k < nbins; ++k) {
      // bin_ratio is ratio_j + 0 (ratio_j+1 - ratio_j) = ratio_j exactly when the weight is 0.
      const double p =
          bin_w[k] == 0.0 ? held_pow[bin_j[k]] : std::pow(bin_ratio(ratio, k), settings.relaxation);
      const double f = p / double(nfft);
      spec[k][0] *= f;
      spec[k][1] *= f;
    }
    fftw_execute(c2r);
    std::copy(real, real + n, m.accel.begin());
    baseline->apply(m.accel);
  }
};

SimqkeGenerator::SimqkeGenerator(const DesignSpectrum& target, double duration,
                                 SimqkeSettings settings)
    : impl_(std::make_unique<Impl>()) {
  Impl& d = *impl_;
  d.settings = settings;
  d.duration = duration;
  const double dt = settings.dt;
  if (!(dt > 0.0)) throw InputError("motion generator: dt must be > 0 s");
  if (!(duration >= 10.0 * dt)) throw InputError("motion generator: duration must be >= 10 dt");
  if (!(settings.match_t_min > 0.0 && settings.match_t_max > settings.match_t_min &&
        settings.match_periods >= 2 && settings.match_extend >= 0))
    throw InputError(
        "motion generator: need 0 < match_t_min < match_t_max, >= 2 periods, "
        "match_extend >= 0");
  if (!(settings.max_iterations >= 0 && settings.tolerance > 0.0))
    throw InputError("motion generator: max_iterations >= 0 and tolerance > 0 required");
  d.n = static_cast<std::size_t>(std::llround(duration / dt)) + 1;
  d.nfft = good_fft_size(std::size_t(std::max(1, settings.padding)) * d.n);
  d.nbins = d.nfft / 2 + 1;

  const Envelope env(settings.envelope, duration);
  d.envelope.resize(d.n);
  for (std::size_t i = 0; i < d.n; ++i) d.envelope[i] = env(dt * double(i));

  const std::vector<double> periods = simqke_match_periods(settings);
  d.target_psa = target.sample(periods);
  d.spectra = std::make_unique<SpectrumCalculator>(periods, target.damping(), dt);
  d.damping = target.damping();
  d.baseline = std::make_unique<BaselineCorrector>(d.n, dt);

  // First guess of the amplitudes and the bins' places among the matching periods.
  const double zeta = std::max(target.damping(), 0.005);
  const double dw = 2.0 * M_PI / (double(d.nfft) * dt);
  const double f_nyq = 0.5 / dt;
  const double f_max =
      settings.max_frequency > 0.0 ? std::min(settings.max_frequency, f_nyq) : 0.8 * f_nyq;
  const double f_min = 1.0 / (1.5 * settings.match_t_max);
  const double ts = env.strong_duration();
  d.amp0.assign(d.nbins, 0.0);
  d.bin_j.assign(d.nbins, 0);
  d.bin_w.assign(d.nbins, 0.0);
  const double lt0 = std::log(periods.front());
  const double dlt = std::log(periods.back() / periods.front()) / double(periods.size() - 1);
  for (std::size_t k = 1; k < d.nbins; ++k) {
    const double w = dw * double(k), f = w / (2.0 * M_PI);
    const double x = (std::log(1.0 / f) - lt0) / dlt;
    if (x <= 0.0) {
      d.bin_j[k] = 0;
    } else if (x >= double(periods.size() - 1)) {
      d.bin_j[k] = periods.size() - 1;
    } else {
      d.bin_j[k] = static_cast<std::size_t>(x);
      d.bin_w[k] = x - double(d.bin_j[k]);
    }
    if (f < f_min || f > f_max) continue;
    const double nu = std::max(1.5, w * ts / (2.0 * M_PI * std::log(2.0)));
    const double r = std::sqrt(2.0 * std::log(2.0 * nu));
    const double sa = target.sa(1.0 / f);
    const double g = 4.0 * zeta * (sa / r) * (sa / r) / (M_PI * w);
    d.amp0[k] = std::sqrt(2.0 * g * dw);
  }

  std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  d.real = fftw_alloc_real(d.nfft);
  d.spec = fftw_alloc_complex(d.nbins);
  if (!d.real || !d.spec) throw NumericalError("motion generator: FFT buffers not allocated");
  d.c2r = fftw_plan_dft_c2r_1d(int(d.nfft), d.spec, d.real, FFTW_ESTIMATE);
  d.r2c = fftw_plan_dft_r2c_1d(int(d.nfft), d.real, d.spec, FFTW_ESTIMATE);
  if (!d.c2r || !d.r2c) throw NumericalError("motion generator: no FFTW plan");
}

SimqkeGenerator::~SimqkeGenerator() = default;

const std::vector<double>& SimqkeGenerator::match_periods() const {
  return impl_->spectra->periods();
}
const std::vector<double>& SimqkeGenerator::match_target() const {
  return impl_->target_psa;
}

std::size_t SimqkeGenerator::fft_bins() const {
  return impl_->nbins;
}

double SimqkeGenerator::bin_frequency(std::size_t k) const {
  return double(k) / (double(impl_->nfft) * impl_->settings.dt);
}

SimqkeStart SimqkeGenerator::start() const {
  SimqkeStart s;
  s.amplitude = impl_->amp0;
  s.target = impl_->target_psa;
  s.max_attempts = impl_->settings.max_attempts;
  s.rms_score = false;
  return s;
}

SimqkeStart SimqkeGenerator::start(const std::vector<double>& ln_factor) const {
  const Impl& d = *impl_;
  if (ln_factor.size() != d.target_psa.size())
    throw InputError("motion generator: " + std::to_string(ln_factor.size()) +
                     " target factors for " + std::to_string(d.target_psa.size()) +
                     " matching periods");
  // The random target at the matching periods, and the first-guess amplitudes scaled by the
  // same factor interpolated in ln T at each bin (as bin_ratio interpolates the correction).
  SimqkeStart s;
  s.target.resize(d.target_psa.size());
  s.amplitude.resize(d.nbins);
  for (std::size_t j = 0; j < s.target.size(); ++j)
    s.target[j] = d.target_psa[j] * std::exp(ln_factor[j]);
  for (std::size_t k = 0; k < d.nbins; ++k)
    s.amplitude[k] = d.amp0[k] * std::exp(d.bin_ratio(ln_factor, k));
  s.max_attempts = d.settings.max_attempts_random_target;
  s.rms_score = true;
  return s;
}

GeneratedMotion SimqkeGenerator::generate(std::uint64_t seed, std::uint64_t index) {
  return run(start(), seed, index);
}

GeneratedMotion SimqkeGenerator::generate(const SimqkeStart& s, std::uint64_t seed,
                                          std::uint64_t index) {
  return run(s, seed, index);
}

GeneratedMotion SimqkeGenerator::generate(std::uint64_t seed, std::uint64_t index,
                                          const std::vector<double>& ln_factor) {
  return run(start(ln_factor), seed, index);
}

// The phase sets of one motion: the attempt with the smallest score is kept (the first of
// equal ones); a set within accept_score ends the search.
GeneratedMotion SimqkeGenerator::run(const SimqkeStart& s, std::uint64_t seed,
                                     std::uint64_t index) {
  std::vector<double> re, im;
  SimqkeAttempt best;
  int best_attempt = 0, evaluations = 0;
  for (int attempt = 0; attempt < s.max_attempts; ++attempt) {
    simqke_phasors(seed, index, std::uint32_t(attempt), s.amplitude, re, im);
    SimqkeAttempt a = match(s, re, im);
    evaluations += a.spectra;
    if (a.score < best.score) {
      best = std::move(a);
      best_attempt = attempt;
    }
    if (best.score <= impl_->settings.accept_score) break;
  }
  return finish(std::move(best), s, seed, index, best_attempt, evaluations);
}

GroundMotion SimqkeGenerator::synthesise(const SimqkeStart& s, const std::vector<double>& re,
                                         const std::vector<double>& im) {
  GroundMotion m;
  impl_->synthesise(s.amplitude, re, im, m);
  return m;
}

void SimqkeGenerator::correct(GroundMotion& m, const std::vector<double>& ratio) {
  impl_->correct(m, ratio);
}

void SimqkeGenerator::spectrum(const GroundMotion& m, std::vector<double>& psa) const {
  impl_->spectra->compute_psa(m.accel, psa);
}

SimqkeAttempt SimqkeGenerator::match(const SimqkeStart& s, const std::vector<double>& re,
                                     const std::vector<double>& im) {
  return match(s, synthesise(s, re, im));
}

SimqkeAttempt SimqkeGenerator::match(const SimqkeStart& s, GroundMotion m) {
  Impl& d = *impl_;
  return iterate(s, std::move(m),
                 [&d](GroundMotion& x, const std::vector<double>& ratio) { d.correct(x, ratio); });
}

SimqkeAttempt SimqkeGenerator::match(const SimqkeStart& s, GroundMotion m,
                                     const Corrector& corrector) {
  return iterate(s, std::move(m), corrector);
}

template <class Correct>
SimqkeAttempt SimqkeGenerator::iterate(const SimqkeStart& s, GroundMotion m,
                                       const Correct& correct) {
  Impl& d = *impl_;
  const std::vector<double>& target = s.target;
  std::vector<double> psa, ratio(target.size()), part, ref;
  // Coarse (SimqkeStart::coarse_stride): every iteration scored at d.coarse_at only.
  const bool coarse = s.coarse_stride > 1;
  if (coarse) {
    if (s.full_every < 1) throw InputError("motion generator: full_every must be >= 1");
    d.make_coarse(s.coarse_stride);
  }
  const std::size_t scored = coarse ? d.coarse_at.size() : target.size();
  SimqkeAttempt best;
  // The stall rules count from the last iteration that improved by the start's stall_gain (with
  // stall_gain 0 that is the best iteration).
  double stall_score = best.score;
  int stall_it = 0;
  for (int it = 0;; ++it) {
    if (it > 0) correct(m, ratio);
    if (coarse && it % s.full_every != 0) {
      d.coarse_psa(m.accel, ref, part, psa);
    } else {
      d.spectra->compute_psa(m.accel, psa);
      if (coarse) ref = psa;  // the reference of the coarse iterations after it
    }
    ++best.spectra;
    // Score: the largest |q - 1| over the matching periods, q = computed / target; for a
    // random target the RMS of ln q instead (simqke.hpp). Coarse: over the computed periods.
    double max_dev = 0.0, sum_sq = 0.0;
    for (std::size_t j = 0, c = 0; j < psa.size(); ++j) {
      if (!(psa[j] > 0.0) || !std::isfinite(psa[j]))
        throw NumericalError("motion generator: non-positive response spectrum at T = " +
                             std::to_string(d.spectra->periods()[j]) + " s");
      ratio[j] = target[j] / psa[j];
      if (coarse) {
        if (j != d.coarse_at[c]) continue;
        ++c;
      }
      const double q = psa[j] / target[j];
      max_dev = std::max(max_dev, std::fabs(q - 1.0));
      if (s.rms_score) {
        const double lq = std::log(q);  // one call (the same bits as two)
        sum_sq += lq * lq;
      }
    }
    const double score = s.rms_score ? std::sqrt(sum_sq / double(scored)) : max_dev;
    if (score < best.score) {
      best.score = score;
      best.motion = m;
      best.iterations = it;
      if (!coarse) {
        best.match = compare_spectra(psa, target);
        best.psa = psa;
      }
    }
    if (score < stall_score * (1.0 - s.stall_gain)) {
      stall_score = score;
      stall_it = it;
    }
    if (max_dev <= d.settings.tolerance || it >= d.settings.max_iterations) break;
    if (s.stop_score > 0.0 && best.score <= s.stop_score) break;
    // Acceptable and no longer improving (an earlier phase set was not acceptable, or this
    // one would not have been drawn, so "acceptable" is this set's best).
    if (best.score <= d.settings.accept_score && it - stall_it >= d.settings.stall) break;
    if (it - stall_it >= 2 * d.settings.stall) break;  // stuck: next phase set
  }
  return best;
}

void SimqkeGenerator::score(const SimqkeStart& s, SimqkeAttempt& a) const {
  std::vector<double>& psa = a.psa;
  spectrum(a.motion, psa);
  ++a.spectra;
  double max_dev = 0.0, sum_sq = 0.0;
  for (std::size_t i = 0; i < psa.size(); ++i) {
    const double q = psa[i] / s.target[i];
    max_dev = std::max(max_dev, std::fabs(q - 1.0));
    const double lq = std::log(q);  // one call (the same bits as two)
    sum_sq += lq * lq;
  }
  a.score = s.rms_score ? std::sqrt(sum_sq / double(psa.size())) : max_dev;
  a.match = compare_spectra(psa, s.target);
}

void SimqkeGenerator::transform(const std::vector<double>& accel,
                                std::vector<std::complex<double>>& x) {
  Impl& d = *impl_;
  std::copy(accel.begin(), accel.begin() + long(std::min(accel.size(), d.n)), d.real);
  std::fill(d.real + std::min(accel.size(), d.n), d.real + d.nfft, 0.0);
  fftw_execute(d.r2c);
  x.resize(d.nbins);
  for (std::size_t k = 0; k < d.nbins; ++k) x[k] = {d.spec[k][0], d.spec[k][1]};
}

void SimqkeGenerator::inverse(const std::vector<std::complex<double>>& x, GroundMotion& m) {
  Impl& d = *impl_;
  const double f = 1.0 / double(d.nfft);
  d.spec[0][0] = d.spec[0][1] = 0.0;
  for (std::size_t k = 1; k < d.nbins; ++k) {
    d.spec[k][0] = f * x[k].real();
    d.spec[k][1] = f * x[k].imag();
  }
  fftw_execute(d.c2r);
  m.dt = d.settings.dt;
  m.accel.assign(d.real, d.real + d.n);
  d.baseline->apply(m.accel);
}

void SimqkeGenerator::bin_power(const std::vector<double>& ratio, double power,
                                std::vector<double>& out) const {
  const Impl& d = *impl_;
  out.assign(d.nbins, 1.0);
  // As correct(): a bin of weight 0 takes ratio_j itself (ratio_j + 0 (ratio_j+1 - ratio_j) is
  // ratio_j exactly), whose power is computed once per matching period.
  // So does a bin whose interpolated ratio comes out as ratio_j (between two equal ratios:
  // ratio_j + w 0), the same argument of pow: with the dead band of
  // ground/station_generator.hpp most of a station's ratios are exp(0) = 1 after a few
  // iterations, and pow costs more than the rest of the correction.
  std::vector<double> held(ratio.size(), -1.0);  // -1: not computed (a power is >= 0 or NaN)
  for (std::size_t k = 1; k < d.nbins; ++k) {
    const std::size_t j = d.bin_j[k];
    if (d.bin_w[k] != 0.0) {
      const double x = d.bin_ratio(ratio, k);
      if (!(x == ratio[j])) {
        out[k] = std::pow(x, power);
        continue;
      }
    }
    double& h = held[j];
    if (h < 0.0) h = std::pow(ratio[j], power);
    out[k] = h;
  }
}

const SimqkeSettings& SimqkeGenerator::settings() const {
  return impl_->settings;
}

GeneratedMotion SimqkeGenerator::finish(SimqkeAttempt best, const SimqkeStart& s,
                                        std::uint64_t seed, std::uint64_t index, int attempt,
                                        int spectra) const {
  GeneratedMotion g;
  g.motion = std::move(best.motion);
  g.iterations = best.iterations;
  g.attempt = attempt;
  g.match = best.match;
  g.psa = std::move(best.psa);
  g.target_psa = s.target;
  g.spectra = spectra;
  g.motion.name = "simqke seed " + std::to_string(seed) + " index " + std::to_string(index);
  const GroundKinematics kin = integrate(g.motion);
  g.final_velocity = kin.final_velocity();
  g.final_displacement = kin.final_displacement();
  return g;
}

GroundMotion generate_spectrum_compatible(const DesignSpectrum& target, double duration,
                                          std::uint64_t seed, const SimqkeSettings& settings) {
  SimqkeGenerator g(target, duration, settings);
  return g.generate(seed, 0).motion;
}

}  // namespace pound
