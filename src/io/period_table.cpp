#include "io/period_table.hpp"

#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "io/options.hpp"
#include "io/utf8_bom.hpp"

namespace pound {

std::vector<PeriodTableRow> read_period_table(const std::string& path, const std::string& what,
                                              const std::string& pair_form) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open " + what + "; give an existing, readable file");
  std::vector<PeriodTableRow> rows;
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (n == 1) strip_utf8_bom(line);  // as Windows editors save "UTF-8" files
    const auto b = line.find_first_not_of(" \t\r");
    if (b == std::string::npos || line[b] == '#') continue;
    PeriodTableRow r;
    r.where = path + ":" + std::to_string(n);
    std::istringstream ls(line);
    std::string t, extra;
    if (!(ls >> t >> r.text) || (ls >> extra))
      throw InputError(r.where + ": expected two numbers " + pair_form);
    r.period = parse_number(t, r.where);
    r.value = parse_number(r.text, r.where);
    if (!(r.period > 0.0) || (!rows.empty() && !(r.period > rows.back().period)))
      throw InputError(r.where + ": period " + t + " s; valid: > 0 and larger than the previous");
    rows.push_back(std::move(r));
  }
  if (in.bad()) throw InputError(path + ": read error in " + what + "; give a readable file");
  return rows;
}

}  // namespace pound
