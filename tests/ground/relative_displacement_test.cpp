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

// Every model at 12 and 50 m, random targets (the campaigns' default), 60 motions each
// (docs/ground.md, "The relative displacement of generated pairs"; measured ratios of the RMS
// relative displacement to the model's: 0.81-1.02, Abrahamson rock 1.32 and 1.18):
//  * the generation does not make the pair much more coherent than the model: the ratio is at
//    least 0.78 (HV86 at 50 m: 0.81, the one model whose pairs stay more coherent than it);
//  * it is at most 1.10 for every model but Abrahamson rock, whose prediction (0.2-0.7 mm, 0.15-
//    0.5 % of the RMS displacement) is below what the stations' own matching at 2-5 s leaves
//    (0.2-0.5 Hz); for it at most 1.40;
//  * what the set has above the model, sqrt(achieved - model), is at most 0.5 % of the RMS
//    displacement (measured at most 0.3 %; 1-6.5 % before the low-frequency pin of step 5 of
//    station_generator.hpp, which gave Luco-Wong and the Abrahamson models 1.5-6 times their
//    prediction).
TEST(GroundRelativeDisplacement, GeneratedPairsMoveApartAsTheirModelPredicts) {
  for (const char* model : {"harichandran-vanmarcke-1986", "hao-oliveira-penzien-1989",
                            "luco-wong-1986", "abrahamson-2007-soil", "abrahamson-2007-rock"})
    for (double d : {12.0, 50.0}) {
      const PairSet s = make_pairs(model, {0.0, d}, 60, 5, true);
      const Relative r = relative_energy(s, 0, 1);
      const double ratio = std::sqrt(r.achieved / r.model);
      // [m]: the RMS of the part of the relative displacement above the model's.
      const double floor =
          r.rms_relative * std::sqrt(std::max(0.0, r.achieved - r.model) / r.achieved);
      std::printf(
          "%s at %g m: RMS relative displacement %.2f mm, model %.2f mm (ratio %.3f), "
          "RMS displacement %.1f mm, above the model %.2f %% of it\n",
          model, d, 1e3 * r.rms_relative, 1e3 * r.rms_relative / ratio, ratio,
          1e3 * r.rms_displacement, 100.0 * floor / r.rms_displacement);
      EXPECT_GT(ratio, 0.78) << model << " at " << d << " m";
      const bool rock = std::string(model) == "abrahamson-2007-rock";
      EXPECT_LT(ratio, rock ? 1.40 : 1.10) << model << " at " << d << " m";
      EXPECT_LT(floor, 0.005 * r.rms_displacement) << model << " at " << d << " m";
    }
}

// The Abrahamson soil model at 12 m, the identical pair's separation: the achieved lagged
// coherency is within 0.1 of the model at 2, 5 and 8 Hz (+- 0.25 Hz) and at least 0.97 at
// 0.2-0.6 Hz (+- 0.05 Hz), where the model is 0.9998-1.
TEST(GroundRelativeDisplacement, AbrahamsonSoilPairAt12mHasItsCoherency) {
  const PairSet s = make_pairs("abrahamson-2007-soil", {0.0, 12.0}, 60, 5, true);
  const AchievedCoherency high =
      achieved_coherency(s.motions, s.positions, {0.0, 0.0}, s.model, {2.0, 5.0, 8.0}, 0.25);
  for (std::size_t f = 0; f < high.frequencies.size(); ++f)
    EXPECT_NEAR(high.pairs[0].achieved[f], high.pairs[0].model[f], 0.1) << high.frequencies[f];
  const AchievedCoherency low = achieved_coherency(s.motions, s.positions, {0.0, 0.0}, s.model,
                                                   {0.2, 0.3, 0.4, 0.5, 0.6}, 0.05);
  for (std::size_t f = 0; f < low.frequencies.size(); ++f)
    EXPECT_GE(low.pairs[0].achieved[f], 0.97) << low.frequencies[f] << " Hz";
}

}  // namespace
}  // namespace pound
