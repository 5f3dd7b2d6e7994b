// The automatic batch of a campaign (issue 13, docs/scaling.md): one sample per message on few
// ranks, where the master's cost per message is far below a sample's; on many ranks enough
// outcomes per message that the master's cost per sample falls below a lumped sample's cost
// divided by the number of workers. Failed writes of the journal in the middle of a run: one
// for want of space is a stop to resume, any other an error; neither stops a later run of
// the same process.
#include "campaign/mpi_campaign.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "../support/scratch_dir.hpp"
#include "campaign/building_arrays.hpp"
#include "campaign/floor_arrays.hpp"
#include "campaign/journal.hpp"
#include "core/error.hpp"
#include "io/options.hpp"

namespace pound {
namespace {

namespace fs = std::filesystem;

TEST(CampaignBatch, AutomaticGrowsWithTheRanksAndAGivenBatchIsKept) {
  EXPECT_EQ(campaign_batch(0, 1), 1);
  EXPECT_EQ(campaign_batch(0, 2), 1);
  EXPECT_EQ(campaign_batch(0, 64), 1);
  EXPECT_EQ(campaign_batch(0, 65), 2);
  EXPECT_EQ(campaign_batch(0, 1000), 16);
  EXPECT_EQ(campaign_batch(0, 1024), 16);
  EXPECT_EQ(campaign_batch(0, 100000), 32);  // at most 32: a worker holds 4 x 32 samples
  EXPECT_EQ(campaign_batch(5, 2), 5);
  EXPECT_EQ(campaign_batch(1, 4096), 1);
}

// Runs `body` in a child process that starts MPI (a singleton, one rank: MPI_Init may run once
// per process) and returns what `body` reported as failed, one line each ("" when nothing
// failed), or how the child ended when it did not end normally.
std::string in_mpi_child(const std::function<void(std::vector<std::string>&)>& body) {
  int fds[2];
  if (::pipe(fds) != 0) return "pipe failed";
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(fds[0]);
    ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
    ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
    MPI_Init(nullptr, nullptr);
    std::vector<std::string> failures;
    try {
      body(failures);
    } catch (const std::exception& e) {
      failures.push_back(std::string("unexpected exception: ") + e.what());
    }
    MPI_Finalize();
    std::string text;
    for (const auto& f : failures) text += f + "\n";
    for (std::size_t at = 0; at < text.size();) {
      const ssize_t n = ::write(fds[1], text.data() + at, text.size() - at);
      if (n <= 0) break;
      at += static_cast<std::size_t>(n);
    }
    ::_exit(0);
  }
  ::close(fds[1]);
  std::string text;
  char buf[4096];
  for (ssize_t n; (n = ::read(fds[0], buf, sizeof buf)) > 0;) text.append(buf, std::size_t(n));
  ::close(fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    text += "the child ended with wait status " + std::to_string(status) + "\n";
  return text;
}

CampaignStudy smoke_study(long samples) {
  Options opt("campaign", "", campaign_option_specs());
  opt.parse({"--config", std::string(POUND_SOURCE_DIR) + "/studies/campaign-smoke.ini"});
  return campaign_from_options(opt, samples, -1);
}

// An outcome of the study's record size at once (the campaign's bookkeeping, not physics).
SampleOutcome canned(const CampaignStudy& st, long id) {
  SampleOutcome o;
  o.id = id;
  o.im = 0.1;
  o.scale = 1.0;
  o.values.assign(st.parameters.size(), 0.5);
  const std::size_t bf = st.buildings() * st.max_floors(), pl = st.pairs() * st.max_levels();
  for (const auto& a : floor_array_fields()) (o.*a.member).assign(bf, 0.01 * double(id));
  for (const auto& a : building_array_fields()) (o.*a.member).assign(st.buildings(), 0.0);
  o.peak_force.assign(pl, 1.0);
  o.impacts.assign(pl, 1.0);
  o.approach_free.assign(pl, 0.0);
  o.peak_column_shear.assign(pl, 0.0);
  o.crush.assign(pl, 0.0);
  o.ground_relative.assign(st.pairs(), 0.0);
  return o;
}

// Points this process's descriptor of `path` at `replacement` opened with `flags`: the next
// write through it fails as writes to `replacement` do (/dev/full: ENOSPC; /dev/null opened
// for reading: EBADF), while the file keeps what was written to it. False when no descriptor
// of `path` is open.
bool redirect_descriptor(const std::string& path, const char* replacement, int flags) {
  const fs::path want = fs::canonical(path);
  for (const auto& e : fs::directory_iterator("/proc/self/fd")) {
    std::error_code ec;
    if (fs::read_symlink(e.path(), ec) != want || ec) continue;
    const int fd = std::stoi(e.path().filename().string());
    const int other = ::open(replacement, flags);
    const bool ok = other >= 0 && ::dup2(other, fd) == fd;
    if (other >= 0) ::close(other);
    return ok;
  }
  return false;
}

// Runs the campaign of `st` into `out` (resuming when asked) with outcomes at once; the
// journal's descriptor is redirected to `replacement` as sample `fail_at` is simulated
// (-1: never).
CampaignSummary run(const CampaignStudy& st, const std::string& out, bool resume, long fail_at,
                    const char* replacement, int flags, std::vector<std::string>& failures) {
  CampaignRunOptions ro;
  ro.out = out;
  ro.resume = resume;
  ro.progress = false;
  ro.simulate = [&](long id) {
    if (id == fail_at && !redirect_descriptor(out + ".journal", replacement, flags))
      failures.push_back("no open descriptor of " + out + ".journal");
    return canned(st, id);
  };
  return run_campaign(st, ro, MPI_COMM_WORLD);
}

#define CHECK(cond)                                                                                \
  do {                                                                                             \
    if (!(cond)) failures.push_back(std::string("line ") + std::to_string(__LINE__) + ": " #cond); \
  } while (0)

// A journal that can no longer be written for want of space (here /dev/full) stops the run as
// SIGTERM does; the next run in the same process (it resumes) is not stopped by it: the stop of
// a write failure belongs to its run (it set the signals' flag, which nothing cleared).
TEST(CampaignWriteFailure, ASpaceStopDoesNotStopTheNextRunOfTheProcess) {
  const std::string out = test::process_scratch_dir() / "space.h5";
  const std::string failed = in_mpi_child([&](std::vector<std::string>& failures) {
    const CampaignStudy st = smoke_study(12);
    const CampaignSummary a = run(st, out, false, 5, "/dev/full", O_WRONLY, failures);
    CHECK(a.interrupted);
    CHECK(a.done == 5);
    CHECK(a.stop_reason == out +
                               ".journal: cannot write the campaign journal (No space left on "
                               "device)");
    CHECK(read_journal(out + ".journal", st).size() == 5u);
    CHECK(!stop_requested());  // no signal came
    const CampaignSummary b = run(st, out, true, -1, nullptr, 0, failures);
    CHECK(!b.interrupted);
    CHECK(b.stop_reason.empty());
    CHECK(b.done == 12);
    CHECK(fs::exists(out) && !fs::exists(out + ".journal"));
    // A third, new run (not resumed) of the same process runs to its end too.
    fs::remove(out);
    const CampaignSummary c = run(st, out, false, -1, nullptr, 0, failures);
    CHECK(!c.interrupted && c.done == 12 && fs::exists(out));
  });
  EXPECT_EQ(failed, "");
}

// Any other failed write of the journal (here EBADF) would fail again on resume: an error
// naming the journal, the system's reason and the samples the journal keeps, which stays for
// a resume once it can be written.
TEST(CampaignWriteFailure, AnotherWriteFailureIsAnErrorAndKeepsTheJournal) {
  const std::string out = test::process_scratch_dir() / "badf.h5";
  const std::string failed = in_mpi_child([&](std::vector<std::string>& failures) {
    const CampaignStudy st = smoke_study(12);
    std::string message;
    try {
      run(st, out, false, 4, "/dev/null", O_RDONLY, failures);
      failures.push_back("a failed write of the journal (EBADF) did not throw");
    } catch (const InputError& e) {
      message = e.what();
    }
    CHECK(message == out +
                         ".journal: cannot write the campaign journal (Bad file descriptor); "
                         "the journal keeps 4 of 12 samples: run again with --resume once " +
                         out + ".journal can be written");
    if (!message.empty()) CHECK(message.find('\n') == std::string::npos);
    CHECK(read_journal(out + ".journal", st).size() == 4u);
    CHECK(!fs::exists(out));
    const CampaignSummary b = run(st, out, true, -1, nullptr, 0, failures);
    CHECK(!b.interrupted && b.done == 12 && fs::exists(out));
  });
  EXPECT_EQ(failed, "");
}

// A journal that cannot be created: a directory in its place (EISDIR, which a run as root
// meets too) is an error, not a stop.
TEST(CampaignWriteFailure, AJournalThatCannotBeCreatedIsAnError) {
  const std::string out = test::process_scratch_dir() / "dir.h5";
  fs::create_directories(out + ".journal");
  const std::string failed = in_mpi_child([&](std::vector<std::string>& failures) {
    const CampaignStudy st = smoke_study(6);
    std::string message;
    try {
      run(st, out, false, -1, nullptr, 0, failures);
      failures.push_back("a journal that is a directory did not throw");
    } catch (const InputError& e) {
      message = e.what();
    }
    CHECK(message == out + ".journal: cannot write the campaign journal (Is a directory)");
  });
  EXPECT_EQ(failed, "");
  fs::remove(out + ".journal");
}

}  // namespace
}  // namespace pound
