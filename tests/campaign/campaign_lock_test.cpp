// One writer per campaign output (issue 31), end to end. While a campaign runs, a second one on
// the same --out (without --resume, with it, with --force; alone or under mpirun) stops at once
// with exit status 75 and one line naming the first (its pid and host), and changes nothing:
// the first's file is then that of an uninterrupted run. --wait-lock waits for the first to end
// and then goes on (or stops with 75 when the wait is too short). And mpirun killed with
// SIGKILL at moments spread over a run, followed at once by --resume, ends in the uninterrupted
// file, directly or after a 75 (the ranks the kill left running still hold the lock) and
// retries.
//
// The first campaign is paused (SIGSTOP, which keeps its lock) while the others meet it, so
// that the tests do not depend on how fast this machine simulates.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "../support/campaign_process.hpp"

namespace {

namespace fs = std::filesystem;
using pound::test::campaign_command;
using pound::test::campaign_dir;
using pound::test::exit_code;
using pound::test::expect_same_numbers;
using pound::test::listing;
using pound::test::run_shell;
using pound::test::session_members;
using pound::test::slurp;
using Clock = std::chrono::steady_clock;

constexpr int kSamples = 160;
const std::string kRun = "--samples " + std::to_string(kSamples);

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// CAMPAIGN_DIR/name/, made: the folder of one output, which then holds only its files.
std::string folder(const std::string& name) {
  const std::string d = campaign_dir() + "/" + name;
  fs::create_directories(d);
  return d;
}

std::string this_host() {
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  return host;
}

// `cmd` run through sh in the background, in a session of its own, stderr to `log`. When the
// object dies (the test ends, or fails on the way), whatever is left of the session is killed,
// mpirun's ranks included (session_members): no process stays behind, stopped or running,
// holding the test's output.
class Background {
 public:
  Background(const std::string& cmd, const std::string& log) {
    ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
    ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
    ::setenv("ASAN_OPTIONS", "detect_leaks=0", 0);  // as run_shell
    pid_ = ::fork();
    if (pid_ == 0) {
      ::setsid();
      ::execl("/bin/sh", "sh", "-c", ("exec " + cmd + " 2>" + log).c_str(), nullptr);
      ::_exit(127);
    }
  }
  ~Background() {
    for (pid_t p : session_members(pid_)) ::kill(p, SIGKILL);
    if (!reaped_) wait();
  }
  Background(const Background&) = delete;
  Background& operator=(const Background&) = delete;

  /// The process started (mpirun, or pound), which leads the session.
  pid_t pid() const { return pid_; }
  /// Waits for it to end; its exit status (-1 when a signal ended it).
  int wait() {
    int status = 0;
    ::waitpid(pid_, &status, 0);
    reaped_ = true;
    return exit_code(status);
  }

