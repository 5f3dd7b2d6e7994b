// How a campaign stops (issues 14 and 24), without privileges: a stop signal that comes while
// the ranks start is honoured (the handlers exist before MPI start-up); a file size limit
// (RLIMIT_FSIZE, set in the child only) fails the journal's or the result file's writes with
// EFBIG, which stops the campaign as a full disk does, exit 75 with the system's reason and the
// resume command; a journal that cannot be opened for writing is an error (exit 2) that leaves
// it for a later resume. The resumed runs give the uninterrupted file. The same cases on a real
// full tmpfs, which needs a mount namespace, are in campaign_stop_tmpfs_test.cpp.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "../support/campaign_process.hpp"
#include "campaign/campaign_study.hpp"
#include "campaign/journal.hpp"
#include "io/options.hpp"

namespace {

namespace fs = std::filesystem;
using pound::test::campaign_command;
using pound::test::campaign_dir;
using pound::test::exit_code;
using pound::test::expect_no_result;
using pound::test::expect_same_numbers;
using pound::test::kSmokeStudy;
using pound::test::listing;
using pound::test::run_shell;
using pound::test::slurp;

// The smoke study's journal: a 40-byte header and 640 bytes a sample (journal_test.cpp checks
// the layout).
constexpr long kHeaderBytes = 40, kRecordBytes = 648;

// `pound campaign` under a file size limit of `bytes` (prlimit, in this child only). One rank
// needs neither PMIx's shared-memory store nor Open MPI's shared-memory transport, whose files
// of some megabytes the limit would refuse (MPI_Init would fail): the hash store and the self
// transport instead. stderr goes to a log, a few kB, well below the limits used here.
std::string limited(long bytes, const std::string& args) {
  return "env PMIX_MCA_gds=hash OMPI_MCA_btl=self prlimit --fsize=" + std::to_string(bytes) +
         " -- " + campaign_command(args);
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
  const std::string ref = campaign_dir() + "/start-ref.h5", cut = campaign_dir() + "/start.h5";
  const std::string started = campaign_dir() + "/start.started";
  const std::string log = campaign_dir() + "/start.log";
  const std::string n = "--samples 24";
  ASSERT_EQ(run_shell(campaign_command(n + " --out " + ref), log), 0);
  // SIGTERM as soon as the handler exists, before MPI start-up is over (before the campaign
  // says it has started). Repeated: each time the run stops at once, keeping the journal.
  int before_start = 0;
  for (int trial = 0; trial < 3; ++trial) {
    fs::remove(started);
    const pid_t pid = ::fork();
    if (pid == 0) {
      ::execl("/bin/sh", "sh", "-c",
              ("exec " +
               campaign_command(n + " --out " + cut + (trial ? " --resume" : "") +
                                " --started-file " + started) +
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
    EXPECT_EQ(WEXITSTATUS(status), 75) << "stopped, resumable (EX_TEMPFAIL)\n" << slurp(log);
    EXPECT_NE(slurp(log).find("campaign: interrupted after"), std::string::npos) << slurp(log);
    EXPECT_TRUE(fs::exists(cut + ".journal"));
    expect_no_result(cut);
  }
  EXPECT_GT(before_start, 0) << "every signal came after the campaign had started";
  ASSERT_EQ(run_shell(campaign_command(n + " --out " + cut + " --resume"), log), 0) << slurp(log);
  expect_same_numbers(ref, cut);
}

TEST(CampaignStop, AFileSizeLimitStopsTheJournalWithTheReasonAndTheResumeGivesTheWholeFile) {
  // 160 samples journal 104 kB; a limit of 40,960 bytes holds the header and 63 whole records.
  const std::string d = campaign_dir() + "/limit-journal", ref = campaign_dir() + "/limit-ref.h5";
  const std::string out = d + "/disk/run.h5";
  ASSERT_EQ(run_shell(campaign_command("--samples 160 --out " + ref), d + ".ref.log"), 0);
  fs::create_directories(d + "/disk");
  const int first = run_shell(limited(40960, "--samples 160 --out " + out), d + "/first.log");
  EXPECT_EQ(exit_code(first), 75) << "a stop, as on SIGTERM\n" << slurp(d + "/first.log");
  const long kept = (40960 - kHeaderBytes) / kRecordBytes;
  ASSERT_EQ(kept, 63);
  const std::string msg = slurp(d + "/first.log");
  for (const std::string& part : std::vector<std::string>{
           out + ".journal: cannot write the campaign journal (File too large); stopping",
           "campaign: stopped after 63 of 160 samples (0 failed): " + out +
               ".journal: cannot write the campaign journal (File too large). ",
           "The journal " + out +
               ".journal keeps them; free some space (or raise the file size "
               "limit) and resume with: mpirun -np 1 pound campaign --config " +
               kSmokeStudy,
           "--resume\n"})
    EXPECT_NE(msg.find(part), std::string::npos) << part << " in:\n" << msg;
  EXPECT_EQ(listing(d + "/disk"), "run.h5.journal\n");  // no result file, no temporary
  EXPECT_EQ(fs::file_size(out + ".journal"), 40960u);   // up to the limit, a torn last record
  const int second =
      run_shell(campaign_command("--samples 160 --out " + out + " --resume"), d + "/second.log");
  EXPECT_EQ(exit_code(second), 0) << slurp(d + "/second.log");
  EXPECT_NE(slurp(d + "/second.log").find("campaign: done: 160 samples, 0 failed"),
            std::string::npos)
      << slurp(d + "/second.log");
  expect_same_numbers(ref, out);
}

TEST(CampaignStop, AFileSizeLimitAtTheResultFileKeepsTheJournalAndTheResumeWritesIt) {
  // 24 samples journal 12,712 bytes; their HDF5 file needs more than a limit of 16,384.
  const std::string d = campaign_dir() + "/limit-result", ref = campaign_dir() + "/limit-end.h5";
  const std::string out = d + "/disk/run.h5";
  ASSERT_EQ(run_shell(campaign_command("--samples 24 --out " + ref), d + ".ref.log"), 0);
  ASSERT_GT(fs::file_size(ref), 16384u);
  fs::create_directories(d + "/disk");
  const int first = run_shell(limited(16384, "--samples 24 --out " + out), d + "/first.log");
  EXPECT_EQ(exit_code(first), 75) << slurp(d + "/first.log");
  const std::string msg = slurp(d + "/first.log");
  for (const std::string part :
       {"campaign: stopped after 24 of 24 samples (0 failed): ", "cannot write the HDF5 file",
        "(File too large)", "resume with:", "--resume\n"})
    EXPECT_NE(msg.find(part), std::string::npos) << part << " in:\n" << msg;
  EXPECT_EQ(listing(d + "/disk"), "run.h5.journal\n");  // the temporary file removed
  EXPECT_EQ(fs::file_size(out + ".journal"),
            static_cast<std::uintmax_t>(kHeaderBytes + 24 * kRecordBytes));
  const int second =
      run_shell(campaign_command("--samples 24 --out " + out + " --resume"), d + "/second.log");
  EXPECT_EQ(exit_code(second), 0) << slurp(d + "/second.log");
  expect_same_numbers(ref, out);
}

// A journal that cannot be written for another reason than space would fail again on every
// resume: the run must end with an error (exit 2, which the Slurm scripts pass on) instead of a
// stop that says "free some space" and exits 75 ("submit again"). Here the journal a file size
// limit left (a torn last record) is resumed while it cannot be opened for writing (mode 0444:
// EACCES). Root ignores permission bits (CAP_DAC_OVERRIDE): as root the resume runs with that
// capability and CAP_DAC_READ_SEARCH dropped (setpriv), and the script checks first that the
// journal really cannot be opened for writing. The journal stays as it was, and the resume
// once it can be written gives the uninterrupted file.
TEST(CampaignStop, AJournalThatCannotBeWrittenIsAnErrorAndStaysForALaterResume) {
  const std::string d = campaign_dir() + "/read-only", ref = campaign_dir() + "/ro-ref.h5";
  const std::string out = d + "/disk/run.h5", journal = out + ".journal";
  ASSERT_EQ(run_shell(campaign_command("--samples 160 --out " + ref), d + ".ref.log"), 0);
  fs::create_directories(d + "/disk");
  const int first = run_shell(limited(40960, "--samples 160 --out " + out), d + "/first.log");
  ASSERT_EQ(exit_code(first), 75) << slurp(d + "/first.log");
  fs::copy_file(journal, d + "/kept");
  fs::permissions(journal, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  std::ofstream(d + "/resume.sh") << "if (: >>" << journal << ") 2>/dev/null; then echo writable >"
                                  << d << "/probe; exit 0; fi\n"
                                  << "exec "
                                  << campaign_command("--samples 160 --out " + out + " --resume")
                                  << "\n";
  const std::string drop = ::geteuid() == 0
                               ? "setpriv --bounding-set=-dac_override,-dac_read_search "
                                 "--inh-caps=-dac_override,-dac_read_search "
                               : "";
  const int ro = run_shell(drop + "sh " + d + "/resume.sh", d + "/ro.log");
  if (!drop.empty() && slurp(d + "/ro.log").rfind("setpriv:", 0) == 0)
    GTEST_SKIP() << "as root the test needs setpriv to drop CAP_DAC_OVERRIDE for the resume: "
                 << slurp(d + "/ro.log");
  if (fs::exists(d + "/probe"))
    GTEST_SKIP() << "this user can open a file of mode 0444 for writing (CAP_DAC_OVERRIDE), so "
                    "the journal cannot be made unwritable without privileges; "
                    "campaign_stop_tmpfs_test.cpp has the read-only file system";
  EXPECT_EQ(exit_code(ro), 2) << slurp(d + "/ro.log");
  const std::string msg = slurp(d + "/ro.log");
  const std::string want = "pound campaign: error: " + journal +
                           ": cannot cut the torn tail of the journal (Permission denied); the "
                           "journal keeps 63 of 160 samples: run again with --resume once " +
                           journal + " can be written\n";
  EXPECT_NE(msg.find(want), std::string::npos) << want << " in:\n" << msg;
  EXPECT_EQ(msg.find("free some space"), std::string::npos) << msg;
  EXPECT_EQ(msg.find("campaign: stopped after"), std::string::npos) << msg;
  EXPECT_EQ(listing(d + "/disk"), "run.h5.journal\n");
  EXPECT_EQ(slurp(d + "/kept"), slurp(journal));  // the journal as the file size limit left it
  fs::permissions(journal, fs::perms::owner_write, fs::perm_options::add);
  const int second =
      run_shell(campaign_command("--samples 160 --out " + out + " --resume"), d + "/second.log");
  EXPECT_EQ(exit_code(second), 0) << slurp(d + "/second.log");
  expect_same_numbers(ref, out);
}

TEST(CampaignStop, AStopAfterFailedSamplesIsAStopAndTheFinishedRunExitsFour) {
  // A fixed Sears step of 10 ms fails every Sears sample of the default study (half of them,
  // CampaignRun.FailedSamplesAreListedUpToTwentyAndExitFour). A file size limit that holds 20
  // records stops the run: 75, not 4, since the run is not finished; the resume finishes it
  // with the failures: 4.
  const std::string study = std::string(POUND_SOURCE_DIR) + "/studies/fragility-default.ini";
  pound::Options opt("campaign", "", pound::campaign_option_specs());
  opt.parse({"--config", study, "--sears.dt", "1e-2"});
  const std::size_t record =
      pound::RecordLayout(pound::campaign_from_options(opt, 60, -1)).record_bytes();
  const std::string d = campaign_dir() + "/failed-then-stop", out = d + "/run.h5";
  fs::create_directories(d);
  const std::string cmd = std::string(POUND_BINARY) + " campaign --config " + study +
                          " --samples 60 --sears.dt 1e-2 --quiet --out " + out;
  const long limit = kHeaderBytes + 20 * static_cast<long>(record) + static_cast<long>(record) / 2;
  const int first =
      run_shell("env PMIX_MCA_gds=hash OMPI_MCA_btl=self prlimit --fsize=" + std::to_string(limit) +
                    " -- " + cmd,
                d + "/first.log");
  EXPECT_EQ(exit_code(first), 75) << slurp(d + "/first.log");
  const std::string msg = slurp(d + "/first.log");
  const auto at = msg.find("campaign: stopped after 20 of 60 samples (");
  ASSERT_NE(at, std::string::npos) << msg;
  EXPECT_GT(std::stoi(msg.substr(msg.find('(', at) + 1)), 0) << "no sample had failed:\n" << msg;
  const int second = run_shell(cmd + " --resume", d + "/second.log");
  EXPECT_EQ(exit_code(second), 4) << slurp(d + "/second.log");
  EXPECT_NE(slurp(d + "/second.log").find("campaign: done: 60 samples, 30 failed"),
            std::string::npos)
      << slurp(d + "/second.log");
}

}  // namespace
