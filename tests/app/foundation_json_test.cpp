// What `pound simulate --json` reports of a foundation (issue 29; docs/ssi.md): each building's
// periods_s with its foundation, the `foundation` object's constants in SI, and its base's peak
// sway and rotation, checked against closed forms written here and against the library's run.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "../support/scratch_dir.hpp"
#include "../support/shell.hpp"
#include "study/simulation_run.hpp"

namespace pound {
namespace {

using test::run_command;
using test::ScratchDir;
using test::slurp;

const std::string kStudy = std::string(POUND_SOURCE_DIR) + "/studies/ch6-sdof-pair.ini";

// The two SDOFs of studies/ch6-sdof-pair.ini: 100 kg each, k = 15791.37 N/m (T = 0.5 s) and
// 7018.39 N/m, 3 m storeys (the default height).
constexpr double kM = 100.0, kK1 = 15791.37, kK2 = 7018.39, kH = 3.0;

// Building 1 on a small cone on very soft soil (r = 0.5 m, Vs = 20 m/s, rho = 1800 kg/m^3,
// nu = 0.3; massless): k / K_x = 0.0093, k h^2 / K_theta = 0.42. Building 2 on a cone at
// nu = 0.45 (Vp capped, trapped soil), with I_0 = 50 kg m^2 and no mass.
const std::vector<std::string> kFlags = {
    "--building1.foundation",          "cone", "--building1.foundation_radius",   "0.5",
    "--building1.soil_shear_velocity", "20",   "--building1.soil_density",        "1800",
    "--building1.soil_poisson",        "0.3",  "--building2.foundation",          "cone",
    "--building2.foundation_radius",   "0.5",  "--building2.soil_shear_velocity", "20",
    "--building2.soil_density",        "1800", "--building2.soil_poisson",        "0.45",
    "--building2.foundation_inertia",  "50"};

// The text of building b's object (0-based) in the JSON.
std::string building(const std::string& json, int b) {
  const std::size_t at = json.find("{\"index\":" + std::to_string(b) + ",");
  EXPECT_NE(at, std::string::npos) << json;
  const std::size_t end = json.find("{\"index\":" + std::to_string(b + 1) + ",", at);
  return json.substr(at, end == std::string::npos ? std::string::npos : end - at);
}

// The number after "key": in `text` (NaN when absent or null).
double number(const std::string& text, const std::string& key) {
  const std::size_t at = text.find("\"" + key + "\":");
  if (at == std::string::npos) return std::nan("");
  const char* s = text.c_str() + at + key.size() + 3;
  char* end = nullptr;
  const double x = std::strtod(s, &end);
  return end == s ? std::nan("") : x;
}

std::vector<double> periods(const std::string& text) {
  std::vector<double> out;
  std::size_t at = text.find("\"periods_s\":[");
  if (at == std::string::npos) return out;
  const char* s = text.c_str() + at + 13;
  while (*s != ']') {
    char* end = nullptr;
    out.push_back(std::strtod(s, &end));
    s = *end == ',' ? end + 1 : end;
  }
  return out;
}

// The periods of an SDOF (m, k, h) on a foundation in coordinates relative to the base
// (floor u, sway u0, rotation theta): M = [[m, m, m h], [m, m + m0, m h], [m h, m h,
// m h^2 + I]], K = diag(k, K_x, K_theta); 2 pi sqrt(mu) for the non-zero eigenvalues mu of
// K^-1 M, longest first.
std::vector<double> relative_sdof_periods(double m, double k, double h, double kx, double kr,
                                          double m0, double inertia) {
  Eigen::Matrix3d M;
  M << m, m, m * h, m, m + m0, m * h, m * h, m * h, m * h * h + inertia;
  const Eigen::Vector3d s(1 / std::sqrt(k), 1 / std::sqrt(kx), 1 / std::sqrt(kr));
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(s.asDiagonal() * M * s.asDiagonal());
  std::vector<double> out;
  for (int i = 2; i >= 0; --i)
    if (eig.eigenvalues()(i) > 1e-13 * eig.eigenvalues()(2))
      out.push_back(2 * M_PI * std::sqrt(eig.eigenvalues()(i)));
  return out;
}

std::string simulate_json(const ScratchDir& dir, const std::vector<std::string>& flags) {
  std::string cmd = std::string(POUND_BINARY) + " simulate --config " + kStudy + " --json";
  for (const auto& f : flags) cmd += " " + f;
  const int code = run_command(cmd + " >" + (dir / "out.json") + " 2>" + (dir / "err.txt"));
  EXPECT_EQ(code, 0) << slurp(dir / "err.txt");
  return slurp(dir / "out.json");
}

// Building 1 (massless cone): one period, Veletsos & Meek's T sqrt(1 + k / K_x + k h^2 / K_theta)
// with Wolf's K_x = 8 G r / (2 - nu), K_theta = 8 G r^3 / (3 (1 - nu)) (physics.md section 5a),
// to 1e-10; its constants in the `foundation` object. Building 2 (cone above nu = 1/3): the
// trapped soil 0.3 pi (nu - 1/3) rho r^5 (Wolf 1994) reported and added to the base's inertia, so
// that its rotation has inertia without foundation_inertia's own: two periods (the massless
// sway condensed), those of the relative model with I = I_0 + Delta M_theta, to 1e-10.
TEST(FoundationJson, PeriodsAndConstantsOfConesMatchTheClosedForms) {
  const ScratchDir dir("pound_foundation_json_");
  const std::string json = simulate_json(dir, kFlags);
  const std::string b1 = building(json, 0), b2 = building(json, 1);
  const double r = 0.5, vs = 20.0, rho = 1800.0, G = rho * vs * vs;
  // Building 1.
  const double nu1 = 0.3, kx1 = 8 * G * r / (2 - nu1), kr1 = 8 * G * r * r * r / (3 * (1 - nu1));
  EXPECT_NEAR(number(b1, "sway_stiffness"), kx1, 1e-12 * kx1);
  EXPECT_NEAR(number(b1, "rocking_stiffness"), kr1, 1e-12 * kr1);
  EXPECT_NEAR(number(b1, "sway_damping"), rho * vs * M_PI * r * r, 1e-9);
  EXPECT_EQ(number(b1, "trapped_rocking_inertia"), 0.0);
  const std::vector<double> p1 = periods(b1);
  ASSERT_EQ(p1.size(), 1u) << b1;
  const double T1 = 2 * M_PI * std::sqrt(kM / kK1);
  const double vm = T1 * std::sqrt(1 + kK1 / kx1 + kK1 * kH * kH / kr1);
  EXPECT_NEAR(p1[0], vm, 1e-10 * vm);
  EXPECT_GT(vm / T1 - 1, 0.15);  // a noticeably flexible base
  // Building 2.
  const double nu2 = 0.45, kx2 = 8 * G * r / (2 - nu2), kr2 = 8 * G * r * r * r / (3 * (1 - nu2));
  const double trapped = 0.3 * M_PI * (nu2 - 1.0 / 3.0) * rho * std::pow(r, 5);
  EXPECT_NEAR(number(b2, "trapped_rocking_inertia"), trapped, 1e-12 * trapped);
  EXPECT_NEAR(number(b2, "foundation_inertia"), 50 + trapped, 1e-12 * (50 + trapped));
  EXPECT_NEAR(number(b2, "rocking_damping"), rho * 2 * vs * M_PI * r * r * r * r / 4, 1e-9);
  const std::vector<double> p2 = periods(b2);
  const std::vector<double> expected =
      relative_sdof_periods(kM, kK2, kH, kx2, kr2, 0.0, 50 + trapped);
  ASSERT_EQ(p2.size(), 2u) << b2;
  ASSERT_EQ(expected.size(), 2u);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(p2[i], expected[i], 1e-10 * expected[i]) << i;
}

// peak_base_sway_m and peak_base_rotation_rad are the library's peaks of the bases' DOFs (the
// same run through prepare_simulation and run_simulation, bit for bit), null on a fixed base;
// the floors' displacements are relative to the free-field ground (they hold the base's sway and
// rocking), the drifts the storey's deformation alone: on a one-storey building on a flexible
// base the peak displacement is not the peak drift times the height, as it is on a fixed one.
TEST(FoundationJson, BasePeaksAreTheLibrarysAndNullOnAFixedBase) {
  const ScratchDir dir("pound_foundation_json_");
  std::vector<std::string> flags(kFlags.begin(), kFlags.begin() + 10);  // building 1's cone
  const std::string json = simulate_json(dir, flags);
  Options opt("simulate", "", simulate_option_specs());
  std::vector<std::string> args = {"--config", kStudy};
  args.insert(args.end(), flags.begin(), flags.end());
  opt.parse(args);
  const SimulationSetup setup = prepare_simulation(opt);
  const SimulationRun run = run_simulation(setup);
  const AssembledRow a = assemble(setup.row);
  const std::string b1 = building(json, 0), b2 = building(json, 1);
  auto peaks = [&](const std::string& text, const std::string& key) {
    const std::size_t at = text.find("\"" + key + "\":{");
    EXPECT_NE(at, std::string::npos) << key;
    return std::make_pair(number(text.substr(at), "pounding"), number(text.substr(at), "free"));
  };
  const auto sway = peaks(b1, "peak_base_sway_m"), rot = peaks(b1, "peak_base_rotation_rad");
  EXPECT_EQ(sway.first, run.sim.pounding.peak_disp(a.sway[0]));
  EXPECT_EQ(sway.second, run.sim.free.peak_disp(a.sway[0]));
  EXPECT_EQ(rot.first, run.sim.pounding.peak_disp(a.rot[0]));
  EXPECT_EQ(rot.second, run.sim.free.peak_disp(a.rot[0]));
  EXPECT_GT(sway.second, 0.0);
  EXPECT_GT(rot.second, 0.0);
  EXPECT_NE(b2.find("\"peak_base_sway_m\":{\"pounding\":null,\"free\":null}"), std::string::npos)
      << b2;
  EXPECT_NE(b2.find("\"peak_base_rotation_rad\":{\"pounding\":null,\"free\":null}"),
            std::string::npos)
      << b2;
  const double d1 = number(b1, "peak_disp_free_m"), r1 = number(b1, "peak_drift_ratio_free");
  const double d2 = number(b2, "peak_disp_free_m"), r2 = number(b2, "peak_drift_ratio_free");
  EXPECT_EQ(d1, run.sim.floors[0].disp_free);
  EXPECT_GT(std::fabs(d1 / (r1 * kH) - 1), 1e-3);
  EXPECT_NEAR(d2, r2 * kH, 1e-15);
}

}  // namespace
}  // namespace pound
