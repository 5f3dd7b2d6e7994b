// How a campaign stops on a real full disk and a read-only file system (issue 14): a tmpfs of
// 44 or 32 KiB mounted in a mount namespace of the test's own (unshare --user --map-root-user
// --mount: nothing is mounted on the host). These need user and mount namespaces, which
// containers, chroots and many machines do not grant: each test then skips with the reason
// (campaign_stop_test.cpp reaches the same code paths without privileges, through a file size
// limit and a journal that cannot be opened for writing), and a CI that grants them runs these.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../support/campaign_process.hpp"

namespace {

namespace fs = std::filesystem;
using pound::test::campaign_command;
using pound::test::campaign_dir;
using pound::test::exit_code;
using pound::test::expect_same_numbers;
using pound::test::kSmokeStudy;
using pound::test::run_shell;
using pound::test::slurp;

// Remounts with only the options given: mount(8) otherwise adds those /proc/self/mountinfo
// shows, among them the tmpfs's uid=, which for an ordinary user is the uid outside the
// namespace, unmapped inside it, and the kernel refuses the remount (EINVAL, "mount point not
// mounted or bad option").
const std::string kRemount = "mount --options-source=disable -o remount,";

// Runs the shell script `body` after "set -u" in a mount namespace of its own (DIR/script.sh).
// Returns the wait status; DIR/unshare.log holds the script's stderr. The campaigns in it run as
// uid 0 of the namespace, whose Open MPI session folder /tmp/ompi.HOST.0 may belong to the real
// root (who then sees it unmapped): TMPDIR puts theirs in DIR.
int run_in_a_mount_namespace(const std::string& d, const std::string& body) {
  std::ofstream(d + "/script.sh") << "set -u\nexport TMPDIR=" << d << "\n" << body;
  return run_shell("unshare --user --map-root-user --mount sh " + d + "/script.sh",
                   d + "/unshare.log");
}

// "" when this process may mount a tmpfs in a mount namespace of its own and remount it larger,
// read-only and writable again (what the tests below do); otherwise why not.
const std::string& why_no_tmpfs() {
  static const std::string why = [] {
    const std::string d = campaign_dir() + "/tmpfs-probe";
    fs::create_directories(d + "/disk");
    const std::string disk = d + "/disk";
    const int status = run_in_a_mount_namespace(
        d, "mount -t tmpfs -o size=40k tmpfs " + disk + " && echo x >" + disk + "/f && " +
               kRemount + "size=64m " + disk + " && " + kRemount + "ro " + disk + " && " +
               kRemount + "rw " + disk + " && echo mounted >" + d + "/ok\n");
    if (exit_code(status) == 0 && slurp(d + "/ok") == "mounted\n") return std::string();
    return "cannot mount and remount a tmpfs in a mount namespace of this test's own here "
           "(unshare --user --map-root-user --mount, exit status " +
           std::to_string(exit_code(status)) + "): " + slurp(d + "/unshare.log");
  }();
  return why;
}

#define SKIP_WITHOUT_A_MOUNT_NAMESPACE() \
  if (!why_no_tmpfs().empty()) GTEST_SKIP() << why_no_tmpfs()

// Runs a campaign of `samples` samples into a tmpfs of `kib` KiB mounted on DIR/disk, so that
// the disk really fills up (ENOSPC); then "frees space" (remounts it at 64 MiB) and resumes.
// Leaves DIR/first.log and DIR/first.status (the stopped run), DIR/left.txt (the files on the
// full disk), DIR/second.log and DIR/second.status (the resume) and DIR/run.h5 (the file the
// resume wrote).
void run_on_a_full_disk(const std::string& d, int kib, int samples) {
  fs::create_directories(d + "/disk");
  const std::string cmd =
      campaign_command("--samples " + std::to_string(samples) + " --out " + d + "/disk/run.h5");
  const int status = run_in_a_mount_namespace(
      d, "mount -t tmpfs -o size=" + std::to_string(kib) + "k tmpfs " + d + "/disk || exit 90\n" +
             cmd + " 2>" + d + "/first.log; echo $? >" + d + "/first.status\n" + "ls " + d +
             "/disk >" + d + "/left.txt\n" + kRemount + "size=64m " + d + "/disk || exit 91\n" +
             cmd + " --resume 2>" + d + "/second.log; echo $? >" + d + "/second.status\n" + "cp " +
             d + "/disk/run.h5 " + d + "/run.h5\n");
  ASSERT_EQ(exit_code(status), 0) << "the script in the mount namespace: "
                                  << slurp(d + "/unshare.log");
}

TEST(CampaignStopOnATmpfs, AFullDiskStopsTheJournalWithTheReasonAndTheResumeGivesTheWholeFile) {
  SKIP_WITHOUT_A_MOUNT_NAMESPACE();
  // 160 samples journal 104 kB (648 bytes a record); a 44 KiB disk leaves the journal 40 KiB
  // (the lock file run.h5.lock takes a page of 4 KiB for its pid and host): 63 of them.
  const std::string d = campaign_dir() + "/tmpfs-journal",
                    ref = campaign_dir() + "/tmpfs-journal-ref.h5";
  ASSERT_EQ(run_shell(campaign_command("--samples 160 --out " + ref), d + ".ref.log"), 0);
  run_on_a_full_disk(d, 44, 160);
  if (HasFatalFailure()) return;
  EXPECT_EQ(slurp(d + "/first.status"), "75\n") << slurp(d + "/first.log");  // as SIGTERM
  const std::string msg = slurp(d + "/first.log");
  for (const std::string& part : std::vector<std::string>{
           d + "/disk/run.h5.journal: cannot write the campaign journal (No space left on device)",
           "campaign: stopped after 63 of 160 samples (0 failed)",
           "The journal " + d + "/disk/run.h5.journal keeps them",
           "resume with: mpirun -np 1 pound campaign --config " + kSmokeStudy, "--resume\n"})
    EXPECT_NE(msg.find(part), std::string::npos) << part << " in:\n" << msg;
  EXPECT_EQ(slurp(d + "/left.txt"), "run.h5.journal\n");  // no result file, no temporary
  EXPECT_EQ(slurp(d + "/second.status"), "0\n") << slurp(d + "/second.log");
  expect_same_numbers(ref, d + "/run.h5");
}

TEST(CampaignStopOnATmpfs, AFullDiskAtTheResultFileKeepsTheJournalAndTheResumeWritesIt) {
  SKIP_WITHOUT_A_MOUNT_NAMESPACE();
  // 24 samples journal 14.2 kB; their HDF5 file needs more than the 12 KiB left of 32 KiB (the
  // journal takes 16 KiB, the lock file 4).
  const std::string d = campaign_dir() + "/tmpfs-result",
                    ref = campaign_dir() + "/tmpfs-result-ref.h5";
  ASSERT_EQ(run_shell(campaign_command("--samples 24 --out " + ref), d + ".ref.log"), 0);
  ASSERT_GT(fs::file_size(ref), 16384u);
  run_on_a_full_disk(d, 32, 24);
  if (HasFatalFailure()) return;
  EXPECT_EQ(slurp(d + "/first.status"), "75\n") << slurp(d + "/first.log");
  const std::string msg = slurp(d + "/first.log");
  for (const std::string part :
       {"campaign: stopped after 24 of 24 samples (0 failed): ", "cannot write the HDF5 file",
        "(No space left on device)", "resume with:", "--resume\n"})
    EXPECT_NE(msg.find(part), std::string::npos) << part << " in:\n" << msg;
  EXPECT_EQ(slurp(d + "/left.txt"), "run.h5.journal\n");
  EXPECT_EQ(slurp(d + "/second.status"), "0\n") << slurp(d + "/second.log");
  expect_same_numbers(ref, d + "/run.h5");
}

// A journal left by a full disk is resumed on the same tmpfs remounted read-only (EROFS, which
// a run as root meets too): an error (exit 2), not a stop; the journal stays whole, and the
// resume once the file system is writable again gives the uninterrupted file.
TEST(CampaignStopOnATmpfs, AReadOnlyJournalIsAnErrorAndStaysForALaterResume) {
  SKIP_WITHOUT_A_MOUNT_NAMESPACE();
  const std::string d = campaign_dir() + "/tmpfs-read-only",
                    ref = campaign_dir() + "/tmpfs-ro-ref.h5";
  ASSERT_EQ(run_shell(campaign_command("--samples 160 --out " + ref), d + ".ref.log"), 0);
  fs::create_directories(d + "/disk");
  const std::string cmd = campaign_command("--samples 160 --out " + d + "/disk/run.h5");
  const int status = run_in_a_mount_namespace(
      d, "mount -t tmpfs -o size=44k tmpfs " + d + "/disk || exit 90\n" + cmd + " 2>" + d +
             "/first.log; echo $? >" + d + "/first.status\n" + "cp " + d + "/disk/run.h5.journal " +
             d + "/kept\n" + kRemount + "ro,size=64m " + d + "/disk || exit 91\n" + cmd +
             " --resume 2>" + d + "/ro.log; echo $? >" + d + "/ro.status\n" + "ls " + d +
             "/disk >" + d + "/left.txt\n" + "cmp -s " + d + "/kept " + d +
             "/disk/run.h5.journal; echo $? >" + d + "/same.status\n" + kRemount + "rw " + d +
             "/disk || exit 92\n" + cmd + " --resume 2>" + d + "/second.log; echo $? >" + d +
             "/second.status\n" + "cp " + d + "/disk/run.h5 " + d + "/run.h5\n");
  ASSERT_EQ(exit_code(status), 0) << "the script in the mount namespace: "
                                  << slurp(d + "/unshare.log");
  ASSERT_EQ(slurp(d + "/first.status"), "75\n") << slurp(d + "/first.log");  // the full disk
  EXPECT_EQ(slurp(d + "/ro.status"), "2\n") << slurp(d + "/ro.log");
  const std::string msg = slurp(d + "/ro.log");
  const std::string want = "pound campaign: error: " + d +
                           "/disk/run.h5.journal: cannot cut the torn tail of the journal "
                           "(Read-only file system); the journal keeps 63 of 160 samples: run "
                           "again with --resume once " +
                           d + "/disk/run.h5.journal can be written\n";
  EXPECT_NE(msg.find(want), std::string::npos) << want << " in:\n" << msg;
  EXPECT_EQ(msg.find("free some space"), std::string::npos) << msg;
  EXPECT_EQ(msg.find("campaign: stopped after"), std::string::npos) << msg;
  EXPECT_EQ(slurp(d + "/left.txt"), "run.h5.journal\n");
  EXPECT_EQ(slurp(d + "/same.status"), "0\n");  // the journal as the full disk left it
  EXPECT_EQ(slurp(d + "/second.status"), "0\n") << slurp(d + "/second.log");
  expect_same_numbers(ref, d + "/run.h5");
}

}  // namespace
