#pragma once
// Shared by the libFuzzer harnesses (one translation unit each): a private scratch folder for
// the files a harness writes from its input, a small campaign study, and the
// -pound_prepare=DIR flag with which fuzz/run.sh asks a harness to write the seeds and the
// dictionary it generates from the library itself (seeds that follow the current formats).
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "campaign/campaign_study.hpp"
#include "io/options.hpp"

namespace pound::fuzz {

/// A folder of this process, removed at exit.
inline const std::string& scratch() {
  // Never destroyed: the exit handler that removes the folder runs after the destructors of
  // statics made later.
  static const std::string* dir = [] {
    auto* t =
        new std::string((std::filesystem::temp_directory_path() / "pound-fuzz-XXXXXX").string());
    if (!::mkdtemp(t->data())) {
      std::perror("pound fuzz: mkdtemp");
      std::abort();
    }
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(scratch(), ec);
    });
    return t;
  }();
  return *dir;
}

/// Writes bytes to scratch()/name (replacing it) and returns the path.
inline std::string write_file(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const std::string path = scratch() + "/" + name;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f || (size && std::fwrite(data, 1, size, f) != size) || std::fclose(f) != 0) {
    std::perror(("pound fuzz: writing " + path).c_str());
    std::abort();
  }
  return path;
}

inline std::string write_file(const std::string& name, const std::string& text) {
  return write_file(name, reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
}

/// A broken invariant: libFuzzer saves the input as a crash.
[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "pound fuzz: invariant broken: %s\n", what.c_str());
  std::abort();
}

/// The DIR of -pound_prepare=DIR, or "" (libFuzzer ignores the flag with a warning).
inline std::string prepare_dir(int argc, char** argv) {
  const std::string flag = "-pound_prepare=";
  for (int i = 1; i < argc; ++i)
    if (std::strncmp(argv[i], flag.c_str(), flag.size()) == 0) return argv[i] + flag.size();
  return "";
}

/// Writes one seed or dictionary file under DIR (made when missing).
inline void write_prepared(const std::string& dir, const std::string& name,
                           const std::string& bytes) {
  std::filesystem::create_directories(std::filesystem::path(dir + "/" + name).parent_path());
  std::ofstream(dir + "/" + name, std::ios::binary) << bytes;
}

/// A libFuzzer dictionary line: the text quoted with \\, " and non-printable bytes escaped.
inline std::string dict_entry(const std::string& text) {
  std::string out = "\"";
  for (unsigned char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 32 || c > 126) {
      char hex[5];
      std::snprintf(hex, sizeof hex, "\\x%02X", c);
      out += hex;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "\"\n";
}

/// A small campaign (two one-storey buildings, e, k_factor and gap sampled, four PGA
/// stripes), like studies/campaign-smoke.ini but fixed here so that the harnesses do not
/// depend on the repository's files.
inline const char* kSmokeStudy =
    "[campaign]\nsamples = 4\nseed = 7\n"
    "[building1]\nname = T0.50\nmasses = 100\nstiffnesses = 15791.37\n"
    "[building2]\nname = T0.75\nmasses = 100\nstiffnesses = 7018.39\n"
    "[pair1]\ngap = 0.01\n[contact]\nmodel = hc-linear\n"
    "[sample]\ne = uniform(0.4, 0.8)\nk_factor = lognormal(50, 0.5, 10, 200)\n"
    "gap = uniform(0, 0.03)\n"
    "[motion]\nsource = generated\n"
    "[generator]\nspectrum = ec8\nec8-type = 1\nground-type = C\nag = 0.3\nduration = 4\n"
    "dt = 0.01\n"
    "[intensity]\nmeasure = pga\nlevels = 0.1, 0.2, 0.3, 0.4\n";

/// The study of kSmokeStudy.
inline CampaignStudy smoke_study() {
  const std::string path = write_file("smoke.ini", kSmokeStudy);
  Options opt("campaign", "", campaign_option_specs());
  opt.parse({"--config", path});
  return campaign_from_options(opt, 0, -1);
}

}  // namespace pound::fuzz
