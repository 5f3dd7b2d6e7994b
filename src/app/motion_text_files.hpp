#pragma once
// The text files of `pound motion generate`: a motion (time [s], acceleration [g]) and a motion's
// own target (period [s], Sa [g]), each written whole or not at all (AtomicPath).
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "motion/ground_motion.hpp"

namespace pound::app {

inline void write_text(const std::string& path, const GroundMotion& m, const std::string& header) {
  AtomicPath out(path);
  {
    std::ofstream f(out.temp());
    if (!f) throw InputError(path + ": cannot write; give a writable --out folder");
    f << header << "# units: g\n# dt: " << m.dt << " s\n# columns: time [s], acceleration [g]\n";
    char line[64];
    for (std::size_t i = 0; i < m.accel.size(); ++i) {
      std::snprintf(line, sizeof line, "%.4f %.9e\n", m.dt * double(i), m.accel[i] / kGravity);
      f << line;
    }
    if (!f) throw InputError(path + ": write failed");
  }
  out.commit();
}

// A motion's own target: period [s], Sa [g].
inline void write_target(const std::string& path, const std::vector<double>& periods,
                         const std::vector<double>& sa, const std::string& header) {
  AtomicPath out(path);
  {
    std::ofstream f(out.temp());
    if (!f) throw InputError(path + ": cannot write; give a writable --out folder");
    f << header << "# columns: period [s], Sa [g] (5 % damping pseudo-acceleration)\n";
    char line[64];
    for (std::size_t j = 0; j < periods.size(); ++j) {
      std::snprintf(line, sizeof line, "%.6f %.9e\n", periods[j], sa[j] / kGravity);
      f << line;
    }
    if (!f) throw InputError(path + ": write failed");
  }
  out.commit();
}

}  // namespace pound::app
