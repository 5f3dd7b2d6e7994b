#include "hysteresis/elastic.hpp"

namespace pound {

double ElasticStorey::advance(const StoreyParameters& p, const StoreyState& committed, double,
                              double d1, StoreyState& trial) const {
  trial = committed;
  return p.k0 * d1;
}

}  // namespace pound
