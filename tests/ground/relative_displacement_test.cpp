// The relative ground displacement of generated station pairs against what their coherency
// model predicts from the motions' own displacement spectra (issue 37, docs/ground.md, "The
// relative displacement of generated pairs"): over N pairs of stations d = 12 or 50 m apart (no
// wave passage), the relative-displacement energy sum_i sum_t (u_k - u_j)^2 of the traces (as
// the solvers integrate them, from rest at -dt, and ended at rest as a campaign's are) against
// the model's 2 sum_f S_d(f) (1 - |gamma(d, f)|) df, S_d from the two stations' own
// displacement spectra: sum_f [C_jj + C_kk - 2 |gamma| sqrt(C_jj C_kk)] (every bin, 0 Hz
// included; equal to 2 C (1 - |gamma|) when C_jj = C_kk = C).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <vector>

#include "ground/achieved_coherency.hpp"
#include "ground/at_rest.hpp"
#include "ground/ground_trace.hpp"
#include "ground/station_generator.hpp"
#include "motion/fftw_support.hpp"
#include "motion/spectral_variability.hpp"
#include "motion/spectrum_ec8.hpp"

namespace pound {
namespace {

const Ec8Spectrum& target() {
  static const Ec8Spectrum t(Ec8Type::type1, Ec8Ground::C, 0.3 * kGravity);
  return t;
}

struct PairSet {
  std::vector<double> positions;
  Coherency model;
  std::vector<std::vector<GroundMotion>> motions;  // [motion][station], ended at rest
};

// `count` motions of 10 s at 0.01 s at `positions` under `model`, with random targets (the
// campaigns' default) or the design spectrum.
PairSet make_pairs(const std::string& model, std::vector<double> positions, int count,
                   std::uint64_t seed, bool random_target) {
  PairSet s;
  s.positions = positions;
  s.model = make_coherency(model, {}, "test");
  StationSettings st;
  st.positions = std::move(positions);
  st.coherency = s.model;
  StationGenerator gen(target(), 10.0, SimqkeSettings{}, st);
  VariabilitySettings vs;
  vs.mode = Variability::spectral;
  const TargetVariability var(vs, gen.match_periods());
  const CounterRng rng(seed, stream_id(kTargetStream));
  for (int i = 0; i < count; ++i) {
    const auto id = std::uint64_t(i);
    const std::vector<GeneratedMotion> g =
        random_target ? gen.generate(seed, id, var.ln_factor(var.epsilon(rng, id)))
                      : gen.generate(seed, id);
    std::vector<GroundMotion> row;
    for (const GeneratedMotion& m : g) row.push_back(m.motion);
    end_at_rest_where_they_differ(row);
    s.motions.push_back(std::move(row));
  }
  return s;
}

// The displacement the solvers see (ground_trace.hpp: from rest at -dt) at the samples [m].
std::vector<double> trace_displacement(const GroundMotion& m) {
  const GroundTrace t(m);
  std::vector<double> u;
  for (std::size_t i = 0; i < m.accel.size(); ++i) u.push_back(t.disp(double(i) * m.dt));
  return u;
}

struct Relative {
  double achieved = 0.0, model = 0.0;  // sum over motions and samples [m^2]; compare the two
  double rms_relative = 0.0;           // the traces' RMS relative displacement [m]
  double rms_displacement = 0.0;       // station j's RMS displacement [m]
};

// Stations j and k of the set: the traces' relative-displacement energy and the model's, with
// the displacement spectra of the traces zero-padded to 4 times the record (Parseval for the
// real transform: sum_t x_t^2 = [|X_0|^2 + 2 sum_{0<f<n/2} |X_f|^2 + |X_{n/2}|^2] / n).
Relative relative_energy(const PairSet& s, std::size_t j, std::size_t k) {
  const double d = s.positions[k] - s.positions[j];
  std::size_t n = 0;
  for (const auto& row : s.motions) n = std::max({n, row[j].accel.size(), row[k].accel.size()});
  RealFft fft(good_fft_size(4 * n));
  const std::size_t nb = fft.bins();
  const double dt = s.motions.front().front().dt, df = 1.0 / (double(fft.n) * dt);
  std::vector<double> cjj(nb, 0.0), ckk(nb, 0.0);
  std::vector<std::complex<double>> uj, uk;
  Relative out;
  double samples = 0.0;
  for (const auto& row : s.motions) {
    const std::vector<double> a = trace_displacement(row[j]), b = trace_displacement(row[k]);
    for (std::size_t t = 0; t < a.size(); ++t) {
      out.achieved += (b[t] - a[t]) * (b[t] - a[t]);
      out.rms_displacement += a[t] * a[t];
      samples += 1.0;
    }
    fft.forward(a, uj);
    fft.forward(b, uk);
    for (std::size_t f = 0; f < nb; ++f) {
      cjj[f] += std::norm(uj[f]);
      ckk[f] += std::norm(uk[f]);
    }
  }
  for (std::size_t f = 0; f < nb; ++f) {
    const double w = (f == 0 || f == nb - 1) ? 1.0 : 2.0;
    const double g = s.model(d, df * double(f));
    out.model += w * (cjj[f] + ckk[f] - 2.0 * g * std::sqrt(cjj[f] * ckk[f])) / double(fft.n);
  }
  out.rms_relative = std::sqrt(out.achieved / samples);
  out.rms_displacement = std::sqrt(out.rms_displacement / samples);
  return out;
}

// Every model at 12 and 50 m, 60 motions each, with random targets (the campaigns' default) and
// with the design spectrum (docs/ground.md, "The relative displacement of generated pairs";
// measured ratios of the RMS relative displacement to the model's: random targets 0.80-1.02,
// design spectrum 0.90-1.11, Abrahamson rock 1.31 and 1.14, 2.83 and 1.38):
//  * the generation does not make the pair much more coherent than the model: the ratio is at
//    least 0.78 (HV86 at 50 m with random targets: 0.80, the pairs a little more coherent than
//    the model at 0.2-1 Hz);
//  * it is at most 1.10 with random targets, 1.12 with the design spectrum, for every model but
//    Abrahamson rock, whose prediction (0.14-0.7 mm, about 0.1-0.5 % of the RMS displacement)
//    is below what the stations' own processing leaves at 0.2-0.5 Hz; for it at most 1.40 and
//    3.0;
//  * for the models that tend to 1 (Luco-Wong, Abrahamson), what the set has above the model,
//    sqrt(achieved - model), is at most 0.5 % of the RMS displacement with random targets
//    (measured at most 0.30 %), 1 % with the design spectrum (0.72 %; its RMS displacement is
//    59 mm against 149); before issue 37's low-frequency pin and capped widening
//    (station_generator.hpp) it was up to 8 %, 1.5-7.7 times the models' prediction.
TEST(GroundRelativeDisplacement, GeneratedPairsMoveApartAsTheirModelPredicts) {
  for (const bool random_target : {true, false})
    for (const char* model : {"harichandran-vanmarcke-1986", "hao-oliveira-penzien-1989",
                              "luco-wong-1986", "abrahamson-2007-soil", "abrahamson-2007-rock"})
      for (double d : {12.0, 50.0}) {
        const PairSet s = make_pairs(model, {0.0, d}, 60, 5, random_target);
        const Relative r = relative_energy(s, 0, 1);
        const double ratio = std::sqrt(r.achieved / r.model);
        // [m]: the RMS of the part of the relative displacement above the model's.
        const double floor =
            r.rms_relative * std::sqrt(std::max(0.0, r.achieved - r.model) / r.achieved);
        std::printf(
            "%s at %g m (%s): RMS relative displacement %.2f mm, model %.2f mm (ratio %.3f), "
            "RMS displacement %.1f mm, above the model %.2f %% of it\n",
            model, d, random_target ? "random targets" : "design spectrum", 1e3 * r.rms_relative,
            1e3 * r.rms_relative / ratio, ratio, 1e3 * r.rms_displacement,
            100.0 * floor / r.rms_displacement);
        const std::string where = std::string(model) + " at " + std::to_string(d) + " m" +
                                  (random_target ? ", random targets" : ", design spectrum");
        EXPECT_GT(ratio, 0.78) << where;
        const bool rock = std::string(model) == "abrahamson-2007-rock";
        const double top = rock ? (random_target ? 1.40 : 3.0) : (random_target ? 1.10 : 1.12);
        EXPECT_LT(ratio, top) << where;
        if (s.model.fitted_min_separation() == 0.0) {
          EXPECT_LT(floor, (random_target ? 0.005 : 0.01) * r.rms_displacement) << where;
        }
      }
}

// The Abrahamson soil model at 12 m, the identical pair's separation: the achieved lagged
// coherency is within 0.05 of the model at 2, 5 and 8 Hz (+- 0.25 Hz; the issue asks 0.1;
// measured 0.9928, 0.9192, 0.6914 against 0.9930, 0.9051, 0.7247) and within 5e-4 of it at
// 0.2-0.6 Hz (+- 0.05 Hz; the issue asks at least 0.97; measured within 8e-5 of the model's
// 0.9998-1).
TEST(GroundRelativeDisplacement, AbrahamsonSoilPairAt12mHasItsCoherency) {
  const PairSet s = make_pairs("abrahamson-2007-soil", {0.0, 12.0}, 60, 5, true);
  const AchievedCoherency high =
      achieved_coherency(s.motions, s.positions, {0.0, 0.0}, s.model, {2.0, 5.0, 8.0}, 0.25);
  for (std::size_t f = 0; f < high.frequencies.size(); ++f) {
    std::printf("%g Hz: model %.4f, achieved %.4f\n", high.frequencies[f], high.pairs[0].model[f],
                high.pairs[0].achieved[f]);
    EXPECT_NEAR(high.pairs[0].achieved[f], high.pairs[0].model[f], 0.05) << high.frequencies[f];
  }
  const AchievedCoherency low = achieved_coherency(s.motions, s.positions, {0.0, 0.0}, s.model,
                                                   {0.2, 0.3, 0.4, 0.5, 0.6}, 0.05);
  for (std::size_t f = 0; f < low.frequencies.size(); ++f) {
    std::printf("%g Hz: model %.5f, achieved %.5f\n", low.frequencies[f], low.pairs[0].model[f],
                low.pairs[0].achieved[f]);
    EXPECT_NEAR(low.pairs[0].achieved[f], low.pairs[0].model[f], 5e-4) << low.frequencies[f];
  }
}

}  // namespace
}  // namespace pound
