#pragma once
// The study keys of each building's foundation (issue 29, docs/ssi.md), read and validated here
// once, by row_from_options, for `pound simulate`, `pound campaign` and the Python module
// (study/row_study.hpp):
//   [buildingN] foundation        fixed (default), springs, cone or gazetas
//   springs: sway_stiffness [N/m], rocking_stiffness [N m/rad], sway_damping [N s/m],
//            rocking_damping [N m s/rad]
//   cone:    foundation_radius [m], soil_shear_velocity [m/s], soil_density [kg/m^3],
//            soil_poisson [-]
//   gazetas: foundation_length [m] (along the row), foundation_width [m], and the cone's soil
//   all:     foundation_mass [kg], foundation_inertia [kg m^2], floor_inertias [kg m^2]
// A key given for another kind than the building's (or with fixed) is checked for its range and
// ignored, as another storey law's keys are.
#include <string>
#include <vector>

#include "io/options.hpp"
#include "structure/building_row.hpp"
#include "structure/foundation.hpp"

namespace pound {

/// The keys above under "building#.", with units, defaults and meanings.
std::vector<OptionSpec> foundation_option_specs();

/// Reads the foundation of the building whose keys start with `prefix` ("building2.") and which
/// has `floors` floors. Throws InputError naming the key and what is valid: an unknown
/// foundation; a stiffness or damping not > 0, Vs or rho not > 0, nu outside [0, 0.5), r not
/// > 0, a negative mass or inertia (whatever the kind); a key the kind needs missing (named at
/// the foundation key, with the key it needs); a list of
/// floor_inertias of neither one value nor one per floor.
Foundation foundation_from_options(const Options& opt, const std::string& prefix,
                                   std::size_t floors);

}  // namespace pound
