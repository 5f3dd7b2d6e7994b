// Spatially varying motions at the stations of a row: the uniform limit is SimqkeGenerator's
// motion bit for bit; a generated set has the model's lagged coherency, the wave-passage lag
// and the design spectrum on average.
#include "ground/station_generator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ground/achieved_coherency.hpp"
#include "ground/wave_passage.hpp"
#include "motion/response_spectrum.hpp"
#include "motion/spectral_variability.hpp"
#include "motion/spectrum_ec8.hpp"

namespace pound {
namespace {

const Ec8Spectrum& target() {
  static const Ec8Spectrum t(Ec8Type::type1, Ec8Ground::C, 0.3 * kGravity);
  return t;
}

TEST(GroundStations, UniformLimitIsSimqkeGeneratorsMotionBitForBit) {
  SimqkeSettings s;
  SimqkeGenerator one(target(), 8.0, s);
  StationSettings none;
  none.positions = {0.0, 30.0, 70.0};
  StationGenerator three(target(), 8.0, s, none);
  StationSettings single;
  single.positions = {5.0};
  single.coherency = make_coherency("harichandran-vanmarcke-1986", {}, "test");
  StationGenerator alone(target(), 8.0, s, single);
  ASSERT_EQ(three.stations(), 3);
  VariabilitySettings vs;
  vs.mode = Variability::spectral;
  const TargetVariability var(vs, one.match_periods());
  const CounterRng rng(11, stream_id(kTargetStream));
  for (std::uint64_t i = 0; i < 3; ++i) {
    const GeneratedMotion m = one.generate(11, i);
    for (const GeneratedMotion& g : three.generate(11, i)) {
      EXPECT_EQ(g.motion.accel, m.motion.accel) << "motion " << i;
      EXPECT_EQ(g.attempt, m.attempt);
      EXPECT_EQ(g.iterations, m.iterations);
    }
    EXPECT_EQ(alone.generate(11, i).front().motion.accel, m.motion.accel);
    const std::vector<double> ln = var.ln_factor(var.epsilon(rng, i));
    const GeneratedMotion r = one.generate(11, i, ln);
    for (const GeneratedMotion& g : three.generate(11, i, ln))
      EXPECT_EQ(g.motion.accel, r.motion.accel) << "motion " << i << " random target";
    EXPECT_EQ(alone.generate(11, i, ln).front().motion.accel, r.motion.accel);
  }
}

TEST(GroundStations, PositionsMustIncreaseStrictly) {
  StationSettings st;
  st.positions = {0.0, 20.0, 20.0};
  EXPECT_THROW(StationGenerator(target(), 8.0, SimqkeSettings{}, st), InputError);
  st.positions = {};
  EXPECT_THROW(StationGenerator(target(), 8.0, SimqkeSettings{}, st), InputError);
}

// One set for the statistical checks: 3 stations at 0, 40 and 100 m (separations 40, 60 and
// 100 m), Harichandran-Vanmarcke SMART-1, apparent velocity 400 m/s (delays 0, 0.1, 0.25 s);
// kCount motions of 10 s at 0.01 s, matched (max_iterations 35) or the first guess alone
// (max_iterations 0: the synthesis without the correction).
constexpr int kCount = 40;
struct Set {
  StationSettings st;
  std::vector<double> delays;
  std::vector<std::vector<GroundMotion>> motions;  // delayed
  std::vector<std::vector<double>> mean_psa;       // per station, at the report periods
  std::vector<double> periods, design;
};

Set make_set(int max_iterations) {
  Set s;
  s.st.positions = {0.0, 40.0, 100.0};
  s.st.coherency = make_coherency("harichandran-vanmarcke-1986", {}, "test");
  s.delays = arrival_delays(s.st.positions, 400.0);
  SimqkeSettings settings;
  settings.max_iterations = max_iterations;
  StationGenerator gen(target(), 10.0, settings, s.st);
  s.periods = log_spaced_periods(0.05, 4.0, 100);
  s.design = target().sample(s.periods);
  const SpectrumCalculator calc(s.periods, 0.05, settings.dt);
  s.mean_psa.assign(3, std::vector<double>(s.periods.size(), 0.0));
  for (int i = 0; i < kCount; ++i) {
    std::vector<GroundMotion> row;
    const std::vector<GeneratedMotion> g = gen.generate(2026, std::uint64_t(i));
    for (std::size_t j = 0; j < g.size(); ++j) {
      row.push_back(delayed(g[j].motion, s.delays[j]));
      std::vector<double> psa;
      calc.compute_psa(row.back().accel, psa);
      for (std::size_t p = 0; p < psa.size(); ++p) s.mean_psa[j][p] += psa[p] / kCount;
    }
    s.motions.push_back(std::move(row));
  }
  return s;
}

const Set& matched_set() {
  static const Set s = make_set(35);
  return s;
}

AchievedCoherency coherency_of(const Set& s) {
  return achieved_coherency(s.motions, s.st.positions, s.delays, s.st.coherency, {1, 2, 4, 6},
                            0.25);
}

TEST(GroundStations, SetHasTheLagOfWavePassage) {
  const AchievedCoherency a = coherency_of(matched_set());
  ASSERT_EQ(a.pairs.size(), 3u);
  for (const PairCoherency& p : a.pairs) {
    EXPECT_DOUBLE_EQ(p.model_lag, p.separation / 400.0);
    // Within a quarter of a sample (0.01 s) of d / v.
    EXPECT_NEAR(p.lag, p.model_lag, 0.25 * 0.01) << "stations " << p.j + 1 << ", " << p.k + 1;
  }
}

// The synthesis (before the spectrum matching) has the model's lagged coherency.
TEST(GroundStations, SynthesisHasTheLaggedCoherencyOfTheModel) {
  const AchievedCoherency a = coherency_of(make_set(0));
  for (const PairCoherency& p : a.pairs)
    for (std::size_t f = 0; f < a.frequencies.size(); ++f)
      EXPECT_NEAR(p.achieved[f], p.model[f], 0.05)
          << "stations " << p.j + 1 << ", " << p.k + 1 << " (" << p.separation << " m) at "
          << a.frequencies[f] << " Hz";
}

// Known shortfall (docs/ground.md, "What the matching does to the coherency"): matching every
// station on its own lowers the set's lagged coherency below the model, by 0.03-0.16 here. The
// test keeps the documented band true: below the model + 0.05, above the model - 0.20.
TEST(GroundStations, MatchedSetLosesSomeCoherencyAsDocumented) {
  const AchievedCoherency a = coherency_of(matched_set());
  double loss = 0.0;
  for (const PairCoherency& p : a.pairs)
    for (std::size_t f = 0; f < a.frequencies.size(); ++f) {
      EXPECT_LT(p.achieved[f], p.model[f] + 0.05);
      EXPECT_GT(p.achieved[f], p.model[f] - 0.20)
          << "stations " << p.j + 1 << ", " << p.k + 1 << " at " << a.frequencies[f] << " Hz";
      loss = std::max(loss, p.model[f] - p.achieved[f]);
    }
  std::printf("largest coherency loss of the matched set: %.3f\n", loss);
}

TEST(GroundStations, SetMatchesTheDesignSpectrumOnAverage) {
  const Set& s = matched_set();
  for (std::size_t j = 0; j < 3; ++j) {
    const SpectrumMatch m = compare_spectra(s.mean_psa[j], s.design);
    EXPECT_GE(m.min_ratio, 0.95) << "station " << j + 1;
    EXPECT_LE(m.max_ratio, 1.05) << "station " << j + 1;
  }
}

}  // namespace
}  // namespace pound
