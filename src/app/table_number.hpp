#pragma once
// A number of a printed table: printf format f, or "-" where it is not finite (no fit, no
// data). Shared by the tables of pound fragility, summary and risk.
#include <cmath>
#include <cstdio>
#include <string>

namespace pound::app {

inline std::string fmt(const char* f, double x) {
  if (!std::isfinite(x)) return "-";
  char b[64];
  std::snprintf(b, sizeof b, f, x);
  return b;
}

}  // namespace pound::app
