// pound merge: joins the result files of a campaign split into sample ranges.
#include <fstream>
#include <iostream>
#include <sstream>

#include "app/commands.hpp"
#include "app/help.hpp"
#include "campaign/merge.hpp"
#include "io/atomic_file.hpp"
#include "io/options.hpp"

namespace pound::app {

int run_merge(int argc, const char* const* argv) {
  Options opt("merge",
              "Joins the parts of a campaign run with --sample-range into one result file equal "
              "to a single run.",
              {{"out", "", "", "merged result file (HDF5)"},
               {"parts", "", "", "the part files (comma or space separated), in any order"},
               {"force", "", "", "overwrite an existing output file", true}});
  if (help_asked(opt, argc, argv)) return 0;
  if (!opt.given("out") || !opt.given("parts"))
    throw InputError("command line: --out MERGED.h5 and --parts 'A.h5,B.h5,...' are required");
  std::string list = opt.get_string("parts");
  for (char& c : list)
    if (c == ',') c = ' ';
  std::istringstream in(list);
  std::vector<std::string> parts;
  for (std::string p; in >> p;) parts.push_back(p);
  const std::string out = opt.get_string("out");
  if (!opt.flag("force") && std::ifstream(out).good())
    throw InputError(out + ": exists; use --force to overwrite it");
  AtomicPath tmp(out);
  merge_campaign_parts(parts, tmp.temp());
  tmp.commit();
  std::cerr << "merge: " << parts.size() << " parts written to " << out << "\n";
  return 0;
}

}  // namespace pound::app
