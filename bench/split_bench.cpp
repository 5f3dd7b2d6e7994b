// Case 10 of bench_speed (issue 38 part 1; docs/speed.md, "Buildings on their own steps"): on
// one core, the lumped samples of a study with one motion under the row, each run three ways on
// the sample's own row, ground and contact law (the campaign's draws: SampleRunner::model):
//   1. the row's free run (solve without the laws): its steps, exact steps, rejected steps and
//      CPU time;
//   2. each building alone (a row of that building, no sites) on the same ground: the same
//      figures, which are what the free run would cost if each building took its own steps;
//   3. the sample's two runs as a campaign takes them (solve_free_and_pounding: the pounding
//      run forked from the free run): the pounding run's own steps (those after the fork) and
//      the CPU time beyond the free run's; its exact and rejected steps are the whole run's.
//   4. the alternative of a split free run (solve_apart) beside a pounding run on its own from
//      t = 0 (no fork, so its steps before its first contact are taken twice).
// The sum of the buildings' alone times against the row's free run is the most a split of the
// free run can save; the longest building alone is the floor a row's stepping cannot go under.
// Samples on spatially varying ground are left out (each building's own channel would have to
// be generated here); sears samples too (FreeStretches steps the floors between contacts on
// the same lumped solver: the same ratios hold there for the stretches).
// Usage: bench_speed SOURCE split STUDY [N [REPEAT [--key value ...]]] (defaults: 30 samples,
// 2 runs each, the smallest CPU time kept).
#include "split_bench.hpp"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "campaign/campaign_study.hpp"
#include "campaign/sample.hpp"
#include "campaign/sampled_parameters.hpp"
#include "contact/registry.hpp"
#include "io/options.hpp"
#include "motion/simqke.hpp"
#include "motion/spectral_variability.hpp"
#include "simulation/contact_spec.hpp"
#include "solver/row_apart.hpp"
#include "solver/row_solver.hpp"

namespace {

using namespace pound;

double cpu_time(const std::function<void()>& f, int repeat) {
  double best = 1e300;
  for (int k = 0; k < repeat; ++k) {
    const std::clock_t c0 = std::clock();
    f();
    best = std::min(best, double(std::clock() - c0) / CLOCKS_PER_SEC);
  }
  return best;
}

struct Count {
  long steps = 0, exact = 0, rejected = 0;
  double cpu = 0.0;
  void add(const RowResult& r, double t) {
    steps += r.steps;
    exact += r.exact_steps;
    rejected += r.rejected;
    cpu += t;
  }
};

void print(const char* what, const Count& c, int n, double row_cpu) {
  std::printf("%-24s %9.0f %9.0f %9.0f %9.3f %7.2f\n", what, double(c.steps) / n,
              double(c.exact) / n, double(c.rejected) / n, 1e3 * c.cpu / n,
              row_cpu > 0 ? c.cpu / row_cpu : 1.0);
}

}  // namespace

