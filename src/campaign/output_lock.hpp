#pragma once
// One writer per campaign output (issue 31). Rank 0 of `pound campaign` holds an exclusive lock
// for its whole run, taken before anything about the output is looked at or changed (before
// --force deletes, before the interrupted-run check, before --resume reads the journal). A
// second campaign on the same output finds it held and stops at once with exit status 75 (or
// waits for it, --wait-lock), naming the holder: its pid and host, which the holder writes into
// the lock file. The kernel releases the lock when its process ends, SIGKILL included: a killed
// run leaves at most the file, unlocked, which the next run takes.
//
// The lock file is RUN.h5.lock, beside the result file, and not the journal or RUN.h5 itself:
// those come and go during a run (--force deletes them, the journal is created, the result
// file appears by a rename from its temporary, and the journal is removed at the end), and a
// lock on a file that is deleted or replaced no longer excludes anyone: the next campaign would
// create a new file and lock that. The lock file stays while its lock is held; the holder
// removes it only at the very end, still holding the lock (unlink, then close). A campaign that
// had opened the old file before the removal and then gets its lock finds that the path no
// longer names the file it locked (another inode, or none), and starts again from open: the
// lock that counts is always the one on the file the path names. So the folder holds no lock
// file once a run has ended, and the results, journal and --force keep their meaning.
//
// flock(2) (the lock belongs to the open file, is released when the file is closed or the
// process dies, and is not lost when the same process closes another descriptor of the file,
// as fcntl(2) record locks are); on NFS, Linux maps it to a lock of the whole file that every
// client sees. A file system without locks (ENOLCK, ENOSYS, EOPNOTSUPP: NFS mounted with
// `nolock`, Lustre without `-o flock`) cannot keep two writers apart: the run goes on unlocked
// after a warning. A folder in which the lock file can be neither created nor opened (it does
// not exist, no permission, a read-only file system) is one where no campaign can create its
// journal or result file either: the run goes on unlocked, and its own checks and writes report
// the folder's problem as they did before the lock existed.
//
// The lock file holds two lines, "pid=PID" and "host=HOST" (gethostname), written when the lock
// is taken (best effort: a full disk leaves it empty, the holder then "unknown").
#include <functional>
#include <string>

namespace pound {

/// Who holds an output's lock, as its lock file says.
struct LockHolder {
  long pid = 0;      ///< process id of the holder (on `host`); 0 when unknown
  std::string host;  ///< host name of the holder; "" when unknown
  /// "pid 4242 on host node7", "pid 4242", or "pid and host unknown".
  std::string text() const;
};

class OutputLock {
 public:
  /// How acquire() ended.
  enum class Outcome {
    taken,        ///< the lock is held until release() or destruction
    busy,         ///< another open file holds it (past the wait): holder() says who
    unsupported,  ///< the file system has no locks: reason() says why; nothing is held
    unusable,     ///< the lock file cannot be created or opened: reason(); nothing is held
  };

  /// The lock file of the output `out`: out + ".lock".
  static std::string path_of(const std::string& out);

  OutputLock() = default;
  ~OutputLock();  ///< release()
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

  /// Takes the lock of output `out`. While another holds it, tries again every kPollSeconds
  /// for up to `wait_seconds` [s] (0: one try). `keep_waiting`, when given, is asked before
  /// each pause, with the holder: false ends the wait at once (Outcome::busy; a stop signal).
  Outcome acquire(const std::string& out, double wait_seconds = 0.0,
                  const std::function<bool(const LockHolder&)>& keep_waiting = {});
  /// Removes the lock file, then releases the lock (nothing when none is held).
  void release();

  bool held() const { return fd_ >= 0; }
  const std::string& path() const { return path_; }
  /// After Outcome::busy: the holder, as its lock file says.
  const LockHolder& holder() const { return holder_; }
  /// After Outcome::unsupported or unusable: the system's reason ("No locks available").
  const std::string& reason() const { return reason_; }

  /// Interval between two tries while waiting [s].
  static constexpr double kPollSeconds = 0.1;

 private:
  enum class Try { taken, busy, replaced, unsupported, unusable };
  Try try_once();

  std::string path_;
  int fd_ = -1;
  LockHolder holder_;
  std::string reason_;
};

/// The line of a campaign that stops because another campaign writes `out` (`lock` after
/// Outcome::busy, having waited `waited_seconds` [s]): who holds it, that nothing was changed
/// and what to do.
std::string busy_output_message(const std::string& out, const OutputLock& lock,
                                double waited_seconds);

}  // namespace pound
