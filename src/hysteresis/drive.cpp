#include "hysteresis/drive.hpp"

namespace pound {

std::vector<double> drive(const StoreyLaw& law, const StoreyParameters& p,
                          const std::vector<double>& drifts) {
  std::vector<double> shear;
  shear.reserve(drifts.size());
  StoreyState committed, trial;
  double d0 = 0.0;
  for (double d1 : drifts) {
    shear.push_back(law.advance(p, committed, d0, d1, trial));
    committed = trial;
    d0 = d1;
  }
  return shear;
}

}  // namespace pound
