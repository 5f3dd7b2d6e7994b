#pragma once
// One number as text by a printf format (messages, option defaults, tables).
#include <cstdio>
#include <string>

namespace pound {

/// x printed by the printf format f (one double conversion, e.g. "%.6g").
inline std::string format_number(double x, const char* f = "%.6g") {
  char b[64];
  std::snprintf(b, sizeof b, f, x);
  return b;
}

}  // namespace pound
