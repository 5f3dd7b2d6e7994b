// bench_amplification: the memory and time of the /amplification writer (issue 15) on a made-up
// result file of N samples laid out as the default study's (2 buildings of up to 5 floors, one
// pair of 3 levels, 12 stripes, 1 % failed samples, the collapse flags per building and two
// contact models in /samples/model, so a table per model too). The file is written in blocks,
// so the process's peak resident memory before the statistics is that of the program itself;
// the growth after them is the writer's (bounded: about 35-40 MB whatever N, docs/campaign.md).
// Usage: bench_amplification [N] [scratch folder] [pooled]; `pooled` leaves out the collapse
// flags and the model labels (a file of before issue 23: the pooled table alone).
#include <hdf5.h>
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "campaign/amplification_file.hpp"
#include "io/h5.hpp"

namespace {

double peak_mb() {
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  return double(ru.ru_maxrss) / 1024.0;  // kB on Linux
}

// A chunked dataset [n, a, b] of doubles (a = 0: 1-D), filled block by block by `fill`.
template <class Fill>
void dataset(hid_t f, const std::string& name, hsize_t n, hsize_t a, hsize_t b, hid_t type,
             Fill fill) {
  const int rank = a ? (b ? 3 : 2) : 1;
  const hsize_t dims[3] = {n, a, b}, chunk[3] = {std::min<hsize_t>(n, 1024), a, b};
  const hid_t sp = H5Screate_simple(rank, dims, nullptr);
  const hid_t pl = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(pl, rank, chunk);
  const hid_t d = H5Dcreate2(f, name.c_str(), type, sp, H5P_DEFAULT, pl, H5P_DEFAULT);
  const hsize_t block = 65536, per = a ? a * (b ? b : 1) : 1;
  std::vector<double> buf;
  for (hsize_t row = 0; row < n; row += block) {
    const hsize_t count = std::min(block, n - row);
    buf.assign(count * per, 0.0);
    for (hsize_t i = 0; i < count; ++i)
      for (hsize_t k = 0; k < per; ++k) buf[i * per + k] = fill(row + i, k);
    const hsize_t start[3] = {row, 0, 0}, cnt[3] = {count, a, b};
    const hid_t fs = H5Dget_space(d);
    H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, nullptr, cnt, nullptr);
    const hid_t ms = H5Screate_simple(rank, cnt, nullptr);
    H5Dwrite(d, H5T_NATIVE_DOUBLE, ms, fs, H5P_DEFAULT, buf.data());
    H5Sclose(ms);
    H5Sclose(fs);
  }
  H5Dclose(d);
  H5Pclose(pl);
  H5Sclose(sp);
}

// /samples/model [n]: variable-length labels, "sears" and "hc-linear" in turn, in blocks.
void labels(hid_t f, hsize_t n) {
  const hid_t t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, H5T_VARIABLE);
  const hsize_t chunk = std::min<hsize_t>(n, 1024);
  const hid_t sp = H5Screate_simple(1, &n, nullptr);
  const hid_t pl = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(pl, 1, &chunk);
  const hid_t d = H5Dcreate2(f, "/samples/model", t, sp, H5P_DEFAULT, pl, H5P_DEFAULT);
  const char* names[2] = {"sears", "hc-linear"};
  std::vector<const char*> buf;
  for (hsize_t row = 0; row < n; row += 65536) {
    const hsize_t count = std::min<hsize_t>(65536, n - row);
    buf.assign(count, nullptr);
    for (hsize_t i = 0; i < count; ++i) buf[i] = names[(row + i) % 2];
    const hid_t fs = H5Dget_space(d);
    H5Sselect_hyperslab(fs, H5S_SELECT_SET, &row, nullptr, &count, nullptr);
    const hid_t ms = H5Screate_simple(1, &count, nullptr);
    H5Dwrite(d, t, ms, fs, H5P_DEFAULT, buf.data());
    H5Sclose(ms);
    H5Sclose(fs);
  }
  H5Dclose(d);
  H5Pclose(pl);
  H5Sclose(sp);
  H5Tclose(t);
}

}  // namespace