 private:
  pid_t pid_ = -1;
  bool reaped_ = false;
};

// Waits up to 120 s until `ready()`; returns whether it came.
template <class Ready>
bool wait_until(Ready ready) {
  const auto t0 = Clock::now();
  while (!ready()) {
    if (seconds_since(t0) > 120) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

// The state letter of a process (/proc/PID/stat): 'T' once stopped.
char state_of(pid_t pid) {
  const std::string stat = slurp("/proc/" + std::to_string(pid) + "/stat");
  const auto close = stat.rfind(')');
  return close == std::string::npos || close + 2 >= stat.size() ? '?' : stat[close + 2];
}

// SIGSTOP, and waits until the process has stopped (the kernel keeps its lock).
void pause_process(pid_t pid) {
  ::kill(pid, SIGSTOP);
  EXPECT_TRUE(wait_until([&] { return state_of(pid) == 'T'; })) << "pid " << pid;
}

// The uninterrupted run of `samples` samples on two ranks, made once per count, and how long it
// ran from its start (the started file) to its end [s]: the span of the runs killed below.
struct Reference {
  std::string path;
  double seconds = 0.0;
};
const Reference& reference(int samples = kSamples) {
  static std::map<int, Reference> made;
  auto [at, fresh] = made.try_emplace(samples);
  Reference& r = at->second;
  if (!fresh) return r;
  r.path = campaign_dir() + "/lock-ref-" + std::to_string(samples) + ".h5";
  const std::string started = r.path + ".started", log = r.path + ".log";
  Background run("mpirun -np 2 --oversubscribe " +
                     campaign_command("--samples " + std::to_string(samples) + " --out " + r.path +
                                      " --started-file " + started),
                 log);
  EXPECT_TRUE(wait_until([&] { return fs::exists(started); })) << slurp(log);
  const auto t0 = Clock::now();
  EXPECT_EQ(run.wait(), 0) << slurp(log);
  r.seconds = seconds_since(t0);
  return r;
}

// The line of a campaign that meets `out` in use by process `pid` of this host.
std::string in_use_line(const std::string& out, pid_t pid) {
  return "campaign: stopped: another campaign is writing " + out + " (pid " + std::to_string(pid) +
         " on host " + this_host() + "; its lock " + out +
         ".lock); nothing was changed: run again once it has ended, or wait for it with "
         "--wait-lock SECONDS\n";
}

TEST(CampaignLock, ASecondCampaignOnAnOutputInUseStopsWithSeventyFiveAndChangesNothing) {
  const Reference& ref = reference();
  const std::string d = folder("in-use"), out = d + "/run.h5", logs = campaign_dir() + "/in-use-";
  Background first(campaign_command(kRun + " --out " + out + " --started-file " + logs + "started"),
                   logs + "first.log");
  ASSERT_TRUE(wait_until([&] { return fs::exists(logs + "started"); }))
      << slurp(logs + "first.log");
  pause_process(first.pid());
  const std::string files = listing(d), journal = slurp(out + ".journal");
  const std::string lock = slurp(out + ".lock");
  EXPECT_EQ(files, "run.h5.journal\nrun.h5.lock\n");
  EXPECT_EQ(lock, "pid=" + std::to_string(first.pid()) + "\nhost=" + this_host() + "\n");
  const std::string want = in_use_line(out, first.pid());
  for (const std::string mode : {"", " --resume", " --force"}) {
    const std::string log = logs + "second.log";
    const auto t0 = Clock::now();
    const int status = run_shell(campaign_command(kRun + " --out " + out + mode), log);
    EXPECT_EQ(exit_code(status), 75) << "with" << mode << ":\n" << slurp(log);
    EXPECT_EQ(slurp(log), want) << "with" << mode;  // that one line, nothing else
    EXPECT_LT(seconds_since(t0), 30.0) << "with" << mode << ": stops at once";
    EXPECT_EQ(listing(d), files) << "with" << mode;
    EXPECT_EQ(slurp(out + ".journal"), journal) << "with" << mode;
    EXPECT_EQ(slurp(out + ".lock"), lock) << "with" << mode;
  }
  // Under mpirun every rank ends (the master decides, the others follow), and mpirun passes 75
  // on; `timeout` turns a rank left waiting into a failure instead of a hang.
  const int status = run_shell("timeout 120 mpirun -np 2 --oversubscribe " +
                                   campaign_command(kRun + " --force --out " + out),
                               logs + "mpirun.log");
  EXPECT_EQ(exit_code(status), 75) << slurp(logs + "mpirun.log");
  EXPECT_NE(slurp(logs + "mpirun.log").find(want), std::string::npos) << slurp(logs + "mpirun.log");
  EXPECT_EQ(listing(d), files);
  EXPECT_EQ(slurp(out + ".journal"), journal);
  // The first goes on undisturbed to the uninterrupted file, and leaves no lock file.
  ::kill(first.pid(), SIGCONT);
  EXPECT_EQ(first.wait(), 0) << slurp(logs + "first.log");
  EXPECT_EQ(listing(d), "run.h5\n");
  expect_same_numbers(ref.path, out);
}

TEST(CampaignLock, WaitLockWaitsForTheFirstCampaignAndThenGoesOn) {
  const Reference& ref = reference();
  const std::string d = folder("wait"), out = d + "/run.h5", logs = campaign_dir() + "/wait-";
  Background first(campaign_command(kRun + " --out " + out + " --started-file " + logs + "started"),
                   logs + "first.log");
  ASSERT_TRUE(wait_until([&] { return fs::exists(logs + "started"); }))
      << slurp(logs + "first.log");
  pause_process(first.pid());
  // Too short a wait: 75 once it is over, nothing changed.
  const std::string files = listing(d), journal = slurp(out + ".journal");
  const auto t0 = Clock::now();
  const int status = run_shell(campaign_command(kRun + " --resume --wait-lock 0.5 --out " + out),
                               logs + "short.log");
  const double waited = seconds_since(t0);
  EXPECT_EQ(exit_code(status), 75) << slurp(logs + "short.log");
  EXPECT_GE(waited, 0.5);
  const std::string holder = "(pid " + std::to_string(first.pid()) + " on host " + this_host();
  EXPECT_EQ(slurp(logs + "short.log"),
            "campaign: another campaign is writing " + out + " " + holder +
                "); waiting up to 0.5 s\ncampaign: stopped: another campaign is still writing " +
                out + " after waiting 0.5 s " + holder + "; its lock " + out +
                ".lock); nothing was changed: run again once it has ended, or wait longer with "
                "--wait-lock SECONDS\n");
  EXPECT_EQ(listing(d), files);
  EXPECT_EQ(slurp(out + ".journal"), journal);
  // A long wait, on two ranks: the second waits until the first ends (stopped here by SIGTERM,
  // its journal kept), then resumes the journal to the end.
  Background second("mpirun -np 2 --oversubscribe " +
                        campaign_command(kRun + " --resume --wait-lock 120 --out " + out),
                    logs + "second.log");
  ASSERT_TRUE(wait_until([&] {
    return slurp(logs + "second.log").find("waiting up to 120 s") != std::string::npos;
  })) << slurp(logs + "second.log");
  ::kill(first.pid(), SIGTERM);
  ::kill(first.pid(), SIGCONT);
  const int first_exit = first.wait();
  EXPECT_TRUE(first_exit == 75 || first_exit == 0) << slurp(logs + "first.log");
  EXPECT_EQ(second.wait(), 0) << slurp(logs + "second.log");
  if (first_exit == 75) {  // stopped with its journal (the usual case): the second resumed it
    EXPECT_NE(slurp(logs + "second.log").find("(resuming)"), std::string::npos)
        << slurp(logs + "second.log");
  }
  EXPECT_EQ(listing(d), "run.h5\n");
  expect_same_numbers(ref.path, out);
}

TEST(CampaignLock, MpirunKilledAtRandomMomentsThenResumedAtOnceGivesTheUninterruptedFile) {
  // SIGKILL to mpirun alone: its ranks live on for a moment, rank 0 still holding the lock. A
  // --resume started at once must then stop with 75 (it used to run beside them, appending to
  // the same journal, and fail at the end with "sample N is missing"), and a retry once they
  // are gone completes the file (or finds it complete: the ranks may finish it before they
  // go); or the resume completes it directly. Five moments, spread over the run (one per fifth
  // of the reference's length, at a seeded random place in it); 480 samples, so that the ranks
  // the kill leaves often die before the end (a second or so after mpirun) and the retry has a
  // journal to resume.
  const int samples = 480;
  const std::string run = "--samples " + std::to_string(samples);
  const Reference& ref = reference(samples);
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> within(0.0, 1.0);
  const double span = ref.seconds;
  int met_in_use = 0;
  for (int trial = 0; trial < 5; ++trial) {
    const double delay = (trial + within(rng)) / 5.0 * span;
    const std::string name = "killed-" + std::to_string(trial);
    const std::string d = folder(name), out = d + "/run.h5", logs = campaign_dir() + "/" + name;
    Background mpirun(
        "mpirun -np 2 --oversubscribe " +
            campaign_command(run + " --out " + out + " --started-file " + logs + ".started"),
        logs + ".log");
    ASSERT_TRUE(wait_until([&] { return fs::exists(logs + ".started"); })) << slurp(logs + ".log");
    std::this_thread::sleep_for(std::chrono::duration<double>(delay));
    ::kill(mpirun.pid(), SIGKILL);  // mpirun alone: its ranks live on a moment
    mpirun.wait();
    std::vector<int> exits;
    while (exits.size() < 200) {  // the resume at once, then retries 0.1 s apart
      const std::string log = logs + "-resume.log";
      exits.push_back(exit_code(run_shell(campaign_command(run + " --resume --out " + out), log)));
      if (exits.back() != 75) break;
      const std::string text = slurp(log);  // one line naming the output in use
      EXPECT_EQ(text.rfind("campaign: stopped: another campaign is writing " + out, 0), 0u) << text;
      EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    std::string seen;
    for (int e : exits) seen += " " + std::to_string(e);
    const bool resumed = slurp(logs + "-resume.log").find("(resuming)") != std::string::npos;
    std::printf(
        "trial %d: mpirun killed %.2f s after the start (the run takes %.2f s); the resume "
        "exited%s (%s)\n",
        trial, delay, span, seen.c_str(), resumed ? "resumed the journal" : "complete");
    met_in_use += exits.front() == 75;
    EXPECT_EQ(exits.back(), 0) << "trial " << trial << ":" << seen << "\n"
                               << slurp(logs + "-resume.log");
    EXPECT_FALSE(fs::exists(out + ".journal")) << "trial " << trial;
    EXPECT_FALSE(fs::exists(out + ".lock")) << "trial " << trial;
    expect_same_numbers(ref.path, out);
  }
  EXPECT_GT(met_in_use, 0) << "no kill left ranks holding the lock: the case this test is for "
                              "did not happen";
}

TEST(CampaignLock, HelpListsTheOutputInUseAndWaitLock) {
  const std::string help = campaign_dir() + "/lock-help.txt";
  ASSERT_EQ(exit_code(run_shell(campaign_command("--help") + " >" + help, help + ".log")), 0);
  const std::string text = slurp(help);
  for (const char* part :
       {"75 also when another campaign is writing the same RUN.h5 (it holds RUN.h5.lock):\n"
        "nothing was changed; run again once it has ended, or wait for it with --wait-lock.\n",
        "  --wait-lock ARG               while another campaign writes the same --out"})
    EXPECT_NE(text.find(part), std::string::npos) << part << " in:\n" << text;
}

}  // namespace
