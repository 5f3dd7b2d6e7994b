#include "campaign/campaign_rows.hpp"

#include <algorithm>
#include <cstring>

#include "core/error.hpp"

namespace pound {
namespace {

// Labels of /samples/model kept at most: a study's contact models are a handful; a file with
// more distinct labels is no campaign file (and one group each would be written).
constexpr std::size_t kMaxModels = 64;
// The longest fixed-length label read (a block of them takes 65,536 times as much memory).
constexpr std::size_t kMaxLabelBytes = 256;

// Why a label cannot name an HDF5 group (/amplification/models/<label>) or be listed in a
// comma-separated attribute; "" when it can.
std::string label_problem(const std::string& label) {
  if (label.empty()) return "an empty label";
  if (label == "." || label == "..") return "the label '" + label + "'";
  if (label.find_first_of("/,") != std::string::npos) return "the label '" + label + "'";
  return "";
}

}  // namespace

RowBlocks::RowBlocks(hid_t file, const std::string& name, const std::string& path)
    : name_(name), path_(path) {
  if (H5Lexists(file, name.c_str(), H5P_DEFAULT) <= 0 ||
      (id_ = H5Dopen2(file, name.c_str(), H5P_DEFAULT)) < 0)
    throw InputError(path + ": no dataset " + name +
                     "; not a campaign result file of 'pound campaign' (schema in "
                     "src/campaign/result_file.hpp)");
  const hid_t s = H5Dget_space(id_);
  dims_.resize(std::size_t(std::max(0, H5Sget_simple_extent_ndims(s))));
  H5Sget_simple_extent_dims(s, dims_.data(), nullptr);
  H5Sclose(s);
}

RowBlocks::~RowBlocks() {
  H5Dclose(id_);
}

void RowBlocks::read1(hsize_t row, hsize_t count, hid_t mem_type, void* out) const {
  if (count == 0) return;
  const hid_t fs = H5Dget_space(id_);
  H5Sselect_hyperslab(fs, H5S_SELECT_SET, &row, nullptr, &count, nullptr);
  const hid_t ms = H5Screate_simple(1, &count, nullptr);
  const herr_t st = H5Dread(id_, mem_type, ms, fs, H5P_DEFAULT, out);
  H5Sclose(ms);
  H5Sclose(fs);
  if (st < 0) throw InputError(path_ + ": reading " + name_ + " failed");
}

void RowBlocks::rows1(hsize_t row, hsize_t count, std::vector<long>& out) const {
  out.resize(std::size_t(count));
  read1(row, count, H5T_NATIVE_LONG, out.data());
}
void RowBlocks::rows1(hsize_t row, hsize_t count, std::vector<int>& out) const {
  out.resize(std::size_t(count));
  read1(row, count, H5T_NATIVE_INT, out.data());
}
void RowBlocks::rows1(hsize_t row, hsize_t count, std::vector<double>& out) const {
  out.resize(std::size_t(count));
  read1(row, count, H5T_NATIVE_DOUBLE, out.data());
}

void RowBlocks::text_rows(hsize_t row, hsize_t count, std::vector<std::string>& out) const {
  out.assign(std::size_t(count), std::string());
  const hid_t ft = H5Dget_type(id_);
  const bool text = H5Tget_class(ft) == H5T_STRING;
  const bool variable = text && H5Tis_variable_str(ft) > 0;
  const std::size_t size = H5Tget_size(ft);
  // The memory type: the file's own, so that no conversion (ASCII and UTF-8 do not convert
  // into each other) is asked for.
  const hid_t mem = H5Tcopy(ft);
  H5Tclose(ft);
  if (!text || size == 0) {
    H5Tclose(mem);
    throw InputError(path_ + ": " + name_ +
                     " does not hold text; valid: one label per sample (strings)");
  }
  if (!variable && size > kMaxLabelBytes) {
    H5Tclose(mem);
    throw InputError(path_ + ": " + name_ + " holds strings of " + std::to_string(size) +
                     " bytes; valid: labels of at most " + std::to_string(kMaxLabelBytes) +
                     " bytes");
  }
  if (variable) {
    std::vector<char*> p(std::size_t(count), nullptr);
    try {
      read1(row, count, mem, p.data());
    } catch (...) {
      H5Tclose(mem);
      throw;
    }
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p[i]) out[i] = p[i];
    const hid_t ms = H5Screate_simple(1, &count, nullptr);
    if (count) H5Dvlen_reclaim(mem, ms, H5P_DEFAULT, p.data());
    H5Sclose(ms);
  } else {
    std::vector<char> buf(std::size_t(count) * size);
    try {
      read1(row, count, mem, buf.data());
    } catch (...) {
      H5Tclose(mem);
      throw;
    }
    for (std::size_t i = 0; i < out.size(); ++i) {
      const char* s = buf.data() + i * size;
      out[i].assign(s, strnlen(s, size));
    }
  }
  H5Tclose(mem);
}

