#include "risk/study_sites.hpp"

#include "campaign/campaign_study.hpp"
#include "core/error.hpp"
#include "io/options.hpp"
#include "study/row_options.hpp"

namespace pound {

std::vector<std::vector<SiteGeometry>> study_pair_sites(const CampaignData& c) {
  Options opt("campaign", "", campaign_option_specs());
  BuildingRow row;
  try {
    opt.parse_text(c.study, c.path + " (stored study)");
    row = row_from_options(opt);
  } catch (const InputError& e) {
    throw InputError(c.path + ": the stored study's buildings cannot be read: " + e.what());
  }
  std::vector<std::vector<SiteGeometry>> out;
  for (std::size_t p = 0; p + 1 < row.buildings.size(); ++p)
    out.push_back(pair_sites(row.buildings[p], row.buildings[p + 1]));
  return out;
}

}  // namespace pound
