#pragma once
// Reads a campaign result file (schema in campaign/result_file.hpp) read-only: the sample
// table, the per-floor responses with and without pounding (campaign/floor_arrays.hpp), the
// peak pounding forces and the root attributes the fragility analysis needs. The file is opened
// with H5F_ACC_RDONLY and never modified.
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "campaign/collapse_flags.hpp"

namespace pound {

/// Responses per sample, building and floor, row-major [samples][buildings][floors]
/// (NaN where a building has fewer floors or the sample failed).
struct FloorArray {
  std::size_t samples = 0, buildings = 0, floors = 0;
  std::vector<double> v;
  double at(std::size_t s, std::size_t b, std::size_t f) const {
    return v[(s * buildings + b) * floors + f];
  }
  /// Largest finite value over the floors of building b in sample s (NaN if none).
  double max_over_floors(std::size_t s, std::size_t b) const;
};

struct SampledColumn {
  std::string key;             ///< study key under [sample], e.g. "gap", "k_factor"
  std::vector<double> values;  ///< per sample (SI, as stored)
};

/// The building names of a result file's attribute building_names ("a, b, c"): item i, trimmed,
/// for building i, or "building<i+1>" where it is empty or missing, for `buildings` buildings
/// (more when the attribute lists more).
std::vector<std::string> split_building_names(const std::string& joined, std::size_t buildings);

struct CampaignData {
  std::string path;
  std::string study;              ///< resolved study text (root attribute "study")
  std::string intensity_measure;  ///< "pga" or "sa"
  double im_period = 0.0;         ///< T1 of Sa(T1) [s] (0 for PGA)
  std::string seed;               ///< study seed (root attribute)
  std::vector<std::string> building_names;
  /// Each building's first period [s] and damping ratio [-] with the study's fixed properties
  /// (root attributes first_periods_s, damping_ratios); empty in a file written before them.
  std::vector<double> first_periods, damping_ratios;
  /// The name of building b (0-based), or "building<b+1>" when the file names none.
  std::string building_name(std::size_t b) const {
    return b < building_names.size() ? building_names[b] : "building" + std::to_string(b + 1);
  }
  std::vector<double> levels;  ///< stripe intensities [m/s^2]; empty: continuous IM
  std::size_t samples = 0;
  std::vector<int> status;                   ///< 0 ok, else failed
  std::vector<double> im;                    ///< intensity of the scaled motion [m/s^2]
  std::vector<double> scale;                 ///< scale factor on the motion [-]
  std::vector<SampledColumn> parameters;     ///< numeric sampled parameters
  std::vector<std::string> text_parameters;  ///< sampled labels (e.g. model), not ranked
  std::size_t buildings = 0;                 ///< buildings of the row
  /// The per-floor arrays of campaign/floor_arrays.hpp that the file holds, by dataset name
  /// under /response ("peak_drift_ratio_pounding", "ductility_free", ...; units as listed
  /// there), also when the file holds it under its former name (stored_dataset_path). A file
  /// written before an array existed lacks it.
  std::map<std::string, FloorArray> floor_arrays;
  /// Peak pounding force [samples][pairs][levels] [N]; pair p lies between buildings p, p+1.
  FloorArray peak_force;
  /// Contact phases started in the pounding run [samples][pairs][levels] [-] (> 0: contact).
  FloorArray impacts;
  /// Peak approach u_L - u_R of the facing floors in the free run [samples][pairs][levels]
  /// [m]; empty (samples = 0) in a file written before it existed (has_approach()).
  FloorArray approach_free;
  bool has_approach() const { return approach_free.samples == samples && samples > 0; }

  /// The per-building arrays of campaign/building_arrays.hpp the file holds
  /// ([samples][buildings]: collapsed_pounding, collapse_time_free, ...); a file written before
  /// they existed lacks them.
  std::map<std::string, std::vector<double>> building_arrays;
  bool has_collapse() const {
    return building_arrays.count("collapsed_pounding") && building_arrays.count("collapsed_free");
  }
  /// Whether building b collapsed in sample s (false without the arrays).
  bool collapsed(std::size_t s, std::size_t b, bool pounding) const {
    const auto it = building_arrays.find(pounding ? "collapsed_pounding" : "collapsed_free");
    return it != building_arrays.end() && it->second[s * buildings + b] == 1.0;
  }
  /// Whether the pounding run of sample s stopped at another building's collapse while
  /// building b stood: b's later response is unknown (the run stops at its first collapse).
  bool censored(std::size_t s, std::size_t b) const {
    const auto it = building_arrays.find("collapsed_pounding");
    return it != building_arrays.end() &&
           stopped_by_another(it->second.data() + s * buildings, buildings, b);
  }
  /// Each sample's contact model when the study samples it (/samples/model), else empty.
  std::vector<std::string> model;
  /// The distinct models of `model`, in first-seen order (empty when not sampled).
  std::vector<std::string> models() const;

  bool has(const std::string& name) const { return floor_arrays.count(name) > 0; }
  /// The per-floor array of that name; throws InputError naming the file and the missing
  /// dataset when the file does not hold it.
  const FloorArray& floor_array(const std::string& name) const;
};

/// Throws InputError naming the file and what is missing when it is not a campaign file.
CampaignData read_campaign(const std::string& path);

}  // namespace pound
