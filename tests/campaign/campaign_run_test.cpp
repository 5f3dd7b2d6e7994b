// The campaign program end to end: the same numbers on 1 and 2 ranks, a SIGKILL in the middle
// of a run followed by --resume gives the uninterrupted file, SIGTERM stops cleanly.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "../support/campaign_process.hpp"
#include "../support/scratch_dir.hpp"

namespace {

namespace fs = std::filesystem;

const std::string kStudy = std::string(POUND_SOURCE_DIR) + "/studies/campaign-smoke.ini";

const std::string& dir() {
  return pound::test::process_scratch_dir().path();
}

int sh(const std::string& cmd) {
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  // Open MPI's dynamically loaded components leak at exit, which LeakSanitizer would report in
  // the sanitizer build; address and undefined-behaviour errors stay fatal.
  ::setenv("ASAN_OPTIONS", "detect_leaks=0", 0);
  const int s = std::system((cmd + " 2>>" + dir() + "/stderr.log").c_str());
  return WIFEXITED(s) ? WEXITSTATUS(s) : -1;
}

using pound::test::expect_same_numbers;
using pound::test::read_raw;
using pound::test::session_members;

// The "units" attribute of a dataset ("" when absent).
std::string units_of(const std::string& file, const std::string& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  std::string out;
  const hid_t a = H5Aopen_by_name(f, path.c_str(), "units", H5P_DEFAULT, H5P_DEFAULT);
  if (a >= 0) {
    const hid_t t = H5Aget_type(a);
    if (H5Tis_variable_str(t) > 0) {
      char* s = nullptr;
      H5Aread(a, t, &s);
      out = s ? s : "";
      H5free_memory(s);
    } else {
      std::vector<char> buf(H5Tget_size(t) + 1, '\0');
      H5Aread(a, t, buf.data());
      out = buf.data();
    }
    H5Tclose(t);
    H5Aclose(a);
  }
  H5Fclose(f);
  return out;
}

// The root attribute "floors" (one integer per building); empty when absent.
std::vector<int> floors_of(const std::string& file) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  std::vector<int> out;
  const hid_t a = H5Aopen(f, "floors", H5P_DEFAULT);
  if (a >= 0) {
    const hid_t s = H5Aget_space(a);
    out.resize(static_cast<std::size_t>(std::max<hssize_t>(0, H5Sget_simple_extent_npoints(s))));
    if (H5Aread(a, H5T_NATIVE_INT, out.data()) < 0) out.clear();
    H5Sclose(s);
    H5Aclose(a);
  }
  H5Fclose(f);
  return out;
}

// Shape of a dataset.
std::vector<hsize_t> dims_of(const std::string& file, const std::string& path) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t d = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
  const hid_t s = H5Dget_space(d);
  std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(0, H5Sget_simple_extent_ndims(s))));
  H5Sget_simple_extent_dims(s, dims.data(), nullptr);
  H5Sclose(s);
  H5Dclose(d);
  H5Fclose(f);
  return dims;
}

// The residual drift, ductility and hysteretic energy datasets with their units and shape
// [samples, buildings, floors] (the smoke study: two one-storey buildings).
void expect_new_response_datasets(const std::string& file, hsize_t samples) {
  const std::pair<const char*, const char*> want[] = {
      {"/response/residual_drift_pounding", "-"},    {"/response/residual_drift_free", "-"},
      {"/response/ductility_pounding", "-"},         {"/response/ductility_free", "-"},
      {"/response/hysteretic_energy_pounding", "J"}, {"/response/hysteretic_energy_free", "J"}};
  for (const auto& [path, units] : want) {
    EXPECT_EQ(units_of(file, path), units) << path << " in " << file;
    EXPECT_EQ(dims_of(file, path), (std::vector<hsize_t>{samples, 2, 1})) << path << " in " << file;
  }
}

std::string pound(const std::string& args) {
  return std::string(POUND_BINARY) + " campaign --config " + kStudy + " --quiet " + args;
}

