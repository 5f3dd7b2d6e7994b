// pound: probabilistic seismic pounding assessment. Dispatches to the subcommands and turns
// every error into one line on stderr and a non-zero exit code.
#include <hdf5.h>

#include <cstring>
#include <exception>
#include <iostream>
#include <string>

#include "app/commands.hpp"
#include "core/error.hpp"
#include "pound/version.hpp"

namespace {

struct Command {
  const char* name;
  int (*run)(int, const char* const*);
  const char* summary;
};

const Command kCommands[] = {
    {"impact", pound::app::run_impact, "two free bodies colliding once through a contact model"},
    {"simulate", pound::app::run_simulate,
     "buildings in a row under a ground motion, with and without pounding"},
    {"motion", pound::app::run_motion,
     "ground motions: response spectra, design spectra, spectrum-compatible generation"},
    {"campaign", pound::app::run_campaign,
     "Monte Carlo campaign over MPI ranks, results in one HDF5 file (mpirun -np N ...)"},
    {"merge", pound::app::run_merge, "joins the parts of a campaign split with --sample-range"},
    {"fragility", pound::app::run_fragility,
     "fragility curves with and without pounding from a campaign file"},
    {"summary", pound::app::run_summary,
     "amplification statistics of a campaign file per intensity, building and floor"},
    {"risk", pound::app::run_risk,
     "pounding risk at every gap from a campaign and a hazard curve; the gap for a target"},
    {"hysteresis", pound::app::run_hysteresis,
     "one storey driven through a drift history by a storey law (drift_m,shear_N)"},
};

void usage(std::ostream& out) {
  out << "pound " << pound::kVersion << " (" << pound::kGitRevision
      << "): probabilistic seismic pounding assessment\n\nUsage: pound COMMAND [options]\n\n"
         "Commands:\n";
  for (const auto& c : kCommands) out << "  " << c.name << "\t" << c.summary << "\n";
  out << "\n'pound COMMAND --help' lists the command's options with units and defaults.\n";
}

}  // namespace

int main(int argc, char** argv) {
  // HDF5 1.10.8 closes the files still registered when the process exits; a file whose close
  // failed on a full disk is one, and closing it again crashes (H5F__close_cb). Every file is
  // closed by its owner (a failed one is then deleted), so the library's exit handler is not
  // needed. Must come before any other HDF5 call.
  H5dont_atexit();
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    usage(std::cout);
    return argc < 2 ? 2 : 0;
  }
  if (!std::strcmp(argv[1], "--version")) {
    std::cout << "pound " << pound::kVersion << " " << pound::kGitRevision << "\n";
    return 0;
  }
  for (const auto& c : kCommands) {
    if (std::strcmp(argv[1], c.name) != 0) continue;
    try {
      return c.run(argc - 1, argv + 1);
    } catch (const pound::InputError& e) {
      std::cerr << "pound " << c.name << ": error: " << e.what() << "\n";
      return 2;
    } catch (const pound::NumericalError& e) {
      std::cerr << "pound " << c.name << ": numerical failure: " << e.what() << "\n";
      return 3;
    } catch (const std::exception& e) {
      std::cerr << "pound " << c.name << ": internal error: " << e.what() << "\n";
      return 1;
    }
  }
  std::string names;
  for (const auto& c : kCommands) names += (names.empty() ? "" : ", ") + std::string(c.name);
  std::cerr << "pound: error: unknown command '" << argv[1] << "'; valid commands: " << names
            << " (see 'pound --help')\n";
  return 2;
}
