#pragma once
// What the commands that analyse a campaign file (pound fragility, pound risk) share: parse the
// options, analyse and write the files, print the result as JSON (--json) or as tables that end
// with the files written, and say how many samples failed.
#include <cstdio>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "app/help.hpp"
#include "io/options.hpp"

namespace pound::app {

/// The last lines of such a command's tables: the files it wrote.
inline void print_files(const std::vector<std::string>& files) {
  std::printf("\nFiles:");
  for (const auto& f : files) std::printf(" %s", f.c_str());
  std::printf("\n");
}

/// Runs `command`: `analyse(opt, true)` reads, analyses and writes the files, then `json(run)`
/// is printed with --json, else `print(run)`, and a note on stderr counts the failed samples
/// (Run::report's failed and samples).
template <class Run>
int run_analysis_command(const char* command, const char* summary, std::vector<OptionSpec> specs,
                         int argc, const char* const* argv, Run (*analyse)(const Options&, bool),
                         std::string (*json)(const Run&), void (*print)(const Run&)) {
  Options opt(command, summary, std::move(specs));
  if (help_asked(opt, argc, argv)) return 0;
  const Run run = analyse(opt, true);
  if (opt.flag("json"))
    std::cout << json(run) << "\n";
  else
    print(run);
  if (run.report.failed)
    std::fprintf(stderr, "%s: %zu of %zu samples failed and are excluded\n", command,
                 run.report.failed, run.report.samples);
  return 0;
}

}  // namespace pound::app
