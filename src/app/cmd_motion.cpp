// pound motion: response spectra, design spectra and spectrum-compatible generation.
#include <iostream>

#include "app/commands.hpp"
#include "core/error.hpp"

namespace pound::app {

int run_motion(int /*argc*/, const char* const* /*argv*/) {
  throw InputError("motion: not implemented yet");
}

}  // namespace pound::app
