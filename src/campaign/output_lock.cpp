#include "campaign/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>

namespace pound {
namespace {

// The holder as the lock file `fd` says ("pid=PID\nhost=HOST\n"). The holder writes it just
// after taking the lock: a file still empty is read again a few times.
LockHolder read_holder(int fd) {
  LockHolder h;
  for (int attempt = 0; attempt < 3; ++attempt) {
    char buf[512];
    const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
    if (n > 0) {
      buf[n] = '\0';
      const std::string text(buf);
      std::size_t p = 0;
      while (p < text.size()) {
        const std::size_t e = std::min(text.find('\n', p), text.size());
        const std::string line = text.substr(p, e - p);
        if (line.rfind("pid=", 0) == 0) h.pid = std::strtol(line.c_str() + 4, nullptr, 10);
        if (line.rfind("host=", 0) == 0) h.host = line.substr(5);
        p = e + 1;
      }
      return h;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return h;
}

// Writes this process's pid and host into the lock file it holds. Best effort: the lock is what
// keeps writers apart, the text only tells a second campaign who holds it (a full disk leaves
// the file empty).
void write_holder(int fd) {
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  const std::string text =
      "pid=" + std::to_string(static_cast<long>(::getpid())) + "\nhost=" + host + "\n";
  if (::pwrite(fd, text.data(), text.size(), 0) == static_cast<ssize_t>(text.size()))
    (void)::ftruncate(fd, static_cast<off_t>(text.size()));  // a stale longer text cut
}

bool same_file(int fd, const std::string& path) {
  struct stat a, b;
  return ::fstat(fd, &a) == 0 && ::stat(path.c_str(), &b) == 0 && a.st_dev == b.st_dev &&
         a.st_ino == b.st_ino;
}

}  // namespace

std::string LockHolder::text() const {
  if (pid <= 0 && host.empty()) return "pid and host unknown";
  std::string s = pid > 0 ? "pid " + std::to_string(pid) : "pid unknown";
  if (!host.empty()) s += " on host " + host;
  return s;
}

std::string OutputLock::path_of(const std::string& out) {
  return out + ".lock";
}

OutputLock::~OutputLock() {
  release();
}

OutputLock::Try OutputLock::try_once() {
  // Open (creating it when absent; `created` then, so that a failure removes it again). Where
  // it cannot be opened for writing (another user's file, a read-only file system), a file
  // opened for reading takes the lock as well; only the holder's text is not written.
  bool created = false, writable = true;
  int fd = ::open(path_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd >= 0) created = true;
  if (fd < 0 && errno == EEXIST) fd = ::open(path_.c_str(), O_RDWR | O_CLOEXEC);
  if (fd < 0 && (errno == EACCES || errno == EPERM || errno == EROFS)) {
    const int first = errno;
    fd = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) errno = first;
    writable = false;
  }
  if (fd < 0) {
    reason_ = std::strerror(errno);
    return Try::unusable;
  }
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int e = errno;
    if (e == EINTR) {
      ::close(fd);
      return Try::replaced;  // try again at once
    }
    if (e == EWOULDBLOCK) {
      holder_ = read_holder(fd);
      ::close(fd);
      return Try::busy;
    }
    reason_ = std::strerror(e);
    if (created) ::unlink(path_.c_str());
    ::close(fd);
    return Try::unsupported;
  }
  // Locked; but the holder we waited for may have removed the file between our open and our
  // lock (and another campaign made it anew): only a lock on the file the path names counts.
  if (!same_file(fd, path_)) {
    ::close(fd);
    return Try::replaced;
  }
  fd_ = fd;
  if (writable) write_holder(fd);
  return Try::taken;
}

OutputLock::Outcome OutputLock::acquire(
    const std::string& out, double wait_seconds,
    const std::function<bool(const LockHolder&)>& keep_waiting) {
  release();
  path_ = path_of(out);
  using Clock = std::chrono::steady_clock;
  const auto deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(
                         std::chrono::duration<double>(wait_seconds > 0 ? wait_seconds : 0.0));
  int replaced = 0;
  while (true) {
    switch (try_once()) {
      case Try::taken:
        return Outcome::taken;
      case Try::unsupported:
        return Outcome::unsupported;
      case Try::unusable:
        return Outcome::unusable;
      case Try::replaced:  // at once: the path names a new file (bounded, should it go on)
        if (++replaced < 100) continue;
        reason_ = "the lock file is replaced again and again";
        return Outcome::unusable;
      case Try::busy:
        break;
    }
    const auto now = Clock::now();
    if (now >= deadline) return Outcome::busy;
    if (keep_waiting && !keep_waiting(holder_)) return Outcome::busy;
    std::this_thread::sleep_for(std::min<Clock::duration>(
        deadline - now,
        std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(kPollSeconds))));
  }
}

void OutputLock::release() {
  if (fd_ < 0) return;
  // Removed while still held (see the header): a campaign waiting for the lock then finds the
  // path free or naming a new file, never this one unlocked.
  ::unlink(path_.c_str());
  ::close(fd_);
  fd_ = -1;
}

std::string busy_output_message(const std::string& out, const OutputLock& lock,
                                double waited_seconds) {
  char waited[64] = "";
  if (waited_seconds > 0)
    std::snprintf(waited, sizeof waited, " after waiting %g s", waited_seconds);
  return std::string("campaign: stopped: another campaign is ") +
         (waited_seconds > 0 ? "still " : "") + "writing " + out + waited + " (" +
         lock.holder().text() + "; its lock " + lock.path() +
         "); nothing was changed: run again once it has ended, or wait " +
         (waited_seconds > 0 ? "longer" : "for it") + " with --wait-lock SECONDS";
}

}  // namespace pound
