#include "ground/station_generator.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/error.hpp"

namespace pound {
namespace {

constexpr double kPivotFloor = 1e-10;  // a pivot below it counts as 0 (semi-definite G)

std::size_t packed(std::size_t j, std::size_t m) {
  return j * (j + 1) / 2 + m;
}

// The coherency of unit phasors exp(i arg z_j), exp(i arg z_k) of circular complex Gaussians
// z_j, z_k of correlation g: E exp(i (arg z_j - arg z_k)) = (pi / 4) g 2F1(1/2, 1/2; 2; g^2)
// = [E(g) - (1 - g^2) K(g)] / g, K and E the complete elliptic integrals of modulus g
// (docs/ground.md). Increasing from 0 to 1 on [0, 1], pi g / 4 near 0.
double phase_coherency(double g) {
  if (g <= 0.0) return 0.0;
  if (g >= 1.0) return 1.0;
  return (std::comp_ellint_2(g) - (1.0 - g * g) * std::comp_ellint_1(g)) / g;
}

// The correlation g of the Gaussians whose unit phasors have the coherency `gamma` in [0, 1]:
// the inverse of phase_coherency, by linear interpolation in a table of 4001 points dense
// near g = 1 (g = 1 - (1 - u)^2, u uniform).
double gaussian_coherency(double gamma) {
  static const std::vector<std::pair<double, double>> table = [] {
    std::vector<std::pair<double, double>> t;
    for (int i = 0; i <= 4000; ++i) {
      const double u = double(i) / 4000.0, g = 1.0 - (1.0 - u) * (1.0 - u);
      t.emplace_back(phase_coherency(g), g);
    }
    return t;
  }();
  if (gamma <= 0.0) return 0.0;
  if (gamma >= 1.0) return 1.0;
  const auto it = std::lower_bound(table.begin(), table.end(), std::make_pair(gamma, -1.0));
  const auto& hi = *it;
  const auto& lo = *(it - 1);
  return lo.second + (gamma - lo.first) / (hi.first - lo.first) * (hi.second - lo.second);
}

void check_positions(const std::vector<double>& x) {
  if (x.empty()) throw InputError("station generator: no station positions");
  for (std::size_t j = 0; j < x.size(); ++j) {
    if (!std::isfinite(x[j]))
      throw InputError("station generator: position " + std::to_string(j + 1) +
                       " is not finite; valid: finite coordinates in m");
    if (j > 0 && !(x[j] > x[j - 1]))
      throw InputError("station generator: position " + std::to_string(j + 1) +
                       " is not greater than position " + std::to_string(j) +
                       "; valid: strictly increasing coordinates in m");
  }
}

}  // namespace

std::uint32_t station_phase_stream(int station, int attempt) {
  return std::uint32_t(attempt) + 65536u * std::uint32_t(station);
}

std::uint32_t station_modulus_stream(int station, int attempt) {
  return 0x80000000u + station_phase_stream(station, attempt);
}

// Rayleigh moduli rho_k = sqrt(-2 ln(1 - u_k)) (E rho^2 = 2) of the bins with amplitude.
void rayleigh_moduli(std::uint64_t seed, std::uint64_t index, int attempt, int station,
                     const std::vector<double>& amplitude, std::vector<double>& rho) {
  rho.assign(amplitude.size(), 0.0);
  for (std::size_t k = 0; k < amplitude.size(); ++k)
    if (amplitude[k] != 0.0)
      rho[k] =
          std::sqrt(-2.0 * std::log1p(-philox_uniform(seed, index, std::uint32_t(k),
                                                      station_modulus_stream(station, attempt))));
}

StationGenerator::StationGenerator(const DesignSpectrum& target, double duration,
                                   SimqkeSettings settings, StationSettings stations)
    : gen_(target, duration, settings), stations_(std::move(stations)) {
  check_positions(stations_.positions);
  if (stations_.positions.size() > 32768)
    throw InputError("station generator: at most 32768 stations");
  accept_score_ = settings.accept_score;

  coherent_ = stations_.coherency.model == CoherencyModel::none || stations_.positions.size() == 1;
  if (!coherent_) factor_coherency();
}

StationGenerator::~StationGenerator() = default;

int StationGenerator::stations() const {
  return int(stations_.positions.size());
}

const std::vector<double>& StationGenerator::match_periods() const {
  return gen_.match_periods();
}

// G_jm = |gamma(|x_j - x_m|, f_k)| at every bin, factored G = L L^T (Cholesky-Banachiewicz)
// with vanishing pivots set to 0: the columns below them are then 0 as well.
void StationGenerator::factor_coherency() {
  const std::size_t s = stations_.positions.size(), tri = s * (s + 1) / 2;
  const std::vector<double>& x = stations_.positions;
  lower_.assign(gen_.fft_bins() * tri, 0.0);
  for (std::size_t k = 0; k < gen_.fft_bins(); ++k) {
    const double f = gen_.bin_frequency(k);
    double* l = lower_.data() + k * tri;
    for (std::size_t j = 0; j < s; ++j) {
      for (std::size_t m = 0; m <= j; ++m) {
        double sum =
            m == j ? 1.0 : gaussian_coherency(stations_.coherency(std::fabs(x[j] - x[m]), f));
        for (std::size_t p = 0; p < m; ++p) sum -= l[packed(j, p)] * l[packed(m, p)];
        if (m == j) {
          l[packed(j, j)] = sum > 0.0 ? std::sqrt(sum) : 0.0;
        } else {
          const double d = l[packed(m, m)];
          l[packed(j, m)] = d > kPivotFloor ? sum / d : 0.0;
        }
      }
    }
  }
}

std::vector<GeneratedMotion> StationGenerator::generate(std::uint64_t seed, std::uint64_t index) {
  return run(gen_.start(), seed, index);
}

std::vector<GeneratedMotion> StationGenerator::generate(std::uint64_t seed, std::uint64_t index,
                                                        const std::vector<double>& ln_factor) {
  return run(gen_.start(ln_factor), seed, index);
}

// Station j's stationary coefficients / A_k, sum_{m <= j} L_jm exp(i phi_m), into (zr, zi).
void StationGenerator::coefficients(std::size_t j, const std::vector<std::vector<double>>& re,
                                    const std::vector<std::vector<double>>& im,
                                    const std::vector<std::vector<double>>& rho,
                                    std::vector<double>& zr, std::vector<double>& zi) const {
  const std::size_t nb = gen_.fft_bins(), s = stations_.positions.size(), tri = s * (s + 1) / 2;
  zr.resize(nb);
  zi.resize(nb);
  for (std::size_t k = 0; k < nb; ++k) {
    const double* l = lower_.data() + k * tri + packed(j, 0);
    double a = 0.0, b = 0.0;
    for (std::size_t m = 0; m <= j; ++m) {
      a += l[m] * rho[m][k] * re[m][k];
      b += l[m] * rho[m][k] * im[m][k];
    }
    // Unit modulus: the phase of the Gaussian combination, the amplitude A_k of one motion
    // (a circular Gaussian is rho exp(i phi) with rho Rayleigh and phi uniform, independent).
    const double r = std::hypot(a, b);
    zr[k] = r > 0.0 ? a / r : 1.0;
    zi[k] = r > 0.0 ? b / r : 0.0;
  }
}

std::vector<GeneratedMotion> StationGenerator::run(const SimqkeStart& start, std::uint64_t seed,
                                                   std::uint64_t index) {
  const std::size_t s = coherent_ ? 1 : stations_.positions.size();
  std::vector<std::vector<double>> re(s), im(s);  // phasors exp(i phi_m) per station m
  std::vector<std::vector<double>> rho(s);        // Rayleigh moduli per station m
  std::vector<double> zr, zi;
  std::vector<SimqkeAttempt> best(s), current(s);
  std::vector<GroundMotion> m(s);
  std::vector<int> spectra(s, 0);
  double best_score = 1e300;
  int best_attempt = 0;
  for (int attempt = 0; attempt < start.max_attempts; ++attempt) {
    for (std::size_t j = 0; j < s; ++j) {
      simqke_phasors(seed, index, station_phase_stream(int(j), attempt), start.amplitude, re[j],
                     im[j]);
      if (!coherent_) rayleigh_moduli(seed, index, attempt, int(j), start.amplitude, rho[j]);
      if (j == 0) {  // L_11 = 1 at every bin: station 1's coefficients are its own phasors
        m[j] = gen_.synthesise(start, re[0], im[0]);
      } else {
        coefficients(j, re, im, rho, zr, zi);
        m[j] = gen_.synthesise(start, zr, zi);
      }
    }
    double score = 0.0;
    bool complete = true;
    for (std::size_t j = 0; j < s; ++j) {
      current[j] = gen_.match(start, std::move(m[j]));
      spectra[j] += current[j].spectra;
      score = std::max(score, current[j].score);
      if (!(score < best_score)) {  // this phase set can no longer beat the best one
        complete = false;
        break;
      }
    }
    if (complete && score < best_score) {
      best_score = score;
      best_attempt = attempt;
      std::swap(best, current);
    }
    if (best_score <= accept_score_) break;
  }
  std::vector<GeneratedMotion> out;
  for (std::size_t j = 0; j < stations_.positions.size(); ++j) {
    const std::size_t src = coherent_ ? 0 : j;
    if (coherent_ && j > 0) {
      out.push_back(out.front());
      continue;
    }
    out.push_back(gen_.finish(best[src], start, seed, index, best_attempt, spectra[src]));
  }
  if (stations_.positions.size() > 1)
    for (std::size_t j = 0; j < out.size(); ++j)
      out[j].motion.name += " station " + std::to_string(j + 1);
  return out;
}

}  // namespace pound
