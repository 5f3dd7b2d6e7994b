#pragma once
// The one registry of contact models: a name maps to a factory. Adding a lumped model is one
// file pair (a ContactLaw) plus one line in registry.cpp. The damped Sears model, simulated by
// src/sears, is known here by its name only (kSearsModelName).
#include <memory>
#include <string>
#include <vector>

#include "contact/contact_law.hpp"

namespace pound {

struct ContactModelInfo {
  std::string name;            ///< the name users write (model = ...)
  std::string reference;       ///< paper / thesis equation
  std::string stiffness_unit;  ///< unit of k: "N/m", "N/m^1.5", or "" when k is unused
  std::unique_ptr<ContactLaw> (*make)(const ContactParameters&);
};

/// The name of the damped Sears model (`contact.model = sears`, or a label of a sampled
/// `model`). It is no lumped ContactLaw of this registry: src/sears simulates it, and whoever
/// chooses between the two kinds of simulation asks is_sears_model(), the one place the name is
/// matched.
inline constexpr char kSearsModelName[] = "sears";
/// Whether a contact model name is the damped Sears model.
inline bool is_sears_model(const std::string& name) {
  return name == kSearsModelName;
}

/// Every registered lumped model, in documentation order.
const std::vector<ContactModelInfo>& contact_models();
/// The lumped model of that name; throws InputError listing every valid name (the damped Sears
/// model's included) when there is none.
const ContactModelInfo& find_contact_model(const std::string& name, const std::string& where);
/// Comma-separated list of the registered (lumped) names.
std::string contact_model_names();
/// Every name a contact model may be given: the registered names, then the damped Sears model.
std::string every_contact_model_name();

}  // namespace pound
