#include "structure/contact_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pound {

std::vector<double> floor_elevations(const Building& b) {
  std::vector<double> z(b.storey_heights.size());
  double level = b.base_elevation;
  for (std::size_t j = 0; j < z.size(); ++j) {
    level += b.storey_heights[j];
    z[j] = level;
  }
  return z;
}

double column_shape(double xi) {
  return xi * xi * (3.0 - 2.0 * xi);
}

double column_point_stiffness(double k_storey, double phi, double xi) {
  const double a = xi * (1.0 - xi);
  if (!(a > 0.0)) return std::numeric_limits<double>::infinity();
  return phi * k_storey / (4.0 * a * a * a);
}

namespace {

// The neighbour's floor that a slab at z meets face to face (0-based), or -1: the nearest
// floor within (t + t_other) / 2.
int facing_floor(double z, double reach, const std::vector<double>& other) {
  int best = -1;
  double dist = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < other.size(); ++k) {
    const double d = std::fabs(other[k] - z);
    if (d <= reach && d < dist) {
      dist = d;
      best = static_cast<int>(k);
    }
  }
  return best;
}

// The neighbour's storey j that a slab at z strikes (0-based) and xi there, or -1: above its
// roof, or at or below its base.
int struck_storey(double z, const Building& other, const std::vector<double>& zo, double& xi) {
  double below = other.base_elevation;
  for (std::size_t j = 0; j < zo.size(); ++j) {
    if (z > below && z < zo[j]) {
      xi = (z - below) / other.storey_heights[j];
      return static_cast<int>(j);
    }
    below = zo[j];
  }
  return -1;
}

}  // namespace

std::vector<SiteGeometry> pair_sites(const Building& left, const Building& right) {
  const std::vector<double> zl = floor_elevations(left), zr = floor_elevations(right);
  const double reach = 0.5 * (left.slab_thickness + right.slab_thickness);
  std::vector<SiteGeometry> out;
  std::vector<char> paired(zr.size(), 0);  // R's slabs already met slab to slab
  for (std::size_t j = 0; j < zl.size(); ++j) {
    SiteGeometry g;
    g.slab_floor = static_cast<int>(j);
    g.elevation = zl[j];
    const int k = facing_floor(zl[j], reach, zr);
    if (k >= 0) {
      g.hit = k;
      paired[static_cast<std::size_t>(k)] = 1;
      out.push_back(g);
      continue;
    }
    double xi = 1.0;
    const int s = struck_storey(zl[j], right, zr, xi);
    if (s < 0) continue;
    g.kind = SiteKind::column;
    g.hit = s;
    g.xi = xi;
    out.push_back(g);
  }
  for (std::size_t k = 0; k < zr.size(); ++k) {
    if (paired[k] || facing_floor(zr[k], reach, zl) >= 0) continue;
    double xi = 1.0;
    const int s = struck_storey(zr[k], left, zl, xi);
    if (s < 0) continue;
    SiteGeometry g;
    g.kind = SiteKind::column;
    g.slab_side = 1;
    g.slab_floor = static_cast<int>(k);
    g.hit = s;
    g.xi = xi;
    g.elevation = zr[k];
    out.push_back(g);
  }
  // By elevation; the left building's slab first at equal elevations (stable).
  std::stable_sort(out.begin(), out.end(), [](const SiteGeometry& a, const SiteGeometry& b) {
    return a.elevation < b.elevation;
  });
  return out;
}

}  // namespace pound
