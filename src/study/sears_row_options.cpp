#include "study/sears_row_options.hpp"

#include <cmath>

#include "sears/contact_stiffness.hpp"
#include "study/row_options.hpp"

namespace pound {

std::vector<OptionSpec> sears_row_option_specs() {
  return {
      {"building#.slab_length", "m", "",
       "sears: floor slab length along the row (one value, or one per floor)"},
      {"building#.E", "Pa", "", "sears: Young's modulus of the floor slabs (one, or per floor)"},
      {"building#.rho", "kg/m^3", "", "sears: density of the floor slabs (one, or per floor)"},
      {"building#.poisson", "-", "0.15", "sears: Poisson's ratio of the floor slabs"},
      {"sears.modes", "-", "100", "sears: internal axial modes per colliding floor N"},
      {"sears.xi_s", "-", "0.05", "sears: modal damping ratio of the slabs' axial vibration"},
      {"sears.chi", "-", "0.125", "sears: wave-speed factor, c = chi sqrt(E/rho)"},
      {"sears.contact", "", "flat", "sears: flat (k_L from D, Th. 8.1-8.2) or hertz (k delta^1.5)"},
      {"sears.D", "-", "1", "sears: fraction factor of the flat contact stiffness, >= 1"},
      {"sears.k", "N/m^1.5", "", "sears: Hertz contact stiffness (contact = hertz)"},
      {"sears.radius_left", "m", "",
       "sears: hertz: radius of the left building's contact face (absent: flat)"},
      {"sears.radius_right", "m", "",
       "sears: hertz: radius of the right building's contact face (absent: flat)"},
      {"sears.force_cap", "N", "", "sears: cap PF_max on the contact force (Th. 9.1)"},
      {"sears.dt", "s", "", "sears: (fine) time step (default: automatic, docs/sears.md)"},
      {"sears.integrator", "", "event",
       "sears: event (coarse steps while a bound excludes contact, docs/speed.md) or fixed"},
      {"sears.contact_step_tolerance", "-", "0.001",
       "sears: event: steps through contacts up to the largest allowed step while the contact "
       "forces' linear interpolation error stays below this fraction of the force; 0: every "
       "one a fine step (docs/speed.md)"},
  };
}

std::vector<OptionSpec> row_and_sears_option_specs() {
  std::vector<OptionSpec> s = row_option_specs();
  const auto sears = sears_row_option_specs();
  s.insert(s.end(), sears.begin(), sears.end());
  return s;
}

sears::SearsRowModel sears_row_from_options(const Options& opt, const BuildingRow& row) {
  sears::SearsRowModel m;
  for (std::size_t b = 1; b <= row.buildings.size(); ++b) {
    const std::string pre = "building" + std::to_string(b) + ".";
    sears::FloorSlabProperties s;
    // One value for every floor, or one per floor where the floors differ.
    const std::size_t floors = row.buildings[b - 1].masses.size();
    auto values = [&](const std::string& key, double& all, std::vector<double>& per_floor) {
      const auto v = opt.get_doubles(pre + key);
      for (double x : v)
        if (!(x > 0)) throw opt.invalid(pre + key, "every value must be > 0");
      if (v.size() == 1) {
        all = v[0];
      } else if (v.size() == floors) {
        per_floor = v;
        all = v[0];
      } else {
        throw opt.invalid(pre + key,
                          "give one value or " + std::to_string(floors) + " (one per floor)");
      }
    };
    values("slab_length", s.length_m, s.length_per_floor_m);
    values("E", s.E_Pa, s.E_per_floor_Pa);
    values("rho", s.rho_kg_m3, s.rho_per_floor_kg_m3);
    s.poisson = opt.get_double(pre + "poisson");
    if (!(s.poisson >= 0 && s.poisson < 0.5)) throw opt.invalid(pre + "poisson", "valid: [0, 0.5)");
    m.slabs.push_back(s);
  }
  const long n = opt.get_int("sears.modes");
  if (n < 1) throw opt.invalid("sears.modes", "valid: a whole number >= 1");
  m.modes = static_cast<int>(n);
  m.xi_s = opt.get_double("sears.xi_s");
  if (!(m.xi_s >= 0 && m.xi_s < 1)) throw opt.invalid("sears.xi_s", "valid: [0, 1)");
  m.chi = opt.get_double("sears.chi");
  if (!(m.chi > 0 && m.chi <= 1)) throw opt.invalid("sears.chi", "valid: (0, 1]");
  const std::string c = opt.get_string("sears.contact");
  if (c == "flat") {
    m.contact = sears::ContactKind::flat;
    m.D = opt.get_double("sears.D");
    if (!(m.D >= 1)) throw opt.invalid("sears.D", "valid: a fraction factor >= 1");
  } else if (c == "hertz") {
    m.contact = sears::ContactKind::hertz;
    if (opt.given("sears.k")) {
      m.hertz_k = opt.get_positive("sears.k");
    } else if (opt.given("sears.radius_left") || opt.given("sears.radius_right")) {
      // A face without a radius is flat.
      m.hertz_radius_left = opt.given("sears.radius_left") ? opt.get_positive("sears.radius_left")
                                                           : sears::kFlatRadius;
      m.hertz_radius_right = opt.given("sears.radius_right")
                                 ? opt.get_positive("sears.radius_right")
                                 : sears::kFlatRadius;
    } else {
      throw opt.invalid("sears.contact",
                        "hertz contact needs sears.k [N/m^1.5] or sears.radius_left and/or "
                        "sears.radius_right [m] (Th. 7.2)");
    }
  } else {
    throw opt.invalid("sears.contact", "valid: flat or hertz");
  }
  if (opt.given("sears.force_cap")) m.force_cap_N = opt.get_positive("sears.force_cap");
  // The shorthands --integrator and --dt (shared with the lumped models) win.
  const std::string dt_key = opt.given("dt") ? "dt" : "sears.dt";
  if (opt.given(dt_key)) m.dt_s = opt.get_positive(dt_key);
  const std::string ikey = opt.given("integrator") ? "integrator" : "sears.integrator";
  const std::string integ = opt.get_string(ikey);
  if (integ == "event" || integ == "adaptive") {
    m.stepping = sears::SearsStepping::event;
  } else if (integ == "fixed") {
    m.stepping = sears::SearsStepping::fixed;
  } else {
    throw opt.invalid(ikey, "valid: event or fixed");
  }
  m.contact_step_tolerance = opt.get_double("sears.contact_step_tolerance");
  if (!(m.contact_step_tolerance >= 0.0 && m.contact_step_tolerance <= 0.1))
    throw opt.invalid("sears.contact_step_tolerance",
                      "valid: 0 (every step through contacts a fine one) or a fraction in "
                      "(0, 0.1]");
  return m;
}

}  // namespace pound
