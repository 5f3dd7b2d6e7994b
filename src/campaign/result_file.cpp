#include "campaign/result_file.hpp"

#include <hdf5.h>

#include <cmath>
#include <cstdio>
#include <iterator>
#include <memory>
#include <vector>

#include "campaign/amplification_file.hpp"
#include "campaign/building_arrays.hpp"
#include "campaign/floor_arrays.hpp"
#include "campaign/journal.hpp"
#include "core/error.hpp"
#include "core/format.hpp"
#include "io/h5.hpp"
#include "pound/version.hpp"
#include "structure/building_on_base.hpp"

namespace pound {
namespace {

// A chunked dataset of doubles [N, a, b] (a = b = 0 for 1-D) written row by row.
class RowDataset {
 public:
  RowDataset(hid_t file, const std::string& path, hsize_t n, hsize_t a, hsize_t b,
             hid_t type = H5T_NATIVE_DOUBLE, const std::string& units = "")
      : type_(type), a_(a), b_(b) {
    const int rank = a ? (b ? 3 : 2) : 1;
    hsize_t dims[3] = {n, a, b};
    hsize_t chunk[3] = {std::min<hsize_t>(n, 1024), a, b};
    const hid_t space = H5Screate_simple(rank, dims, nullptr);
    const hid_t plist = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_chunk(plist, rank, chunk);
    if (type == H5T_NATIVE_DOUBLE) {
      const double nan = std::nan("");
      H5Pset_fill_value(plist, H5T_NATIVE_DOUBLE, &nan);
    } else if (type == H5T_NATIVE_INT) {  // a row never written reads not_run (-1)
      const int not_run = static_cast<int>(SampleStatus::not_run);
      H5Pset_fill_value(plist, H5T_NATIVE_INT, &not_run);
    }
    h5::ensure_group(file, path.substr(0, path.rfind('/')));
    id_ = H5Dcreate2(file, path.c_str(), type, space, H5P_DEFAULT, plist, H5P_DEFAULT);
    H5Pclose(plist);
    H5Sclose(space);
    if (id_ < 0) throw InputError("HDF5: cannot create dataset " + path);
    if (!units.empty()) h5::attribute(file, path, "units", units);
    // A type-converting write (the variable-length strings) would allocate and clear HDF5's
    // default 1 MB conversion buffers for every row (11 s for 960 rows of the default study,
    // issue 13): a buffer for one row is enough.
    dxpl_ = H5Pcreate(H5P_DATASET_XFER);
    H5Pset_buffer(dxpl_, 4096, nullptr, nullptr);
  }
  ~RowDataset() {
    H5Pclose(dxpl_);
    H5Dclose(id_);
  }
  /// The first row (of a 1-D int dataset) holding `value`, read in blocks; -1 when none.
  long find_int(int value, hsize_t n) const {
    const hsize_t block = 65536;
    std::vector<int> buf(static_cast<std::size_t>(std::min(block, n)));
    for (hsize_t start = 0; start < n; start += block) {
      hsize_t count = std::min(block, n - start);
      const hid_t fspace = H5Dget_space(id_);
      H5Sselect_hyperslab(fspace, H5S_SELECT_SET, &start, nullptr, &count, nullptr);
      const hid_t mspace = H5Screate_simple(1, &count, nullptr);
      const herr_t s = H5Dread(id_, H5T_NATIVE_INT, mspace, fspace, H5P_DEFAULT, buf.data());
      H5Sclose(mspace);
      H5Sclose(fspace);
      if (s < 0) throw InputError("HDF5: reading back the sample status failed");
      for (hsize_t i = 0; i < count; ++i)
        if (buf[i] == value) return static_cast<long>(start + i);
    }
    return -1;
  }
  void write(hsize_t row, const void* data) {
    const hid_t fspace = H5Dget_space(id_);
    const int rank = a_ ? (b_ ? 3 : 2) : 1;
    hsize_t start[3] = {row, 0, 0}, count[3] = {1, a_, b_};
    H5Sselect_hyperslab(fspace, H5S_SELECT_SET, start, nullptr, count, nullptr);
    const hid_t mspace = H5Screate_simple(rank, count, nullptr);
    const herr_t s = H5Dwrite(id_, type_, mspace, fspace, dxpl_, data);
    H5Sclose(mspace);
    H5Sclose(fspace);
    if (s < 0) throw InputError("HDF5: row write failed");
  }

