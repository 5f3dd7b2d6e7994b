#pragma once
// A number of a printed table: printf format f, or "-" where it is not finite (no fit, no
// data). Shared by the tables of pound fragility, summary and risk.
#include <cmath>
#include <cstdio>
#include <string>

#include "core/format.hpp"

namespace pound::app {

inline std::string fmt(const char* f, double x) {
  return std::isfinite(x) ? format_number(x, f) : "-";
}

}  // namespace pound::app
