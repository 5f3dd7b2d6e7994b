// libFuzzer harness: the study-file parser with option resolution. The input is INI text, then
// (after the first NUL byte) command-line arguments separated by NUL bytes; both go through
// Options::parse (--config FILE plus the arguments, the command line winning) and the study is
// resolved as `pound campaign` resolves it (campaign_from_options) and as `pound simulate`
// does (buildings, contact or Sears model, integrator, the motion file). Only InputError may
// leave the library: anything else (another exception, a sanitizer report) is a finding.
//
// Files named by the input are read from a scratch copy of the repository's layout
// (studies/study.ini, motions/elcentro-1940-ns.dat); an input naming a device, a FIFO, /proc,
// /sys, /dev, /run or a file over 1 MB is skipped, since reading those measures the machine,
// not the parser.
#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "campaign/campaign_study.hpp"
#include "contact/registry.hpp"
#include "core/error.hpp"
#include "fuzz_support.hpp"
#include "io/options.hpp"
#include "study/row_options.hpp"
#include "study/row_study.hpp"
#include "study/sears_row_options.hpp"

namespace {

using namespace pound;

std::string g_studies;  // scratch()/studies, the working directory

// True when every value of the options that names an existing path names a small regular
// file or a directory outside the kernel's and the devices' folders.
bool paths_are_safe(const Options& o) {
  for (const auto& key : o.given_keys()) {
    std::string v = o.get_string(key);
    for (char& c : v)
      if (c == ',' || c == '\t' || c == '\n' || c == '\r') c = ' ';
    std::size_t p = 0;
    while (p < v.size()) {
      const auto b = v.find_first_not_of(' ', p);
      if (b == std::string::npos) break;
      const auto e = v.find(' ', b);
      const std::string tok = v.substr(b, e == std::string::npos ? std::string::npos : e - b);
      p = e == std::string::npos ? v.size() : e;
      char real[PATH_MAX];
      if (!::realpath(tok.c_str(), real)) continue;  // no such path: the reader says so
      const std::string r = real;
      for (const char* bad : {"/proc", "/sys", "/dev", "/run"})
        if (r == bad || r.rfind(std::string(bad) + "/", 0) == 0) return false;
      struct stat st {};
      if (::stat(real, &st) != 0) return false;
      if (!S_ISDIR(st.st_mode) && !(S_ISREG(st.st_mode) && st.st_size <= (1 << 20))) return false;
    }
  }
  return true;
}

// A seed: INI text, then each argument after a NUL byte.
std::string with_args(std::string ini, std::initializer_list<const char*> args) {
  for (const char* a : args) ini += std::string(1, '\0') + a;
  return ini;
}

// As `pound simulate` reads a study.
void resolve_simulate(const Options& o) {
  read_row_study(o);
  if (o.given("motion.file")) motion_from_options(o);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  g_studies = fuzz::scratch() + "/studies";
  std::filesystem::create_directories(g_studies);
  std::filesystem::create_directories(fuzz::scratch() + "/motions");
  std::error_code ec;  // without the repository the motion file is missing: an error path too
  std::filesystem::copy_file(std::string(POUND_SOURCE_DIR) + "/motions/elcentro-1940-ns.dat",
                             fuzz::scratch() + "/motions/elcentro-1940-ns.dat", ec);
  if (::chdir(g_studies.c_str()) != 0) fuzz::fail("cannot enter " + g_studies);

  const std::string dir = fuzz::prepare_dir(*argc, *argv);
  if (dir.empty()) return 0;
  // Seeds: the study with arguments (the repository's studies/ are seeds as they are), and
  // a dictionary of every key, its section header and command-line form, and the words of
  // the values.
  const std::string smoke = fuzz::kSmokeStudy;
  fuzz::write_prepared(dir, "seeds/smoke-args",
                       with_args(smoke, {"--samples", "12", "--sample.gap", "uniform(0, 0.02)"}));
  fuzz::write_prepared(dir, "seeds/simulate",
                       with_args("[building1]\nmasses = 1000, 1000\nstiffnesses = 1e6, 1e6\n"
                                 "[building2]\nmasses = 1000\nstiffnesses = 5e5\n[pair1]\n"
                                 "gap = 0.01\n[contact]\nmodel = hc-linear\ne = 0.5\nk = 5e7\n"
                                 "[motion]\nfile = ../motions/elcentro-1940-ns.dat\n"
                                 "duration = 2\n",
                                 {"--motion.scale", "2"}));
  std::string dict;
  std::vector<OptionSpec> specs = campaign_option_specs();
  for (const auto& s : row_and_sears_option_specs()) specs.push_back(s);
  for (const auto& s : specs) {
    std::string k = s.key;
    for (char& c : k)
      if (c == '#') c = '1';
    dict += fuzz::dict_entry(k) + fuzz::dict_entry("--" + k);
    const auto dot = k.rfind('.');
    if (dot != std::string::npos) {
      dict += fuzz::dict_entry("[" + k.substr(0, dot) + "]");
      dict += fuzz::dict_entry(k.substr(dot + 1) + " = ");
    }
  }
  for (const char* w : {"uniform(",  "normal(",      "lognormal(",
                        "discrete(", "fixed(",       "true",
                        "false",     "lhs",          "mc",
                        "pga",       "sa",           "generated",
                        "records",   "ec8",          "nzs1170",
                        "asce7",     "japan",        "table",
                        "sears",     "lve",          "hc-hertz",
                        "bilinear",  "bouc-wen",     "elastic",
                        "spectral",  "0x10",         "1e308",
                        "nan",       "inf",          "-0",
                        ".5e-3",     "\xEF\xBB\xBF", "../motions/elcentro-1940-ns.dat",
                        "--config",  "--help",       " # ",
                        " ; ",       "\r\n"})
    dict += fuzz::dict_entry(w);
  fuzz::write_prepared(dir, "dict", dict);
  std::exit(0);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string in(reinterpret_cast<const char*>(data), size);
  const auto nul = in.find('\0');
  const std::string ini = in.substr(0, nul);
  std::vector<std::string> args = {"--config", fuzz::write_file("studies/study.ini", ini)};
  if (nul != std::string::npos) {
    std::size_t p = nul + 1;
    while (p <= in.size()) {
      const auto e = in.find('\0', p);
      args.push_back(in.substr(p, e == std::string::npos ? std::string::npos : e - p));
      if (e == std::string::npos) break;
      p = e + 1;
    }
  }
  try {
    Options c("campaign", "", campaign_option_specs());
    c.parse(args);
    if (!paths_are_safe(c)) return 0;
    campaign_from_options(c, 0, -1);
  } catch (const InputError&) {
  }
  try {
    Options s("simulate", "", row_and_sears_option_specs());
    s.parse(args);
    if (!paths_are_safe(s)) return 0;
    resolve_simulate(s);
  } catch (const InputError&) {
  }
  return 0;
}
