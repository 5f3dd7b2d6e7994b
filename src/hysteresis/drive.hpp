#pragma once
// One storey driven through a prescribed drift history by its law's incremental form (the
// storey-law tester `pound hysteresis`, issue 23): engineers calibrate a law against a cyclic
// test this way. Kernel only: no files, no printing.
#include <vector>

#include "hysteresis/storey_law.hpp"

namespace pound {

/// The storey shears [N] at the drifts [m] of a history that starts at rest (drift 0): every
/// drift is reached from the one before (from 0 for the first) along one monotone path with
/// StoreyLaw::advance() from the committed state, which the result then becomes.
std::vector<double> drive(const StoreyLaw& law, const StoreyParameters& p,
                          const std::vector<double>& drifts);

}  // namespace pound
