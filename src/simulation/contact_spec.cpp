#include "simulation/contact_spec.hpp"

#include "contact/column_series.hpp"
#include "contact/registry.hpp"

namespace pound {

std::vector<std::unique_ptr<ContactLaw>> make_site_laws(const ContactSpec& spec,
                                                        const AssembledRow& assembled) {
  const auto& info = find_contact_model(spec.model, "contact.model");
  std::vector<std::unique_ptr<ContactLaw>> laws;
  for (const auto& s : assembled.sites) {
    ContactParameters p = spec.params;
    // The sides' apparent masses (a slab: its floor mass; physics.md section 5b).
    p.m1 = s.mass_left;
    p.m2 = s.mass_right;
    laws.push_back(column_law(info, p, s.column_stiffness));
  }
  return laws;
}

}  // namespace pound
