#pragma once
// Running a command line through the shell from a test, and reading what it wrote.
#include <stdlib.h>
#include <sys/wait.h>

#include <fstream>
#include <sstream>
#include <string>

namespace pound::test {

/// Runs `cmd` with std::system; returns its exit status, -1 when a signal ended it. Open MPI's
/// dynamically loaded components leak at exit, which LeakSanitizer would report in the
/// sanitizer build: leak checks are off for the child (address and undefined-behaviour errors
/// stay fatal); and Open MPI may run as root (CI containers).
inline int run_command(const std::string& cmd) {
  ::setenv("ASAN_OPTIONS", "detect_leaks=0", 0);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  const int s = std::system(cmd.c_str());
  return WIFEXITED(s) ? WEXITSTATUS(s) : -1;
}

/// The whole file, bytes as they are ("" when it cannot be read).
inline std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

}  // namespace pound::test
