#include "campaign/merge.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "campaign/amplification_file.hpp"
#include "campaign/floor_arrays.hpp"
#include "core/error.hpp"
#include "io/h5.hpp"
#include "io/number.hpp"

namespace pound {
namespace {

// A root attribute the merge needs; its absence means the file is no campaign result.
std::string required_attribute(hid_t file, const char* name, const std::string& path) {
  if (H5Aexists(file, name) <= 0)
    throw InputError(path + ": not a campaign result (no '" + std::string(name) + "' attribute)");
  return h5::root_attribute_text(file, name);
}

struct Part {
  std::string path;
  hid_t file = -1;
  long lo = 0, hi = 0;
};

// Closes an HDF5 identifier at scope exit (error paths included: an identifier left open
// keeps its file open).
struct Id {
  hid_t id;
  herr_t (*close)(hid_t);
  ~Id() {
    if (id >= 0) close(id);
  }
};

// The part's "samples" root attribute: one number, or -1.
double sample_count(hid_t file) {
  if (H5Aexists(file, "samples") <= 0) return -1;
  const Id a{H5Aopen(file, "samples", H5P_DEFAULT), H5Aclose};
  const Id space{H5Aget_space(a.id), H5Sclose};
  const Id type{H5Aget_type(a.id), H5Tclose};
  double n = -1;
  const H5T_class_t c = H5Tget_class(type.id);
  if (H5Sget_simple_extent_npoints(space.id) != 1 || (c != H5T_FLOAT && c != H5T_INTEGER) ||
      H5Aread(a.id, H5T_NATIVE_DOUBLE, &n) < 0)
    return -1;
  return n;
}

herr_t copy_attribute(hid_t src, const char* name, const H5A_info_t*, void* dst_ptr) {
  const hid_t dst = *static_cast<hid_t*>(dst_ptr);
  const Id a{H5Aopen(src, name, H5P_DEFAULT), H5Aclose};
  const Id t{H5Aget_type(a.id), H5Tclose};
  const Id s{H5Aget_space(a.id), H5Sclose};
  const hssize_t n = H5Sget_simple_extent_npoints(s.id);
  const std::size_t size = H5Tget_size(t.id);
  if (a.id < 0 || t.id < 0 || s.id < 0 || n < 0 || size == 0) return -1;
  std::vector<char> buf(static_cast<std::size_t>(n) * size);
  if (H5Aread(a.id, t.id, buf.data()) < 0) return -1;
  const Id b{H5Acreate2(dst, name, t.id, s.id, H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
  const herr_t w = b.id < 0 ? -1 : H5Awrite(b.id, t.id, buf.data());
  if (H5Tis_variable_str(t.id) > 0 || H5Tget_class(t.id) == H5T_VLEN)
    H5Dvlen_reclaim(t.id, s.id, H5P_DEFAULT, buf.data());
  return w < 0 ? -1 : 0;
}

// The parts, open, closed when this goes out of scope (error paths included).
struct OpenParts {
  std::vector<Part> parts;
  OpenParts() = default;
  OpenParts(const OpenParts&) = delete;
  OpenParts& operator=(const OpenParts&) = delete;
  ~OpenParts() {
    for (auto& x : parts)
      if (x.file >= 0) H5Fclose(x.file);
  }
};

// Opens every part, reads its sample range and checks that all come from the same campaign
// (study, seed and sample count). Returns the sample count as stored (-1 when absent).
double open_parts(const std::vector<std::string>& paths, OpenParts& open) {
  std::vector<Part>& parts = open.parts;
  std::string study, seed;
  double samples = -1;
  for (const auto& path : paths) {
    Part p;
    p.path = path;
    p.file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (p.file < 0) throw InputError(path + ": cannot open (not an HDF5 file?)");
    parts.push_back(p);
    Part& q = parts.back();
    const std::string st = required_attribute(q.file, "study", path);
    const std::string sd = required_attribute(q.file, "seed", path);
    const std::string range = required_attribute(q.file, "sample_range", path);
    const double n = sample_count(q.file);
    // LO:HI, two whole decimal numbers (io/number.hpp; "12abc" and "0x10" are refused).
    const auto colon = range.find(':');
    double lo = -1, hi = -1;
    if (colon == std::string::npos || !read_decimal(range.substr(0, colon), &lo) ||
        !read_decimal(range.substr(colon + 1), &hi) || lo != std::floor(lo) ||
        hi != std::floor(hi) || !(lo >= 0 && hi >= lo && hi <= 1e15))
      throw InputError(path + ": bad sample_range '" + range + "' (expected LO:HI)");
    q.lo = static_cast<long>(lo);
    q.hi = static_cast<long>(hi);
    if (parts.size() == 1) {
      study = st;
      seed = sd;
      samples = n;
    } else if (st != study || sd != seed || n != samples) {
      throw InputError(path +
                       ": belongs to another campaign (study, seed or sample count differ "
                       "from " +
                       parts.front().path + ")");
    }
  }
  return samples;
}

// Sorts the parts by range and checks that they cover 0..samples-1 exactly once. Returns the
// sample count.
hsize_t check_ranges(std::vector<Part>& parts, double samples) {
  std::sort(parts.begin(), parts.end(), [](const Part& x, const Part& y) { return x.lo < y.lo; });
  long next = 0;
  for (const auto& p : parts) {
    if (p.lo != next)
      throw InputError(p.path + ": holds samples " + std::to_string(p.lo) + ".." +
                       std::to_string(p.hi - 1) + " but the parts so far end at " +
                       std::to_string(next - 1) + (p.lo < next ? " (overlap)" : " (gap)"));
    next = p.hi;
  }
  // The attribute as stored (NaN, 1e300, 2.5 or -1 when absent or not one number): converting
  // such a value to long would be undefined behaviour, so only a valid count is converted.
  const bool whole = samples >= 1 && samples <= 1e15 && samples == std::floor(samples);
  if (!whole || next != static_cast<long>(samples)) {
    char shown[32];
    std::snprintf(shown, sizeof shown, "%.15g", samples);
    throw InputError(parts.back().path + ": the parts end at sample " + std::to_string(next - 1) +
                     " but the campaign has " + shown + " samples" +
                     (whole ? "" : " (attribute samples; valid: one whole number from 1 to 1e15)"));
  }
  return static_cast<hsize_t>(samples);
}

// One dataset of the joined file: its type, shape and attributes from the first part.
struct JoinedDataset {
  std::string name;  ///< e.g. /response/peak_force
  hid_t type;        ///< the first part's type (owned by the caller)
  int rank;
  std::vector<hsize_t> dims;  ///< dims[0] = the campaign's sample count
  hid_t id;                   ///< the joined dataset (owned by the caller)
};

// Copies part p's rows of the dataset into their place [p.lo, p.hi) of the joined one.
void copy_rows(const Part& p, const Part& first, const JoinedDataset& d, const std::string& out) {
  auto bad = [&](const std::string& what) {
    return InputError(p.path + ": " + d.name + " " + what);
  };
  const Id dp{H5Dopen2(p.file, stored_dataset_path(p.file, d.name).c_str(), H5P_DEFAULT), H5Dclose};
  if (dp.id < 0) throw InputError(p.path + ": dataset " + d.name + " is missing");
  const Id sp{H5Dget_space(dp.id), H5Sclose};
  std::vector<hsize_t> pd(static_cast<std::size_t>(d.rank));
  if (H5Sget_simple_extent_ndims(sp.id) != d.rank)
    throw bad("has another number of dimensions than in " + first.path);
  H5Sget_simple_extent_dims(sp.id, pd.data(), nullptr);
  for (int k = 1; k < d.rank; ++k)
    if (pd[k] != d.dims[k]) throw bad("has another shape than in " + first.path);
  if (static_cast<long>(pd[0]) != p.hi - p.lo)
    throw InputError(p.path + ": " + d.name + " has " + std::to_string(pd[0]) +
                     " rows, its sample_range says " + std::to_string(p.hi - p.lo));
  // A damaged part may declare more rows than it stores (found by fuzz_campaign_file); a
  // compressed one stores fewer bytes than it holds (h5::declared_values_problem).
  const hssize_t npts = H5Sget_simple_extent_npoints(sp.id);
  const Id ptype{H5Dget_type(dp.id), H5Tclose};
  if (npts < 0) throw bad("has no readable shape (a damaged file)");
  if (const std::string why = h5::declared_values_problem(
          dp.id, static_cast<hsize_t>(npts), H5Tget_size(ptype.id), H5Tget_size(d.type));
      !why.empty())
    throw bad(why + " (a damaged file)");
  std::vector<char> buf(static_cast<std::size_t>(npts) * H5Tget_size(d.type));
  if (H5Dread(dp.id, d.type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data()) < 0)
    throw bad("cannot be read as in " + first.path);
  const Id fs{H5Dget_space(d.id), H5Sclose};
  std::vector<hsize_t> start(static_cast<std::size_t>(d.rank), 0);
  start[0] = static_cast<hsize_t>(p.lo);
  H5Sselect_hyperslab(fs.id, H5S_SELECT_SET, start.data(), nullptr, pd.data(), nullptr);
  const Id ms{H5Screate_simple(d.rank, pd.data(), nullptr), H5Sclose};
  const herr_t w = H5Dwrite(d.id, d.type, ms.id, fs.id, H5P_DEFAULT, buf.data());
  if (H5Tis_variable_str(d.type) > 0 || H5Tget_class(d.type) == H5T_VLEN)
    H5Dvlen_reclaim(d.type, ms.id, H5P_DEFAULT, buf.data());
  if (w < 0) throw InputError(out + ": writing " + d.name + " failed");
}

// Creates dataset `name` of the joined file `f` (`total` rows, as in the first part) and copies
// every part's rows into it.
void join_dataset(hid_t f, const std::vector<Part>& parts, const std::string& group,
                  const std::string& name, hsize_t total, const std::string& out) {
  const Part& first = parts.front();
  auto bad = [&](const std::string& what) {
    return InputError(first.path + ": " + name + " " + what);
  };
  const Id d0{H5Dopen2(first.file, stored_dataset_path(first.file, name).c_str(), H5P_DEFAULT),
              H5Dclose};
  if (d0.id < 0) throw bad("is not a dataset");
  const Id type{H5Dget_type(d0.id), H5Tclose};
  const Id s0{H5Dget_space(d0.id), H5Sclose};
  const int rank = H5Sget_simple_extent_ndims(s0.id);
  if (rank < 1 || rank > 3 || H5Tget_size(type.id) == 0)
    throw bad("is not a table of rows (1 to 3 dimensions)");
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(s0.id, dims.data(), nullptr);
  dims[0] = total;
  h5::ensure_group(f, group);
  const Id space{H5Screate_simple(rank, dims.data(), nullptr), H5Sclose};
  const Id d{H5Dcreate2(f, name.c_str(), type.id, space.id, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
             H5Dclose};
  if (d.id < 0) throw bad("cannot be copied");
  H5Aiterate2(d0.id, H5_INDEX_NAME, H5_ITER_NATIVE, nullptr, copy_attribute,
              const_cast<hid_t*>(&d.id));
  const JoinedDataset joined{name, type.id, rank, dims, d.id};
  for (const auto& p : parts) copy_rows(p, first, joined, out);
}

}  // namespace

void merge_campaign_parts(const std::vector<std::string>& paths, const std::string& out) {
  if (paths.empty()) throw InputError("merge: no part files given");
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  OpenParts open;
  const double samples = open_parts(paths, open);
  std::vector<Part>& parts = open.parts;
  const hsize_t total = check_ranges(parts, samples);

  h5::File f(out);
  for (const char* group : {"/samples", "/response", "/run"})
    for (const auto& member : h5::group_members(parts.front().file, group))
      join_dataset(f.id(), parts, group, current_dataset_path(std::string(group) + "/" + member),
                   total, out);
  // Root attributes of the first part, with the merged range.
  {
    Id root{H5Gopen2(f.id(), "/", H5P_DEFAULT), H5Gclose};
    H5Aiterate2(parts.front().file, H5_INDEX_NAME, H5_ITER_NATIVE, nullptr, copy_attribute,
                &root.id);
    H5Adelete(root.id, "sample_range");
  }
  h5::attribute(f.id(), "/", "sample_range", "0:" + std::to_string(total));
  std::string from;
  for (const auto& p : parts) from += (from.empty() ? "" : ", ") + p.path;
  h5::attribute(f.id(), "/", "merged_from", from);
  // The parts' /amplification describe their own samples: recomputed for the joined file (its
  // errors name the parts, since `out` is a temporary name).
  write_amplification(f.id(), compute_amplification(f.id(), "the parts joined (" + from + ")"));
  f.close();
}

}  // namespace pound
