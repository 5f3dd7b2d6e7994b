// write_amplification and read_amplification (amplification_file.hpp): the /amplification group
// of a campaign file, the pooled table and one per contact model in the same layout.
#include "campaign/amplification_file.hpp"

#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "io/h5.hpp"
#include "io/options.hpp"

namespace pound {
namespace {

void write_array(hid_t file, const std::string& name, hid_t mem_type, const void* data,
                 std::vector<hsize_t> dims, const std::string& units = "") {
  h5::ensure_group(file, name.substr(0, name.rfind('/')));
  const hid_t space = H5Screate_simple(int(dims.size()), dims.data(), nullptr);
  const hid_t ds =
      H5Dcreate2(file, name.c_str(), mem_type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (ds < 0) throw InputError("HDF5: cannot create dataset " + name);
  hsize_t total = 1;
  for (hsize_t d : dims) total *= d;
  const herr_t st = total ? H5Dwrite(ds, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) : 0;
  H5Dclose(ds);
  H5Sclose(space);
  if (st < 0) throw InputError("HDF5: writing " + name + " failed");
  if (!units.empty()) h5::attribute(file, name, "units", units);
}

void write_doubles(hid_t f, const std::string& name, const std::vector<double>& v,
                   std::vector<hsize_t> dims, const std::string& units = "") {
  write_array(f, name, H5T_NATIVE_DOUBLE, v.data(), std::move(dims), units);
}
void write_longs(hid_t f, const std::string& name, const std::vector<long>& v,
                 std::vector<hsize_t> dims) {
  write_array(f, name, H5T_NATIVE_LONG, v.data(), std::move(dims));
}

// One table's datasets under `root` (/amplification or /amplification/models/<label>) and the
// attributes a reader needs (design, failed).
void write_table(hid_t file, const std::string& root, const AmplificationTable& t) {
  h5::ensure_group(file, root);
  h5::attribute(file, root, "design", t.stripes ? "stripes" : "bins");
  h5::attribute(file, root, "failed", double(t.failed_total));
  const hsize_t G = t.groups;
  write_doubles(file, root + "/im", t.im, {G}, "m/s^2");
  write_doubles(file, root + "/im_lo", t.im_lo, {G}, "m/s^2");
  write_doubles(file, root + "/im_hi", t.im_hi, {G}, "m/s^2");
  write_longs(file, root + "/samples", t.samples, {G});
  write_longs(file, root + "/failed", t.failed, {G});
  const std::vector<hsize_t> gbf = {G, t.buildings, t.floors}, gpl = {G, t.pairs, t.levels};
  for (const auto& m : t.measures) {
    const std::string p = root + "/" + m.name;
    write_longs(file, p + "/count", m.count, gbf);
    write_doubles(file, p + "/mean", m.mean, gbf, "-");
    write_doubles(file, p + "/median", m.median, gbf, "-");
    write_doubles(file, p + "/p16", m.p16, gbf, "-");
    write_doubles(file, p + "/p84", m.p84, gbf, "-");
    write_doubles(file, p + "/fraction_above_1", m.fraction_above_1, gbf, "-");
  }
  write_longs(file, root + "/contact/count", t.contact_count, gpl);
  write_doubles(file, root + "/contact/pounded_fraction", t.pounded_fraction, gpl, "-");
  write_doubles(file, root + "/contact/force_median", t.force_median, gpl, "N");
  write_doubles(file, root + "/contact/force_median_pounded", t.force_median_pounded, gpl, "N");
  const std::vector<hsize_t> gb = {G, t.buildings};
  if (t.has_column_shear) {
    write_longs(file, root + "/column_shear/count", t.column_shear_count, gb);
    write_doubles(file, root + "/column_shear/failed_pounding", t.column_shear_failed_pounding, gb,
                  "-");
    write_doubles(file, root + "/column_shear/failed_free", t.column_shear_failed_free, gb, "-");
    h5::attribute(file, root + "/column_shear", "definition",
                  "share of the group's samples with a column-shear ratio (count) whose struck "
                  "columns' shear demand reached their strength (/response/"
                  "column_shear_ratio_pounding, _free >= 1), with and without pounding");
  }
  if (!t.has_collapse) return;
  write_longs(file, root + "/collapse/count", t.collapse_count, gb);
  write_doubles(file, root + "/collapse/collapsed_pounding", t.collapsed_pounding, gb, "-");
  write_doubles(file, root + "/collapse/collapsed_free", t.collapsed_free, gb, "-");
  if (!t.stopped_pounding.empty())  // empty: read from a group written before it existed
    write_doubles(file, root + "/collapse/stopped_pounding", t.stopped_pounding, gb, "-");
  h5::attribute(file, root + "/collapse", "definition",
                "share of the group's successful samples (count) whose building collapsed "
                "(/response/collapsed_pounding, collapsed_free = 1), with and without pounding; "
                "stopped_pounding: share whose pounding run stopped at another building's "
                "collapse while this one stood (its later response unknown)");
}

// Reads the datasets of one table under `root`, refusing a damaged group with one line before
// anything is indexed.
class TableReader {
 public:
  TableReader(hid_t file, const std::string& path, const std::string& root)
      : file_(file), path_(path), root_(root) {}

  void read(AmplificationTable* t) {
    const std::string design = h5::attribute_text(file_, root_, "design");
    if (design != "stripes" && design != "bins")
      throw bad(" has no attribute design = stripes or bins; " + kKind);
    t->stripes = design == "stripes";
    const std::string failed = h5::attribute_text(file_, root_, "failed");
    t->failed_total =
        failed.empty()
            ? 0
            : count_of(parse_number(failed, path_ + ": " + root_ + ":failed"), ":failed");
    groups(t);
    measures(t);
    contacts(t);
    collapse(t);
    column_shear(t);
  }

 private:
  static inline const std::string kKind =
      "not the /amplification group of 'pound campaign' (docs/campaign.md)";

  InputError bad(const std::string& what) const { return InputError(path_ + ": " + root_ + what); }

  // Counts are whole numbers from 0 to 1e15: a damaged file's NaN or 1e300 is refused here,
  // before a conversion to long (undefined behaviour out of range).
  long count_of(double x, const std::string& name) const {
    if (!(x >= 0.0 && x <= 1e15 && x == std::floor(x))) {
      char shown[32];
      std::snprintf(shown, sizeof shown, "%.15g", x);
      throw bad(name + " holds " + shown + "; valid: whole numbers from 0 to 1e15 (counts); " +
                kKind);
    }
    return long(x);
  }
  std::vector<long> as_longs(const std::vector<double>& v, const std::string& name) const {
    std::vector<long> out;
    out.reserve(v.size());
    for (double x : v) out.push_back(count_of(x, name));
    return out;
  }
  // Every array has G rows (the groups of im) and every 3-D array of a kind the same shape.
  std::vector<double> one_d(const std::string& name, std::size_t groups) {
    std::vector<double> v = h5::read_numbers(file_, root_ + name, path_, &dims_, kKind);
    if (dims_.size() != 1 || (name != "/im" && v.size() != groups))
      throw bad(name + " is not one value per group of " + root_ + "/im; " + kKind);
    return v;
  }
  // A 3-D array [G, a, b]; its a and b when `shape` is empty, else they must be those.
  std::vector<double> three_d(const std::string& name, std::size_t groups,
                              std::vector<hsize_t>& shape) {
    std::vector<double> v = h5::read_numbers(file_, root_ + name, path_, &dims_, kKind);
    if (dims_.size() != 3 || dims_[0] != groups || (!shape.empty() && dims_ != shape))
      throw bad(name + " is not of the shape [groups, " +
                (shape.empty() ? std::string("a, b")
                               : std::to_string(shape[1]) + ", " + std::to_string(shape[2])) +
                "]; " + kKind);
    shape = dims_;
    return v;
  }
  void groups(AmplificationTable* t) {
    t->im = one_d("/im", 0);
    t->groups = t->im.size();
    t->im_lo = one_d("/im_lo", t->groups);
    t->im_hi = one_d("/im_hi", t->groups);
    t->samples = as_longs(one_d("/samples", t->groups), "/samples");
    t->failed = as_longs(one_d("/failed", t->groups), "/failed");
  }
  void measures(AmplificationTable* t) {
    t->measures.clear();
    std::vector<hsize_t> floors;
    for (const char* name : kAmplificationMeasures) {
      AmplificationMeasure a;
      a.name = name;
      const std::string p = std::string("/") + name;
      a.count = as_longs(three_d(p + "/count", t->groups, floors), p + "/count");
      a.mean = three_d(p + "/mean", t->groups, floors);
      a.median = three_d(p + "/median", t->groups, floors);
      a.p16 = three_d(p + "/p16", t->groups, floors);
      a.p84 = three_d(p + "/p84", t->groups, floors);
      a.fraction_above_1 = three_d(p + "/fraction_above_1", t->groups, floors);
      t->measures.push_back(std::move(a));
    }
    if (floors[1] < 1 || floors[2] < 1)
      throw bad(
          "/disp/count has no building or no floor (shape [groups, buildings, floors] with "
          "buildings, floors >= 1); " +
          kKind);
    t->buildings = floors[1];
    t->floors = floors[2];
  }
  void contacts(AmplificationTable* t) {
    std::vector<hsize_t> levels;
    t->contact_count = as_longs(three_d("/contact/count", t->groups, levels), "/contact/count");
    t->pounded_fraction = three_d("/contact/pounded_fraction", t->groups, levels);
    t->force_median = three_d("/contact/force_median", t->groups, levels);
    t->force_median_pounded = three_d("/contact/force_median_pounded", t->groups, levels);
    t->pairs = levels[1];
    t->levels = levels[2];
  }
  // [G, B]: the collapse shares, when the group has them.
  std::vector<double> two_d(const std::string& name, const AmplificationTable& t) {
    std::vector<double> v = h5::read_numbers(file_, root_ + name, path_, &dims_, kKind);
    if (dims_.size() != 2 || dims_[0] != t.groups || dims_[1] != t.buildings)
      throw bad(name + " is not of the shape [groups, " + std::to_string(t.buildings) +
                "] (the buildings of /disp/count); " + kKind);
    return v;
  }
  void column_shear(AmplificationTable* t) {
    t->has_column_shear = H5Lexists(file_, (root_ + "/column_shear").c_str(), H5P_DEFAULT) > 0;
    if (!t->has_column_shear) return;
    t->column_shear_count = as_longs(two_d("/column_shear/count", *t), "/column_shear/count");
    t->column_shear_failed_pounding = two_d("/column_shear/failed_pounding", *t);
    t->column_shear_failed_free = two_d("/column_shear/failed_free", *t);
  }
  void collapse(AmplificationTable* t) {
    t->has_collapse = H5Lexists(file_, (root_ + "/collapse").c_str(), H5P_DEFAULT) > 0;
    if (!t->has_collapse) return;
    t->collapse_count = as_longs(two_d("/collapse/count", *t), "/collapse/count");
    t->collapsed_pounding = two_d("/collapse/collapsed_pounding", *t);
    t->collapsed_free = two_d("/collapse/collapsed_free", *t);
    t->stopped_pounding.clear();  // a group written before it existed: computed again
    if (H5Lexists(file_, (root_ + "/collapse/stopped_pounding").c_str(), H5P_DEFAULT) > 0)
      t->stopped_pounding = two_d("/collapse/stopped_pounding", *t);
  }

  hid_t file_;
  std::string path_, root_;
  std::vector<hsize_t> dims_;
};

}  // namespace

void write_amplification(hid_t file, const AmplificationTable& t) {
  const std::string root = "/amplification";
  write_table(file, root, t);
  h5::attribute(file, root, "quantiles",
                "linear interpolation between order statistics (Hyndman & Fan 1996, type 7)");
  h5::attribute(file, root, "definition",
                "amplification = peak with pounding / peak without pounding of each floor "
                "(drift: of the storey below it), samples with a finite, positive free value; "
                "failed samples are counted in 'failed', not used");
  if (t.models.empty()) return;
  const std::string models = root + "/models";
  h5::ensure_group(file, models);
  std::string labels;
  for (const auto& m : t.models) labels += (labels.empty() ? "" : ", ") + m.model;
  h5::attribute(file, models, "labels", labels);
  h5::attribute(file, models, "definition",
                "per contact model (/samples/model): the statistics of /amplification over the "
                "samples of that model alone, in the same intensity groups (stripes, or the "
                "pooled bin edges)");
  for (const auto& m : t.models) {
    write_table(file, models + "/" + m.model, m);
    h5::attribute(file, models + "/" + m.model, "model", m.model);
  }
}

bool read_amplification(hid_t file, const std::string& path, AmplificationTable* t) {
  const std::string root = "/amplification";
  if (H5Lexists(file, root.c_str(), H5P_DEFAULT) <= 0) return false;
  TableReader(file, path, root).read(t);
  t->model.clear();
  t->models.clear();
  const std::string models = root + "/models";
  for (const std::string& label : h5::group_members(file, models)) {
    AmplificationTable m;
    const std::string where = models + "/" + label;
    TableReader(file, path, where).read(&m);
    if (m.stripes != t->stripes || m.groups != t->groups || m.buildings != t->buildings ||
        m.floors != t->floors || m.pairs != t->pairs || m.levels != t->levels ||
        m.has_collapse != t->has_collapse)
      throw InputError(path + ": " + where +
                       " does not have the groups and shapes of /amplification; not the "
                       "/amplification group of 'pound campaign' (docs/campaign.md)");
    m.model = label;
    t->models.push_back(std::move(m));
  }
  return true;
}

bool amplification_complete(hid_t file, const AmplificationTable& t) {
  const bool collapse = H5Lexists(file, "/response", H5P_DEFAULT) > 0 &&
                        H5Lexists(file, "/response/collapsed_pounding", H5P_DEFAULT) > 0;
  const bool models = H5Lexists(file, "/samples", H5P_DEFAULT) > 0 &&
                      H5Lexists(file, "/samples/model", H5P_DEFAULT) > 0;
  return t.has_collapse == collapse && (!collapse || !t.stopped_pounding.empty()) &&
         models == !t.models.empty();
}

}  // namespace pound
