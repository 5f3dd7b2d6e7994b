#include "campaign/merge.hpp"

#include <hdf5.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "campaign/amplification_file.hpp"
#include "core/error.hpp"
#include "io/h5.hpp"

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

herr_t copy_attribute(hid_t src, const char* name, const H5A_info_t*, void* dst_ptr) {
  const hid_t dst = *static_cast<hid_t*>(dst_ptr);
  const hid_t a = H5Aopen(src, name, H5P_DEFAULT);
  const hid_t t = H5Aget_type(a);
  const hid_t s = H5Aget_space(a);
  const hssize_t n = H5Sget_simple_extent_npoints(s);
  std::vector<char> buf(static_cast<std::size_t>(n) * H5Tget_size(t));
  H5Aread(a, t, buf.data());
  const hid_t b = H5Acreate2(dst, name, t, s, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(b, t, buf.data());
  if (H5Tis_variable_str(t) > 0 || H5Tget_class(t) == H5T_VLEN)
    H5Dvlen_reclaim(t, s, H5P_DEFAULT, buf.data());
  H5Aclose(b);
  H5Sclose(s);
  H5Tclose(t);
  H5Aclose(a);
  return 0;
}

}  // namespace

void merge_campaign_parts(const std::vector<std::string>& paths, const std::string& out) {
  if (paths.empty()) throw InputError("merge: no part files given");
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  std::vector<Part> parts;
  struct Closer {
    std::vector<Part>& p;
    ~Closer() {
      for (auto& x : p)
        if (x.file >= 0) H5Fclose(x.file);
    }
  } closer{parts};
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
    const hid_t a = H5Aopen(q.file, "samples", H5P_DEFAULT);
    double n = -1;
    if (a >= 0) {
      H5Aread(a, H5T_NATIVE_DOUBLE, &n);
      H5Aclose(a);
    }
    const auto colon = range.find(':');
    try {
      if (colon == std::string::npos) throw std::invalid_argument("no colon");
      q.lo = std::stol(range.substr(0, colon));
      q.hi = std::stol(range.substr(colon + 1));
    } catch (const std::logic_error&) {  // std::stol's invalid_argument and out_of_range
      throw InputError(path + ": bad sample_range '" + range + "' (expected LO:HI)");
    }
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
  std::sort(parts.begin(), parts.end(), [](const Part& x, const Part& y) { return x.lo < y.lo; });
  long next = 0;
  for (const auto& p : parts) {
    if (p.lo != next)
      throw InputError(p.path + ": holds samples " + std::to_string(p.lo) + ".." +
                       std::to_string(p.hi - 1) + " but the parts so far end at " +
                       std::to_string(next - 1) + (p.lo < next ? " (overlap)" : " (gap)"));
    next = p.hi;
  }
  if (next != static_cast<long>(samples))
    throw InputError(parts.back().path + ": the parts end at sample " + std::to_string(next - 1) +
                     " but the campaign has " + std::to_string(static_cast<long>(samples)) +
                     " samples");

  h5::File f(out);
  const hsize_t total = static_cast<hsize_t>(samples);
  for (const char* group : {"/samples", "/response", "/run"}) {
    for (const auto& member : h5::group_members(parts.front().file, group)) {
      const std::string name = std::string(group) + "/" + member;
      const hid_t d0 = H5Dopen2(parts.front().file, name.c_str(), H5P_DEFAULT);
      const hid_t type = H5Dget_type(d0);
      const hid_t s0 = H5Dget_space(d0);
      const int rank = H5Sget_simple_extent_ndims(s0);
      std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
      H5Sget_simple_extent_dims(s0, dims.data(), nullptr);
      dims[0] = total;
      h5::ensure_group(f.id(), group);
      const hid_t space = H5Screate_simple(rank, dims.data(), nullptr);
      const hid_t d =
          H5Dcreate2(f.id(), name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      H5Aiterate2(d0, H5_INDEX_NAME, H5_ITER_NATIVE, nullptr, copy_attribute,
                  const_cast<hid_t*>(&d));
      for (const auto& p : parts) {
        const hid_t dp = H5Dopen2(p.file, name.c_str(), H5P_DEFAULT);
        if (dp < 0) throw InputError(p.path + ": dataset " + name + " is missing");
        const hid_t sp = H5Dget_space(dp);
        const hssize_t npts = H5Sget_simple_extent_npoints(sp);
        std::vector<hsize_t> pd(static_cast<std::size_t>(rank));
        H5Sget_simple_extent_dims(sp, pd.data(), nullptr);
        if (static_cast<long>(pd[0]) != p.hi - p.lo)
          throw InputError(p.path + ": " + name + " has " + std::to_string(pd[0]) +
                           " rows, its sample_range says " + std::to_string(p.hi - p.lo));
        std::vector<char> buf(static_cast<std::size_t>(npts) * H5Tget_size(type));
        H5Dread(dp, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data());
        const hid_t fs = H5Dget_space(d);
        std::vector<hsize_t> start(static_cast<std::size_t>(rank), 0);
        start[0] = static_cast<hsize_t>(p.lo);
        H5Sselect_hyperslab(fs, H5S_SELECT_SET, start.data(), nullptr, pd.data(), nullptr);
        const hid_t ms = H5Screate_simple(rank, pd.data(), nullptr);
        if (H5Dwrite(d, type, ms, fs, H5P_DEFAULT, buf.data()) < 0)
          throw InputError(out + ": writing " + name + " failed");
        if (H5Tis_variable_str(type) > 0) H5Dvlen_reclaim(type, ms, H5P_DEFAULT, buf.data());
        H5Sclose(ms);
        H5Sclose(fs);
        H5Sclose(sp);
        H5Dclose(dp);
      }
      H5Dclose(d);
      H5Sclose(space);
      H5Sclose(s0);
      H5Tclose(type);
      H5Dclose(d0);
    }
  }
  // Root attributes of the first part, with the merged range.
  hid_t root = H5Gopen2(f.id(), "/", H5P_DEFAULT);
  H5Aiterate2(parts.front().file, H5_INDEX_NAME, H5_ITER_NATIVE, nullptr, copy_attribute, &root);
  H5Adelete(root, "sample_range");
  H5Gclose(root);
  h5::attribute(f.id(), "/", "sample_range", "0:" + std::to_string(total));
  std::string from;
  for (const auto& p : parts) from += (from.empty() ? "" : ", ") + p.path;
  h5::attribute(f.id(), "/", "merged_from", from);
  // The parts' /amplification describe their own samples: recomputed for the joined file.
  write_amplification(f.id(), compute_amplification(f.id(), out));
}

}  // namespace pound
