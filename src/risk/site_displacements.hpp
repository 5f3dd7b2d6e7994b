#pragma once
// What the code rules of `pound risk` combine at each contact site of a pair (docs/risk.md,
// "Code rules"; issue 36). EN 1998-1 4.4.2.7 takes the peak displacements of the two buildings
// at the level of the potential contact. At a slab-to-slab site that is each building's
// colliding floor; at a slab-to-column site it is the striking slab's floor and the struck
// point of the neighbour's storey j at xi, which sways as the columns of a shear building do:
//
//   u = (1 - s) u_{j-1} + s u_j,   s = column_shape(xi) = 3 xi^2 - 2 xi^3,   u_0 = 0 (the base)
//
// taken on the peak floor displacements (an estimate: the two floors' peaks need not be
// simultaneous; the weights sum to 1, so it lies between them). Whether the pair's floors
// coincide, the case of the ec8 rule, follows from the same sites. Pure: numbers in and out.
#include <vector>

#include "risk/code_rules.hpp"
#include "structure/contact_geometry.hpp"

namespace pound {

/// The peak displacements [m] of the left and the right building's points at one site.
struct SiteDisplacements {
  double left = 0.0, right = 0.0;
};

/// The struck point of storey j (0-based; it joins floor j-1, the base when j = 0, to floor j)
/// at xi: (1 - s) u[j-1] + s u[j] with u[-1] = 0 [m]; u: peak displacement per floor, floor 1
/// first [m].
double struck_point_displacement(const std::vector<double>& u, int storey, double xi);

/// Each side's displacement at site g of a pair, from the peak displacements per floor of the
/// left and the right building [m]. A slab site takes the two floors' own values (bit for bit).
SiteDisplacements site_displacements(const SiteGeometry& g, const std::vector<double>& left,
                                     const std::vector<double>& right);

/// The sites of a pair whose floors were not read: floor l against floor l, l < levels, slab to
/// slab (the pairing before issue 36).
std::vector<SiteGeometry> same_index_sites(std::size_t levels);

/// EN 1998-1 4.4.2.7(3) for a pair with these sites: floors_coincide when there is a site and
/// every one is slab to slab, floors_offset otherwise.
Ec8Case ec8_case(const std::vector<SiteGeometry>& sites);

}  // namespace pound
