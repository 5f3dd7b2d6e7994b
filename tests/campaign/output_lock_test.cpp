// The output lock of a campaign (issue 31), in one process: flock(2) keeps two open files of the
// same lock file apart as it keeps two processes apart, so two OutputLock objects stand for two
// campaigns. A held lock is busy for the other and names its holder; releasing removes the
// file and frees the lock; a wait takes it once it is free, or ends busy after its time; a
// stale file (a killed holder's) is taken; and many lockers taking and releasing the same
// output by turns never hold it at the same time, the removal of the file at each release
// included.
#include "campaign/output_lock.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "../support/scratch_dir.hpp"

namespace pound {
namespace {

namespace fs = std::filesystem;
using Outcome = OutputLock::Outcome;

std::string scratch(const std::string& name) {
  return test::process_scratch_subdir("output_lock") + "/" + name;
}

std::string this_host() {
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  return host;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

TEST(OutputLock, AHeldLockIsBusyForAnotherAndNamesItsHolder) {
  const std::string out = scratch("held.h5");
  OutputLock first, second;
  ASSERT_EQ(first.acquire(out), Outcome::taken);
  EXPECT_TRUE(first.held());
  EXPECT_EQ(first.path(), out + ".lock");
  const std::string text = "pid=" + std::to_string(::getpid()) + "\nhost=" + this_host() + "\n";
  std::ifstream in(out + ".lock");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), text);
  EXPECT_EQ(second.acquire(out), Outcome::busy);
  EXPECT_FALSE(second.held());
  EXPECT_EQ(second.holder().pid, ::getpid());
  EXPECT_EQ(second.holder().host, this_host());
  EXPECT_EQ(second.holder().text(),
            "pid " + std::to_string(::getpid()) + " on host " + this_host());
  const std::string line = busy_output_message(out, second, 0.0);
  EXPECT_EQ(line, "campaign: stopped: another campaign is writing " + out + " (pid " +
                      std::to_string(::getpid()) + " on host " + this_host() + "; its lock " + out +
                      ".lock); nothing was changed: run again once it has ended, or wait " +
                      "for it with --wait-lock SECONDS");
  EXPECT_EQ(busy_output_message(out, second, 2.5)
                .find("is still writing " + out + " after waiting 2.5 s (pid"),
            std::string("campaign: stopped: another campaign ").size());
  // The busy attempt changed nothing.
  std::ifstream again(out + ".lock");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(again), {}), text);
  EXPECT_TRUE(first.held());
}

TEST(OutputLock, ReleaseRemovesTheLockFileAndFreesTheLock) {
  const std::string out = scratch("release.h5");
  OutputLock first, second;
  ASSERT_EQ(first.acquire(out), Outcome::taken);
  first.release();
  EXPECT_FALSE(first.held());
  EXPECT_FALSE(fs::exists(out + ".lock"));
  EXPECT_EQ(second.acquire(out), Outcome::taken);
  {
    OutputLock scoped;
    EXPECT_EQ(scoped.acquire(out), Outcome::busy);
  }
  second.release();
  {
    OutputLock scoped;
    EXPECT_EQ(scoped.acquire(out), Outcome::taken);
  }  // released by the destructor
  EXPECT_FALSE(fs::exists(out + ".lock"));
}

TEST(OutputLock, AStaleLockFileOfAKilledHolderIsTaken) {
  // SIGKILL leaves the file with its holder's text, unlocked (the kernel released the lock).
  const std::string out = scratch("stale.h5");
  std::ofstream(out + ".lock") << "pid=999999999\nhost=elsewhere-and-longer-than-this-one\n";
  OutputLock lock;
  ASSERT_EQ(lock.acquire(out), Outcome::taken);
  std::ifstream in(out + ".lock");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}),
            "pid=" + std::to_string(::getpid()) + "\nhost=" + this_host() + "\n");
}

TEST(OutputLock, AWaitTakesTheLockOnceItIsReleased) {
  const std::string out = scratch("wait.h5");
  OutputLock first, second;
  ASSERT_EQ(first.acquire(out), Outcome::taken);
  std::thread releaser([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(400));
    first.release();
  });
  int asked = 0;
  const auto t0 = std::chrono::steady_clock::now();
  const Outcome got = second.acquire(out, 30.0, [&](const LockHolder& h) {
    EXPECT_EQ(h.pid, ::getpid());
    ++asked;
    return true;
  });
  const double waited = seconds_since(t0);
  releaser.join();
  EXPECT_EQ(got, Outcome::taken);
  EXPECT_GE(waited, 0.35);
  EXPECT_LT(waited, 10.0);
  EXPECT_GE(asked, 2);  // asked before each pause
}

TEST(OutputLock, AWaitTooShortEndsBusyAfterItsTime) {
  const std::string out = scratch("short.h5");
  OutputLock first, second;
  ASSERT_EQ(first.acquire(out), Outcome::taken);
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_EQ(second.acquire(out, 0.5), Outcome::busy);
  const double waited = seconds_since(t0);
  EXPECT_GE(waited, 0.5);
  EXPECT_LT(waited, 5.0);
  EXPECT_EQ(second.holder().pid, ::getpid());
  // keep_waiting saying no (a stop signal) ends a long wait at once.
  const auto t1 = std::chrono::steady_clock::now();
  EXPECT_EQ(second.acquire(out, 60.0, [](const LockHolder&) { return false; }), Outcome::busy);
  EXPECT_LT(seconds_since(t1), 5.0);
}

TEST(OutputLock, AFolderThatDoesNotExistIsUnusableAndCreatesNothing) {
  const std::string out = scratch("no-such-folder/run.h5");
  OutputLock lock;
  EXPECT_EQ(lock.acquire(out), Outcome::unusable);
  EXPECT_FALSE(lock.held());
  EXPECT_EQ(lock.reason(), "No such file or directory");
  EXPECT_FALSE(fs::exists(scratch("no-such-folder")));
}

TEST(OutputLock, LockersByTurnsNeverHoldTheOutputTogether) {
  // Each locker takes the lock (waiting for it), checks that no other holds it, and releases
  // it, removing the file while it holds it: a locker that opened the file before its removal
  // must not count a lock on it (the path then names another file, or none).
  const std::string out = scratch("turns.h5");
  std::atomic<int> inside{0}, overlaps{0}, taken{0};
  auto locker = [&] {
    for (int i = 0; i < 25; ++i) {
      OutputLock lock;
      if (lock.acquire(out, 60.0) != Outcome::taken) continue;
      ++taken;
      if (inside.fetch_add(1) != 0) ++overlaps;
      std::this_thread::sleep_for(std::chrono::microseconds(300));
      inside.fetch_sub(1);
    }
  };
  std::vector<std::thread> lockers;
  for (int t = 0; t < 4; ++t) lockers.emplace_back(locker);
  for (auto& t : lockers) t.join();
  EXPECT_EQ(taken.load(), 100);
  EXPECT_EQ(overlaps.load(), 0);
  EXPECT_FALSE(fs::exists(out + ".lock"));
}

}  // namespace
}  // namespace pound
