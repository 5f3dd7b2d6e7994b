#pragma once
// The sampled soil and foundation parameters of a campaign (issue 29, docs/ssi.md), entries of
// the table of sampled_parameters.hpp kept here: [sample] soil_shear_velocity, soil_density
// and soil_poisson set the soil under every building on a cone or a Gazetas footing (one
// site); buildingN.soil_shear_velocity, soil_density and soil_poisson the soil under building
// N (cone or gazetas), buildingN.foundation_radius its cone's footing,
// buildingN.foundation_scale multiplies its springs and dashpots. Each is applied to the
// sample's Building::foundation and checked, when the study is read, against the foundation the
// building has (a clear message when it has another).
#include <vector>

#include "campaign/sampled_parameters.hpp"

namespace pound {

/// `table` with the soil and foundation entries after its own.
std::vector<SampledParameterSpec> with_foundation_parameters(
    std::vector<SampledParameterSpec> table);

}  // namespace pound
