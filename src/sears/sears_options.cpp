#include "sears/sears_options.hpp"

#include <cmath>
#include <sstream>

#include "sears/contact_stiffness.hpp"
#include "sears/step_rule.hpp"

namespace pound::sears {

std::vector<OptionSpec> sears_impact_option_specs() {
  return {
      {"length1", "m", "", "sears: length of bar 1 (the striker) along the impact line, > 0"},
      {"length2", "m", "", "sears: length of bar 2 (struck) along the impact line, > 0"},
      {"E", "Pa", "", "sears: Young's modulus of both bars, > 0 (or --E1/--E2)"},
      {"E1", "Pa", "", "sears: Young's modulus of bar 1, > 0 (overrides --E)"},
      {"E2", "Pa", "", "sears: Young's modulus of bar 2, > 0 (overrides --E)"},
      {"rho", "kg/m^3", "", "sears: density of both bars, > 0 (or --rho1/--rho2)"},
      {"rho1", "kg/m^3", "", "sears: density of bar 1, > 0 (overrides --rho)"},
      {"rho2", "kg/m^3", "", "sears: density of bar 2, > 0 (overrides --rho)"},
      {"poisson", "-", "", "sears: Poisson's ratio of both bars, in [0, 0.5) (Hertz contact)"},
      {"poisson1", "-", "", "sears: Poisson's ratio of bar 1 (overrides --poisson)"},
      {"poisson2", "-", "", "sears: Poisson's ratio of bar 2 (overrides --poisson)"},
      {"modes", "-", "100", "sears: internal axial modes per bar N, whole number >= 1"},
      {"xi-s", "-", "0.05", "sears: modal damping ratio of the slabs' axial vibration, [0, 1)"},
      {"chi", "-", "0.125", "sears: wave-speed factor, c = chi sqrt(E/rho), in (0, 1]"},
      {"contact", "", "flat", "sears: contact law, flat (F = k_L delta) or hertz (k delta^1.5)"},
      {"D", "-", "1", "sears: flat contact fraction factor, k_A = D E A / l, >= 1"},
      {"radius1", "m", "", "sears: hertz: radius of bar 1's contact face, > 0 (absent: flat)"},
      {"radius2", "m", "", "sears: hertz: radius of bar 2's contact face, > 0 (absent: flat)"},
      {"force-cap", "N", "", "sears: cap PF_max on the contact force, > 0 (absent: none)"},
  };
}

namespace {

double positive(const Options& opt, const std::string& key, const std::string& unit) {
  const double v = opt.get_double(key);
  if (!(v > 0.0)) throw opt.invalid(key, "must be > 0 [" + unit + "]");
  return v;
}

// Per-bar value: key1/key2 when given, else the shared key; a missing value names both.
std::string bar_key(const Options& opt, const std::string& shared, int bar) {
  const std::string own = shared + std::to_string(bar);
  if (opt.given(own)) return own;
  if (opt.has(shared)) return shared;
  throw opt.invalid(shared, "missing: give --" + shared + " or --" + own +
                                " for the damped Sears model (bar " + std::to_string(bar) + ")");
}

Slab read_bar(const Options& opt, int bar, double mass, double chi, bool need_poisson) {
  Slab s;
  s.mass_kg = mass;
  s.chi = chi;
  const std::string n = std::to_string(bar);
  if (!opt.has("length" + n))
    throw opt.invalid("length" + n, "missing: the length of bar " + n + " [m] is required");
  s.length_m = positive(opt, "length" + n, "m");
  s.E_Pa = positive(opt, bar_key(opt, "E", bar), "Pa");
  s.rho_kg_m3 = positive(opt, bar_key(opt, "rho", bar), "kg/m^3");
  const bool has_poisson = opt.given("poisson" + n) || opt.has("poisson");
  if (need_poisson || has_poisson) {
    const std::string key = bar_key(opt, "poisson", bar);
    s.poisson = opt.get_double(key);
    if (!(s.poisson >= 0.0 && s.poisson < 0.5)) throw opt.invalid(key, "must be in [0, 0.5)");
  }
  return s;
}

}  // namespace

SearsImpactSpec sears_impact_spec_from(const Options& opt, double m1, double m2, double v0) {
  SearsImpactSpec spec;
  spec.v0_m_s = v0;

  const long modes = opt.get_int("modes");
  if (modes < 1 || modes > 100000)
    throw opt.invalid("modes", "must be a whole number in [1, 100000]");
  spec.modes = static_cast<int>(modes);
  spec.xi_s = opt.get_double("xi-s");
  if (!(spec.xi_s >= 0.0 && spec.xi_s < 1.0)) throw opt.invalid("xi-s", "must be in [0, 1)");
  const double chi = opt.get_double("chi");
  if (!(chi > 0.0 && chi <= 1.0)) throw opt.invalid("chi", "must be in (0, 1]");

  const std::string kind = opt.get_string("contact");
  if (kind != "flat" && kind != "hertz") throw opt.invalid("contact", "valid values: flat, hertz");
  spec.contact.kind = kind == "flat" ? ContactKind::flat : ContactKind::hertz;
  const bool k_given = opt.given("k");
  const bool need_poisson = spec.contact.kind == ContactKind::hertz && !k_given;
  spec.bar1 = read_bar(opt, 1, m1, chi, need_poisson);
  spec.bar2 = read_bar(opt, 2, m2, chi, need_poisson);

  if (k_given) {
    spec.contact.stiffness = positive(opt, "k", "N/m or N/m^1.5");
  } else if (spec.contact.kind == ContactKind::flat) {
    const double D = opt.get_double("D");
    if (!(D >= 1.0 && std::isfinite(D))) throw opt.invalid("D", "must be >= 1");
    spec.contact.stiffness = flat_contact_stiffness(spec.bar1, spec.bar2, D);
  } else {
    const double r1 = opt.given("radius1") ? positive(opt, "radius1", "m") : kFlatRadius;
    const double r2 = opt.given("radius2") ? positive(opt, "radius2", "m") : kFlatRadius;
    if (std::isinf(r1) && std::isinf(r2))
      throw opt.invalid("radius1",
                        "missing: hertz contact needs --radius1 and/or --radius2 [m] "
                        "(a curved face) or --k [N/m^1.5]");
    spec.contact.stiffness = hertz_stiffness(spec.bar1.E_Pa, spec.bar1.poisson, r1, spec.bar2.E_Pa,
                                             spec.bar2.poisson, r2);
  }
  if (opt.given("force-cap")) spec.contact.force_cap_N = positive(opt, "force-cap", "N");

  if (opt.given("dt")) {
    const double dt = positive(opt, "dt", "s");
    const StepLimits lim = sears_impact_step_limits(spec);
    if (dt > lim.max_dt_s) {
      std::ostringstream m;
      m.precision(4);
      m << "too large for the damped Sears model: the largest allowed step is " << lim.max_dt_s
        << " s (half the shortest modal period retained, or 1/20 of the contact time); "
        << "omit --dt for the automatic step " << lim.auto_dt_s << " s";
      throw opt.invalid("dt", m.str());
    }
    spec.dt_s = dt;
  }
  return spec;
}

}  // namespace pound::sears
