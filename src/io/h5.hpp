#pragma once
// Small RAII helpers over the serial HDF5 C API: create a file, named groups and datasets of
// doubles or ints (1-D and 2-D, row-major), string attributes, and the two reads the result
// files' readers share. Used by the programs' writers and readers only; kernels never touch
// files.
#include <hdf5.h>

#include <string>
#include <vector>

namespace pound::h5 {

class File {
 public:
  /// Creates (truncates) the file. Throws InputError when it cannot.
  explicit File(const std::string& path);
  ~File();
  File(const File&) = delete;
  File& operator=(const File&) = delete;
  hid_t id() const { return id_; }
  void flush();

 private:
  hid_t id_ = -1;
  std::string path_;
};

/// Creates every missing group of a path such as "/pounding/response".
void ensure_group(hid_t file, const std::string& path);
/// Writes a dataset of shape {rows, cols} (cols = 0: 1-D of length rows) with an optional
/// "units" attribute.
void write(hid_t file, const std::string& path, const std::vector<double>& data, std::size_t rows,
           std::size_t cols = 0, const std::string& units = "");
void write(hid_t file, const std::string& path, const std::vector<int>& data);
/// A variable-length string attribute on an object ("/" for the file).
void attribute(hid_t file, const std::string& object, const std::string& name,
               const std::string& value);
void attribute(hid_t file, const std::string& object, const std::string& name, double value);

/// An attribute of the file's root group as text: a string (variable or fixed length) as it
/// is, a number as the shortest text that reads back the same. "" when absent or unreadable.
std::string root_attribute_text(hid_t file, const std::string& name);
/// The names of the links directly under a group, in name order; empty when it is absent.
std::vector<std::string> group_members(hid_t file, const std::string& group);

}  // namespace pound::h5
