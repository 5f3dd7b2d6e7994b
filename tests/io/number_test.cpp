// What a number is: decimal with an optional sign, point and exponent; everything strtod
// would also take (hexadecimal, inf, nan, leading blanks) or half take (trailing text) is
// refused.
#include "io/number.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace pound {
namespace {

TEST(Number, DecimalFormsAreReadExactlyAsStrtod) {
  const std::pair<const char*, double> ok[] = {
      {"16", 16.0},           {"-0.5", -0.5},       {"+2", 2.0},
      {".25", 0.25},          {"3.", 3.0},          {"2.1e9", 2.1e9},
      {"1E-3", 1e-3},         {"-7.5e+02", -750.0}, {"0", 0.0},
      {"-0", -0.0},           {"0.000", 0.0},       {"1e308", 1e308},
      {"4.9e-324", 4.9e-324},  // the smallest subnormal: finite, read as it is
  };
  for (const auto& [text, want] : ok) {
    double v = -99.0;
    EXPECT_TRUE(read_decimal(text, &v)) << text;
    EXPECT_EQ(v, want) << text;
  }
}

TEST(Number, HexInfNanJunkAndBlanksAreRefused) {
  for (const char* text : {"0x10",
                           "0X1p3",
                           "inf",
                           "-inf",
                           "infinity",
                           "nan",
                           "NaN",
                           "nan(1)",
                           "1e",
                           "1e+",
                           "e5",
                           ".",
                           "-",
                           "+",
                           "",
                           " 1",
                           "1 ",
                           "12kg",
                           "1,5",
                           "1.2.3",
                           "1e999",
                           "-1e999",
                           "--1",
                           "1e5.5",
                           "0b101",
                           "1_000",
                           "\xEF\xBB\xBF"
                           "1",
                           "1\n",
                           "٣"}) {
    double v = -99.0;
    EXPECT_FALSE(read_decimal(text, &v)) << "'" << text << "'";
    EXPECT_EQ(v, -99.0) << text;  // untouched
  }
}

TEST(Number, HeaderFieldsAreReadUpToWhatCannotContinueThem) {
  const std::string h = "npts=  5590, dt=   .0050 sec";
  double n = 0.0, dt = 0.0;
  ASSERT_TRUE(read_decimal_at(h, 5, &n));
  ASSERT_TRUE(read_decimal_at(h, h.find("dt=") + 3, &dt));
  EXPECT_EQ(n, 5590.0);
  EXPECT_EQ(dt, 0.005);
  double v = -1.0;
  EXPECT_FALSE(read_decimal_at("npts= 0x10, dt= 0.01", 5, &v));  // not 0, not 16
  EXPECT_FALSE(read_decimal_at("dt= 1.2.3", 3, &v));
  EXPECT_FALSE(read_decimal_at("dt=", 3, &v));
  EXPECT_FALSE(read_decimal_at("dt= inf", 3, &v));
  EXPECT_EQ(v, -1.0);
}

TEST(Number, NonFiniteNamesAreRecognisedForTheirOwnMessage) {
  for (const char* t : {"nan", "NaN", "-inf", "+Infinity", "nan(0x7)"})
    EXPECT_TRUE(names_non_finite(t)) << t;
  for (const char* t : {"0x10", "abc", "info", "1"}) EXPECT_FALSE(names_non_finite(t)) << t;
}

}  // namespace
}  // namespace pound