int split_case(const std::string& src, const std::vector<std::string>& arguments) {
  if (arguments.empty()) {
    std::fprintf(stderr, "bench_speed split: STUDY [N [REPEAT [--key value ...]]]\n");
    return 2;
  }
  const long samples = arguments.size() > 1 ? std::stol(arguments[1]) : 30;
  const int repeat = arguments.size() > 2 ? std::stoi(arguments[2]) : 2;
  Options oc("campaign", "split benchmark", campaign_option_specs());
  std::vector<std::string> args = {"--config", src + "/" + arguments[0]};
  if (arguments.size() > 3) args.insert(args.end(), arguments.begin() + 3, arguments.end());
  oc.parse(args);
  const CampaignStudy study = campaign_from_options(oc, samples, -1);
  if (study.source != MotionSource::generated || study.measure != IntensityMeasure::pga ||
      study.levels.empty()) {
    std::fprintf(stderr, "bench_speed split: generated motions on PGA stripes only\n");
    return 2;
  }
  SampleRunner runner(study);
  SimqkeGenerator gen(*study.spectrum, study.motion_duration, study.generator);
  const TargetVariability var(study.variability, gen.match_periods());
  const int nb = study.buildings();
  std::vector<Count> alone(static_cast<std::size_t>(nb));
  Count row_free, sum_alone, longest, pounding_own, both, apart_free, pounding_alone;
  int n = 0;
  for (long id = 0; id < samples; ++id) {
    const SampleDraw d = runner.draw(id);
    if (is_sears_model(d.model)) continue;
    const SampleModel sm = runner.model(d);
    if (sm.ground.positions_matter() ||
        std::any_of(sm.ground.motion_files.begin(), sm.ground.motion_files.end(),
                    [](const std::string& f) { return !f.empty(); }))
      continue;
    GroundMotion m = (d.spectral_epsilon.empty()
                          ? gen.generate(d.motion_seed, 0)
                          : gen.generate(d.motion_seed, 0, var.ln_factor(d.spectral_epsilon)))
                         .motion;
    const RowGround ground = RowGround::uniform(m, 1).scaled(d.level / m.pga());
    const RowGround row_ground = RowGround::uniform(m, nb).scaled(d.level / m.pga());
    const auto problem = [&](RowProblem& p, const AssembledRow& a, const RowGround& g) {
      p.row = &a;
      study.simulation.apply_to(p, g);
    };
    // 1. The row's free run.
    const AssembledRow a = assemble(sm.row);
    RowProblem pf;
    problem(pf, a, row_ground);
    RowResult rf;
    const double tf = cpu_time([&] { rf = solve(pf, study.integrator); }, repeat);
    row_free.add(rf, tf);
    // 2. Each building alone.
    Count sum, worst;
    for (int b = 0; b < nb; ++b) {
      BuildingRow one;
      one.buildings = {sm.row.buildings[static_cast<std::size_t>(b)]};
      const AssembledRow ab = assemble(one);
      RowProblem pb;
      problem(pb, ab, ground);
      RowResult rb;
      const double tb = cpu_time([&] { rb = solve(pb, study.integrator); }, repeat);
      alone[static_cast<std::size_t>(b)].add(rb, tb);
      sum.add(rb, tb);
      if (tb > worst.cpu) {
        worst = Count{};
        worst.add(rb, tb);
      }
    }
    sum_alone.steps += sum.steps;
    sum_alone.exact += sum.exact;
    sum_alone.rejected += sum.rejected;
    sum_alone.cpu += sum.cpu;
    longest.steps += worst.steps;
    longest.exact += worst.exact;
    longest.rejected += worst.rejected;
    longest.cpu += worst.cpu;
    // 3. The pounding run after its fork.
    const auto laws = make_site_laws(sm.contact, a);
    RowProblem pp;
    problem(pp, a, row_ground);
    for (const auto& l : laws) pp.laws.push_back(l.get());
    pp.force_cap = sm.contact.force_cap;
    RunPair runs;
    const double tp =
        cpu_time([&] { runs = solve_free_and_pounding(pp, study.integrator); }, repeat);
    RowResult own = runs.pounding;
    own.steps -= runs.pounding.steps_from_free;
    pounding_own.add(own, std::max(tp - tf, 0.0));
    both.add(runs.pounding, tp);
    // 4. The alternative: the free run building by building (solve_apart) and the pounding
    // run on its own from the start (no fork).
    RowResult ap, alone_p;
    const double tap = cpu_time([&] { ap = solve_apart(sm.row, pf, study.integrator); }, repeat);
    const double tpa = cpu_time([&] { alone_p = solve(pp, study.integrator); }, repeat);
    apart_free.add(ap, tap);
    pounding_alone.add(alone_p, tpa);
    ++n;
  }
  if (!n) {
    std::printf("no lumped sample on one motion among samples 0-%ld\n", samples - 1);
    return 0;
  }
  std::printf(
      "\n10. buildings on their own steps: %s, the %d lumped samples among 0-%ld, per sample "
      "(steps, exact steps, rejected, process CPU time, the smallest of %d runs; ratio to the "
      "row's free run)\n",
      arguments[0].c_str(), n, samples - 1, repeat);
  std::printf("%-24s %9s %9s %9s %9s %7s\n", "run", "steps", "exact", "rejected", "cpu[ms]",
              "ratio");
  const double rc = row_free.cpu;
  print("row, free run", row_free, n, rc);
  for (int b = 0; b < nb; ++b) {
    const std::string name = "building " + std::to_string(b + 1) + " alone";
    print(name.c_str(), alone[static_cast<std::size_t>(b)], n, rc);
  }
  print("sum of the alone runs", sum_alone, n, rc);
  print("slowest alone run", longest, n, rc);
  print("pounding run, own part", pounding_own, n, rc);
  print("both runs (forked)", both, n, rc);
  print("solve_apart, free run", apart_free, n, rc);
  print("pounding run from t = 0", pounding_alone, n, rc);
  return 0;
}
