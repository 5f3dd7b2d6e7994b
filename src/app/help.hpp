#pragma once
// The start every command shares: parse the options, and with --help print them and stop.
#include <iostream>

#include "io/options.hpp"

namespace pound::app {

/// Parses argv into opt; prints the help and returns true when --help was asked for.
inline bool help_asked(Options& opt, int argc, const char* const* argv) {
  opt.parse(argc, argv);
  if (!opt.help_requested()) return false;
  std::cout << opt.help_text();
  return true;
}

}  // namespace pound::app