 private:
  hid_t id_ = -1, type_, dxpl_ = -1;
  hsize_t a_, b_;
};

}  // namespace

namespace {

// The per-site arrays [samples, pairs, levels] of a sample's outcome (result_file.hpp).
struct SiteArray {
  const char* name;  // under /response
  const char* unit;
  std::vector<double> SampleOutcome::*member;
};
const SiteArray kSiteArrays[] = {
    {"peak_force", "N", &SampleOutcome::peak_force},
    {"impacts", "-", &SampleOutcome::impacts},
    {"approach_free", "m", &SampleOutcome::approach_free},
    {"peak_column_shear", "N", &SampleOutcome::peak_column_shear},
    {"crush", "m", &SampleOutcome::crush},
};

}  // namespace

void write_result_file(const std::string& path, const CampaignStudy& st,
                       const std::string& journal_path, const RunInfo& info) {
  // Rows: the samples of this run's range, sample id = range_lo + row.
  const hsize_t n = static_cast<hsize_t>(st.range_size());
  const long lo = st.range_lo;
  const hsize_t nb = st.buildings(), nf = st.max_floors(), np = st.pairs(), nl = st.max_levels();
  h5::File f(path);
  const hid_t fid = f.id();
  const hid_t str = H5Tcopy(H5T_C_S1);
  H5Tset_size(str, H5T_VARIABLE);
  {
    RowDataset id(fid, "/samples/id", n, 0, 0, H5T_NATIVE_LONG);
    RowDataset status(fid, "/samples/status", n, 0, 0, H5T_NATIVE_INT);
    RowDataset message(fid, "/samples/message", n, 0, 0, str);
    RowDataset im(fid, "/samples/im", n, 0, 0, H5T_NATIVE_DOUBLE, "m/s^2");
    RowDataset scale(fid, "/samples/scale", n, 0, 0, H5T_NATIVE_DOUBLE, "-");
    std::vector<std::unique_ptr<RowDataset>> params;
    for (const auto& p : st.parameters)
      params.push_back(std::make_unique<RowDataset>(fid, "/samples/" + p.key, n, 0, 0,
                                                    p.is_label() ? str : H5T_NATIVE_DOUBLE));
    const auto& fields = floor_array_fields();
    std::vector<std::unique_ptr<RowDataset>> floors;
    for (const auto& a : fields)
      floors.push_back(std::make_unique<RowDataset>(fid, std::string("/response/") + a.name, n, nb,
                                                    nf, H5T_NATIVE_DOUBLE, a.unit));
    const auto& bfields = building_array_fields();
    std::vector<std::unique_ptr<RowDataset>> per_building;
    for (const auto& a : bfields)
      per_building.push_back(std::make_unique<RowDataset>(fid, std::string("/response/") + a.name,
                                                          n, nb, 0, H5T_NATIVE_DOUBLE, a.unit));
    std::vector<std::unique_ptr<RowDataset>> per_site;
    for (const SiteArray& a : kSiteArrays)
      per_site.push_back(std::make_unique<RowDataset>(fid, std::string("/response/") + a.name, n,
                                                      np, nl, H5T_NATIVE_DOUBLE, a.unit));
    RowDataset ground_relative(fid, "/response/ground_relative", n, np, 0, H5T_NATIVE_DOUBLE, "m");
    RowDataset rank(fid, "/run/rank", n, 0, 0, H5T_NATIVE_INT);
    RowDataset wall(fid, "/run/wall_seconds", n, 0, 0, H5T_NATIVE_DOUBLE, "s");

    // Rows are written as the journal streams them (a duplicate record, which a run does not
    // write, would overwrite its row with the same numbers); a row never written keeps the
    // status fill value not_run, found by a scan in blocks. Memory independent of the sample
    // count.
    for_each_record(journal_path, st, [&](const SampleOutcome& o) {
      if (o.id < lo || static_cast<hsize_t>(o.id - lo) >= n) return;
      const hsize_t r = static_cast<hsize_t>(o.id - lo);
      const long idv = o.id;
      const int stv = static_cast<int>(o.status);
      const char* msg = o.message.c_str();
      id.write(r, &idv);
      status.write(r, &stv);
      message.write(r, &msg);
      im.write(r, &o.im);
      scale.write(r, &o.scale);
      for (std::size_t i = 0; i < st.parameters.size(); ++i) {
        if (st.parameters[i].is_label()) {
          const char* label =
              st.parameters[i].distribution.labels()[static_cast<std::size_t>(o.values[i])].c_str();
          params[i]->write(r, &label);
        } else {
          params[i]->write(r, &o.values[i]);
        }
      }
      for (std::size_t i = 0; i < fields.size(); ++i)
        floors[i]->write(r, (o.*fields[i].member).data());
      for (std::size_t i = 0; i < bfields.size(); ++i)
        per_building[i]->write(r, (o.*bfields[i].member).data());
      for (std::size_t i = 0; i < std::size(kSiteArrays); ++i)
        per_site[i]->write(r, (o.*kSiteArrays[i].member).data());
      ground_relative.write(r, o.ground_relative.data());
      rank.write(r, &o.rank);
      wall.write(r, &o.wall_seconds);
    });
    const long missing = status.find_int(static_cast<int>(SampleStatus::not_run), n);
    if (missing >= 0)
      throw InputError(journal_path + ": sample " + std::to_string(lo + missing) +
                       " is missing; resume the campaign with --resume");
  }
  H5Tclose(str);
  h5::attribute(fid, "/", "study", st.resolved);
  h5::attribute(fid, "/", "engine_version", kVersion);
  h5::attribute(fid, "/", "git_revision", kGitRevision);
  h5::attribute(fid, "/", "seed", std::to_string(st.seed));
  h5::attribute(fid, "/", "sample_range",
                std::to_string(st.range_lo) + ":" + std::to_string(st.range_hi));
  h5::attribute(fid, "/", "samples", static_cast<double>(st.samples));
  h5::attribute(fid, "/", "sampling",
                st.sampling == SamplingMethod::latin_hypercube ? "lhs" : "mc");
  h5::attribute(fid, "/", "intensity_measure", st.measure == IntensityMeasure::pga ? "pga" : "sa");
  h5::attribute(fid, "/", "im_period_s", st.im_period);
  h5::attribute(fid, "/", "im_building", static_cast<double>(st.im_building));
  std::string levels;
  for (double l : st.levels) levels += (levels.empty() ? "" : ", ") + std::to_string(l);
  h5::attribute(fid, "/", "im_levels_mps2", levels);
  h5::attribute(fid, "/", "ranks", static_cast<double>(info.ranks));
  h5::attribute(fid, "/", "start_time", info.start_time);
  h5::attribute(fid, "/", "end_time", info.end_time);
  h5::attribute(fid, "/", "host", info.host);
  std::string names;
  for (const auto& b : st.row.buildings) names += (names.empty() ? "" : ", ") + b.name;
  h5::attribute(fid, "/", "building_names", names);
  // Each building's first mode, with its foundation and the study's fixed (not sampled)
  // properties, for `pound risk`'s code rules, which then need not read the study again.
  std::string periods, damping;
  for (const auto& b : st.row.buildings) {
    periods +=
        (periods.empty() ? "" : ", ") + format_number(assemble_on_base(b).periods(0), "%.17g");
    damping += (damping.empty() ? "" : ", ") + format_number(b.damping_ratio, "%.17g");
  }
  h5::attribute(fid, "/", "first_periods_s", periods);
  h5::attribute(fid, "/", "damping_ratios", damping);
  // The floors of each building, so that readers need not parse the study text (the per-floor
  // arrays are as wide as the tallest building, NaN beyond a building's own floors).
  std::vector<int> floors;
  for (const auto& b : st.row.buildings) floors.push_back(b.floors());
  h5::attribute(fid, "/", "floors", floors);
  // The amplification statistics, read back from the rows just written (in blocks).
  write_amplification(fid, compute_amplification(fid, path));
  f.close();  // a failed write (disk full) is reported here, before the file is renamed
}

}  // namespace pound
