// libFuzzer harness: one ground-motion reader (POUND_FUZZ_FORMAT: at2, columns, fixed-width or
// automatic, one binary each). The last input byte chooses what the caller gives besides the
// file (bit 0: units g; bit 1: dt 0.01 s; bit 2: the plausibility check off; bit 3, automatic
// only: the .AT2 extension), the bytes before it are the file (so that a record file is a
// seed as it is: its final newline, 0x0A, gives dt and the .AT2 name). A record that is read must
// hold at least two finite values at a positive finite step, within the plausible peak when
// checked; the only error allowed is InputError.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/error.hpp"
#include "fuzz_support.hpp"
#include "motion/motion_reader.hpp"

#ifndef POUND_FUZZ_FORMAT
#error "POUND_FUZZ_FORMAT (at2, columns, fixed-width or automatic) is set by fuzz/CMakeLists.txt"
#endif
#define POUND_STR2(x) #x
#define POUND_STR(x) POUND_STR2(x)

namespace {

using namespace pound;

const MotionFormat kFormat = parse_motion_format(POUND_STR(POUND_FUZZ_FORMAT), "harness");

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  const std::string dir = fuzz::prepare_dir(*argc, *argv);
  if (dir.empty()) return 0;
  // Seeds: the files of the reader tests (tests/motion/motion_reader_test.cpp), each with a
  // last byte giving nothing, and the dictionary of the header words (the repository's
  // motions/ and fuzz/seeds/motion/ are seeds as they are).
  const std::pair<const char*, const char*> seeds[] = {
      {"at2",
       "PEER NGA STRONG MOTION DATABASE RECORD\nSome event, station 090\n"
       "ACCELERATION TIME SERIES IN UNITS OF G\nNPTS=     5, DT=   .0050 SEC\n"
       "  .1000000E-01 -.2000000E-01  .3000000E-01\n  4.0  -.5000000E-01\n"},
      {"at2-alt",
       "PEER\nevent\nACCELERATION TIME SERIES IN UNITS OF G\n3 0.01 NPTS, DT\n0.1 0.2 0.3\n"},
      {"two-columns", "# units: cm/s2\n0.00 1.5\n0.01 -2.5\n0.02 3.0\n0.03 0.5\n"},
      {"one-column", "# units: g\n# dt: 0.02\n0.01\n-0.02\n0.03\n"},
      {"fixed-width",
       "#El Centro test\n#5 points at equal spacing of 0.02 sec\n#The units are (g)\n"
       "   0.00630   0.00364   0.00099  -0.00428  -0.00758   0.00000   0.00000   0.00000\n"
       "#*** End Data ***\n"},
  };
  for (const auto& [name, text] : seeds)
    fuzz::write_prepared(dir, std::string("seeds/") + name, text + std::string(1, '\0'));
  std::string dict;
  for (const char* w : {"NPTS=",
                        "DT=",
                        " SEC",
                        "NPTS, DT",
                        "UNITS OF G",
                        "ACCELERATION TIME SERIES IN UNITS OF G",
                        "points at equal spacing of",
                        "sec",
                        "The units are (g)",
                        "(g)",
                        "[g]",
                        "# dt: ",
                        "# units: ",
                        "# units: g",
                        "m/s2",
                        "cm/s2",
                        "m/s^2",
                        "(gal)",
                        "#*** End Data ***",
                        "0x10",
                        "nan",
                        "inf",
                        "1e30",
                        "1e-30",
                        ".5E-03",
                        "-0",
                        "\xEF\xBB\xBF",
                        "\r\n",
                        "\t"})
    dict += fuzz::dict_entry(w);
  fuzz::write_prepared(dir, "dict", dict);
  std::exit(0);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::uint8_t how = data[size - 1];
  MotionFileSpec spec;
  spec.format = kFormat;
  const bool at2_name =
      kFormat == MotionFormat::peer_at2 || (kFormat == MotionFormat::automatic && (how & 8));
  spec.path = fuzz::write_file(at2_name ? "record.AT2" : "record.txt", data, size - 1);
  if (how & 1) spec.units = AccelUnits::g;
  if (how & 2) spec.dt = 0.01;
  spec.check_pga = !(how & 4);
  GroundMotion m;
  try {
    m = read_motion(spec);
  } catch (const InputError&) {
    return 0;
  }
  if (m.accel.size() < 2) fuzz::fail("a record of fewer than 2 values was read");
  if (!(m.dt > 0.0) || !std::isfinite(m.dt)) fuzz::fail("a step that is not > 0 and finite");
  double pga = 0.0;
  for (double a : m.accel) {
    if (!std::isfinite(a)) fuzz::fail("a non-finite acceleration was read");
    pga = std::max(pga, std::fabs(a));
  }
  if (spec.check_pga && !(pga >= kMinPlausiblePga && pga <= kMaxPlausiblePga))
    fuzz::fail("an implausible peak acceleration passed the check");
  return 0;
}
