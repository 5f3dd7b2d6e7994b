// Spatially varying motions at the stations of a row: the uniform limit is SimqkeGenerator's
// motion bit for bit; a matched set has the model's lagged coherency (1-6 Hz and 0.1-1 Hz), the
// wave-passage lag, close stations that move apart as the model says, and every station matched
// as one motion is (docs/ground.md, "Generation").
#include "ground/station_generator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "ground/achieved_coherency.hpp"
#include "ground/wave_passage.hpp"
#include "motion/motion_processing.hpp"
#include "motion/response_spectrum.hpp"
#include "motion/spectral_variability.hpp"
#include "motion/spectrum_ec8.hpp"

namespace pound {
namespace {

const Ec8Spectrum& target() {
  static const Ec8Spectrum t(Ec8Type::type1, Ec8Ground::C, 0.3 * kGravity);
  return t;
}

Coherency hv() {
  return make_coherency("harichandran-vanmarcke-1986", {}, "test");
}

// The innovation's smoothing (step 2 of ground/station_generator.hpp), eight bins' sums side by
// side since issue 38, against the sums written out one bin after another from the lowest: the
// same bits, at every length (groups of eight and the rest, the windows cut at both ends).
TEST(GroundStations, MovingPowerSumIsEachBinsSumInOrder) {
  for (std::size_t n : {1u, 2u, 3u, 7u, 8u, 9u, 17u, 40u, 129u, 1025u}) {
    std::vector<double> p(n);
    for (std::size_t k = 0; k < n; ++k)  // powers over many decades, so that order matters
      p[k] = std::exp(8.0 * std::sin(0.7 * double(k)) + 3.0 * std::cos(0.13 * double(k)));
    const std::vector<double> s = moving_power_sum(p);
    ASSERT_EQ(s.size(), n);
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t h = std::max<std::size_t>(1, k / 10);
      const std::size_t lo = k > h ? k - h : 0, hi = std::min(n - 1, k + h);
      double sum = 0.0;
      for (std::size_t b = lo; b <= hi; ++b) sum += p[b];
      EXPECT_EQ(s[k], sum) << "n " << n << " bin " << k;
    }
  }
}

TEST(GroundStations, UniformLimitIsSimqkeGeneratorsMotionBitForBit) {
  SimqkeSettings s;
  SimqkeGenerator one(target(), 8.0, s);
  StationSettings none;
  none.positions = {0.0, 30.0, 70.0};
  StationGenerator three(target(), 8.0, s, none);
  StationSettings single;
  single.positions = {5.0};
  single.coherency = hv();
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

// Station 1 of a coherent set is SimqkeGenerator's motion too.
TEST(GroundStations, FirstStationIsSimqkeGeneratorsMotion) {
  StationSettings st;
  st.positions = {0.0, 25.0};
  st.coherency = hv();
  StationGenerator gen(target(), 8.0, SimqkeSettings{}, st);
  SimqkeGenerator one(target(), 8.0, SimqkeSettings{});
  for (std::uint64_t i = 0; i < 2; ++i)
    EXPECT_EQ(gen.generate(4, i).front().motion.accel, one.generate(4, i).motion.accel);
}

// The lower level the generator is made of: match() with SimqkeGenerator's own correction as
// the caller's step gives the same numbers, and inverse(transform(m)) is m up to the DC bin,
// which inverse() drops as correct() does (1e-4 of the peak here).
TEST(GroundStations, SimqkeLowerLevelAsTheGeneratorUsesIt) {
  SimqkeGenerator gen(target(), 8.0, SimqkeSettings{});
  const SimqkeStart s = gen.start();
  std::vector<double> re, im;
  simqke_phasors(3, 1, 0, s.amplitude, re, im);
  const GroundMotion m0 = gen.synthesise(s, re, im);
  const SimqkeAttempt a = gen.match(s, m0);
  const SimqkeAttempt b =
      gen.match(s, m0, [&](GroundMotion& m, const std::vector<double>& r) { gen.correct(m, r); });
  EXPECT_EQ(a.motion.accel, b.motion.accel);
  EXPECT_EQ(a.iterations, b.iterations);
  std::vector<std::complex<double>> x;
  gen.transform(a.motion.accel, x);
  GroundMotion back;
  gen.inverse(x, back);
  ASSERT_EQ(back.accel.size(), a.motion.accel.size());
  for (std::size_t i = 0; i < back.accel.size(); ++i)
    EXPECT_NEAR(back.accel[i], a.motion.accel[i], 1e-3 * a.motion.pga());
}

// Every station carries the spectrum its score was taken on (GeneratedMotion::psa), which the
// next station's widened band reads instead of evaluating it again (issue 38): bit for bit the
// spectrum of the returned motion, with the design spectrum and a random target, for stations
// left as matched (Harichandran-Vanmarcke at 25 m) and pinned below f_lo (Abrahamson's soil
// model at 12 m, step 5). The pinned set also differs from the unpinned one.
TEST(GroundStations, EveryStationCarriesTheSpectrumOfItsMotion) {
  SimqkeGenerator one(target(), 8.0, SimqkeSettings{});
  VariabilitySettings vs;
  vs.mode = Variability::spectral;
  const TargetVariability var(vs, one.match_periods());
  const CounterRng rng(5, stream_id(kTargetStream));
  for (const char* model : {"harichandran-vanmarcke-1986", "abrahamson-2007-soil"}) {
    StationSettings st;
    st.positions = {0.0, std::string(model) == "abrahamson-2007-soil" ? 12.0 : 25.0, 60.0};
    st.coherency = make_coherency(model, {}, "test");
    StationGenerator gen(target(), 8.0, SimqkeSettings{}, st);
    for (std::uint64_t i = 0; i < 2; ++i)
      for (const bool random : {false, true}) {
        const std::vector<GeneratedMotion> set =
            random ? gen.generate(5, i, var.ln_factor(var.epsilon(rng, i))) : gen.generate(5, i);
        ASSERT_EQ(set.size(), 3u);
        for (std::size_t j = 0; j < set.size(); ++j) {
          std::vector<double> psa;
          one.spectrum(set[j].motion, psa);
          EXPECT_EQ(set[j].psa, psa)
              << model << " motion " << i << " station " << j << (random ? " random target" : "");
        }
      }
  }
}

TEST(GroundStations, PositionsMustIncreaseStrictly) {
  StationSettings st;
  st.positions = {0.0, 20.0, 20.0};
  EXPECT_THROW(StationGenerator(target(), 8.0, SimqkeSettings{}, st), InputError);
  st.positions = {};
  EXPECT_THROW(StationGenerator(target(), 8.0, SimqkeSettings{}, st), InputError);
}

// A set of count motions of 10 s at 0.01 s at the stations `positions` (Harichandran-Vanmarcke
// SMART-1), delayed by the apparent velocity v (inf: none), matched (max_iterations 35) or the
// synthesis alone (0), with or without random targets.
struct Set {
  StationSettings st;
  std::vector<double> delays;
  std::vector<std::vector<GroundMotion>> motions;  // delayed
  std::vector<std::vector<double>> mean_psa;       // per station, at the report periods
  std::vector<std::vector<double>> score;          // [station][motion]: max |q - 1| or RMS ln q
  std::vector<double> periods, design;
};

Set make_set(std::vector<double> positions, double v, int count, std::uint64_t seed,
             int max_iterations, bool random_target = false) {
  Set s;
  s.st.positions = std::move(positions);
  s.st.coherency = hv();
  s.delays = arrival_delays(s.st.positions, v);
  SimqkeSettings settings;
  settings.max_iterations = max_iterations;
  StationGenerator gen(target(), 10.0, settings, s.st);
  VariabilitySettings vs;
  vs.mode = Variability::spectral;
  const TargetVariability var(vs, gen.match_periods());
  const CounterRng rng(seed, stream_id(kTargetStream));
  s.periods = log_spaced_periods(0.05, 4.0, 100);
  s.design = target().sample(s.periods);
  const SpectrumCalculator calc(s.periods, 0.05, settings.dt);
  SimqkeGenerator one(target(), 10.0, settings);
  const std::size_t ns = s.st.positions.size();
  s.mean_psa.assign(ns, std::vector<double>(s.periods.size(), 0.0));
  s.score.assign(ns, {});
  for (int i = 0; i < count; ++i) {
    std::vector<GroundMotion> row;
    const std::vector<GeneratedMotion> g =
        random_target ? gen.generate(seed, std::uint64_t(i),
                                     var.ln_factor(var.epsilon(rng, std::uint64_t(i))))
                      : gen.generate(seed, std::uint64_t(i));
    for (std::size_t j = 0; j < g.size(); ++j) {
      row.push_back(delayed(g[j].motion, s.delays[j]));
      std::vector<double> psa;
      calc.compute_psa(row.back().accel, psa);
      for (std::size_t p = 0; p < psa.size(); ++p) s.mean_psa[j][p] += psa[p] / count;
      // The match at the generator's matching periods, against the motion's own target.
      std::vector<double> own;
      one.spectrum(g[j].motion, own);
      double mx = 0.0, ss = 0.0;
      for (std::size_t p = 0; p < own.size(); ++p) {
        const double q = own[p] / g[j].target_psa[p];
        mx = std::max(mx, std::fabs(q - 1.0));
        ss += std::log(q) * std::log(q);
      }
      s.score[j].push_back(random_target ? std::sqrt(ss / double(own.size())) : mx);
    }
    s.motions.push_back(std::move(row));
  }
  return s;
}

// The set of docs/ground.md: stations at 0, 40 and 100 m, apparent velocity 400 m/s (delays 0,
// 0.1, 0.25 s), 40 motions, seed 2026.
const Set& matched_set() {
  static const Set s = make_set({0.0, 40.0, 100.0}, 400.0, 40, 2026, 35);
  return s;
}

// A row for the coherency: stations at 0, 12, 40 and 100 m (separations 12, 28, 40, 60, 88,
// 100 m), apparent velocity 400 m/s, 200 motions (standard error of the estimate at 6 Hz about
// 0.015 for 100 m), seed 2026.
const Set& row_set() {
  static const Set s = make_set({0.0, 12.0, 40.0, 100.0}, 400.0, 200, 2026, 35);
  return s;
}

AchievedCoherency coherency_of(const Set& s, const std::vector<double>& f, double half_band) {
  return achieved_coherency(s.motions, s.st.positions, s.delays, s.st.coherency, f, half_band);
}

TEST(GroundStations, SetHasTheLagOfWavePassage) {
  const AchievedCoherency a = coherency_of(matched_set(), {1, 2, 4, 6}, 0.25);
  ASSERT_EQ(a.pairs.size(), 3u);
  for (const PairCoherency& p : a.pairs) {
    EXPECT_DOUBLE_EQ(p.model_lag, p.separation / 400.0);
    // Within a quarter of a sample (0.01 s) of d / v.
    EXPECT_NEAR(p.lag, p.model_lag, 0.25 * 0.01) << "stations " << p.j + 1 << ", " << p.k + 1;
  }
}

// The synthesis (before the matching) has the coherency it is generated with, gamma_in.
TEST(GroundStations, SynthesisHasTheInputCoherency) {
  const Set s = make_set({0.0, 40.0, 100.0}, 400.0, 200, 2026, 0);
  const StationGenerator gen(target(), 10.0, SimqkeSettings{}, s.st);
  const AchievedCoherency a = coherency_of(s, {1, 2, 4, 6}, 0.25);
  for (const PairCoherency& p : a.pairs)
    for (std::size_t f = 0; f < a.frequencies.size(); ++f)
      EXPECT_NEAR(p.achieved[f], gen.input_coherency(p.separation, a.frequencies[f]), 0.05)
          << "stations " << p.j + 1 << ", " << p.k + 1 << " (" << p.separation << " m) at "
          << a.frequencies[f] << " Hz";
}

// The acceptance: the matched set's lagged coherency is within 0.05 of the model at
// 1-6 Hz (+- 0.25 Hz) and at 0.2-1 Hz (+- 0.05 Hz), every pair of the row.
TEST(GroundStations, MatchedSetHasTheLaggedCoherencyOfTheModel) {
  double worst = 0.0;
  for (const auto& [f, band] :
       {std::pair<std::vector<double>, double>{{1, 2, 4, 6}, 0.25}, {{0.2, 0.3, 0.5, 1.0}, 0.05}}) {
    const AchievedCoherency a = coherency_of(row_set(), f, band);
    ASSERT_EQ(a.pairs.size(), 6u);
    for (const PairCoherency& p : a.pairs)
      for (std::size_t i = 0; i < a.frequencies.size(); ++i) {
        EXPECT_NEAR(p.achieved[i], p.model[i], 0.05)
            << "stations " << p.j + 1 << ", " << p.k + 1 << " (" << p.separation << " m) at "
            << a.frequencies[i] << " Hz";
        if (std::fabs(p.achieved[i] - p.model[i]) > std::fabs(worst))
          worst = p.achieved[i] - p.model[i];
      }
  }
  std::printf("largest difference achieved - model: %+.3f\n", worst);
}

// Every station is matched as one motion is: at most 10 more of the 200 motions than station 1
// (SimqkeGenerator's motion) miss accept_score (0.095) or leave 0.90-1.20, and the mean spectra
// are within 0.95-1.05 of the design spectrum (at the report periods).
TEST(GroundStations, EveryStationMatchesAsOneMotionDoes) {
  const Set& s = row_set();
  const auto misses = [&](std::size_t j) {
    return std::count_if(s.score[j].begin(), s.score[j].end(), [](double x) { return x > 0.095; });
  };
  for (std::size_t j = 0; j < s.score.size(); ++j) {
    std::printf("station %zu: %ld of %zu motions above 0.095\n", j + 1, long(misses(j)),
                s.score[j].size());
    EXPECT_LE(misses(j), misses(0) + 10) << "station " << j + 1;
    EXPECT_LT(*std::max_element(s.score[j].begin(), s.score[j].end()), 0.20);
    const SpectrumMatch m = compare_spectra(s.mean_psa[j], s.design);
    EXPECT_GE(m.min_ratio, 0.95) << "station " << j + 1;
    EXPECT_LE(m.max_ratio, 1.05) << "station " << j + 1;
  }
}

TEST(GroundStations, SetMatchesTheDesignSpectrumOnAverage) {
  const Set& s = matched_set();
  for (std::size_t j = 0; j < 3; ++j) {
    const SpectrumMatch m = compare_spectra(s.mean_psa[j], s.design);
    EXPECT_GE(m.min_ratio, 0.95) << "station " << j + 1;
    EXPECT_LE(m.max_ratio, 1.05) << "station " << j + 1;
  }
}

// Peak relative displacement of stations 1 and 2 [m] and the larger peak displacement [m].
std::pair<double, double> peaks(const std::vector<GroundMotion>& row) {
  const GroundKinematics a = integrate(row[0]), b = integrate(row[1]);
  double rel = 0.0, pgd = 0.0;
  for (std::size_t i = 0; i < a.displacement.size(); ++i) {
    rel = std::max(rel, std::fabs(a.displacement[i] - b.displacement[i]));
    pgd = std::max({pgd, std::fabs(a.displacement[i]), std::fabs(b.displacement[i])});
  }
  return {rel, pgd};
}

double median(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  return x[x.size() / 2];
}

// Two stations 12 m apart without wave passage (the pounding case): below 1 Hz the
// lagged coherency is within 0.05 of the model (> 0.98), the relative-displacement energy is
// within a factor 2 of what the model expects for the set's own spectra, sum [S_11 + S_22 - 2
// |gamma| sqrt(S_11 S_22)], and the median peak relative displacement over the peak ground
// displacement within a factor 1.5 of the synthesis's (its coherency is gamma_in = gamma there).
TEST(GroundStations, CloseStationsMoveApartAsTheModelSays) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const Set matched = make_set({0.0, 12.0}, kInf, 60, 5, 35);
  const Set synthesis = make_set({0.0, 12.0}, kInf, 60, 5, 0);
  const AchievedCoherency a = coherency_of(matched, {0.1, 0.2, 0.3, 0.5, 1.0}, 0.05);
  for (std::size_t i = 0; i < a.frequencies.size(); ++i)
    EXPECT_NEAR(a.pairs[0].achieved[i], a.pairs[0].model[i], 0.05) << a.frequencies[i] << " Hz";
  const RelativeEnergy e =
      relative_displacement_energy(matched.motions, 0, 1, 12.0, matched.st.coherency, 0.05, 10.0);
  std::vector<double> ratio_m, ratio_s, rel_m;
  for (std::size_t i = 0; i < matched.motions.size(); ++i) {
    const auto [rm, pm] = peaks(matched.motions[i]);
    const auto [rs, ps] = peaks(synthesis.motions[i]);
    ratio_m.push_back(rm / pm);
    ratio_s.push_back(rs / ps);
    rel_m.push_back(rm);
  }
  std::printf(
      "12 m: relative-displacement energy / model %.2f; peak relative displacement median %.2f "
      "cm, max %.2f cm; over PGD median %.3f (synthesis %.3f), max %.3f\n",
      e.achieved / e.model, 100 * median(rel_m),
      100 * *std::max_element(rel_m.begin(), rel_m.end()), median(ratio_m), median(ratio_s),
      *std::max_element(ratio_m.begin(), ratio_m.end()));
  EXPECT_GT(e.achieved / e.model, 0.5);
  EXPECT_LT(e.achieved / e.model, 2.0);
  EXPECT_GT(median(ratio_m) / median(ratio_s), 1.0 / 1.5);
  EXPECT_LT(median(ratio_m) / median(ratio_s), 1.5);
}

// With random targets (record-to-record variability) the stations share the motion's target:
// each matches it as station 1 does (median RMS of ln(computed / target) within 0.01 of station
// 1's), and the coherency at 0.2-6 Hz stays within 0.05 of the model.
TEST(GroundStations, RandomTargetStationsMatchAndCohere) {
  const Set s = make_set({0.0, 12.0, 40.0}, 400.0, 250, 2026, 35, true);
  for (std::size_t j = 0; j < s.score.size(); ++j)
    EXPECT_LT(median(s.score[j]), median(s.score[0]) + 0.01) << "station " << j + 1;
  for (const auto& [f, band] :
       {std::pair<std::vector<double>, double>{{1, 2, 4, 6}, 0.25}, {{0.2, 0.5}, 0.05}}) {
    const AchievedCoherency a = coherency_of(s, f, band);
    for (const PairCoherency& p : a.pairs)
      for (std::size_t i = 0; i < a.frequencies.size(); ++i)
        EXPECT_NEAR(p.achieved[i], p.model[i], 0.05)
            << "stations " << p.j + 1 << ", " << p.k + 1 << " at " << a.frequencies[i] << " Hz";
  }
}

// Coarse iterations (issue 38: stations 2.. with a random target take the spectrum at every
// fourth matching period, in full at every fourth iteration and for the kept one) match as the
// full iterations do: over 30 random targets, two stations 20 m apart under
// Harichandran-Vanmarcke, station 2's RMS ln(computed / target) has a mean within 2 % and a
// median within 0.005 of the full iterations' (measured: mean 0.0958 against 0.0967, median
// 0.0877 against 0.0892). Station 1 is the same motion either way.
TEST(GroundStations, CoarseIterationsMatchAsFullOnes) {
  StationSettings st;
  st.positions = {0.0, 20.0};
  st.coherency = hv();
  StationGenerator coarse(target(), 10.0, SimqkeSettings{}, st);
  st.coarse_iterations = false;
  StationGenerator full(target(), 10.0, SimqkeSettings{}, st);
  VariabilitySettings vs;
  vs.mode = Variability::spectral;
  const TargetVariability var(vs, coarse.match_periods());
  const CounterRng rng(7, stream_id(kTargetStream));
  std::vector<double> score[2];  // station 2's: 0 full, 1 coarse
  for (std::uint64_t i = 0; i < 30; ++i) {
    const std::vector<double> ln = var.ln_factor(var.epsilon(rng, i));
    const std::vector<GeneratedMotion> f = full.generate(7, i, ln), c = coarse.generate(7, i, ln);
    EXPECT_EQ(f[0].motion.accel, c[0].motion.accel);  // station 1 as it was
    for (int k = 0; k < 2; ++k) {
      const GeneratedMotion& m = (k == 0 ? f : c)[1];
      double sum = 0.0;
      for (std::size_t j = 0; j < m.psa.size(); ++j)
        sum += std::pow(std::log(m.psa[j] / m.target_psa[j]), 2);
      score[k].push_back(std::sqrt(sum / double(m.psa.size())));
    }
  }
  double mean[2];
  for (int k = 0; k < 2; ++k) {
    mean[k] = 0.0;
    for (double v : score[k]) mean[k] += v / double(score[k].size());
  }
  const double med_full = median(score[0]), med_coarse = median(score[1]);
  std::printf("station 2, RMS score: full mean %.4f median %.4f, coarse mean %.4f median %.4f\n",
              mean[0], med_full, mean[1], med_coarse);
  EXPECT_NEAR(mean[1], mean[0], 0.02 * mean[0]);
  EXPECT_NEAR(med_coarse, med_full, 0.005);
}

}  // namespace
}  // namespace pound
