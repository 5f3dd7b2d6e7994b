#pragma once
// The contact sites of a campaign's row, for the code rules of `pound risk` (issue 36): the
// study stored in the campaign file (root attribute "study", the resolved keys) is read again
// as `pound campaign` read it (row_from_options over the campaign's keys), and each adjacent
// pair's sites follow from its floors' elevations (structure/contact_geometry.hpp). The nominal
// row: no sampled parameter moves a floor. Reads no file.
#include <vector>

#include "fragility/campaign_reader.hpp"
#include "structure/contact_geometry.hpp"

namespace pound {

/// Per adjacent pair (buildings p and p+1), its sites as pair_sites() lists them. Throws
/// InputError naming the campaign file when its stored study cannot be read (a file written by
/// another version whose keys this one does not know).
std::vector<std::vector<SiteGeometry>> study_pair_sites(const CampaignData& c);

}  // namespace pound
