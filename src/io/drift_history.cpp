#include "io/drift_history.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "io/options.hpp"
#include "io/utf8_bom.hpp"

namespace pound {

std::vector<double> read_drift_history(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path + ": is a directory; give a file of drifts in m, one per line");
  std::ifstream in(path);
  if (!in)
    throw InputError(path +
                     ": cannot open the drift history; give an existing, readable "
                     "file of drifts in m, one per line");
  std::vector<double> drifts;
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (n == 1) strip_utf8_bom(line);
    const auto b = line.find_first_not_of(" \t\r");
    if (b == std::string::npos || line[b] == '#') continue;
    const std::string where = path + ":" + std::to_string(n);
    std::istringstream ls(line);
    std::string t, extra;
    ls >> t;
    if (ls >> extra)
      throw InputError(where + ": expected one drift in m per line, got '" +
                       line.substr(b, line.find_last_not_of(" \t\r") + 1 - b) + "'");
    drifts.push_back(parse_number(t, where));
  }
  if (in.bad()) throw InputError(path + ": read error in the drift history; give a readable file");
  if (drifts.empty())
    throw InputError(path +
                     ": no drifts; give one drift in m per line (blank lines and lines "
                     "starting with # are skipped)");
  return drifts;
}

}  // namespace pound
