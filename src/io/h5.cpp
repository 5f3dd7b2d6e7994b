#include "io/h5.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "core/error.hpp"

namespace pound::h5 {
namespace {

// The first system error reported by a failing HDF5 call since the last File was opened: its
// text and errno.
std::string g_system_error;
int g_system_errno = 0;

// Finds "errno = N" in an entry of HDF5's error stack (the sec2 driver writes it on every
// failed open, read, write, truncate and close).
herr_t find_errno(unsigned, const H5E_error2_t* e, void* out) {
  const char* p = e->desc ? std::strstr(e->desc, "errno = ") : nullptr;
  if (!p) return 0;
  const int code = std::atoi(p + 8);
  int& found = *static_cast<int*>(out);
  if (code != 0 && found == 0) found = code;
  return 0;
}

// Called by HDF5 (instead of printing the stack) whenever an API call fails.
herr_t remember_system_error(hid_t stack, void*) {
  int code = 0;
  H5Ewalk2(stack, H5E_WALK_DOWNWARD, find_errno, &code);
  if (code != 0 && g_system_error.empty()) {
    g_system_error = std::strerror(code);
    g_system_errno = code;
  }
  return 0;
}

std::string with_reason(const std::string& what) {
  return g_system_error.empty() ? what : what + " (" + g_system_error + ")";
}

// A WriteError with the remembered system error (its text in the message, its errno).
WriteError write_error(const std::string& what) {
  return WriteError(with_reason(what), g_system_errno);
}

void check(herr_t status, const std::string& what) {
  if (status < 0) throw write_error("HDF5: " + what + " failed");
}

std::string parent_of(const std::string& path) {
  const auto slash = path.rfind('/');
  return slash == 0 || slash == std::string::npos ? "/" : path.substr(0, slash);
}

}  // namespace

File::File(const std::string& path) : path_(path) {
  // Errors become exceptions, not prints; the system's reason of each is remembered.
  H5Eset_auto2(H5E_DEFAULT, remember_system_error, nullptr);
  g_system_error.clear();
  g_system_errno = 0;
  id_ = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (id_ < 0) throw write_error(path + ": cannot create the HDF5 file");
}

File::~File() {
  if (id_ >= 0) H5Fclose(id_);
}

void File::close() {
  const herr_t s = H5Fclose(id_);
  id_ = -1;
  if (s < 0 || !g_system_error.empty()) throw write_error(path_ + ": cannot write the HDF5 file");
}

std::string system_error() {
  return g_system_error;
}

int system_errno() {
  return g_system_errno;
}

void File::flush() {
  check(H5Fflush(id_, H5F_SCOPE_GLOBAL), "flush of " + path_);
}

void ensure_group(hid_t file, const std::string& path) {
  if (path.empty() || path == "/") return;
  ensure_group(file, parent_of(path));
  if (H5Lexists(file, path.c_str(), H5P_DEFAULT) > 0) return;
  const hid_t g = H5Gcreate2(file, path.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (g < 0) throw write_error("HDF5: cannot create group " + path);
  H5Gclose(g);
}

namespace {

void write_shaped(hid_t file, const std::string& path, hid_t type, const void* data,
                  const std::vector<std::size_t>& shape) {
  ensure_group(file, parent_of(path));
  const std::vector<hsize_t> dims(shape.begin(), shape.end());
  const hid_t space = H5Screate_simple(int(dims.size()), dims.data(), nullptr);
  const hid_t ds =
      H5Dcreate2(file, path.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (ds < 0) throw write_error("HDF5: cannot create dataset " + path);
  if (data) check(H5Dwrite(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write of " + path);
  H5Dclose(ds);
  H5Sclose(space);
}

}  // namespace

void write_array(hid_t file, const std::string& path, const std::vector<double>& data,
                 const std::vector<std::size_t>& shape, const std::string& units) {
  write_shaped(file, path, H5T_NATIVE_DOUBLE, data.empty() ? nullptr : data.data(), shape);
  if (!units.empty()) attribute(file, path, "units", units);
}

void write_array(hid_t file, const std::string& path, const std::vector<int>& data,
                 const std::vector<std::size_t>& shape) {
  write_shaped(file, path, H5T_NATIVE_INT, data.empty() ? nullptr : data.data(), shape);
}

void write(hid_t file, const std::string& path, const std::vector<double>& data, std::size_t rows,
           std::size_t cols, const std::string& units) {
  write_array(file, path, data, cols ? std::vector<std::size_t>{rows, cols} : std::vector{rows},
              units);
}

void write(hid_t file, const std::string& path, const std::vector<int>& data) {
  write_array(file, path, data, {data.size()});
}

void attribute(hid_t file, const std::string& object, const std::string& name,
               const std::string& value) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate_by_name(file, object.c_str(), name.c_str(), type, space, H5P_DEFAULT,
                                       H5P_DEFAULT, H5P_DEFAULT);
  if (attr < 0) throw write_error("HDF5: cannot create attribute " + object + ":" + name);
  const char* p = value.c_str();
  check(H5Awrite(attr, type, &p), "attribute " + name);
  H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
}

void attribute(hid_t file, const std::string& object, const std::string& name, double value) {
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate_by_name(file, object.c_str(), name.c_str(), H5T_NATIVE_DOUBLE, space,
                                       H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (attr < 0) throw write_error("HDF5: cannot create attribute " + object + ":" + name);
  check(H5Awrite(attr, H5T_NATIVE_DOUBLE, &value), "attribute " + name);
  H5Aclose(attr);
  H5Sclose(space);
}

void attribute(hid_t file, const std::string& object, const std::string& name,
               const std::vector<int>& values) {
  const hsize_t n = values.size();
  const hid_t space = H5Screate_simple(1, &n, nullptr);
  const hid_t attr = H5Acreate_by_name(file, object.c_str(), name.c_str(), H5T_NATIVE_INT, space,
                                       H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Sclose(space);
  if (attr < 0) throw write_error("HDF5: cannot create attribute " + object + ":" + name);
  if (!values.empty()) check(H5Awrite(attr, H5T_NATIVE_INT, values.data()), "attribute " + name);
  H5Aclose(attr);
}

std::string root_attribute_text(hid_t file, const std::string& name) {
  return attribute_text(file, "/", name);
}

std::string attribute_text(hid_t file, const std::string& object, const std::string& name) {
  if (H5Lexists(file, object.c_str(), H5P_DEFAULT) <= 0 && object != "/") return "";
  if (H5Aexists_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT) <= 0) return "";
  const hid_t a = H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  if (a < 0) return "";
  const hid_t t = H5Aget_type(a);
  const hid_t space = H5Aget_space(a);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  H5Sclose(space);
  std::string out;
  if (n != 1) {
    // One value is read into room for one: an attribute of several values (a damaged or
    // foreign file) would overflow it (found by fuzz_campaign_file, inside HDF5's copy).
  } else if (H5Tget_class(t) != H5T_STRING) {
    double x = 0.0;
    if (H5Aread(a, H5T_NATIVE_DOUBLE, &x) >= 0) {
      std::ostringstream s;
      s << x;
      out = s.str();
    }
  } else if (H5Tis_variable_str(t) > 0) {
    const hid_t mem = H5Tcopy(H5T_C_S1);
    H5Tset_size(mem, H5T_VARIABLE);
    H5Tset_cset(mem, H5Tget_cset(t));  // ASCII and UTF-8 do not convert into each other
    char* p = nullptr;
    if (H5Aread(a, mem, &p) >= 0 && p) out = p;
    H5free_memory(p);
    H5Tclose(mem);
  } else {
    std::vector<char> buf(H5Tget_size(t) + 1, '\0');
    if (H5Aread(a, t, buf.data()) >= 0) out = buf.data();
  }
  H5Tclose(t);
  H5Aclose(a);
  return out;
}

std::string declared_values_problem(hid_t ds, hsize_t count, std::size_t file_bytes,
                                    std::size_t memory_bytes) {
  if (count == 0) return "";
  const hid_t plist = H5Dget_create_plist(ds);
  if (plist < 0) return "has no readable storage layout";
  const int filters = H5Pget_nfilters(plist);
  // Whether every filter is one whose output is at most 1032 times smaller than its input:
  // deflate (zlib's limit), shuffle and the Fletcher checksum (neither shrinks).
  bool deflate_only = true;
  for (int i = 0; i < filters; ++i) {
    unsigned flags = 0;
    std::size_t nvalues = 0;
    const H5Z_filter_t id =
        H5Pget_filter2(plist, unsigned(i), &flags, &nvalues, nullptr, 0, nullptr, nullptr);
    deflate_only = deflate_only && (id == H5Z_FILTER_DEFLATE || id == H5Z_FILTER_SHUFFLE ||
                                    id == H5Z_FILTER_FLETCHER32);
  }
  hsize_t chunk[H5S_MAX_RANK];
  const int chunk_rank =
      H5Pget_layout(plist) == H5D_CHUNKED ? H5Pget_chunk(plist, H5S_MAX_RANK, chunk) : -1;
  H5Pclose(plist);
  if (filters < 0) return "has no readable storage layout";
  const std::string not_stored =
      "declares " + std::to_string(count) + " values but the file does not store them";
  if (filters == 0) {  // stored as it is: every value takes its bytes in the file
    if (file_bytes == 0 || count > H5Dget_storage_size(ds) / file_bytes) return not_stored;
    return "";
  }
  // Filtered (HDF5 filters chunks only): the file stores fewer bytes than the values take, but
  // it must hold every chunk that covers them.
  const hid_t space = H5Dget_space(ds);
  const int rank = H5Sget_simple_extent_ndims(space);
  hsize_t dims[H5S_MAX_RANK];
  hsize_t chunks = 0;
  const bool shaped = rank == chunk_rank && rank > 0 &&
                      H5Sget_simple_extent_dims(space, dims, nullptr) == rank &&
                      H5Dget_num_chunks(ds, space, &chunks) >= 0;  // the whole extent
  H5Sclose(space);
  if (!shaped) return "has no readable storage layout";
  hsize_t needed = 1;
  for (int i = 0; i < rank; ++i) {
    if (chunk[i] == 0) return "has no readable storage layout";
    const hsize_t n = dims[i] / chunk[i] + (dims[i] % chunk[i] != 0);
    needed = n != 0 && needed > ~hsize_t{0} / n ? ~hsize_t{0} : needed * n;
  }
  if (chunks < needed) return not_stored;
  // A damaged chunk may declare 4 GB it does not hold: gzip unpacks to at most 1032 times what
  // it stores (1100 with the chunks' headers), so more values than that are not in the file
  // (read, they would take that memory before H5Dread found the chunk damaged).
  const hsize_t stored = H5Dget_storage_size(ds);
  const hsize_t most = stored > ~hsize_t{0} / 1100 ? ~hsize_t{0} : stored * 1100;
  if (deflate_only && (file_bytes == 0 || count > most / file_bytes))
    return "declares " + std::to_string(count) + " values in " + std::to_string(stored) +
           " compressed bytes, more than gzip unpacks them to";
  // A chunk may decompress to far more than it stores: the values must fit in this machine's
  // memory.
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  const hsize_t memory = pages > 0 && page > 0 ? hsize_t(pages) * hsize_t(page) : ~hsize_t{0};
  if (memory_bytes == 0 || count > memory / memory_bytes)
    return "declares " + std::to_string(count) +
           " values (compressed), more than the memory of this machine holds";
  return "";
}

std::vector<double> read_numbers(hid_t file, const std::string& dataset, const std::string& path,
                                 std::vector<hsize_t>* dims, const std::string& missing) {
  if (H5Lexists(file, dataset.c_str(), H5P_DEFAULT) <= 0)
    throw InputError(path + ": no " + dataset + "; " + missing);
  const hid_t ds = H5Dopen2(file, dataset.c_str(), H5P_DEFAULT);
  if (ds < 0) throw InputError(path + ": " + dataset + " is not a dataset; " + missing);
  const hid_t sp = H5Dget_space(ds), type = H5Dget_type(ds);
  const int rank = H5Sget_simple_extent_ndims(sp);
  std::vector<hsize_t> d(std::size_t(std::max(rank, 0)));
  if (rank > 0) H5Sget_simple_extent_dims(sp, d.data(), nullptr);
  // A damaged file may declare more values than it stores (10^18 rows), which no vector holds.
  hsize_t count = 1;
  for (hsize_t x : d) count = x != 0 && count > ~hsize_t{0} / x ? ~hsize_t{0} : count * x;
  const std::size_t bytes = H5Tget_size(type);
  const H5T_class_t cls = H5Tget_class(type);
  std::string error;
  if (rank < 0) {
    error = path + ": " + dataset + " has no readable shape; " + missing;
  } else if (cls != H5T_FLOAT && cls != H5T_INTEGER) {
    error = path + ": " + dataset + " does not hold numbers; " + missing;
  } else if (const std::string why = declared_values_problem(ds, count, bytes, sizeof(double));
             !why.empty()) {
    error = path + ": " + dataset + " " + why + "; a damaged file or " + missing;
  }
  std::vector<double> v;
  if (error.empty()) {
    v.resize(std::size_t(count));
    if (count && H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0)
      error = path + ": cannot read " + dataset + " as numbers";
  }
  H5Tclose(type);
  H5Sclose(sp);
  H5Dclose(ds);
  if (!error.empty()) throw InputError(error);
  if (dims) *dims = d;
  return v;
}

std::vector<std::string> read_strings(hid_t file, const std::string& dataset,
                                      const std::string& path) {
  if (H5Lexists(file, dataset.c_str(), H5P_DEFAULT) <= 0)
    throw InputError(path + ": no " + dataset);
  const hid_t ds = H5Dopen2(file, dataset.c_str(), H5P_DEFAULT);
  if (ds < 0) throw InputError(path + ": " + dataset + " is not a dataset");
  const hid_t sp = H5Dget_space(ds), type = H5Dget_type(ds);
  hsize_t n = 0;
  std::string error;
  if (H5Sget_simple_extent_ndims(sp) != 1 || H5Tget_class(type) != H5T_STRING ||
      H5Tis_variable_str(type) <= 0) {
    error = path + ": " + dataset + " is not a list of labels (variable-length strings)";
  } else {
    H5Sget_simple_extent_dims(sp, &n, nullptr);
    if (const std::string why = declared_values_problem(ds, n, sizeof(char*), sizeof(char*));
        !why.empty())
      error = path + ": " + dataset + " " + why + " (a damaged file)";
  }
  std::vector<std::string> out;
  if (error.empty()) {
    const hid_t mem = H5Tcopy(H5T_C_S1);
    H5Tset_size(mem, H5T_VARIABLE);
    std::vector<char*> raw(static_cast<std::size_t>(n), nullptr);
    if (n && H5Dread(ds, mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, raw.data()) < 0) {
      error = path + ": cannot read " + dataset + " as labels";
    } else {
      for (char* p : raw) out.emplace_back(p ? p : "");
      if (n) H5Dvlen_reclaim(mem, sp, H5P_DEFAULT, raw.data());
    }
    H5Tclose(mem);
  }
  H5Tclose(type);
  H5Sclose(sp);
  H5Dclose(ds);
  if (!error.empty()) throw InputError(error);
  return out;
}

std::vector<std::string> group_members(hid_t file, const std::string& group) {
  std::vector<std::string> out;
  if (H5Lexists(file, group.c_str(), H5P_DEFAULT) <= 0) return out;
  const hid_t g = H5Gopen2(file, group.c_str(), H5P_DEFAULT);
  H5G_info_t info;
  if (g >= 0 && H5Gget_info(g, &info) >= 0) {
    for (hsize_t i = 0; i < info.nlinks; ++i) {
      const ssize_t len =
          H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
      // A damaged group (found by fuzz_campaign_file) may count links it cannot name: -1 made
      // a string of 2^64 - 1 characters. The members before it are the ones there are.
      if (len < 0) break;
      std::string name(std::size_t(len), '\0');
      H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), std::size_t(len) + 1,
                         H5P_DEFAULT);
      out.push_back(name);
    }
  }
  if (g >= 0) H5Gclose(g);
  return out;
}

}  // namespace pound::h5
