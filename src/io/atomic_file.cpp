#include "io/atomic_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

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

}  // namespace pound
