// libFuzzer harness: the hazard-curve reader of `pound risk` (read_hazard_curve), given the
// input bytes as a CSV file. The only error allowed is InputError; a curve that is read must
// be what the risk integrals rely on (risk/hazard_curve.hpp): at least two points, intensities
// finite, positive and strictly increasing, rates finite, positive and strictly decreasing, a
// known measure and unit, and a rate_at that reproduces its points and falls between them.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/error.hpp"
#include "fuzz_support.hpp"
#include "risk/hazard_curve.hpp"

using namespace pound;

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  const std::string dir = fuzz::prepare_dir(*argc, *argv);
  if (dir.empty()) return 0;
  // Seeds: small curves of each header form (the repository's studies/*.csv are seeds too).
  const std::pair<const char*, const char*> seeds[] = {
      {"pga-g",
       "# a test curve\npga [g], annual_rate [1/yr]\n0.05, 2.1e-2\n0.1, 8e-3\n"
       "0.5, 4e-4\n1.0, 5e-5\n"},
      {"sa-ms2", "sa(0.5) [m/s2], annual_rate [1/yr]\n1.0, 1e-2\n5.0, 1e-3\n10, 1e-4\n"},
      {"crlf", "pga [g],annual_rate [1/yr]\r\n0.1,1e-2\r\n0.2,1e-3\r\n"},
  };
  for (const auto& [name, text] : seeds)
    fuzz::write_prepared(dir, std::string("seeds/") + name, text);
  std::string dict;
  for (const char* w : {"pga", "sa(", ")", "[g]", "[m/s2]", "annual_rate", "[1/yr]", ", ", "#",
                        "e-", "\n", "\r\n", "0.", "1e-3"})
    dict += fuzz::dict_entry(w);
  fuzz::write_prepared(dir, "dict", dict);
  std::exit(0);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = fuzz::write_file("hazard.csv", data, size);
  HazardCurve h;
  try {
    h = read_hazard_curve(path);
  } catch (const InputError&) {
    return 0;
  }
  const std::size_t n = h.im.size();
  if (n < 2 || h.rate.size() != n) fuzz::fail("a curve of fewer than two points was read");
  if (h.measure != "pga" && h.measure != "sa") fuzz::fail("unknown measure " + h.measure);
  if (h.measure == "sa" && !(h.period_s > 0.0 && std::isfinite(h.period_s)))
    fuzz::fail("sa(T) without a finite positive T");
  for (std::size_t i = 0; i < n; ++i) {
    if (!(std::isfinite(h.im[i]) && h.im[i] > 0.0) ||
        !(std::isfinite(h.rate[i]) && h.rate[i] > 0.0))
      fuzz::fail("a point that is not finite and positive");
    if (i > 0 && !(h.im[i] > h.im[i - 1] && h.rate[i] < h.rate[i - 1]))
      fuzz::fail("intensities not increasing or rates not decreasing");
    const double r = h.rate_at(h.im[i]);
    if (!(std::fabs(r - h.rate[i]) <= 1e-9 * h.rate[i])) fuzz::fail("rate_at misses a point");
    if (i > 0) {
      const double mid = std::sqrt(h.im[i] * h.im[i - 1]);
      const double rm = h.rate_at(mid);
      if (std::isfinite(mid) && mid > h.im[i - 1] && mid < h.im[i] &&
          !(rm <= h.rate[i - 1] * (1 + 1e-12) && rm >= h.rate[i] * (1 - 1e-12)))
        fuzz::fail("rate_at leaves the segment's rates");
    }
  }
  return 0;
}
