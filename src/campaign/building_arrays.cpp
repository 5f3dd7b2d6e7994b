#include "campaign/building_arrays.hpp"

#include <limits>

#include "campaign/sample.hpp"
#include "simulation/simulate_row.hpp"

namespace pound {
namespace {

// A building's collapse in one run of the simulation (standing when the run does not check).
BuildingCollapse of(const std::vector<BuildingCollapse>& c, int b) {
  return static_cast<std::size_t>(b) < c.size() ? c[static_cast<std::size_t>(b)]
                                                : BuildingCollapse{};
}
double flag(const BuildingCollapse& c) {
  return c.collapsed ? 1.0 : 0.0;
}
double at(const std::vector<double>& v, int b) {
  return static_cast<std::size_t>(b) < v.size() ? v[static_cast<std::size_t>(b)]
                                                : std::numeric_limits<double>::quiet_NaN();
}
double time(const BuildingCollapse& c) {
  return c.collapsed ? c.time : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

const std::vector<BuildingArrayField>& building_array_fields() {
  using O = SampleOutcome;
  using S = RowSimulation;
  static const std::vector<BuildingArrayField> fields = {
      {"collapsed_pounding", "-",
       "1 when the building collapsed in the pounding run (which stops at its first collapse), "
       "else 0",
       &O::collapsed_pounding, [](const S& s, int b) { return flag(of(s.collapse_pounding, b)); }},
      {"collapsed_free", "-", "1 when the building collapsed without pounding, else 0",
       &O::collapsed_free, [](const S& s, int b) { return flag(of(s.collapse_free, b)); }},
      {"collapse_time_pounding", "s",
       "time of the building's collapse in the pounding run (NaN: standing)",
       &O::collapse_time_pounding,
       [](const S& s, int b) { return time(of(s.collapse_pounding, b)); }},
      {"collapse_time_free", "s",
       "time of the building's collapse without pounding (NaN: standing)", &O::collapse_time_free,
       [](const S& s, int b) { return time(of(s.collapse_free, b)); }},
      {"column_shear_ratio_pounding", "-",
       "largest shear demand over column_shear_strength of the building's storeys that a "
       "neighbour's slab strikes, with pounding (NaN: no strength or no such storey; issue 36)",
       &O::column_shear_ratio_pounding,
       [](const S& s, int b) { return at(s.column_shear_ratio_pounding, b); }},
      {"column_shear_ratio_free", "-",
       "the same without pounding: the sway shear of the face's columns alone",
       &O::column_shear_ratio_free,
       [](const S& s, int b) { return at(s.column_shear_ratio_free, b); }},
  };
  return fields;
}

}  // namespace pound
