#pragma once
// The one registry of storey hysteresis laws: a name maps to the law. Adding a law is one file
// pair (a StoreyLaw) plus one line in registry.cpp.
#include <string>
#include <vector>

#include "hysteresis/storey_law.hpp"

namespace pound {

struct StoreyLawInfo {
  std::string name;       ///< the name users write ([buildingN] hysteresis = ...)
  std::string reference;  ///< paper or book
  const StoreyLaw* law;   ///< stateless; shared by every storey
};

/// Every registered law, in documentation order ("elastic" first).
const std::vector<StoreyLawInfo>& storey_laws();
/// The law of that name; throws InputError naming `where` and the valid names.
const StoreyLaw& find_storey_law(const std::string& name, const std::string& where);
/// Comma-separated list of the registered names.
std::string storey_law_names();

}  // namespace pound
