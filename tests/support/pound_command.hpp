#pragma once
// `pound COMMAND ARGS` run from a test with its output in a scratch folder (the app tests, whose
// target defines POUND_BINARY): its exit code, stdout, and stderr without the "pound COMMAND: "
// prefix that every error line of the command starts with.
#include <string>

#include "scratch_dir.hpp"
#include "shell.hpp"

#ifndef POUND_BINARY
#error "pound_command.hpp needs POUND_BINARY, the pound executable's path"
#endif

namespace pound::test {

struct PoundOutcome {
  int code = -1;
  std::string out, message;  // stdout; stderr without the "pound COMMAND: " prefix
};

inline PoundOutcome run_pound_command(const ScratchDir& dir, const std::string& command,
                                      const std::string& args) {
  const std::string err = dir / (command + ".err"), out = dir / (command + ".out");
  const int code = run_command(std::string(POUND_BINARY) + " " + command + " " + args + " >" + out +
                               " 2>" + err);
  std::string text = slurp(err);
  const std::string prefix = "pound " + command + ": ";
  if (text.rfind(prefix, 0) == 0) text.erase(0, prefix.size());
  return {code, slurp(out), text};
}

}  // namespace pound::test
