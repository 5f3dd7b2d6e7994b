// The hazard curve: reading the CSV with its unit header, log-log interpolation and the
// extension of the end segments, the inverse, and bad input named by file and point.
#include "risk/hazard_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "../support/scratch_dir.hpp"
#include "core/error.hpp"
#include "motion/ground_motion.hpp"

namespace pound {
namespace {

std::string write(const std::string& name, const std::string& text) {
  const std::string path = test::process_scratch_dir() / name;
  std::ofstream(path) << text;
  return path;
}

TEST(HazardCurve, ReadsTheUnitsAndInterpolatesLogLog) {
  const std::string path = write("h.csv",
                                 "# a comment saying where the numbers come from\n"
                                 "pga [g], annual_rate [1/yr]\n"
                                 "0.1, 1e-2\n"
                                 "0.4, 1e-3\n"
                                 "\n"
                                 "1.6, 2e-5\n");
  const HazardCurve h = read_hazard_curve(path);
  EXPECT_EQ(h.measure, "pga");
  EXPECT_EQ(h.file_unit, "g");
  ASSERT_EQ(h.im.size(), 3u);
  EXPECT_DOUBLE_EQ(h.im[1], 0.4 * kGravity);
  // At the points, the rates; between them, a power law: at the geometric mean intensity the
  // geometric mean rate.
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(h.rate_at(h.im[i]), h.rate[i], 1e-12 * h.rate[i]);
  EXPECT_NEAR(h.rate_at(0.2 * kGravity), std::sqrt(1e-2 * 1e-3), 1e-12);
  // Beyond the ends the end segments' power laws: slope -ln(10)/ln(4) below, -ln(50)/ln(4) above.
  const double k_lo = std::log(10.0) / std::log(4.0), k_hi = std::log(50.0) / std::log(4.0);
  EXPECT_NEAR(h.rate_at(0.05 * kGravity), 1e-2 * std::pow(0.5, -k_lo), 1e-12);
  EXPECT_NEAR(h.rate_at(3.2 * kGravity), 2e-5 * std::pow(2.0, -k_hi), 1e-15);
  // The inverse, inside and beyond the points.
  for (double x : {0.03, 0.1, 0.25, 0.4, 1.0, 1.6, 5.0}) {
    const double r = h.rate_at(x * kGravity);
    EXPECT_NEAR(h.im_at_rate(r), x * kGravity, 1e-9 * x * kGravity) << x;
  }
  // m/s2 and sa(T) headers.
  const HazardCurve s = read_hazard_curve(
      write("s.csv", "sa(0.53) [m/s2], annual_rate [1/yr]\n1.0, 0.1\n10.0, 1e-4\n"));
  EXPECT_EQ(s.measure, "sa");
  EXPECT_DOUBLE_EQ(s.period_s, 0.53);
  EXPECT_DOUBLE_EQ(s.im[1], 10.0);
}

// The error message of reading `text` (empty when it reads).
std::string error_of(const std::string& name, const std::string& text) {
  try {
    read_hazard_curve(write(name, text));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(HazardCurve, BadInputNamesTheFileAndWhatIsValid) {
  const std::string head = "pga [g], annual_rate [1/yr]\n";
  const struct {
    const char* name;
    std::string text;
    const char* says;
  } cases[] = {
      {"rising.csv", head + "0.1, 1e-3\n0.2, 2e-3\n", "must fall strictly"},
      {"flat.csv", head + "0.1, 1e-3\n0.2, 1e-3\n", "must fall strictly"},
      {"negative.csv", head + "0.1, 1e-3\n0.2, -1e-4\n", "must be a finite number > 0"},
      {"zero.csv", head + "0.1, 1e-3\n0.2, 0\n", "must be a finite number > 0"},
      {"order.csv", head + "0.2, 1e-3\n0.1, 1e-4\n", "must increase strictly"},
      {"one.csv", head + "0.2, 1e-3\n", "at least two"},
      {"text.csv", head + "0.1, abc\n", "not a finite number"},
      {"unit.csv", "pga [cm/s2], annual_rate [1/yr]\n0.1, 1e-3\n0.2, 1e-4\n", "valid: g, m/s2"},
      {"measure.csv", "pgv [g], annual_rate [1/yr]\n0.1, 1e-3\n0.2, 1e-4\n", "valid: pga, sa(T)"},
      {"header.csv", "0.1, 1e-3\n0.2, 1e-4\n", "header"},
      {"rate-unit.csv", "pga [g], annual_rate [1/s]\n0.1, 1e-3\n0.2, 1e-4\n",
       "valid: 1/yr, 1/year"},
      {"unit-caret.csv", "pga [cm/s^2], annual_rate [1/yr]\n0.1, 1e-3\n0.2, 1e-4\n",
       "valid: g, m/s2, m/s^2"},
      {"columns.csv", head + "0.1, 1e-3, 5\n", "two comma-separated columns"},
  };
  for (const auto& c : cases) {
    const std::string m = error_of(c.name, c.text);
    EXPECT_NE(m.find(c.name), std::string::npos) << c.name << ": " << m;
    EXPECT_NE(m.find(c.says), std::string::npos) << c.name << ": " << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
  EXPECT_THROW(read_hazard_curve(test::process_scratch_dir() / "missing.csv"), InputError);
}

TEST(HazardCurve, SkipsAUtf8ByteOrderMarkAndAcceptsEverySpellingOfTheUnits) {
  // A "UTF-8" CSV saved by a Windows editor starts with EF BB BF; before the header line, and
  // before a first comment line.
  for (const std::string first : {"", "# USGS\n"}) {
    const HazardCurve h = read_hazard_curve(
        write("bom.csv",
              "\xEF\xBB\xBF" + first + "pga [m/s^2], annual_rate [1/year]\n1, 0.1\n10, 1e-4\n"));
    EXPECT_EQ(h.measure, "pga");
    EXPECT_EQ(h.file_unit, "m/s2");
    ASSERT_EQ(h.im.size(), 2u);
    EXPECT_EQ(h.im[1], 10.0);
    EXPECT_EQ(h.rate[1], 1e-4);
  }
}

TEST(HazardCurve, AMessageShowsASmallRateReadably) {
  // 6.5e-7 /yr (a 1.5-million-year event) was shown as std::to_string's 0.000000.
  const std::string m =
      error_of("small.csv", "pga [g], annual_rate [1/yr]\n2.5, 6.5e-7\n3.75, 8e-7\n");
  EXPECT_NE(m.find("small.csv: point 2 (3.75 g, 8e-07 /yr): the rate of exceedance must fall"),
            std::string::npos)
      << m;
  // And the point before it, through the API: NaN is named, not left blank.
  try {
    make_hazard_curve({0.1, 0.2}, {6.5e-7, NAN}, "pga", 0.0, "g", "api");
    ADD_FAILURE() << "a NaN rate was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("api: point 2 (0.2 g, nan /yr)"), std::string::npos)
        << e.what();
  }
}

TEST(HazardCurve, PointsARoundingApartAreRefusedAndRateAtHitsEveryPoint) {
  // fuzz_hazard (the hour run): intensities 2222222222222220.0025 and ...0.2025 g, one double
  // apart, made a slope of ln(rate) / 1e-16 and rate_at missed the second point by 1e-4.
  const std::string m = error_of(
      "close.csv",
      "pga [g], annual_rate [1/yr]\n2222222222222220.0025, 657\n2222222222222220.2025, 5.6\n");
  EXPECT_NE(m.find("close.csv: point 2"), std::string::npos) << m;
  EXPECT_NE(m.find("more than 1e-6 of the previous one"), std::string::npos) << m;
  // Points 2e-6 apart with rates a factor 1e6 apart (a slope of -7e6): rate_at, from each
  // segment's own point, returns every point's rate to 1e-12.
  const HazardCurve h = make_hazard_curve({1e-3, 1e-3 * (1 + 2e-6), 2.0, 40.0},
                                          {1e2, 1e-4, 1e-6, 1e-12}, "pga", 0.0, "g", "api");
  for (std::size_t i = 0; i < h.im.size(); ++i)
    EXPECT_NEAR(h.rate_at(h.im[i]), h.rate[i], 1e-12 * h.rate[i]) << "point " << i + 1;
}

}  // namespace
}  // namespace pound
