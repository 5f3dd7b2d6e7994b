#pragma once
// Small RAII helpers over the serial HDF5 C API: create a file, named groups and datasets of
// doubles or ints (1-D and 2-D, row-major), string, number and integer-list attributes, and the
// two reads the result files' readers share. Used by the programs' writers and readers only;
// kernels never touch files.
#include <hdf5.h>

#include <string>
#include <vector>

namespace pound::h5 {

/// A file being written. The system's error of any HDF5 call that fails while it is open
/// (HDF5 reports "errno = 28" deep in its error stack; a dataset closed by a destructor
/// included) is remembered, and close() reports it: a file that the system did not store
/// whole is never taken for a result.
class File {
 public:
  /// Creates (truncates) the file. Throws WriteError, with the system's reason, when it cannot.
  explicit File(const std::string& path);
  /// Closes the file if close() was not called (an error path: failures are not reported).
  ~File();
  File(const File&) = delete;
  File& operator=(const File&) = delete;
  hid_t id() const { return id_; }
  void flush();
  /// Closes the file; throws WriteError naming the file and the system's error text when the
  /// close or any earlier call on the file failed in the system (disk full, ...).
  void close();

 private:
  hid_t id_ = -1;
  std::string path_;
};

/// The system's error text ("No space left on device") of the first HDF5 call that failed with
/// an errno since the last File was opened; "" when none did.
std::string system_error();
/// The errno of that call (ENOSPC, ...); 0 when none failed with one.
int system_errno();

/// Creates every missing group of a path such as "/pounding/response".
void ensure_group(hid_t file, const std::string& path);
/// Writes a dataset of shape {rows, cols} (cols = 0: 1-D of length rows) with an optional
/// "units" attribute.
void write(hid_t file, const std::string& path, const std::vector<double>& data, std::size_t rows,
           std::size_t cols = 0, const std::string& units = "");
void write(hid_t file, const std::string& path, const std::vector<int>& data);
/// A dataset of any rank: `shape` (row-major, the product = data.size()) and an optional
/// "units" attribute.
void write_array(hid_t file, const std::string& path, const std::vector<double>& data,
                 const std::vector<std::size_t>& shape, const std::string& units = "");
void write_array(hid_t file, const std::string& path, const std::vector<int>& data,
                 const std::vector<std::size_t>& shape);
/// A variable-length string attribute on an object ("/" for the file).
void attribute(hid_t file, const std::string& object, const std::string& name,
               const std::string& value);
void attribute(hid_t file, const std::string& object, const std::string& name, double value);
/// A one-dimensional attribute of integers (one per building, ...).
void attribute(hid_t file, const std::string& object, const std::string& name,
               const std::vector<int>& values);

/// An attribute of an object ("/" for the root group) as text: a string (variable or fixed
/// length) as it is, a number as the shortest text that reads back the same. "" when the
/// object or the attribute is absent, or it is not one value, or unreadable.
std::string attribute_text(hid_t file, const std::string& object, const std::string& name);
/// attribute_text of the root group.
std::string root_attribute_text(hid_t file, const std::string& name);

/// Why the `count` values of `file_bytes` bytes each that dataset `ds` declares cannot be read
/// into `memory_bytes` each, as words that follow its name ("declares 10 values but the file
/// does not store them"); "" when they can. A damaged file may declare 10^18 rows it does not
/// store (found by fuzz_campaign_file): a dataset stored as it is must hold the bytes of every
/// value. A filtered one (gzip, as `h5repack -f GZIP=6` leaves it) stores fewer bytes than its
/// values take, so its size says nothing: it must hold every chunk that covers its values, and
/// these must fit in this machine's memory and, with gzip alone, in 1100 times the bytes the
/// file stores (zlib unpacks at most 1032 times); H5Dread then decompresses them (and fails on a
/// damaged chunk).
std::string declared_values_problem(hid_t ds, hsize_t count, std::size_t file_bytes,
                                    std::size_t memory_bytes);

/// A whole numeric dataset as doubles (integers convert), row-major, with its dimensions.
/// Throws InputError naming `path` (the file, for messages) and the dataset when it is absent
/// (`missing` says what the file should have been), not numeric, unreadable, or declares more
/// values than it can hold (declared_values_problem).
std::vector<double> read_numbers(hid_t file, const std::string& dataset, const std::string& path,
                                 std::vector<hsize_t>* dims, const std::string& missing);
/// A whole one-dimensional dataset of variable-length strings (labels), one per row. Throws
/// InputError naming `path` and the dataset when it is absent, not such a dataset, unreadable
/// or declares more rows than it can hold.
std::vector<std::string> read_strings(hid_t file, const std::string& dataset,
                                      const std::string& path);
/// The names of the links directly under a group, in name order; empty when it is absent.
std::vector<std::string> group_members(hid_t file, const std::string& group);

}  // namespace pound::h5
