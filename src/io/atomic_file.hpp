#pragma once
// Output files appear whole or not at all: write to a temporary name beside the target, then
// commit() renames it into place. Destroying an uncommitted AtomicPath removes the temporary,
// so an error never leaves a partial result file.
#include <string>

namespace pound {

class AtomicPath {
 public:
  explicit AtomicPath(std::string target);
  ~AtomicPath();
  AtomicPath(const AtomicPath&) = delete;
  AtomicPath& operator=(const AtomicPath&) = delete;

  /// The temporary path to write to.
  const std::string& temp() const { return temp_; }
  const std::string& target() const { return target_; }
  /// Renames the temporary onto the target. Throws InputError when that fails.
  void commit();

 private:
  std::string target_, temp_;
  bool committed_ = false;
};

/// Writes `text` to `path` whole or not at all (through an AtomicPath); throws InputError naming
/// the file when it cannot be written.
void write_text_file(const std::string& path, const std::string& text);

/// A number for a CSV field (10 significant digits), or an empty field for NaN and infinity.
std::string csv_number(double x);

}  // namespace pound