int main(int argc, char** argv) {
  const hsize_t n = argc > 1 ? hsize_t(std::atoll(argv[1])) : 1000000;
  const std::string path = std::string(argc > 2 ? argv[2] : "/tmp") + "/bench_amplification.h5";
  const bool pooled = argc > 3 && std::string(argv[3]) == "pooled";
  const auto t0 = std::chrono::steady_clock::now();
  {
    pound::h5::File file(path);
    const hid_t f = file.id();
    pound::h5::ensure_group(f, "/samples");
    pound::h5::ensure_group(f, "/response");
    auto failed = [](hsize_t s) { return s % 100 == 37; };
    auto ratio = [](hsize_t s, hsize_t k) {
      return 0.8 + 0.4 * double((s * 7919 + k * 104729) % 1000) / 1000;
    };
    dataset(f, "/samples/id", n, 0, 0, H5T_NATIVE_LONG,
            [](hsize_t s, hsize_t) { return double(s); });
    dataset(f, "/samples/status", n, 0, 0, H5T_NATIVE_INT,
            [&](hsize_t s, hsize_t) { return failed(s) ? 1.0 : 0.0; });
    dataset(f, "/samples/im", n, 0, 0, H5T_NATIVE_DOUBLE,
            [](hsize_t s, hsize_t) { return 0.5 + double(s % 12); });
    for (const char* m : {"disp", "drift", "accel"}) {
      // Building 2 has 3 floors: NaN at its floors 4 and 5, as in the result files.
      auto free = [&](hsize_t s, hsize_t k) {
        return failed(s) || k >= 8 ? NAN : 0.01 * double(k + 1);
      };
      dataset(f, std::string("/response/peak_") + m + "_free", n, 2, 5, H5T_NATIVE_DOUBLE, free);
      dataset(f, std::string("/response/peak_") + m + "_pounding", n, 2, 5, H5T_NATIVE_DOUBLE,
              [&](hsize_t s, hsize_t k) { return free(s, k) * ratio(s, k); });
    }
    dataset(f, "/response/impacts", n, 1, 3, H5T_NATIVE_DOUBLE,
            [&](hsize_t s, hsize_t k) { return failed(s) ? NAN : double((s + k) % 3); });
    dataset(f, "/response/peak_force", n, 1, 3, H5T_NATIVE_DOUBLE,
            [&](hsize_t s, hsize_t k) { return failed(s) ? NAN : 1e5 * double((s + k) % 3); });
    if (!pooled) {
      labels(f, n);
      for (const char* c : {"/response/collapsed_pounding", "/response/collapsed_free"})
        dataset(f, c, n, 2, 0, H5T_NATIVE_DOUBLE, [&](hsize_t s, hsize_t k) {
          return failed(s) ? NAN : (s + k) % 23 == 0 ? 1.0 : 0.0;
        });
    }
    std::string levels;
    for (int j = 0; j < 12; ++j) levels += (j ? ", " : "") + std::to_string(0.5 + j);
    pound::h5::attribute(f, "/", "im_levels_mps2", levels);
  }
  const double before = peak_mb();
  const auto t1 = std::chrono::steady_clock::now();
  {
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    const pound::AmplificationTable t = pound::compute_amplification(f, path);
    pound::write_amplification(f, t);
    H5Fclose(f);
  }
  const auto t2 = std::chrono::steady_clock::now();
  const double after = peak_mb();
  std::printf("bench_amplification: %llu samples%s, file written in %.1f s\n",
              static_cast<unsigned long long>(n),
              pooled ? " (pooled table alone)" : " (collapse flags, two contact models)",
              std::chrono::duration<double>(t1 - t0).count());
  std::printf(
      "  /amplification: %.2f s; peak resident memory %.1f MB before, %.1f MB after "
      "(growth %.1f MB, %.1f bytes per sample)\n",
      std::chrono::duration<double>(t2 - t1).count(), before, after, after - before,
      (after - before) * 1048576.0 / double(n));
  std::remove(path.c_str());
  return 0;
}
