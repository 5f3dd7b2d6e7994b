#pragma once
// A campaign result file's rows read in blocks, in memory that does not grow with the sample
// count: a dataset of rows [samples], [samples, a] or [samples, a, b] one block at a time, and
// the sample table (/samples/id, status, im and, where the study samples the contact model,
// /samples/model) by which the amplification statistics (amplification_file.hpp) group the
// samples and keep one model's.
#include <hdf5.h>

#include <memory>
#include <string>
#include <vector>

namespace pound {

/// Rows read at a time.
constexpr hsize_t kBlockRows = 65536;

/// An open dataset of the file, closed at scope exit.
class RowBlocks {
 public:
  /// Throws InputError naming `path` (the file) when it has no dataset `name`.
  RowBlocks(hid_t file, const std::string& name, const std::string& path);
  ~RowBlocks();
  RowBlocks(const RowBlocks&) = delete;
  RowBlocks& operator=(const RowBlocks&) = delete;
  const std::vector<hsize_t>& dims() const { return dims_; }
  const std::string& name() const { return name_; }

  /// Rows [row, row + count) of a 1-D dataset, converted to the vector's type.
  void rows1(hsize_t row, hsize_t count, std::vector<long>& out) const;
  void rows1(hsize_t row, hsize_t count, std::vector<int>& out) const;
  void rows1(hsize_t row, hsize_t count, std::vector<double>& out) const;
  /// Rows [row, row + count) of a 1-D dataset of text (variable or fixed length strings);
  /// throws InputError when it does not hold text.
  void text_rows(hsize_t row, hsize_t count, std::vector<std::string>& out) const;
  /// Rows [row, row + count) of a 2-D [N, a] or 3-D [N, a, b] dataset, columns [a0, a0 + na)
  /// of its second dimension, as doubles, row-major: [count, na, b] (b = 1 for 2-D).
  void rows(hsize_t row, hsize_t count, hsize_t a0, hsize_t na, std::vector<double>& out) const;

 private:
  void read1(hsize_t row, hsize_t count, hid_t mem_type, void* out) const;
  std::string name_, path_;
  hid_t id_ = -1;
  std::vector<hsize_t> dims_;
};

/// The sample table of a campaign file, read in blocks of rows. With /samples/model (a study
/// that samples the contact model: each sample's label) it knows the models, and a filter
/// keeps one model's samples.
class SampleRows {
 public:
  /// Opens /samples/id, status and im (one length) and, when present, /samples/model; throws
  /// InputError naming `path` when one is missing, their lengths differ, or a label cannot be a
  /// group name (empty, ".", with '/' or ',').
  SampleRows(hid_t file, const std::string& path);
  hsize_t rows() const { return n_; }
  /// The distinct labels of /samples/model in byte order; empty without it.
  const std::vector<std::string>& models() const { return models_; }
  /// Keep only the samples of models()[m]; -1 (or any m not in models()) keeps every sample.
  void keep_model(int m) { keep_ = m >= 0 && std::size_t(m) < models_.size() ? m : -1; }
  int kept_model() const { return keep_; }
  /// Rows [row, row + count) into id, status, im (and model, with a filter).
  void read(hsize_t row, hsize_t count);
  /// Whether row i of the last block passes the filter.
  bool kept(std::size_t i) const { return keep_ < 0 || model[i] == keep_; }

  std::vector<long> id;
  std::vector<int> status;
  std::vector<double> im;
  std::vector<int> model;  ///< index into models(), read only with a filter

 private:
  std::string path_;
  RowBlocks id_, status_, im_;
  std::unique_ptr<RowBlocks> label_;  // /samples/model, when the file has it
  hsize_t n_ = 0;
  std::vector<std::string> models_;
  int keep_ = -1;
  std::vector<std::string> text_;
};

}  // namespace pound
