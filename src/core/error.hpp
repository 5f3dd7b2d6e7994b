#pragma once
// Exceptions used across the engine. main() turns any of them into one line on stderr and a
// non-zero exit code; kernels throw, they never print.
#include <cerrno>
#include <stdexcept>
#include <string>

namespace pound {

/// Bad user input: a study file, a command-line value or an input file. The message already
/// says where (file:line, key) and what would be valid.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// True for the errno values that freeing space or raising a limit cures: ENOSPC (disk full),
/// EDQUOT (quota) and EFBIG (file size limit).
inline bool out_of_space(int error_number) {
  return error_number == ENOSPC || error_number == EDQUOT || error_number == EFBIG;
}

/// Writing an output file failed in the system (disk full, quota, file size limit, I/O
/// error). The message names the file and carries the system's error text; error_number() is
/// the errno of the failed call (0 when unknown). A campaign stops on an out_of_space() one as
/// on SIGTERM, keeping its journal; any other (read-only file system, permission, I/O error)
/// is an error there too, and elsewhere it is bad input like any other (exit 2).
class WriteError : public InputError {
 public:
  explicit WriteError(const std::string& what, int error_number = 0)
      : InputError(what), error_number_(error_number) {}
  int error_number() const { return error_number_; }

 private:
  int error_number_ = 0;
};

/// Numerical failure inside a simulation (non-finite state, step-size underflow, too many
/// events). Carries no file position; callers add the sample id.
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace pound
