#include "motion/motion_reader.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/error.hpp"
#include "core/format.hpp"
#include "io/number.hpp"
#include "io/utf8_bom.hpp"

namespace pound {
namespace {

struct Line {
  std::string text;
  int number = 0;  // 1-based
};

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

std::string at(const std::string& path, int line) {
  return path + ":" + std::to_string(line);
}

std::vector<Line> read_lines(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw InputError(path + ": is a directory, not a motion file; give the record file itself");
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the motion file; give an existing readable file");
  std::vector<Line> lines;
  std::string s;
  int n = 0;
  while (std::getline(in, s)) lines.push_back(Line{s, ++n});
  // A UTF-8 byte-order mark, as some editors save text files.
  if (!lines.empty()) strip_utf8_bom(lines[0].text);
  return lines;
}

// One finite number, or an InputError naming file and line.
double number(const std::string& tok, const std::string& where, const std::string& what) {
  double v = 0.0;
  if (read_decimal(tok, &v)) return v;
  if (names_non_finite(tok))
    throw InputError(where + ": '" + tok + "' is not finite; valid: " + what);
  throw InputError(where + ": '" + tok + "' is not a number; valid: " + what + ", each " +
                   kNumberForm);
}

std::vector<std::string> split(const std::string& s) {
  std::string t = s;
  std::replace(t.begin(), t.end(), ',', ' ');
  std::istringstream in(t);
  std::vector<std::string> out;
  std::string tok;
  while (in >> tok) out.push_back(tok);
  return out;
}

// Units named in a header line, if any.
std::optional<AccelUnits> header_units(const std::string& line) {
  const std::string s = lower(line);
  for (const char* k : {"cm/s2", "cm/s^2", "cm/sec2", "cm/s/s", "(gal)", "[gal]"})
    if (s.find(k) != std::string::npos) return AccelUnits::cm_per_s2;
  for (const char* k : {"m/s2", "m/s^2", "m/sec2", "m/s/s"})
    if (s.find(k) != std::string::npos) return AccelUnits::m_per_s2;
  for (const char* k : {"(g)", "[g]", "units of g", "units: g", "units = g"})
    if (s.find(k) != std::string::npos) return AccelUnits::g;
  return std::nullopt;
}

// The units of the values and where they come from ("stated by the header on line 3").
struct Units {
  AccelUnits units;
  std::string source;
};

// The units from the spec and the header, which must agree; one of them must exist.
Units resolve_units(const MotionFileSpec& spec, std::optional<AccelUnits> header, int header_line) {
  if (spec.units && header && *spec.units != *header)
    throw InputError(at(spec.path, header_line) + ": the header states units " +
                     units_name(*header) + " but " + units_name(*spec.units) +
                     " were given; give matching units or none");
  if (header) return {*header, "as the header states on line " + std::to_string(header_line)};
  if (spec.units)
    return {*spec.units, "as given (units = " + std::string(units_name(*spec.units)) + ")"};
  throw InputError(spec.path +
                   ":1: the units of acceleration are not stated in the header; give units "
                   "g, m/s2 or cm/s2");
}

void check_not_empty(const std::vector<double>& a, const MotionFileSpec& spec, int last_line) {
  if (a.empty())
    throw InputError(at(spec.path, last_line) +
                     ": the record holds no acceleration values; valid: at least 2 values");
  if (a.size() < 2)
    throw InputError(at(spec.path, last_line) +
                     ": the record holds one value; valid: at least 2 values");
}

// A peak acceleration outside [kMinPlausiblePga, kMaxPlausiblePga] is refused: the record's
// units or values are wrong (1e30 g), or it holds no motion (all zero), unless the spec turns
// the check off.
void check_plausible_pga(const MotionFileSpec& spec, const std::vector<double>& a_mps2,
                         const Units& u) {
  double pga = 0.0;
  for (double x : a_mps2) pga = std::max(pga, std::fabs(x));
  if (!spec.check_pga || (pga >= kMinPlausiblePga && pga <= kMaxPlausiblePga)) return;
  char text[160];
  std::snprintf(text, sizeof text, "%.6g g (%.6g m/s2)", pga / kGravity, pga);
  throw InputError(spec.path + ": peak ground acceleration " + text + " with the values read as " +
                   units_name(u.units) + " " + u.source +
                   ", which is not plausible for a ground motion; valid: a peak between 1e-06 g "
                   "and 10 g. Check the units and the values, or give " +
                   spec.check_pga_key + " to accept the record");
}

GroundMotion finish(const MotionFileSpec& spec, std::vector<double> a, double dt, const Units& u) {
  const double f = to_m_per_s2(u.units);
  for (double& x : a) {
    if (!std::isfinite(x * f))  // 1e308 g: finite as written, not in m/s2
      throw InputError(spec.path + ": the value " + std::to_string(x) + " " + units_name(u.units) +
                       " is beyond the range of a double in m/s2; valid: finite accelerations");
    x *= f;
  }
  check_plausible_pga(spec, a, u);
  return GroundMotion{spec.path, dt, std::move(a)};
}

// --- PEER NGA .AT2 -------------------------------------------------------------------------

GroundMotion read_at2(const MotionFileSpec& spec, const std::vector<Line>& lines) {
  if (lines.size() < 4)
    throw InputError(at(spec.path, int(lines.size())) +
                     ": a PEER .AT2 file needs 4 header lines; the file is shorter");
  const std::optional<AccelUnits> hu = header_units(lines[2].text);  // "UNITS OF G"
  const Units units = resolve_units(spec, hu, 3);
  // Line 4: "NPTS=  5590, DT=   .0050 SEC" or "5590   0.0050   NPTS, DT".
  const std::string h = lower(lines[3].text);
  const std::string where4 = at(spec.path, 4);
  double n = -1.0, dt = -1.0;
  const auto pn = h.find("npts=");
  const auto pd = h.find("dt=");
  bool read = false;
  if (pn != std::string::npos && pd != std::string::npos) {
    read = read_decimal_at(h, pn + 5, &n) && read_decimal_at(h, pd + 3, &dt);
  } else {
    const auto tok = split(h);
    read = tok.size() >= 2 && read_decimal(tok[0], &n) && read_decimal(tok[1], &dt);
  }
  const long npts = read && n >= 0.0 && n == std::floor(n) && n < 1e15 ? long(n) : -1;
  if (npts < 0 || !(dt > 0.0))
    throw InputError(where4 +
                     ": cannot read NPTS and DT; valid: 'NPTS= n, DT= dt SEC' or "
                     "'n dt NPTS, DT'");
  std::vector<double> a;
  for (std::size_t i = 4; i < lines.size(); ++i)
    for (const auto& tok : split(lines[i].text))
      a.push_back(number(tok, at(spec.path, lines[i].number), "acceleration values"));
  const int last = lines.empty() ? 1 : lines.back().number;
  check_not_empty(a, spec, last);
  if (long(a.size()) != npts)
    throw InputError(at(spec.path, last) + ": " + std::to_string(a.size()) +
                     " values but the header (line 4) says NPTS= " + std::to_string(npts) +
                     "; give a complete record");
  return finish(spec, std::move(a), dt, units);
}

// --- fixed-width (El Centro) ----------------------------------------------------------------

bool looks_fixed_width(const std::vector<Line>& lines) {
  bool g = false, spacing = false;
  for (const auto& l : lines) {
    if (l.text.empty() || l.text[0] != '#') break;
    const std::string s = lower(l.text);
    if (s.find("(g)") != std::string::npos) g = true;
    if (s.find("spacing") != std::string::npos && s.find("sec") != std::string::npos)
      spacing = true;
  }
  return g && spacing;
}

GroundMotion read_fixed_width(const MotionFileSpec& spec, const std::vector<Line>& lines) {
  constexpr std::size_t kWidth = 10;  // FORTRAN F10.5 fields
  std::optional<AccelUnits> hu;
  int units_line = 1;
  double n = -1.0, dt = -1.0;
  std::size_t i = 0;
  for (; i < lines.size() && !lines[i].text.empty() && lines[i].text[0] == '#'; ++i) {
    const std::string s = lower(lines[i].text);
    if (auto u = header_units(s)) {
      hu = u;
      units_line = lines[i].number;
    }
    // "#1559 points at equal spacing of 0.02 sec"
    const auto p = s.find("points at equal spacing of");
    if (p != std::string::npos && !(read_decimal_at(s, 1, &n) && read_decimal_at(s, p + 26, &dt))) {
      n = -1.0;
      dt = -1.0;
    }
  }
  const long npts = n > 0.0 && n == std::floor(n) && n < 1e15 ? long(n) : -1;
  if (npts <= 0 || !(dt > 0.0))
    throw InputError(at(spec.path, 1) +
                     ": no header line 'N points at equal spacing of DT sec'; the fixed-width "
                     "format needs it");
  // The values beyond N are dropped below, so N itself must make a record (found by
  // fuzz_motion_auto: "1 points" and two values gave a record of one).
  if (npts < 2)
    throw InputError(at(spec.path, 1) + ": the header says " + std::to_string(npts) +
                     " point; valid: at least 2 points");
  const Units units = resolve_units(spec, hu, units_line);
  std::vector<double> a;
  int last = lines.empty() ? 1 : lines.back().number;
  for (; i < lines.size(); ++i) {
    const std::string& t = lines[i].text;
    if (!t.empty() && t[0] == '#') {  // "#*** End Data ***"
      last = lines[i].number;
      break;
    }
    const std::string where = at(spec.path, lines[i].number);
    for (std::size_t c = 0; c < t.size(); c += kWidth) {
      const std::string field = trim(t.substr(c, kWidth));
      if (field.empty()) continue;
      a.push_back(number(field, where, "10-character numeric fields (8F10.5)"));
    }
    last = lines[i].number;
  }
  check_not_empty(a, spec, last);
  if (long(a.size()) < npts)
    throw InputError(at(spec.path, last) + ": " + std::to_string(a.size()) +
                     " values but the header says " + std::to_string(npts) +
                     " points; give a complete record");
  for (std::size_t k = std::size_t(npts); k < a.size(); ++k)
    if (a[k] != 0.0)
      throw InputError(at(spec.path, last) + ": more values than the header's " +
                       std::to_string(npts) +
                       " points; only zero padding of the last line is valid");
  a.resize(std::size_t(npts));
  return finish(spec, std::move(a), dt, units);
}

// --- one or two columns ---------------------------------------------------------------------

GroundMotion read_columns(const MotionFileSpec& spec, const std::vector<Line>& lines) {
  std::optional<AccelUnits> hu;
  int units_line = 1;
  double header_dt = 0.0;
  std::vector<double> t, a;
  std::vector<int> line_of;
  std::size_t ncol = 0;
  int last = lines.empty() ? 1 : lines.back().number;
  for (const auto& l : lines) {
    const std::string s = trim(l.text);
    if (s.empty()) continue;
    const std::string where = at(spec.path, l.number);
    if (s[0] == '#') {
      if (auto u = header_units(s)) {
        hu = u;
        units_line = l.number;
      }
      const std::string ls = lower(s);
      const auto p = ls.find("dt");
      if (p != std::string::npos && p + 2 < ls.size() && (ls[p + 2] == ':' || ls[p + 2] == '=') &&
          (p == 0 || !std::isalpha(static_cast<unsigned char>(ls[p - 1])))) {
        const auto tok = split(ls.substr(p + 3));
        if (!tok.empty()) header_dt = number(tok[0], where, "'# dt: X' with X in s");
      }
      continue;
    }
    const auto tok = split(s);
    if (tok.empty())  // only commas (found by fuzz_motion_columns)
      throw InputError(where +
                       ": no number on the line, only separators; valid: one column "
                       "(acceleration) or two (time in s, acceleration) on every line");
    if (ncol == 0) ncol = tok.size();
    if (ncol > 2 || tok.size() != ncol)
      throw InputError(where + ": " + std::to_string(tok.size()) +
                       " numbers on the line; valid: one column (acceleration) or two "
                       "(time in s, acceleration) on every line");
    if (ncol == 2) t.push_back(number(tok[0], where, "a time in s"));
    a.push_back(number(tok.back(), where, "an acceleration value"));
    line_of.push_back(l.number);
  }
  check_not_empty(a, spec, last);
  const Units units = resolve_units(spec, hu, units_line);
  double dt = 0.0;
  if (ncol == 2) {
    const std::size_t n = t.size();
    dt = (t.back() - t.front()) / double(n - 1);
    if (!(dt > 0.0))
      throw InputError(at(spec.path, line_of.back()) +
                       ": time does not increase; valid: uniformly increasing times");
    // Tolerance 1e-3 dt against t0 + i dt allows times printed with a few decimals.
    for (std::size_t i = 1; i < n; ++i)
      if (std::fabs(t[i] - t[0] - double(i) * dt) > 1e-3 * dt)
        throw InputError(at(spec.path, line_of[i]) + ": time " + std::to_string(t[i]) +
                         " s breaks the uniform step " + std::to_string(dt) +
                         " s; valid: a uniform time step (resample the record)");
    if (spec.dt > 0.0 && std::fabs(spec.dt - dt) > 1e-6 * dt)
      throw InputError(at(spec.path, line_of[1]) + ": the time column has step " +
                       std::to_string(dt) + " s but dt = " + std::to_string(spec.dt) +
                       " s was given; give a matching dt or none");
  } else {
    if (spec.dt > 0.0 && header_dt > 0.0 && std::fabs(spec.dt - header_dt) > 1e-6 * header_dt)
      throw InputError(spec.path + ":1: the header states dt " + std::to_string(header_dt) +
                       " s but " + std::to_string(spec.dt) + " s was given; give a matching dt");
    dt = spec.dt > 0.0 ? spec.dt : header_dt;
    if (!(dt > 0.0))
      throw InputError(spec.path +
                       ":1: one-column record without a time step; give dt [s] (> 0) or a "
                       "header line '# dt: X'");
  }
  return finish(spec, std::move(a), dt, units);
}

bool has_at2_extension(const std::string& path) {
  return path.size() >= 4 && lower(path.substr(path.size() - 4)) == ".at2";
}

}  // namespace

double to_m_per_s2(AccelUnits units) {
  switch (units) {
    case AccelUnits::g:
      return kGravity;
    case AccelUnits::m_per_s2:
      return 1.0;
    case AccelUnits::cm_per_s2:
      return 0.01;
  }
  return 1.0;
}

const char* units_name(AccelUnits units) {
  switch (units) {
    case AccelUnits::g:
      return "g";
    case AccelUnits::m_per_s2:
      return "m/s2";
    case AccelUnits::cm_per_s2:
      return "cm/s2";
  }
  return "?";
}

AccelUnits parse_accel_units(const std::string& text, const std::string& where) {
  const std::string s = lower(trim(text));
  if (s == "g") return AccelUnits::g;
  if (s == "m/s2" || s == "m/s^2") return AccelUnits::m_per_s2;
  if (s == "cm/s2" || s == "cm/s^2" || s == "gal") return AccelUnits::cm_per_s2;
  throw InputError(where + ": '" + text + "' is not a unit of acceleration; valid: g, m/s2, cm/s2");
}

MotionFormat parse_motion_format(const std::string& text, const std::string& where) {
  const std::string s = lower(trim(text));
  if (s == "automatic" || s == "auto") return MotionFormat::automatic;
  if (s == "at2" || s == "peer") return MotionFormat::peer_at2;
  if (s == "columns") return MotionFormat::columns;
  if (s == "fixed-width") return MotionFormat::fixed_width;
  throw InputError(where + ": '" + text +
                   "' is not a motion file format; valid: automatic, at2, columns, fixed-width");
}

GroundMotion read_motion(const MotionFileSpec& spec) {
  if (spec.dt < 0.0 || !std::isfinite(spec.dt))
    throw InputError(spec.path + ": dt " + std::to_string(spec.dt) + " s; valid: dt > 0 s");
  const std::vector<Line> lines = read_lines(spec.path);
  MotionFormat format = spec.format;
  if (format == MotionFormat::automatic)
    format = has_at2_extension(spec.path) ? MotionFormat::peer_at2
             : looks_fixed_width(lines)   ? MotionFormat::fixed_width
                                          : MotionFormat::columns;
  switch (format) {
    case MotionFormat::peer_at2:
      return read_at2(spec, lines);
    case MotionFormat::fixed_width:
      return read_fixed_width(spec, lines);
    default:
      return read_columns(spec, lines);
  }
}

GroundMotion motion_from_values(const std::string& name, double dt, std::vector<double> accel,
                                bool check_pga, const std::string& check_pga_key) {
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw InputError(name + ": sample spacing dt = " + format_number(dt, "%g") +
                     " s; valid: a finite dt > 0 s");
  if (accel.size() < 2)
    throw InputError(name + ": the record holds " + std::to_string(accel.size()) +
                     (accel.size() == 1 ? " value" : " values") + "; valid: at least 2 values");
  for (std::size_t i = 0; i < accel.size(); ++i)
    if (!std::isfinite(accel[i]))
      throw InputError(name + ": value " + std::to_string(i) +
                       " (t = " + format_number(double(i) * dt) + " s) is " +
                       format_number(accel[i], "%g") + "; valid: finite accelerations in m/s2");
  MotionFileSpec spec;
  spec.path = name;
  spec.check_pga = check_pga;
  spec.check_pga_key = check_pga_key;
  check_plausible_pga(spec, accel, Units{AccelUnits::m_per_s2, "(the values are in m/s2)"});
  return GroundMotion{name, dt, std::move(accel)};
}

}  // namespace pound
