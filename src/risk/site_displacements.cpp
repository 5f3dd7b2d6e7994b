#include "risk/site_displacements.hpp"

#include <limits>

namespace pound {
namespace {

// u[f], NaN where the list has no floor f (a campaign file narrower than its study's row).
double floor_at(const std::vector<double>& u, int f) {
  return f >= 0 && std::size_t(f) < u.size() ? u[std::size_t(f)]
                                             : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

double struck_point_displacement(const std::vector<double>& u, int storey, double xi) {
  const double s = column_shape(xi);
  const double below = storey > 0 ? floor_at(u, storey - 1) : 0.0;  // u_0 = 0: the base
  return (1.0 - s) * below + s * floor_at(u, storey);
}

SiteDisplacements site_displacements(const SiteGeometry& g, const std::vector<double>& left,
                                     const std::vector<double>& right) {
  SiteDisplacements d;
  if (g.kind == SiteKind::slab) {  // L's floor slab_floor against R's floor hit
    d.left = floor_at(left, g.slab_floor);
    d.right = floor_at(right, g.hit);
  } else if (g.slab_side == 0) {  // L's slab against R's storey hit at xi
    d.left = floor_at(left, g.slab_floor);
    d.right = struck_point_displacement(right, g.hit, g.xi);
  } else {  // R's slab against L's storey hit at xi
    d.left = struck_point_displacement(left, g.hit, g.xi);
    d.right = floor_at(right, g.slab_floor);
  }
  return d;
}

std::vector<SiteGeometry> same_index_sites(std::size_t levels) {
  std::vector<SiteGeometry> out(levels);
  for (std::size_t l = 0; l < out.size(); ++l) out[l].slab_floor = out[l].hit = int(l);
  return out;
}

Ec8Case ec8_case(const std::vector<SiteGeometry>& sites) {
  // EN 1998-1 4.4.2.7(3): the 0.7 reduction only where the floor elevations coincide.
  if (sites.empty()) return Ec8Case::floors_offset;
  for (const auto& g : sites)
    if (g.kind != SiteKind::slab) return Ec8Case::floors_offset;
  return Ec8Case::floors_coincide;
}

}  // namespace pound
