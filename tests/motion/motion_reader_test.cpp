// Record readers: the El Centro file, PEER .AT2, one and two columns, and every rejection
// naming the file and line.
#include "motion/motion_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "../support/scratch_dir.hpp"
#include "core/error.hpp"

namespace pound {
namespace {

const std::string kElCentro = std::string(POUND_SOURCE_DIR) + "/motions/elcentro-1940-ns.dat";

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = test::process_scratch_dir() / name;
  std::ofstream(path) << text;
  return path;
}

// The error message of read_motion(spec), or "" when it does not throw InputError.
std::string error_of(const MotionFileSpec& spec) {
  try {
    read_motion(spec);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(MotionReader, ElCentroFixedWidthAutomatic) {
  MotionFileSpec spec;
  spec.path = kElCentro;
  const GroundMotion m = read_motion(spec);
  ASSERT_EQ(m.accel.size(), 1559u);  // header: 1559 points; the zero padding is dropped
  EXPECT_DOUBLE_EQ(m.dt, 0.02);
  EXPECT_NEAR(m.accel[0], 0.00630 * kGravity, 1e-12);
  // Peak -0.31882 g at t = 2.02 s (sample 101).
  EXPECT_NEAR(m.pga(), 0.31882 * kGravity, 1e-12);
  EXPECT_NEAR(m.accel[101], -0.31882 * kGravity, 1e-12);
}

TEST(MotionReader, ElCentroConflictingUnitsRejected) {
  MotionFileSpec spec;
  spec.path = kElCentro;
  spec.units = AccelUnits::cm_per_s2;
  EXPECT_NE(error_of(spec).find("elcentro-1940-ns.dat:5:"), std::string::npos) << error_of(spec);
}

TEST(MotionReader, PeerAt2) {
  const std::string p = write_temp("rec.AT2",
                                   "PEER NGA STRONG MOTION DATABASE RECORD\n"
                                   "Some event, station 090\n"
                                   "ACCELERATION TIME SERIES IN UNITS OF G\n"
                                   "NPTS=     5, DT=   .0050 SEC\n"
                                   "  .1000000E-01  -.2000000E-01  .3000000E-01\n"
                                   "  .0000000E+00   .5000000E+00\n");
  MotionFileSpec spec;
  spec.path = p;
  const GroundMotion m = read_motion(spec);
  ASSERT_EQ(m.accel.size(), 5u);
  EXPECT_DOUBLE_EQ(m.dt, 0.005);
  EXPECT_NEAR(m.accel[1], -0.02 * kGravity, 1e-14);
  EXPECT_NEAR(m.accel[4], 0.5 * kGravity, 1e-14);
}

TEST(MotionReader, PeerAt2AlternativeHeaderAndShortCount) {
  const std::string p = write_temp("alt.at2",
                                   "PEER\nx\nACCELERATION TIME SERIES IN UNITS OF G\n"
                                   "   4   0.0100   NPTS, DT\n1 2 3\n");
  MotionFileSpec spec;
  spec.path = p;
  const std::string e = error_of(spec);
  EXPECT_NE(e.find("alt.at2:5: 3 values but the header (line 4) says NPTS= 4"), std::string::npos)
      << e;
}

TEST(MotionReader, TwoColumnsCmPerS2) {
  const std::string p = write_temp("two.txt", "# test\n0.00 1.0\n0.01 -2.0\n0.02 3.0\n");
  MotionFileSpec spec;
  spec.path = p;
  spec.units = AccelUnits::cm_per_s2;
  const GroundMotion m = read_motion(spec);
  ASSERT_EQ(m.accel.size(), 3u);
  EXPECT_NEAR(m.dt, 0.01, 1e-15);
  EXPECT_NEAR(m.accel[2], 0.03, 1e-15);
}

TEST(MotionReader, OneColumnHeaderUnitsAndDt) {
  const std::string p = write_temp("one.txt", "# units: m/s2\n# dt: 0.005 s\n1\n2\n3\n4\n");
  MotionFileSpec spec;
  spec.path = p;
  const GroundMotion m = read_motion(spec);
  ASSERT_EQ(m.accel.size(), 4u);
  EXPECT_DOUBLE_EQ(m.dt, 0.005);
  EXPECT_DOUBLE_EQ(m.accel[3], 4.0);
}

TEST(MotionReader, RejectsNonUniformStep) {
  const std::string p = write_temp("nonuni.txt", "0.00 1\n0.01 2\n0.025 3\n0.03 4\n");
  MotionFileSpec spec;
  spec.path = p;
  spec.units = AccelUnits::g;
  const std::string e = error_of(spec);
  EXPECT_NE(e.find("nonuni.txt:3:"), std::string::npos) << e;
  EXPECT_NE(e.find("uniform time step"), std::string::npos) << e;
}

TEST(MotionReader, RejectsNaN) {
  const std::string p = write_temp("nan.txt", "0.00 1\n0.01 nan\n0.02 3\n");
  MotionFileSpec spec;
  spec.path = p;
  spec.units = AccelUnits::g;
  EXPECT_NE(error_of(spec).find("nan.txt:2: 'nan' is not finite"), std::string::npos)
      << error_of(spec);
}

TEST(MotionReader, RejectsNonNumericLine) {
  const std::string p = write_temp("text.txt", "1\n2\nthree\n4\n");
  MotionFileSpec spec;
  spec.path = p;
  spec.units = AccelUnits::g;
  spec.dt = 0.01;
  EXPECT_NE(error_of(spec).find("text.txt:3: 'three' is not a number"), std::string::npos)
      << error_of(spec);
}

TEST(MotionReader, RejectsEmptyRecord) {
  const std::string p = write_temp("empty.txt", "# units: g\n# dt: 0.01\n");
  MotionFileSpec spec;
  spec.path = p;
  EXPECT_NE(error_of(spec).find("empty.txt:2: the record holds no acceleration values"),
            std::string::npos)
      << error_of(spec);
}

TEST(MotionReader, RejectsMissingUnitsAndDt) {
  const std::string p = write_temp("nounits.txt", "1\n2\n3\n");
  MotionFileSpec spec;
  spec.path = p;
  spec.dt = 0.01;
  const std::string e = error_of(spec);
  EXPECT_NE(e.find("nounits.txt:1: the units of acceleration are not stated"), std::string::npos)
      << e;
  EXPECT_NE(e.find("g, m/s2 or cm/s2"), std::string::npos) << e;
  spec.units = AccelUnits::g;
  spec.dt = 0.0;
  EXPECT_NE(error_of(spec).find("without a time step"), std::string::npos) << error_of(spec);
}

TEST(MotionReader, RejectsMissingFileAndRaggedColumns) {
  MotionFileSpec spec;
  spec.path = "/nonexistent/record.txt";
  EXPECT_NE(error_of(spec).find("cannot open"), std::string::npos);
  spec.path = write_temp("ragged.txt", "0 1\n0.01 2\n0.02\n");
  spec.units = AccelUnits::g;
  EXPECT_NE(error_of(spec).find("ragged.txt:3:"), std::string::npos) << error_of(spec);
}

TEST(MotionReader, ParseUnits) {
  EXPECT_EQ(parse_accel_units("g", "x"), AccelUnits::g);
  EXPECT_EQ(parse_accel_units("m/s2", "x"), AccelUnits::m_per_s2);
  EXPECT_EQ(parse_accel_units("cm/s2", "x"), AccelUnits::cm_per_s2);
  try {
    parse_accel_units("ft/s2", "study.ini:3: key 'units'");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "study.ini:3: key 'units': 'ft/s2' is not a unit of acceleration; valid: g, "
                 "m/s2, cm/s2");
  }
}

TEST(MotionReader, ADirectoryIsNamedSo) {
  MotionFileSpec spec;
  spec.path = test::process_scratch_dir().path();
  spec.units = AccelUnits::g;
  spec.dt = 0.01;
  EXPECT_EQ(error_of(spec),
            spec.path + ": is a directory, not a motion file; give the record file itself");
}

TEST(MotionReader, Utf8ByteOrderMarkBeforeTheFirstLineIsSkipped) {
  MotionFileSpec spec;
  spec.path = write_temp("bom.txt", "\xEF\xBB\xBF# units: g\n# dt: 0.01\n0.1\n-0.2\n0.05\n");
  const GroundMotion m = read_motion(spec);
  ASSERT_EQ(m.accel.size(), 3u);
  EXPECT_DOUBLE_EQ(m.accel[1], -0.2 * kGravity);
  EXPECT_DOUBLE_EQ(m.dt, 0.01);
}

TEST(MotionReader, HexadecimalValuesAndHeaderFieldsAreRefused) {
  MotionFileSpec spec;
  spec.path = write_temp("hex.txt", "0.1\n0x10\n0.2\n");
  spec.units = AccelUnits::g;
  spec.dt = 0.01;
  EXPECT_NE(error_of(spec).find("hex.txt:2: '0x10' is not a number; valid: an acceleration value, "
                                "each a decimal number such as 16, -0.5 or 2.1e9"),
            std::string::npos)
      << error_of(spec);
  spec = MotionFileSpec{};
  spec.path = write_temp("hex.AT2",
                         "PEER NGA STRONG MOTION DATABASE RECORD\nevent\n"
                         "ACCELERATION TIME SERIES IN UNITS OF G\nNPTS= 0x3, DT= .01 SEC\n"
                         "0.1 0.2 0.3\n");
  EXPECT_NE(error_of(spec).find("hex.AT2:4: cannot read NPTS and DT"), std::string::npos)
      << error_of(spec);
}

// A record whose values are in the wrong units (1e30 g, or m/s2 values read as g on a
// micro-tremor) is refused with the units the reader assumed and where they came from.
TEST(MotionReader, ImplausiblePeakAccelerationIsRefusedWithTheAssumedUnits) {
  MotionFileSpec spec;
  spec.path = write_temp("huge.txt", "# units: g\n# dt: 0.01\n0.1\n1e30\n-0.3\n");
  std::string e = error_of(spec);
  EXPECT_NE(e.find("huge.txt: peak ground acceleration 1e+30 g (9.80665e+30 m/s2) with the values "
                   "read as g as the header states on line 1"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("valid: a peak between 1e-06 g and 10 g"), std::string::npos) << e;
  EXPECT_NE(e.find("[motion] check_pga = false"), std::string::npos) << e;
  // Units given by the caller: the message says so.
  spec.path = write_temp("cm.txt", "# dt: 0.01\n0.1\n2e6\n-0.3\n");
  spec.units = AccelUnits::cm_per_s2;
  e = error_of(spec);
  EXPECT_NE(e.find("with the values read as cm/s2 as given (units = cm/s2)"), std::string::npos)
      << e;
  // Below 1e-6 g: all zeros, or values in m/s2 of a record in mm.
  spec.path = write_temp("zero.txt", "# units: m/s2\n# dt: 0.01\n0\n0\n0\n");
  spec.units.reset();
  e = error_of(spec);
  EXPECT_NE(e.find("peak ground acceleration 0 g (0 m/s2)"), std::string::npos) << e;
  // The bounds themselves are plausible; just outside them is not.
  for (const auto& [peak_g, ok] : std::vector<std::pair<double, bool>>{
           {10.0, true}, {1e-6, true}, {10.0 * (1 + 1e-9), false}, {1e-6 * (1 - 1e-9), false}}) {
    char text[64];
    std::snprintf(text, sizeof text, "# units: g\n# dt: 0.01\n0\n%.17g\n", peak_g);
    spec.path = write_temp("edge.txt", text);
    EXPECT_EQ(error_of(spec).empty(), ok) << peak_g << ": " << error_of(spec);
  }
  // The unusual case: the check turned off.
  spec.path = write_temp("huge2.txt", "# units: g\n# dt: 0.01\n0.1\n1e30\n-0.3\n");
  spec.check_pga = false;
  const GroundMotion m = read_motion(spec);
  EXPECT_DOUBLE_EQ(m.accel[1], 1e30 * kGravity);
}

// Found by fuzz_motion_columns (issue 14): a line of only separators read the last token of an
// empty list (undefined behaviour) instead of being refused.
TEST(MotionReader, ALineOfOnlyCommasIsRefused) {
  MotionFileSpec spec;
  spec.units = AccelUnits::g;
  spec.dt = 0.01;
  spec.path = write_temp("commas.txt", ", \n");  // the fuzzer's input, less its last byte
  EXPECT_EQ(error_of(spec), spec.path +
                                ":1: no number on the line, only separators; valid: one column "
                                "(acceleration) or two (time in s, acceleration) on every line");
  spec.path = write_temp("commas2.txt", "0.1\n0.2\n,,\n0.3\n");
  EXPECT_NE(error_of(spec).find("commas2.txt:3: no number on the line"), std::string::npos)
      << error_of(spec);
}

TEST(MotionReader, AFixedWidthHeaderOfOnePointIsRefused) {
  // fuzz_motion_auto's input, reduced: the header's "1 points" and two values on the line (the
  // second zero padding) used to give a record of one value.
  MotionFileSpec spec;
  spec.path =
      write_temp("one-point.txt", "#1 points at equal spacing of 0.01 sec (g)\n 0.02075  00\n");
  EXPECT_EQ(error_of(spec), spec.path + ":1: the header says 1 point; valid: at least 2 points");
  // Two points read as a record of two.
  spec.path = write_temp("two-points.txt",
                         "#2 points at equal spacing of 0.01 sec (g)\n   0.02075  -0.01000\n");
  const GroundMotion m = read_motion(spec);
  ASSERT_EQ(m.accel.size(), 2u);
  EXPECT_NEAR(m.accel[1], -0.01 * kGravity, 1e-15);
}

}  // namespace
}  // namespace pound