TEST(CampaignRun, SameNumbersOnOneAndTwoRanks) {
  const std::string one = dir() + "/one.h5", two = dir() + "/two.h5";
  ASSERT_EQ(sh("mpirun -np 1 " + pound("--out " + one)), 0);
  ASSERT_EQ(sh("mpirun -np 2 --oversubscribe " + pound("--out " + two)), 0);
  expect_same_numbers(one, two);
  expect_new_response_datasets(two, 24);
  EXPECT_FALSE(fs::exists(one + ".journal"));
}

TEST(CampaignRun, SameNumbersOnOneAndTwoRanksWithSpectralVariability) {
  // Random target spectra (issue 12): every eps comes from the sample's own stream, so the
  // runs agree bit for bit; and the motions are not those without variability.
  const std::string var = " --generator.variability spectral";
  const std::string one = dir() + "/var1.h5", two = dir() + "/var2.h5", none = dir() + "/var0.h5";
  ASSERT_EQ(sh("mpirun -np 1 " + pound("--samples 12 --out " + one + var)), 0);
  ASSERT_EQ(sh("mpirun -np 2 --oversubscribe " + pound("--samples 12 --out " + two + var)), 0);
  expect_same_numbers(one, two);
  ASSERT_EQ(sh("mpirun -np 1 " + pound("--samples 12 --out " + none)), 0);
  EXPECT_NE(read_raw(one, "/samples/scale"), read_raw(none, "/samples/scale"));
}

// Starts `pound campaign` with these arguments in the background, under `launcher` (e.g.
// "mpirun -np 2") when one is given: the process returned is the launcher's.
pid_t start_campaign(const std::string& args, const std::string& launcher = "") {
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execl("/bin/sh", "sh", "-c", ("exec " + launcher + " " + pound(args)).c_str(), nullptr);
    ::_exit(127);
  }
  return pid;
}

