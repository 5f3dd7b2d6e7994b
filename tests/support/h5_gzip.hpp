#pragma once
// What `h5repack -f GZIP=6` makes of a file, for tests (h5repack is not always installed): every
// dataset of integers or floating-point numbers rewritten in place as one chunk compressed with
// gzip, keeping its name, type, shape, values and attributes.
#include <hdf5.h>

#include <string>
#include <vector>

namespace pound::test {
namespace gzip_detail {

inline herr_t collect(hid_t group, const char* name, const H5L_info_t*, void* out) {
  const hid_t o = H5Oopen(group, name, H5P_DEFAULT);
  if (o < 0) return 0;
  if (H5Iget_type(o) == H5I_DATASET) static_cast<std::vector<std::string>*>(out)->push_back(name);
  H5Oclose(o);
  return 0;
}

inline herr_t copy_attribute(hid_t src, const char* name, const H5A_info_t*, void* dst_ptr) {
  const hid_t dst = *static_cast<hid_t*>(dst_ptr);
  const hid_t a = H5Aopen(src, name, H5P_DEFAULT);
  const hid_t t = H5Aget_type(a), s = H5Aget_space(a);
  std::vector<char> buf(std::size_t(H5Sget_simple_extent_npoints(s)) * H5Tget_size(t));
  herr_t st = H5Aread(a, t, buf.data());
  const hid_t b = H5Acreate2(dst, name, t, s, H5P_DEFAULT, H5P_DEFAULT);
  if (st >= 0) st = b < 0 ? -1 : H5Awrite(b, t, buf.data());
  if (H5Tis_variable_str(t) > 0 || H5Tget_class(t) == H5T_VLEN)
    H5Dvlen_reclaim(t, s, H5P_DEFAULT, buf.data());
  if (b >= 0) H5Aclose(b);
  H5Sclose(s);
  H5Tclose(t);
  H5Aclose(a);
  return st < 0 ? -1 : 0;
}

}  // namespace gzip_detail

/// Compresses every numeric dataset of the file at `path`; returns how many it compressed
/// (-1 when the file cannot be opened or a dataset cannot be rewritten).
inline int gzip_numeric_datasets(const std::string& path) {
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (f < 0) return -1;
  std::vector<std::string> names;
  H5Lvisit(f, H5_INDEX_NAME, H5_ITER_INC, gzip_detail::collect, &names);
  int done = 0;
  bool failed = false;
  for (const auto& name : names) {
    const hid_t d = H5Dopen2(f, name.c_str(), H5P_DEFAULT);
    const hid_t t = H5Dget_type(d), s = H5Dget_space(d);
    const H5T_class_t cls = H5Tget_class(t);
    const int rank = H5Sget_simple_extent_ndims(s);
    const hssize_t n = H5Sget_simple_extent_npoints(s);
    if ((cls == H5T_INTEGER || cls == H5T_FLOAT) && rank > 0 && n > 0) {
      std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
      H5Sget_simple_extent_dims(s, dims.data(), nullptr);
      std::vector<char> buf(std::size_t(n) * H5Tget_size(t));
      const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
      H5Pset_chunk(dcpl, rank, dims.data());
      H5Pset_deflate(dcpl, 6);
      const std::string tmp = name + ".gzip";
      const hid_t z = H5Dcreate2(f, tmp.c_str(), t, s, H5P_DEFAULT, dcpl, H5P_DEFAULT);
      bool ok = z >= 0 && H5Dread(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data()) >= 0 &&
                H5Dwrite(z, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data()) >= 0 &&
                H5Aiterate2(d, H5_INDEX_NAME, H5_ITER_INC, nullptr, gzip_detail::copy_attribute,
                            const_cast<hid_t*>(&z)) >= 0;
      if (z >= 0) H5Dclose(z);
      H5Pclose(dcpl);
      H5Sclose(s);
      H5Tclose(t);
      H5Dclose(d);
      ok = ok && H5Ldelete(f, name.c_str(), H5P_DEFAULT) >= 0 &&
           H5Lmove(f, tmp.c_str(), f, name.c_str(), H5P_DEFAULT, H5P_DEFAULT) >= 0;
      if (!ok) {
        failed = true;
        break;
      }
      ++done;
    } else {
      H5Sclose(s);
      H5Tclose(t);
      H5Dclose(d);
    }
  }
  H5Fclose(f);
  return failed ? -1 : done;
}

}  // namespace pound::test
