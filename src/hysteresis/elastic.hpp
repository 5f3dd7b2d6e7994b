#pragma once
// Linear elastic storey, V = k0 d (physics.md section 1, Th. 3.6): the default, with which
// every result stays as it was before storeys could yield.
#include "hysteresis/storey_law.hpp"

namespace pound {

class ElasticStorey final : public StoreyLaw {
 public:
  const char* name() const override { return "elastic"; }
  bool linear() const override { return true; }
  double shear(const StoreyParameters& p, const StoreyState&, double d,
               const double*) const override {
    return p.k0 * d;
  }
  bool branch_line(const StoreyParameters& p, const StoreyState&, double& slope,
                   double& offset) const override {
    slope = p.k0;
    offset = 0.0;
    return true;
  }
  double stored(const StoreyParameters& p, const StoreyState&, double d,
                const double*) const override {
    return 0.5 * p.k0 * d * d;
  }
  double advance(const StoreyParameters& p, const StoreyState& committed, double, double d1,
                 StoreyState& trial) const override;
};

}  // namespace pound
