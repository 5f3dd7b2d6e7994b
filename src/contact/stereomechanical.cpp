#include "contact/stereomechanical.hpp"

namespace pound {
Stereomechanical::Stereomechanical(const ContactParameters& p) : e_(p.e) {}
}  // namespace pound
