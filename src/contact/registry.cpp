#include "contact/registry.hpp"

#include "contact/hunt_crossley.hpp"
#include "contact/lve.hpp"
#include "contact/mlve.hpp"
#include "contact/nlve.hpp"
#include "contact/rate_damped.hpp"
#include "contact/stereomechanical.hpp"
#include "core/error.hpp"

namespace pound {
namespace {
template <class Law>
std::unique_ptr<ContactLaw> make(const ContactParameters& p) {
  return std::make_unique<Law>(p);
}
template <int TenthsOfExponent>
std::unique_ptr<ContactLaw> make_hc(const ContactParameters& p) {
  return std::make_unique<HuntCrossley>(p, TenthsOfExponent / 10.0);
}
}  // namespace

const std::vector<ContactModelInfo>& contact_models() {
  static const std::vector<ContactModelInfo> models = {
      {"stereomechanical", "Goldsmith 1960", "", make<Stereomechanical>},
      {"lve", "Anagnostopoulos 1988 (Th. 3.1)", "N/m", make<LinearViscoelastic>},
      {"mlve", "Mahmoud & Jankowski 2011 (Th. 3.2)", "N/m", make<ModifiedLinearViscoelastic>},
      {"nlve", "Jankowski 2005 (Th. 3.3)", "N/m^1.5", make<NonlinearViscoelastic>},
      {"hertzdamp", "Muthukumar & DesRoches 2006", "N/m^1.5", make_hertzdamp},
      {"hertzdamp-ye", "Ye, Li & Zhu 2009", "N/m^1.5", make_hertzdamp_ye},
      {"kelvin-ye", "Ye, Li & Zhu 2009", "N/m", make_kelvin_ye},
      {"hc-linear", "exact Hunt-Crossley, Khatiwada et al. 2014 (Th. 4.20)", "N/m", make_hc<10>},
      {"hc-hertz", "exact Hunt-Crossley, Khatiwada et al. 2014 (Th. 4.20)", "N/m^1.5", make_hc<15>},
  };
  return models;
}

std::string contact_model_names() {
  std::string s;
  for (const auto& m : contact_models()) s += (s.empty() ? "" : ", ") + m.name;
  return s;
}

std::string every_contact_model_name() {
  return contact_model_names() + ", " + kSearsModelName;
}

const ContactModelInfo& find_contact_model(const std::string& name, const std::string& where) {
  for (const auto& m : contact_models())
    if (m.name == name) return m;
  throw InputError(where + ": unknown contact model '" + name +
                   "'; valid: " + every_contact_model_name());
}

}  // namespace pound
