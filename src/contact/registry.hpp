#pragma once
// The one registry of contact models: a name maps to a factory. Adding a lumped model is one
// file pair (a ContactLaw) plus one line in registry.cpp.
#include <memory>
#include <string>
#include <vector>

#include "contact/contact_law.hpp"

namespace pound {

struct ContactModelInfo {
  std::string name;            ///< the name users write (model = ...)
  std::string reference;       ///< paper / thesis equation
  std::string stiffness_unit;  ///< unit of k: "N/m", "N/m^1.5", or "" when k is unused
  bool uses_e = true;          ///< whether the coefficient of restitution enters
  std::unique_ptr<ContactLaw> (*make)(const ContactParameters&);
};

/// Every registered lumped model, in documentation order.
const std::vector<ContactModelInfo>& contact_models();
/// The model of that name; throws InputError listing the valid names (plus any `extra`
/// names handled elsewhere, such as "sears") when there is none.
const ContactModelInfo& find_contact_model(const std::string& name, const std::string& where);
/// Comma-separated list of the registered names.
std::string contact_model_names();

}  // namespace pound
