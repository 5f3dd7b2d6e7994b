// How a campaign stops (issue 14): a stop signal that comes while the ranks start is honoured
// (the handlers exist before MPI start-up), and a disk that fills up (a small tmpfs) stops the
// campaign as SIGTERM does, with the system's reason and the resume command; the run resumed
// after freeing space gives the uninterrupted file, whether the journal or the result file
// met the full disk.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "../support/scratch_dir.hpp"

namespace {

namespace fs = std::filesystem;

const std::string kStudy = std::string(POUND_SOURCE_DIR) + "/studies/campaign-smoke.ini";

const std::string& dir() {
  return pound::test::process_scratch_dir().path();
}

std::string pound(const std::string& args) {
  return std::string(POUND_BINARY) + " campaign --config " + kStudy + " --quiet " + args;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

// Runs the command through sh with stderr to `log`. Returns the wait status.
int run(const std::string& cmd, const std::string& log) {
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

std::vector<char> read_raw(const std::string& file, const std::string& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(f, 0) << file;
  const hid_t d = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
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

void expect_same_numbers(const std::string& a, const std::string& b) {
  for (const char* p :
       {"/samples/id", "/samples/status", "/samples/im", "/samples/scale", "/samples/e",
        "/samples/gap", "/samples/k_factor", "/response/peak_disp_pounding",
        "/response/peak_drift_free", "/response/peak_accel_pounding",
        "/response/ductility_pounding", "/response/peak_force", "/response/impacts"})
    EXPECT_EQ(read_raw(a, p), read_raw(b, p)) << p << " differs between " << a << " and " << b;
}

// No result file and no temporary of one beside it.
void expect_no_result(const std::string& out) {
  EXPECT_FALSE(fs::exists(out));
  for (const auto& e : fs::directory_iterator(fs::path(out).parent_path()))
    EXPECT_NE(e.path().filename().string().rfind(fs::path(out).filename().string() + ".tmp", 0), 0u)
        << e.path();
}

// The caught-signal mask of a process (/proc/PID/status, SigCgt) has SIGTERM.
bool catches_sigterm(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("SigCgt:", 0) == 0)
      return (std::stoull(line.substr(7), nullptr, 16) >> (SIGTERM - 1)) & 1ull;
  return false;
}

TEST(CampaignStop, SigtermWhileTheRankStartsStopsCleanlyAndResumes) {
  const std::string ref = dir() + "/start-ref.h5", cut = dir() + "/start.h5";
  const std::string started = dir() + "/start.started", log = dir() + "/start.log";
  const std::string n = "--samples 24";
  ASSERT_EQ(run(pound(n + " --out " + ref), log), 0);
  // SIGTERM as soon as the handler exists, before MPI start-up is over (before the campaign
  // says it has started). Repeated: each time the run stops at once, keeping the journal.
  int before_start = 0;
  for (int trial = 0; trial < 3; ++trial) {
    fs::remove(started);
    const pid_t pid = ::fork();
    if (pid == 0) {
      ::execl(
          "/bin/sh", "sh", "-c",
          ("exec " +
           pound(n + " --out " + cut + (trial ? " --resume" : "") + " --started-file " + started) +
           " 2>" + log)
              .c_str(),
          nullptr);
      ::_exit(127);
    }
    const auto t0 = std::chrono::steady_clock::now();
    while (!catches_sigterm(pid) &&
           std::chrono::steady_clock::now() - t0 < std::chrono::seconds(60))
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    before_start += !fs::exists(started);
    ::kill(pid, SIGTERM);
    int status = 0;
    ::waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
    EXPECT_EQ(WEXITSTATUS(status), 75) << slurp(log);  // stopped, resumable (EX_TEMPFAIL)
    EXPECT_NE(slurp(log).find("campaign: interrupted after"), std::string::npos) << slurp(log);
    EXPECT_TRUE(fs::exists(cut + ".journal"));
    expect_no_result(cut);
  }
  EXPECT_GT(before_start, 0) << "every signal came after the campaign had started";
  ASSERT_EQ(run(pound(n + " --out " + cut + " --resume"), log), 0) << slurp(log);
  expect_same_numbers(ref, cut);
}

// Runs a campaign of `samples` samples into a tmpfs of `kib` KiB mounted on DIR/disk in a
// mount namespace of its own (unshare: the test needs no root, and the host sees no mount),
// so that the disk really fills up (ENOSPC); then "frees space" (remounts it at 64 MiB) and
// resumes. Leaves DIR/first.log and DIR/first.status (the stopped run), DIR/left.txt (the
// files on the full disk), DIR/second.log and DIR/second.status (the resume) and DIR/run.h5
// (the file the resume wrote).
// Runs the shell script `body` after "set -u" in a mount namespace of its own (DIR/script.sh;
// unshare: no root needed, and the host sees no mount).
void run_in_a_mount_namespace(const std::string& d, const std::string& body) {
  std::ofstream(d + "/script.sh") << "set -u\n" << body;
  const int status =
      run("unshare --user --map-root-user --mount sh " + d + "/script.sh", d + "/unshare.log");
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
      << "unshare and mount of a tmpfs: " << slurp(d + "/unshare.log");
}

void run_on_a_full_disk(const std::string& d, int kib, int samples) {
  fs::create_directories(d + "/disk");
  const std::string cmd =
      pound("--samples " + std::to_string(samples) + " --out " + d + "/disk/run.h5");
  run_in_a_mount_namespace(
      d, "mount -t tmpfs -o size=" + std::to_string(kib) + "k tmpfs " + d + "/disk || exit 90\n" +
             cmd + " 2>" + d + "/first.log; echo $? >" + d + "/first.status\n" + "ls " + d +
             "/disk >" + d + "/left.txt\n" + "mount -o remount,size=64m " + d +
             "/disk || exit 91\n" + cmd + " --resume 2>" + d + "/second.log; echo $? >" + d +
             "/second.status\n" + "cp " + d + "/disk/run.h5 " + d + "/run.h5\n");
}

TEST(CampaignStop, AFullDiskStopsTheJournalWithTheReasonAndTheResumeGivesTheWholeFile) {
  // 160 samples journal 83 kB (520 bytes a record); a 40 KiB disk holds about 78 of them.
  const std::string d = dir() + "/full-journal", ref = dir() + "/full-ref.h5";
  ASSERT_EQ(run(pound("--samples 160 --out " + ref), dir() + "/ref.log"), 0);
  run_on_a_full_disk(d, 40, 160);
  EXPECT_EQ(slurp(d + "/first.status"), "75\n");  // as a SIGTERM stop
  const std::string msg = slurp(d + "/first.log");
  for (const std::string& part : std::vector<std::string>{
           d + "/disk/run.h5.journal: cannot write the campaign journal (No space left on device)",
           "campaign: stopped after ", " of 160 samples (0 failed)",
           "The journal " + d + "/disk/run.h5.journal keeps them",
           "resume with: mpirun -np 1 pound campaign --config " + kStudy, "--resume\n"})
    EXPECT_NE(msg.find(part), std::string::npos) << part << " in:\n" << msg;
  EXPECT_EQ(slurp(d + "/left.txt"), "run.h5.journal\n");  // no result file, no temporary
  EXPECT_EQ(slurp(d + "/second.status"), "0\n") << slurp(d + "/second.log");
  expect_same_numbers(ref, d + "/run.h5");
}

TEST(CampaignStop, AFullDiskAtTheResultFileKeepsTheJournalAndTheResumeWritesIt) {
  // 24 samples journal 12.5 kB; their HDF5 file needs more than the 16 KiB left of 32 KiB.
  const std::string d = dir() + "/full-result", ref = dir() + "/end-ref.h5";
  ASSERT_EQ(run(pound("--samples 24 --out " + ref), dir() + "/ref.log"), 0);
  ASSERT_GT(fs::file_size(ref), 16384u);
  run_on_a_full_disk(d, 32, 24);
  EXPECT_EQ(slurp(d + "/first.status"), "75\n");
  const std::string msg = slurp(d + "/first.log");
  for (const std::string part :
       {"campaign: stopped after 24 of 24 samples (0 failed): ", "cannot write the HDF5 file",
        "(No space left on device)", "resume with:", "--resume\n"})
    EXPECT_NE(msg.find(part), std::string::npos) << part << " in:\n" << msg;
  EXPECT_EQ(slurp(d + "/left.txt"), "run.h5.journal\n");
  EXPECT_EQ(slurp(d + "/second.status"), "0\n") << slurp(d + "/second.log");
  expect_same_numbers(ref, d + "/run.h5");
}

// A journal that cannot be written for another reason than space would fail again on every
// resume: the job must end with an error (exit 2, which the Slurm scripts pass on) instead of
// a stop that says "free some space" and exits 75 ("submit again").
// Here a journal left by a full disk is resumed on the same tmpfs remounted read-only
// (EROFS, which a run as root meets too); the journal stays whole, and the resume once the
// file system is writable again gives the uninterrupted file.
TEST(CampaignStop, AReadOnlyJournalIsAnErrorAndStaysForALaterResume) {
  const std::string d = dir() + "/read-only", ref = dir() + "/ro-ref.h5";
  ASSERT_EQ(run(pound("--samples 160 --out " + ref), dir() + "/ref.log"), 0);
  fs::create_directories(d + "/disk");
  const std::string cmd = pound("--samples 160 --out " + d + "/disk/run.h5");
  run_in_a_mount_namespace(
      d, "mount -t tmpfs -o size=40k tmpfs " + d + "/disk || exit 90\n" + cmd + " 2>" + d +
             "/first.log; echo $? >" + d + "/first.status\n" + "cp " + d + "/disk/run.h5.journal " +
             d + "/kept\n" + "mount -o remount,ro,size=64m " + d + "/disk || exit 91\n" + cmd +
             " --resume 2>" + d + "/ro.log; echo $? >" + d + "/ro.status\n" + "ls " + d +
             "/disk >" + d + "/left.txt\n" + "cmp -s " + d + "/kept " + d +
             "/disk/run.h5.journal; echo $? >" + d + "/same.status\n" + "mount -o remount,rw " + d +
             "/disk || exit 92\n" + cmd + " --resume 2>" + d + "/second.log; echo $? >" + d +
             "/second.status\n" + "cp " + d + "/disk/run.h5 " + d + "/run.h5\n");
  if (HasFatalFailure()) return;
  ASSERT_EQ(slurp(d + "/first.status"), "75\n") << slurp(d + "/first.log");  // the full disk
  EXPECT_EQ(slurp(d + "/ro.status"), "2\n") << slurp(d + "/ro.log");
  const std::string msg = slurp(d + "/ro.log");
  const std::string want = "pound campaign: error: " + d +
                           "/disk/run.h5.journal: cannot cut the torn tail of the journal "
                           "(Read-only file system); the journal keeps ";
  EXPECT_NE(msg.find(want), std::string::npos) << want << " in:\n" << msg;
  EXPECT_NE(msg.find(" of 160 samples: run again with --resume once " + d +
                     "/disk/run.h5.journal can be written\n"),
            std::string::npos)
      << msg;
  EXPECT_EQ(msg.find("free some space"), std::string::npos) << msg;
  EXPECT_EQ(msg.find("campaign: stopped after"), std::string::npos) << msg;
  EXPECT_EQ(slurp(d + "/left.txt"), "run.h5.journal\n");
  EXPECT_EQ(slurp(d + "/same.status"), "0\n");  // the journal as the full disk left it
  EXPECT_EQ(slurp(d + "/second.status"), "0\n") << slurp(d + "/second.log");
  expect_same_numbers(ref, d + "/run.h5");
}

}  // namespace
