#pragma once
// Exceptions used across the engine. main() turns any of them into one line on stderr and a
// non-zero exit code; kernels throw, they never print.
#include <stdexcept>
#include <string>

namespace pound {

/// Bad user input: a study file, a command-line value or an input file. The message already
/// says where (file:line, key) and what would be valid.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Writing an output file failed in the system (disk full, quota, file size limit, I/O
/// error). The message names the file and carries the system's error text. A campaign stops
/// on it as on SIGTERM, keeping its journal; elsewhere it is bad input like any other (exit 2).
class WriteError : public InputError {
 public:
  using InputError::InputError;
};

/// Numerical failure inside a simulation (non-finite state, step-size underflow, too many
/// events). Carries no file position; callers add the sample id.
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace pound
