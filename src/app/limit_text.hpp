#pragma once
// A damage limit as the tables of pound fragility and pound risk print it.
#include <string>

#include "app/table_number.hpp"
#include "fragility/fragility_analysis.hpp"

namespace pound::app {

/// "-" for collapse, drift ratios in %, a ductility as a number, others with their SI unit.
inline std::string limit_text(Edp e, double x) {
  if (e == Edp::collapse) return "-";
  if (e == Edp::column_shear) return fmt("%.3g", x) + " x strength";
  if (e == Edp::drift || e == Edp::residual_drift) return fmt("%.3g %%", 100 * x);
  if (e == Edp::ductility) return fmt("%.4g", x);
  return fmt("%.4g ", x) + unit_of(e);
}

}  // namespace pound::app
