#pragma once
// Which contact model acts between the buildings of a row, with its parameters.
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "contact/contact_law.hpp"
#include "structure/building_row.hpp"

namespace pound {

struct ContactSpec {
  std::string model = "lve";  ///< a registered lumped model name (see contact/registry.hpp)
  ContactParameters params;   ///< k, e, v0_min, xi_relation; m1, m2 are set per site
  /// Crushing faces: the cap on every site's contact force [N] (RowProblem::force_cap;
  /// docs/contact-models.md); infinite: none.
  double force_cap = std::numeric_limits<double>::infinity();
};

/// One law per contact site of the assembled row, with that site's floor masses.
std::vector<std::unique_ptr<ContactLaw>> make_site_laws(const ContactSpec& spec,
                                                        const AssembledRow& assembled);

}  // namespace pound
