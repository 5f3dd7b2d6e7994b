#pragma once
// A drift history for `pound hysteresis`: one storey drift [m] per line. Blank lines and lines
// starting with '#' are skipped; a UTF-8 byte-order mark and Windows line ends are read as any
// other text file's.
#include <string>
#include <vector>

namespace pound {

/// The drifts of the file [m]. Throws InputError naming the file (and line) and what is valid
/// when it cannot be read, a line is not one number, or there is no drift at all.
std::vector<double> read_drift_history(const std::string& path);

}  // namespace pound
