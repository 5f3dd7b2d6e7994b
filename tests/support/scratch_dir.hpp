#pragma once
// A fresh private directory for a test (mkdtemp), removed with everything in it when the object
// dies. Names built from getpid() are not enough: process ids repeat from one run to the next (a
// CI container starts from the same ids), so such a name can meet files an earlier run left.
#include <stdlib.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace pound::test {

class ScratchDir {
 public:
  /// Makes <temp>/<prefix>XXXXXX with a unique suffix; throws if it cannot.
  explicit ScratchDir(const std::string& prefix) {
    std::string name = (std::filesystem::temp_directory_path() / (prefix + "XXXXXX")).string();
    if (::mkdtemp(name.data()) == nullptr)
      throw std::runtime_error("cannot create a scratch directory " + name);
    path_ = name;
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::string& path() const { return path_; }
  /// path()/name.
  std::string operator/(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

/// One scratch directory for the whole test process, made on first use, removed at exit.
inline const ScratchDir& process_scratch_dir() {
  static const ScratchDir d("pound_test_");
  return d;
}

/// process_scratch_dir()/name, made on first use: the files of one test file apart from those
/// of the others compiled into the same test program (tests/app holds one per command).
inline std::string process_scratch_subdir(const std::string& name) {
  const std::string path = process_scratch_dir() / name;
  std::filesystem::create_directories(path);
  return path;
}

}  // namespace pound::test
