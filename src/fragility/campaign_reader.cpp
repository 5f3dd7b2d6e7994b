#include "fragility/campaign_reader.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "campaign/building_arrays.hpp"
#include "campaign/floor_arrays.hpp"
#include "campaign/sampled_parameters.hpp"
#include "core/error.hpp"
#include "io/h5.hpp"
#include "io/options.hpp"

namespace pound {
namespace {

// Closes an HDF5 identifier with the matching function at scope exit.
struct Handle {
  hid_t id;
  herr_t (*close)(hid_t);
  ~Handle() {
    if (id >= 0) close(id);
  }
};

const char* const kNotACampaign =
    "not a campaign result file of 'pound campaign' (schema in src/campaign/result_file.hpp)";

class Reader {
 public:
  explicit Reader(const std::string& path) : path_(path) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    if (H5Fis_hdf5(path.c_str()) <= 0)
      throw InputError(path +
                       ": cannot open as an HDF5 file; give a campaign result file "
                       "written by 'pound campaign --out'");
    file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file_ < 0) throw InputError(path + ": cannot open for reading");
  }
  ~Reader() { H5Fclose(file_); }
  hid_t id() const { return file_; }

  bool exists(const std::string& p) const { return H5Lexists(file_, p.c_str(), H5P_DEFAULT) > 0; }

  // A dataset of doubles (any numeric type converts) with its dimensions.
  std::vector<double> doubles(const std::string& p, std::vector<hsize_t>* dims = nullptr) const {
    return h5::read_numbers(file_, p, path_, dims, kNotACampaign);
  }

  bool is_numeric(const std::string& p) const {
    Handle ds{H5Dopen2(file_, p.c_str(), H5P_DEFAULT), H5Dclose};
    Handle ty{H5Dget_type(ds.id), H5Tclose};
    const H5T_class_t c = H5Tget_class(ty.id);
    return c == H5T_FLOAT || c == H5T_INTEGER;
  }

  // A string attribute of the root ("" when absent), or a number written as text.
  std::string text_attribute(const std::string& name) const {
    return h5::root_attribute_text(file_, name);
  }

  std::vector<std::string> members(const std::string& group) const {
    if (!exists(group)) throw missing(group);
    return h5::group_members(file_, group);
  }

  InputError missing(const std::string& what) const {
    return InputError(path_ + ": no " + what + "; " + kNotACampaign);
  }

 private:
  std::string path_;
  hid_t file_ = -1;
};

FloorArray floor_array(const Reader& r, const std::string& p, std::size_t samples) {
  std::vector<hsize_t> d;
  FloorArray a;
  a.v = r.doubles(p, &d);
  if (d.size() != 3 || d[0] != samples)
    throw InputError(r.missing(p + " of shape [samples, a, b]").what());
  a.samples = d[0];
  a.buildings = d[1];
  a.floors = d[2];
  return a;
}

}  // namespace

std::vector<std::string> split_building_names(const std::string& joined, std::size_t buildings) {
  std::vector<std::string> out;
  std::stringstream in(joined);
  std::string item;
  while (!joined.empty() && std::getline(in, item, ',')) {
    const auto b = item.find_first_not_of(" \t"), e = item.find_last_not_of(" \t");
    out.push_back(b == std::string::npos ? "" : item.substr(b, e - b + 1));
  }
  if (!joined.empty() && joined.back() == ',') out.emplace_back();  // getline drops it
  if (out.size() < buildings) out.resize(buildings);
  for (std::size_t i = 0; i < out.size(); ++i)
    if (out[i].empty()) out[i] = "building" + std::to_string(i + 1);
  return out;
}

double FloorArray::max_over_floors(std::size_t s, std::size_t b) const {
  double m = NAN;
  for (std::size_t f = 0; f < floors; ++f) {
    const double x = at(s, b, f);
    if (std::isfinite(x) && !(x <= m)) m = x;
  }
  return m;
}