void RowBlocks::rows(hsize_t row, hsize_t count, hsize_t a0, hsize_t na,
                     std::vector<double>& out) const {
  const int rank = int(dims_.size());
  const hsize_t inner = rank == 3 ? dims_[2] : 1;
  const hsize_t start[3] = {row, a0, 0}, n[3] = {count, na, inner};
  out.resize(std::size_t(count * na * inner));
  if (out.empty()) return;
  const hid_t fs = H5Dget_space(id_);
  H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, nullptr, n, nullptr);
  const hid_t ms = H5Screate_simple(rank, n, nullptr);
  const herr_t st = H5Dread(id_, H5T_NATIVE_DOUBLE, ms, fs, H5P_DEFAULT, out.data());
  H5Sclose(ms);
  H5Sclose(fs);
  if (st < 0) throw InputError(path_ + ": reading " + name_ + " failed");
}

SampleRows::SampleRows(hid_t file, const std::string& path)
    : path_(path),
      id_(file, "/samples/id", path),
      status_(file, "/samples/status", path),
      im_(file, "/samples/im", path) {
  n_ = id_.dims().empty() ? 0 : id_.dims()[0];
  for (const RowBlocks* d : {&id_, &status_, &im_})
    if (d->dims().size() != 1 || d->dims()[0] != n_)
      throw InputError(path + ": /samples/id, status and im differ in length");
  if (H5Lexists(file, "/samples/model", H5P_DEFAULT) <= 0) return;
  label_ = std::make_unique<RowBlocks>(file, "/samples/model", path);
  if (label_->dims().size() != 1 || label_->dims()[0] != n_)
    throw InputError(path + ": /samples/model is not one label per sample of /samples/id");
  // The distinct labels, streamed.
  for (hsize_t row = 0; row < n_; row += kBlockRows) {
    label_->text_rows(row, std::min(kBlockRows, n_ - row), text_);
    for (const std::string& s : text_) {
      if (std::find(models_.begin(), models_.end(), s) != models_.end()) continue;
      if (const std::string why = label_problem(s); !why.empty())
        throw InputError(path + ": /samples/model holds " + why +
                         "; valid: contact model names (not empty, without '/' or ',')");
      if (models_.size() == kMaxModels)
        throw InputError(path + ": /samples/model holds more than " + std::to_string(kMaxModels) +
                         " distinct labels; valid: the contact models of the study");
      models_.push_back(s);
    }
  }
  std::sort(models_.begin(), models_.end());
}

void SampleRows::read(hsize_t row, hsize_t count) {
  id_.rows1(row, count, id);
  status_.rows1(row, count, status);
  im_.rows1(row, count, im);
  if (keep_ < 0 || !label_) return;
  label_->text_rows(row, count, text_);
  model.resize(text_.size());
  for (std::size_t i = 0; i < text_.size(); ++i)
    model[i] = int(std::find(models_.begin(), models_.end(), text_[i]) - models_.begin());
}

}  // namespace pound
