#pragma once
// Runs `pound campaign` as a separate process (the tests of how a campaign stops and resumes in
// tests/campaign, the small campaigns of the command tests in tests/app), and compares the
// numbers of two result files.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "scratch_dir.hpp"
#include "shell.hpp"

namespace pound::test {

/// The small study of the campaign tests: an SDOF pair, 648 journal bytes a sample.
inline const std::string kSmokeStudy =
    std::string(POUND_SOURCE_DIR) + "/studies/campaign-smoke.ini";

/// The test process's scratch directory.
inline const std::string& campaign_dir() {
  return process_scratch_dir().path();
}

/// `pound campaign` of the smoke study, quiet, with these further arguments.
inline std::string campaign_command(const std::string& args) {
  return std::string(POUND_BINARY) + " campaign --config " + kSmokeStudy + " --quiet " + args;
}

/// Makes `out`: a campaign of the smoke study with `samples` samples and the further arguments
/// `extra`, its stderr in out + ".log" (shown when it fails, which fails the calling test).
/// Returns `out`.
inline std::string make_smoke_campaign(const std::string& out, int samples,
                                       const std::string& extra = "") {
  const std::string log = out + ".log";
  EXPECT_EQ(run_command(campaign_command("--samples " + std::to_string(samples) + " " + extra +
                                         " --out " + out) +
                        " 2>" + log),
            0)
      << slurp(log);
  return out;
}

/// Runs `cmd` through sh with stderr to `log` (sh -c 'exec CMD 2>LOG'). Returns the wait status.
inline int run_shell(const std::string& cmd, const std::string& log) {
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  ::setenv("ASAN_OPTIONS", "detect_leaks=0", 0);  // Open MPI's components leak at exit
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execl("/bin/sh", "sh", "-c", ("exec " + cmd + " 2>" + log).c_str(), nullptr);
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

/// The exit status of a run_shell() status, -1 when a signal ended it.
inline int exit_code(int status) {
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// The processes of session `sid` (a job started with setsid: mpirun and its ranks, which
/// Open MPI puts into process groups of their own).
inline std::vector<pid_t> session_members(pid_t sid) {
  std::vector<pid_t> out;
  for (const auto& e : std::filesystem::directory_iterator("/proc")) {
    const std::string name = e.path().filename();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream in(e.path() / "stat");
    std::string stat((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t close = stat.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream rest(stat.substr(close + 1));
    std::string state;
    long ppid = 0, pgrp = 0, session = 0;
    rest >> state >> ppid >> pgrp >> session;
    if (session == sid) out.push_back(static_cast<pid_t>(std::stol(name)));
  }
  return out;
}

/// The raw bytes of one dataset.
inline std::vector<char> read_raw(const std::string& file, const std::string& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(f, 0) << file;
  const hid_t d = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
  EXPECT_GE(d, 0) << path;
  const hid_t t = H5Dget_type(d);
  const hid_t s = H5Dget_space(d);
  std::vector<char> buf(static_cast<std::size_t>(H5Sget_simple_extent_npoints(s)) * H5Tget_size(t));
  H5Dread(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data());
  H5Sclose(s);
  H5Tclose(t);
  H5Dclose(d);
  H5Fclose(f);
  return buf;
}

/// The sampled inputs and the responses of two result files agree bit for bit.
inline void expect_same_numbers(const std::string& a, const std::string& b) {
  for (const char* p : {"/samples/id",
                        "/samples/status",
                        "/samples/im",
                        "/samples/scale",
                        "/samples/e",
                        "/samples/gap",
                        "/samples/k_factor",
                        "/response/peak_disp_pounding",
                        "/response/peak_disp_free",
                        "/response/peak_drift_ratio_pounding",
                        "/response/peak_drift_ratio_free",
                        "/response/peak_accel_pounding",
                        "/response/peak_accel_free",
                        "/response/residual_drift_pounding",
                        "/response/residual_drift_free",
                        "/response/ductility_pounding",
                        "/response/ductility_free",
                        "/response/hysteretic_energy_pounding",
                        "/response/hysteretic_energy_free",
                        "/response/peak_force",
                        "/response/impacts",
                        "/response/approach_free"})
    EXPECT_EQ(read_raw(a, p), read_raw(b, p)) << p << " differs between " << a << " and " << b;
}

/// No result file and no temporary of one beside it.
inline void expect_no_result(const std::string& out) {
  namespace fs = std::filesystem;
  EXPECT_FALSE(fs::exists(out));
  for (const auto& e : fs::directory_iterator(fs::path(out).parent_path()))
    EXPECT_NE(e.path().filename().string().rfind(fs::path(out).filename().string() + ".tmp", 0), 0u)
        << e.path();
}

/// The names in a folder, sorted, one per line (as `ls` prints them).
inline std::string listing(const std::string& folder) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(folder))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  std::string out;
  for (const auto& n : names) out += n + "\n";
  return out;
}

}  // namespace pound::test
