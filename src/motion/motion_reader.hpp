#pragma once
// Readers for recorded ground motions. Three formats:
//
//  * PEER NGA `.AT2`: four header lines (the third names the units, "... IN UNITS OF G"; the
//    fourth gives "NPTS= n, DT= dt SEC" or "n dt NPTS, DT"), then the values, any number per
//    line. The value count must equal NPTS.
//  * Plain columns: one column (acceleration, dt from the spec or a "# dt: X" header line) or
//    two columns (time [s], acceleration). Lines starting with '#' are header lines; a header
//    line "# units: g|m/s2|cm/s2" (or one containing "(g)", "[g]", ...) states the units.
//  * Fixed width, like the 1940 El Centro file: '#' header lines saying "N points at equal
//    spacing of DT sec" and "The units are (g)", then 10-character fields (FORTRAN 8F10.5).
//    The last data line may be padded with zeros to a full line; values beyond N must be 0.
//
// Units are never guessed: they come from the spec or from the header; when both are given
// they must agree. Every error is an InputError "FILE:LINE: what is wrong; what is valid".
#include <optional>
#include <string>
#include <vector>

#include "motion/ground_motion.hpp"
#include "motion/motion_processing.hpp"

namespace pound {

enum class AccelUnits { g, m_per_s2, cm_per_s2 };
enum class MotionFormat { automatic, peer_at2, columns, fixed_width };

struct MotionFileSpec {
  std::string path;
  /// automatic: a .AT2 extension -> peer_at2; a '#' header naming "(g)" and "... spacing of
  /// DT sec" like the El Centro file -> fixed_width; otherwise columns.
  MotionFormat format = MotionFormat::automatic;
  /// Units of the values in the file; required unless the header states them.
  std::optional<AccelUnits> units;
  /// Sample spacing [s]; required for one-column files unless the header states it.
  double dt = 0.0;
  /// Refuse a record whose peak acceleration lies outside [kMinPlausiblePga,
  /// kMaxPlausiblePga] (wrong units or values, or no motion at all), naming the units the
  /// values were read in and where they came from.
  bool check_pga = true;
  /// How the user turns that check off, for its error message.
  std::string check_pga_key = "[motion] check_pga = false";
};

/// Bounds of a plausible peak ground acceleration [m/s^2]: 1e-6 g (far below any felt
/// motion) and 10 g (above the largest recorded, about 4 g in Iwate-Miyagi 2008).
inline constexpr double kMinPlausiblePga = 1e-6 * kGravity;
inline constexpr double kMaxPlausiblePga = 10.0 * kGravity;

/// Reads a record; the acceleration is converted to m/s^2 (g -> kGravity). The name is the
/// file path. Throws InputError naming the file and line on: a file that cannot be opened, a
/// non-numeric or non-finite value, a non-uniform time step, a missing or conflicting unit or
/// dt, a value count different from the header's, an empty record, a directory, and (with
/// check_pga) a peak acceleration that is not plausible.
GroundMotion read_motion(const MotionFileSpec& spec);

/// A record given as values instead of a file (the Python module's motion=(dt, ag)), checked as
/// read_motion checks a file's: dt finite and > 0 [s], at least 2 values, every value finite
/// [m/s^2] and, with check_pga, a plausible peak. `name` names the record in the messages (it
/// becomes the motion's name), `check_pga_key` says how the caller turns the check off.
GroundMotion motion_from_values(const std::string& name, double dt, std::vector<double> accel,
                                bool check_pga, const std::string& check_pga_key);

/// "g", "m/s2" (also "m/s^2"), "cm/s2" (also "cm/s^2", "gal"). Throws InputError
/// "WHERE: 'text' is not a unit of acceleration; valid: g, m/s2, cm/s2".
AccelUnits parse_accel_units(const std::string& text, const std::string& where);

/// Factor converting a value in `units` to m/s^2.
double to_m_per_s2(AccelUnits units);

/// "g", "m/s2" or "cm/s2".
const char* units_name(AccelUnits units);

/// "automatic", "at2", "columns", "fixed-width"; parse_motion_format accepts the same names.
MotionFormat parse_motion_format(const std::string& text, const std::string& where);

}  // namespace pound
