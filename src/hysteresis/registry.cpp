#include "hysteresis/registry.hpp"

#include "core/error.hpp"
#include "hysteresis/bilinear.hpp"
#include "hysteresis/bouc_wen.hpp"
#include "hysteresis/elastic.hpp"
#include "hysteresis/imk.hpp"

namespace pound {

const std::vector<StoreyLawInfo>& storey_laws() {
  static const ElasticStorey elastic;
  static const BilinearStorey bilinear;
  static const BoucWenStorey bouc_wen;
  static const ImkStorey imk;
  static const std::vector<StoreyLawInfo> laws = {
      {"elastic", "linear elastic, Th. 3.6", &elastic},
      {"bilinear", "kinematic hardening, OpenSees Steel01 without isotropic hardening", &bilinear},
      {"bouc-wen", "Bouc 1967, Wen 1976", &bouc_wen},
      {"imk", "peak-oriented modified Ibarra-Medina-Krawinkler, OpenSees IMKPeakOriented", &imk},
  };
  return laws;
}

std::string storey_law_names() {
  std::string s;
  for (const auto& l : storey_laws()) s += (s.empty() ? "" : ", ") + l.name;
  return s;
}

const StoreyLaw& find_storey_law(const std::string& name, const std::string& where) {
  for (const auto& l : storey_laws())
    if (l.name == name) return *l.law;
  throw InputError(where + ": unknown hysteresis law '" + name + "'; valid: " + storey_law_names());
}

}  // namespace pound