// Sends the signal and returns the wait status.
int signal_and_wait(pid_t pid, int sig) {
  ::kill(pid, sig);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

TEST(CampaignRun, KilledRunResumesToTheUninterruptedFile) {
  const std::string ref = dir() + "/ref.h5", cut = dir() + "/cut.h5";
  const std::string n = "--samples 160";
  ASSERT_EQ(sh(pound(n + " --out " + ref)), 0);
  // Start the same run and SIGKILL it once its journal holds some samples.
  const pid_t pid = start_campaign(n + " --out " + cut);
  const std::string journal = cut + ".journal";
  const auto t0 = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - t0 < std::chrono::seconds(60)) {
    struct stat s;
    if (::stat(journal.c_str(), &s) == 0 && s.st_size > 40 * 1024 / 10) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  const int status = signal_and_wait(pid, SIGKILL);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run finished before it could be killed";
  ASSERT_TRUE(fs::exists(journal));
  EXPECT_FALSE(fs::exists(cut));
  // Without --resume the existing journal is refused; with it the run completes.
  EXPECT_EQ(sh(pound(n + " --out " + cut)), 2);
  ASSERT_EQ(sh("mpirun -np 2 --oversubscribe " + pound(n + " --out " + cut + " --resume")), 0);
  expect_same_numbers(ref, cut);
}

TEST(CampaignRun, BatchedOutcomesGiveTheSameNumbersOnThreeRanks) {
  // Workers return their outcomes five at a time (campaign.batch, issue 13): the journal holds
  // them in another order, the result file is the same.
  const std::string one = dir() + "/batch1.h5", three = dir() + "/batch3.h5";
  const std::string n = "--samples 40";
  ASSERT_EQ(sh("mpirun -np 1 " + pound(n + " --out " + one)), 0);
  ASSERT_EQ(sh("mpirun -np 3 --oversubscribe " + pound(n + " --campaign.batch 5 --out " + three)),
            0);
  expect_same_numbers(one, three);
}

TEST(CampaignRun, KilledBatchedRunOnThreeRanksResumesToTheUninterruptedFile) {
  // SIGKILL to every process of a three-rank run whose workers batch their outcomes (a node
  // lost at once): the journal keeps the whole messages written before, a resumed run on two
  // ranks completes it to the uninterrupted file.
  const std::string ref = dir() + "/kref.h5", cut = dir() + "/kcut.h5";
  const std::string n = "--samples 160 --campaign.batch 4";
  ASSERT_EQ(sh(pound(n + " --out " + ref)), 0);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::setsid();
    ::execl("/bin/sh", "sh", "-c",
            ("exec mpirun -np 3 --oversubscribe " + pound(n + " --out " + cut)).c_str(), nullptr);
    ::_exit(127);
  }
  const std::string journal = cut + ".journal";
  const auto t0 = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - t0 < std::chrono::seconds(60)) {
    struct stat s;
    if (::stat(journal.c_str(), &s) == 0 && s.st_size > 40 * 1024 / 10) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  for (pid_t p : session_members(pid)) ::kill(p, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run finished before it could be killed";
  ASSERT_TRUE(fs::exists(journal));
  EXPECT_FALSE(fs::exists(cut));
  ASSERT_EQ(sh("mpirun -np 2 --oversubscribe " + pound(n + " --out " + cut + " --resume")), 0);
  expect_same_numbers(ref, cut);
}

// Starts `launcher pound campaign ...` of 160 samples writing NAME.h5, sends `sig` to the started
// process once the campaign says that it has started (every rank runs with its handlers),
// however long MPI start-up takes on this machine, and expects a clean stop with exit status 75
// whose --resume gives the uninterrupted file (or, rarely, a run that finished first: 0).
void expect_signal_stops_and_resumes(const std::string& launcher, int sig,
                                     const std::string& name) {
  const std::string ref = dir() + "/" + name + "_ref.h5", cut = dir() + "/" + name + ".h5";
  const std::string n = "--samples 160";
  ASSERT_EQ(sh(pound(n + " --out " + ref)), 0);
  const std::string started = dir() + "/" + name + ".started";
  const pid_t pid = start_campaign(n + " --out " + cut + " --started-file " + started, launcher);
  const auto t0 = std::chrono::steady_clock::now();
  while (!fs::exists(started) && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(120))
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_TRUE(fs::exists(started)) << "the campaign did not start within 120 s";
  const int status = signal_and_wait(pid, sig);
  ASSERT_TRUE(WIFEXITED(status));
  if (fs::exists(cut + ".journal")) {  // stopped before the end (the usual case)
    EXPECT_EQ(WEXITSTATUS(status), 75) << "stopped early: EX_TEMPFAIL, resumable";
    EXPECT_FALSE(fs::exists(cut));
    ASSERT_EQ(sh(pound(n + " --out " + cut + " --resume")), 0);
  } else {
    EXPECT_EQ(WEXITSTATUS(status), 0) << "the run finished before the signal";
  }
  expect_same_numbers(ref, cut);
}

TEST(CampaignRun, SigtermStopsCleanlyAndTheRunResumes) {
  expect_signal_stops_and_resumes("", SIGTERM, "term");
}

// Under mpirun the exit status a script sees is mpirun's. SIGUSR1 sent to mpirun itself (the
// way to stop a run by hand, docs/campaign.md) is forwarded to the ranks, which stop cleanly,
// and mpirun passes their 75 on.
TEST(CampaignRun, SigusrToMpirunStopsTheRanksAndMpirunExitsSeventyFive) {
  expect_signal_stops_and_resumes("mpirun -np 2 --oversubscribe", SIGUSR1, "usr");
}

TEST(CampaignRun, PartsOfASplitCampaignMergeIntoTheSingleRun) {
  // Three sample ranges (as three jobs of a Slurm array would run them), merged. Two contact
  // models and a collapse limit that the stronger stripes pass: the collapse shares and the
  // per-model tables of /amplification are recomputed too.
  const std::string ref = dir() + "/whole.h5";
  const std::string n =
      "--samples 30 --sample.model 'discrete(hc-linear: 1, lve: 1)' "
      "--simulation.collapse_drift_ratio 0.01";
  ASSERT_EQ(sh(pound(n + " --out " + ref)), 0);
  const char* ranges[] = {"0:7", "7:20", "20:30"};
  std::string parts;
  for (int i = 2; i >= 0; --i) {  // in any order
    const std::string part = dir() + "/part" + std::to_string(i) + ".h5";
    ASSERT_EQ(sh(pound(n + " --sample-range " + ranges[i] + " --out " + part)), 0);
    parts += (parts.empty() ? "" : ",") + part;
  }
  const std::string merged = dir() + "/merged.h5";
  ASSERT_EQ(sh(std::string(POUND_BINARY) + " merge --out " + merged + " --parts " + parts), 0);
  expect_same_numbers(ref, merged);  // the residual drift, ductility and energy included
  expect_new_response_datasets(merged, 30);
  // The floors of each building (two one-storey buildings), copied by the merge.
  EXPECT_EQ(floors_of(ref), (std::vector<int>{1, 1}));
  EXPECT_EQ(floors_of(merged), floors_of(ref));
  // /amplification is computed again for the joined samples: the single run's, bit for bit
  // (the parts' own describe only their samples).
  for (const char* p : {"/amplification/im",
                        "/amplification/samples",
                        "/amplification/failed",
                        "/amplification/disp/count",
                        "/amplification/disp/median",
                        "/amplification/drift/p16",
                        "/amplification/accel/p84",
                        "/amplification/disp/fraction_above_1",
                        "/amplification/contact/count",
                        "/amplification/contact/pounded_fraction",
                        "/amplification/contact/force_median",
                        "/amplification/collapse/count",
                        "/amplification/collapse/collapsed_pounding",
                        "/amplification/collapse/collapsed_free",
                        "/amplification/models/hc-linear/samples",
                        "/amplification/models/lve/im",
                        "/amplification/models/lve/accel/median",
                        "/amplification/models/hc-linear/drift/p84",
                        "/amplification/models/lve/contact/pounded_fraction",
                        "/amplification/models/hc-linear/collapse/collapsed_pounding",
                        "/amplification/models/lve/collapse/collapsed_free"})
    EXPECT_EQ(read_raw(ref, p), read_raw(merged, p)) << p;
  for (const char* p : {"/amplification/disp/count", "/amplification/collapse/collapsed_free",
                        "/amplification/models/lve/samples"})
    EXPECT_NE(read_raw(dir() + "/part0.h5", p), read_raw(merged, p)) << p;
  // Some building collapsed and some stood: the shares compared above are not all 0 or all 1.
  const std::vector<char> free = read_raw(merged, "/amplification/collapse/collapsed_free");
  std::vector<double> shares(free.size() / sizeof(double));
  std::copy(free.begin(), free.end(), reinterpret_cast<char*>(shares.data()));
  EXPECT_GT(*std::max_element(shares.begin(), shares.end()), 0.0);
  EXPECT_LT(*std::min_element(shares.begin(), shares.end()), 1.0);
  EXPECT_EQ(units_of(merged, "/response/approach_free"), "m");
  // A gap is refused and leaves no file.
  const std::string bad = dir() + "/bad-merge.h5";
  EXPECT_EQ(sh(std::string(POUND_BINARY) + " merge --out " + bad + " --parts " + dir() +
               "/part0.h5," + dir() + "/part2.h5"),
            2);
  EXPECT_FALSE(fs::exists(bad));
}

TEST(CampaignRun, StudyErrorCreatesNoFile) {
  const std::string out = dir() + "/bad.h5";
  EXPECT_EQ(sh(std::string(POUND_BINARY) + " campaign --config " + kStudy +
               " --sample.e 'uniform(0.5, 1.5)' --out " + out),
            2);
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out + ".journal"));
  // An existing result is not overwritten without --force.
  ASSERT_EQ(sh(pound("--samples 4 --out " + out)), 0);
  EXPECT_EQ(sh(pound("--samples 4 --out " + out)), 2);
  EXPECT_EQ(sh(pound("--samples 4 --out " + out + " --force")), 0);
}

