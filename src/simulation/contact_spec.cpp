#include "simulation/contact_spec.hpp"

#include "contact/registry.hpp"

namespace pound {

std::vector<std::unique_ptr<ContactLaw>> make_site_laws(const ContactSpec& spec,
                                                        const AssembledRow& assembled) {
  const auto& info = find_contact_model(spec.model, "contact.model");
  std::vector<std::unique_ptr<ContactLaw>> laws;
  for (const auto& s : assembled.sites) {
    ContactParameters p = spec.params;
    p.m1 = 1.0 / assembled.inv_mass(s.dof_left);
    p.m2 = 1.0 / assembled.inv_mass(s.dof_right);
    laws.push_back(info.make(p));
  }
  return laws;
}

}  // namespace pound