std::vector<std::string> CampaignData::models() const {
  std::vector<std::string> out;
  for (const auto& m : model)
    if (std::find(out.begin(), out.end(), m) == out.end()) out.push_back(m);
  return out;
}

const FloorArray& CampaignData::floor_array(const std::string& name) const {
  const auto it = floor_arrays.find(name);
  if (it == floor_arrays.end())
    throw InputError(path + ": no dataset /response/" + name +
                     "; the file was written by a pound without it: run the campaign again "
                     "with this version to get it");
  return it->second;
}

CampaignData read_campaign(const std::string& path) {
  const Reader r(path);
  CampaignData c;
  c.path = path;
  const auto status = r.doubles("/samples/status");
  c.samples = status.size();
  for (double s : status) c.status.push_back(std::isfinite(s) ? int(s) : 1);
  c.im = r.doubles("/samples/im");
  c.scale = r.doubles("/samples/scale");
  if (c.im.size() != c.samples || c.scale.size() != c.samples)
    throw r.missing("/samples/im and /samples/scale of one length per sample");
  for (const auto& key : r.members("/samples")) {
    if (key == "id" || key == "status" || key == "message" || key == "im" || key == "scale")
      continue;
    if (!r.is_numeric("/samples/" + key)) {
      c.text_parameters.push_back(key);
      continue;
    }
    c.parameters.push_back({key, r.doubles("/samples/" + key)});
  }
  // The per-floor arrays the file holds (an older file lacks the newer ones, and may hold an
  // array under its former name), one shape.
  std::size_t floors = 0;
  for (const auto& field : floor_array_fields()) {
    const std::string p = stored_dataset_path(r.id(), std::string("/response/") + field.name);
    if (!r.exists(p)) continue;
    FloorArray a = floor_array(r, p, c.samples);
    if (c.floor_arrays.empty()) c.buildings = a.buildings, floors = a.floors;
    if (a.buildings != c.buildings || a.floors != floors)
      throw r.missing(p + " of the shape of the other /response arrays");
    c.floor_arrays.emplace(field.name, std::move(a));
  }
  if (c.floor_arrays.empty())
    throw r.missing(std::string("/response/") + floor_array_fields().front().name);
  for (const auto& field : building_array_fields()) {
    const std::string p = std::string("/response/") + field.name;
    if (!r.exists(p)) continue;
    std::vector<hsize_t> d;
    std::vector<double> v = r.doubles(p, &d);
    if (d.size() != 2 || d[0] != c.samples || d[1] != c.buildings)
      throw r.missing(p + " of shape [samples, buildings]");
    c.building_arrays.emplace(field.name, std::move(v));
  }
  if (r.exists("/samples/" + std::string(kSampledContactModelKey)))
    c.model = h5::read_strings(r.id(), "/samples/" + std::string(kSampledContactModelKey), path);
  if (!c.model.empty() && c.model.size() != c.samples)
    throw r.missing("/samples/model of one label per sample");
  c.peak_force = floor_array(r, "/response/peak_force", c.samples);
  c.impacts = floor_array(r, "/response/impacts", c.samples);
  if (r.exists("/response/approach_free"))
    c.approach_free = floor_array(r, "/response/approach_free", c.samples);

  c.study = r.text_attribute("study");
  c.intensity_measure = r.text_attribute("intensity_measure");
  c.seed = r.text_attribute("seed");
  const std::string period = r.text_attribute("im_period_s");
  c.im_period = period.empty() ? 0.0 : std::atof(period.c_str());
  c.building_names = split_building_names(r.text_attribute("building_names"), c.buildings);
  for (auto [name, to] : {std::pair{"first_periods_s", &c.first_periods},
                          std::pair{"damping_ratios", &c.damping_ratios}}) {
    const std::string text = r.text_attribute(name);
    if (!text.empty()) *to = parse_number_list(text, path + ": attribute " + name);
  }
  const std::string levels = r.text_attribute("im_levels_mps2");
  if (!levels.empty()) c.levels = parse_number_list(levels, path + ": attribute im_levels_mps2");
  return c;
}

}  // namespace pound