// Runs `pound campaign` on the smoke study with these arguments; returns the exit code and
// stderr.
std::pair<int, std::string> run_with_log(const std::string& args) {
  ::setenv("ASAN_OPTIONS", "detect_leaks=0", 0);  // as in sh()
  const std::string log = dir() + "/run.log";
  const int s = std::system((pound(args) + " >/dev/null 2>" + log).c_str());
  std::ifstream in(log);
  return {WIFEXITED(s) ? WEXITSTATUS(s) : -1, std::string(std::istreambuf_iterator<char>(in), {})};
}

TEST(CampaignRun, BadStrengthOrHardeningIsOneLineExitTwoAndNoFile) {
  const std::string out = dir() + "/bad-sample.h5";
  const std::pair<std::string, std::vector<std::string>> cases[] = {
      // Building 1 of the smoke study has no yield shears.
      {"--sample.building1.strength_scale 'uniform(0.8,1.2)'",
       {"--sample.building1.strength_scale", "no yield_shears", "hysteresis"}},
      {"--sample.hardening 'uniform(0.5, 1.5)'", {"--sample.hardening", "[0, 1)"}},
  };
  for (const auto& [arg, parts] : cases) {
    const auto [code, msg] = run_with_log("--out " + out + " " + arg);
    EXPECT_EQ(code, 2) << arg;
    EXPECT_EQ(std::count(msg.begin(), msg.end(), '\n'), 1) << msg;
    for (const auto& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << p << " in: " << msg;
    EXPECT_FALSE(fs::exists(out)) << arg;
    EXPECT_FALSE(fs::exists(out + ".journal")) << arg;
  }
}

TEST(CampaignRun, BadVariabilityInputIsOneLineExitTwoAndNoFile) {
  const std::string out = dir() + "/bad-variability.h5";
  const std::pair<std::string, std::string> cases[] = {
      {"--generator.sigma_lnsa -0.2", "--generator.sigma_lnsa"},
      {"--generator.sigma_table " + dir() + "/no-such-table.txt", "cannot open the sigma table"},
      {"--generator.correlation baker-jayaram", "valid: baker-jayaram-2008, none, full"},
  };
  for (const auto& [arg, needle] : cases) {
    const auto [code, msg] =
        run_with_log("--out " + out + " --generator.variability spectral " + arg);
    EXPECT_EQ(code, 2) << arg;
    EXPECT_EQ(std::count(msg.begin(), msg.end(), '\n'), 1) << msg;
    EXPECT_NE(msg.find(needle), std::string::npos) << needle << " in: " << msg;
    EXPECT_FALSE(fs::exists(out)) << arg;
    EXPECT_FALSE(fs::exists(out + ".journal")) << arg;
  }
}

TEST(CampaignRun, AJournalOfAnOlderPoundIsNotResumed) {
  const std::string out = dir() + "/old-journal.h5";
  {
    std::ofstream j(out + ".journal", std::ios::binary);
    j << "POUNDJ01" << std::string(32, '\0');
  }
  const auto [code, log] = run_with_log("--samples 4 --resume --out " + out);
  EXPECT_EQ(code, 2);
  // After the start-up echo of the study, one error line.
  const auto at = log.find("error:");
  ASSERT_NE(at, std::string::npos) << log;
  const std::string msg = log.substr(log.rfind('\n', at) + 1);
  EXPECT_EQ(std::count(msg.begin(), msg.end(), '\n'), 1) << msg;
  EXPECT_NE(msg.find(out + ".journal"), std::string::npos) << msg;
  EXPECT_NE(msg.find("older pound"), std::string::npos) << msg;
  EXPECT_NE(msg.find("--force"), std::string::npos) << msg;
  EXPECT_FALSE(fs::exists(out));
  // --force starts again.
  EXPECT_EQ(sh(pound("--samples 4 --force --out " + out)), 0);
  EXPECT_TRUE(fs::exists(out));
}

TEST(CampaignRun, BadSampleRangeOrChunkSaysWhatIsValid) {
  ::setenv("ASAN_OPTIONS", "detect_leaks=0", 0);  // as in sh()
  const std::string out = dir() + "/range.h5", log = dir() + "/range.log";
  for (const std::string arg : {"--sample-range 1.5:3", "--sample-range a:3", "--sample-range 5",
                                "--sample-range 0:21", "--chunk 2/2", "--chunk 0.5/2"}) {
    const int s =
        std::system((pound("--samples 20 --out " + out + " " + arg) + " 2>" + log).c_str());
    ASSERT_TRUE(WIFEXITED(s));
    EXPECT_EQ(WEXITSTATUS(s), 2) << arg;
    std::ifstream in(log);
    const std::string msg((std::istreambuf_iterator<char>(in)), {});
    EXPECT_NE(msg.find(arg.find("chunk") != std::string::npos ? "valid: K/C" : "valid: LO:HI"),
              std::string::npos)
        << arg << ": " << msg;
    EXPECT_EQ(std::count(msg.begin(), msg.end(), '\n'), 1) << msg;
    EXPECT_FALSE(fs::exists(out)) << arg;
  }
}

TEST(CampaignRun, FailedSamplesAreListedUpToTwentyAndExitFour) {
  // A fixed Sears step of 10 ms is above every sampled Sears sample's largest allowed step:
  // the 30 Sears samples of 60 fail as input failures, the hc-linear ones run.
  ::setenv("ASAN_OPTIONS", "detect_leaks=0", 0);  // as in sh()
  const std::string out = dir() + "/failing.h5", log = dir() + "/failing.log";
  const std::string study = std::string(POUND_SOURCE_DIR) + "/studies/fragility-default.ini";
  const int s = std::system((std::string(POUND_BINARY) + " campaign --config " + study +
                             " --samples 60 --sears.dt 1e-2 --quiet --out " + out + " 2>" + log)
                                .c_str());
  ASSERT_TRUE(WIFEXITED(s));
  EXPECT_EQ(WEXITSTATUS(s), 4);
  std::ifstream in(log);
  int listed = 0, notice = 0;
  std::string done;
  for (std::string line; std::getline(in, line);) {
    if (line.find("too large; the largest allowed step") != std::string::npos) ++listed;
    if (line.find("not listed here") != std::string::npos) ++notice;
    if (line.rfind("campaign: done:", 0) == 0) done = line;
  }
  EXPECT_EQ(listed, 20);
  EXPECT_EQ(notice, 1);
  EXPECT_NE(done.find("60 samples, 30 failed"), std::string::npos) << done;
  EXPECT_TRUE(fs::exists(out));  // the samples that ran are kept, the failures marked
}

TEST(CampaignRun, HelpListsTheExitStatuses) {
  // Scripts and job chains read how a run ended from its status (issue 24): --help says which.
  const std::string help = dir() + "/help.txt";
  ASSERT_EQ(sh(pound("--help") + " >" + help), 0);
  std::ifstream in(help);
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  for (const char* part :
       {"Exit status: 0 finished (RUN.h5 complete, or already complete); 2 bad input",
        "4 finished with\nfailed samples",
        "75 (EX_TEMPFAIL) stopped early by\nSIGTERM, SIGUSR1, "
        "SIGINT or a full disk, the journal kept: run again "
        "with --resume.\n"})
    EXPECT_NE(text.find(part), std::string::npos) << part << " in:\n" << text;
}

}  // namespace
