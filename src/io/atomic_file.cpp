#include "io/atomic_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "core/error.hpp"

namespace pound {

AtomicPath::AtomicPath(std::string target)
    : target_(std::move(target)), temp_(target_ + ".tmp." + std::to_string(::getpid())) {}

AtomicPath::~AtomicPath() {
  if (!committed_) std::remove(temp_.c_str());
}

void AtomicPath::commit() {
  if (std::rename(temp_.c_str(), target_.c_str()) != 0)
    throw InputError(target_ + ": cannot write the result file (" + std::strerror(errno) + ")");
  committed_ = true;
}

void write_text_file(const std::string& path, const std::string& text) {
  AtomicPath out(path);
  {
    std::ofstream f(out.temp(), std::ios::binary);
    if (!f) throw InputError(path + ": cannot write; give a writable --out folder");
    f << text;
    f.flush();
    if (!f) throw InputError(path + ": write failed");
  }
  out.commit();
}

std::string csv_number(double x) {
  if (!std::isfinite(x)) return "";
  char b[32];
  std::snprintf(b, sizeof b, "%.10g", x);
  return b;
}

}  // namespace pound
