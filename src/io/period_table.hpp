#pragma once
// Text tables of a value against the period, one "T value" pair a line: `#` comments and blank
// lines skipped, periods in s, positive and strictly increasing. Read by the user's design
// spectrum (`spectrum_table`) and sigma of ln Sa (`sigma_lnsa`) files; the caller checks the
// values' own range with the line each came from.
#include <string>
#include <vector>

namespace pound {

struct PeriodTableRow {
  double period = 0.0;  ///< [s]
  double value = 0.0;   ///< in the file's unit (the caller converts)
  std::string where;    ///< "FILE:LINE", for errors about this row
  std::string text;     ///< the value as written, for errors
};

/// Reads every row of `path`. `what` names the table in errors ("the sigma table") and
/// `pair_form` says what a line holds ("'T sigma' (T in s, sigma of ln Sa, -)"). Throws
/// InputError naming the file and line for an unreadable file, a line that is not two
/// numbers, or a period that is not > 0 and larger than the previous one.
std::vector<PeriodTableRow> read_period_table(const std::string& path, const std::string& what,
                                              const std::string& pair_form);

}  // namespace pound
