#include "campaign/sample.hpp"

#include <chrono>
#include <cmath>
#include <limits>

#include "campaign/building_arrays.hpp"
#include "campaign/floor_arrays.hpp"
#include "core/error.hpp"
#include "motion/response_spectrum.hpp"
#include "sampling/counter_rng.hpp"
#include "structure/building_on_base.hpp"
#include "study/ground_options.hpp"
#include "study/simulation_run.hpp"

namespace pound {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

SampleRunner::SampleRunner(const CampaignStudy& study)
    : st_(study), lhs_(study.seed, static_cast<std::uint64_t>(study.samples)) {
  if (st_.source == MotionSource::generated) {
    // One station per building under a coherency model (at the buildings' positions), else one
    // motion for all (StationGenerator's one station is SimqkeGenerator's motion, bit for bit).
    StationSettings stations;
    stations.coherency = st_.ground.coherency;
    if (stations.coherency.model != CoherencyModel::none)
      stations.positions = st_.ground.positions;
    else
      stations.positions = {0.0};
    generator_ = std::make_unique<StationGenerator>(*st_.spectrum, st_.motion_duration,
                                                    st_.generator, stations);
    variability_ =
        std::make_unique<TargetVariability>(st_.variability, generator_->match_periods());
  }
}

SampleRunner::~SampleRunner() = default;

SampleDraw SampleRunner::draw(long id) {
  SampleDraw d;
  d.id = id;
  const auto uid = static_cast<std::uint64_t>(id);
  auto uniform = [&](const std::string& stream) {
    const std::uint64_t s = stream_id(stream);
    return st_.sampling == SamplingMethod::latin_hypercube ? lhs_.uniform(s, uid)
                                                           : CounterRng(st_.seed, s).uniform(uid);
  };
  d.model = st_.contact.model;
  for (const auto& p : st_.parameters) {
    const double u = uniform("sample." + p.key);
    if (p.is_label()) {
      const std::size_t i = p.distribution.index(u);
      if (p.is_contact_model()) d.model = p.distribution.labels()[i];
      d.values.push_back(static_cast<double>(i));
    } else {
      d.values.push_back(p.distribution.value(u));
    }
  }
  if (st_.levels.empty()) {
    d.level = kNaN;
    d.scale_draw = st_.scale.value(uniform("intensity.scale"));
  } else {
    d.level = st_.levels[static_cast<std::size_t>(id) % st_.levels.size()];
    d.scale_draw = kNaN;
  }
  d.motion_seed = CounterRng(st_.seed, stream_id("motion")).bits(uid);
  // The random target of the generated motion: its own stream, keyed by the sample id.
  if (variability_ && variability_->enabled())
    d.spectral_epsilon = variability_->epsilon(CounterRng(st_.seed, stream_id(kTargetStream)), uid);
  if (st_.source == MotionSource::records)
    d.record = static_cast<int>(CounterRng(st_.seed, stream_id("motion.record")).uniform(uid) *
                                static_cast<double>(st_.records.size()));
  return d;
}

SampleModel SampleRunner::model(const SampleDraw& d) const {
  SampleModel m{st_.row, st_.ground, st_.contact, st_.sears};
  m.contact.model = d.model;
  apply_sampled(st_.parameters, d.values, m);
  return m;
}

SampleOutcome SampleRunner::run(const SampleDraw& d) {
  const auto t0 = std::chrono::steady_clock::now();
  const long id = d.id;
  SampleOutcome out;
  out.id = id;
  out.values = d.values;
  const int nb = st_.buildings(), nf = st_.max_floors(), np = st_.pairs(), nl = st_.max_levels();
  for (const auto& a : floor_array_fields())
    (out.*a.member).assign(static_cast<std::size_t>(nb * nf), kNaN);
  for (const auto& a : building_array_fields())
    (out.*a.member).assign(static_cast<std::size_t>(nb), kNaN);
  out.peak_force.assign(static_cast<std::size_t>(np * nl), kNaN);
  out.impacts.assign(static_cast<std::size_t>(np * nl), kNaN);
  out.approach_free.assign(static_cast<std::size_t>(np * nl), kNaN);
  out.peak_column_shear.assign(static_cast<std::size_t>(np * nl), kNaN);
  out.crush.assign(static_cast<std::size_t>(np * nl), kNaN);
  out.ground_relative.assign(static_cast<std::size_t>(np), kNaN);
  try {
    // The sample's building row, contact and Sears model.
    const SampleModel sm = model(d);
    const BuildingRow& row = sm.row;

    // The ground (issue 28): the motion (matched to the design spectrum, or to the sample's
    // random target; one per building under a coherency model), delayed under each building
    // by its arrival (wave passage), each made to end at rest when they differ (at_rest.hpp),
    // scaled to the stripe level or by the sampled factor.
    std::vector<GroundMotion> stations;
    GroundMotion reference;
    if (st_.source == MotionSource::records) {
      reference = st_.records[static_cast<std::size_t>(d.record)];
    } else {
      std::vector<GeneratedMotion> g =
          d.spectral_epsilon.empty()
              ? generator_->generate(d.motion_seed, 0)
              : generator_->generate(d.motion_seed, 0, variability_->ln_factor(d.spectral_epsilon));
      if (g.size() > 1)
        for (auto& m : g) stations.push_back(m.motion);
      reference = std::move(g.front().motion);
    }
    const RowGround unscaled =
        row_ground(sm.ground, reference, stations, st_.source == MotionSource::generated);
    // The intensity of the motion at the base of intensity.building.
    const GroundMotion& base = unscaled.under(st_.im_building).motion();
    double im0;
    if (st_.measure == IntensityMeasure::pga) {
      im0 = base.pga();
    } else {
      // Sa(T1) of the (sampled) building, 5 % damping.
      const double t1 = assemble_on_base(row.buildings[st_.im_building]).periods(0);
      im0 = response_spectrum(base, {t1}, 0.05).psa[0];
    }
    if (!(im0 > 0)) throw NumericalError("the motion has zero intensity");
    out.scale = st_.levels.empty() ? d.scale_draw : d.level / im0;
    out.im = im0 * out.scale;
    const RowGround ground = unscaled.scaled(out.scale);  // every building's by the same factor

    const RowSimulation sim =
        simulate_model(row, ground, sm.contact, sm.sears, st_.integrator, st_.simulation).sim;
    for (int p = 0; p < np; ++p)
      out.ground_relative[static_cast<std::size_t>(p)] =
          sim.ground_relative[static_cast<std::size_t>(p)];
    for (const auto& f : sim.floors) {
      const std::size_t i = static_cast<std::size_t>(f.building * nf + f.floor - 1);
      for (const auto& a : floor_array_fields()) (out.*a.member)[i] = f.*a.source;
      if (!std::isfinite(f.disp_pounding) || !std::isfinite(f.accel_pounding) ||
          !std::isfinite(f.disp_free))
        throw NumericalError("non-finite peak response");
    }
    for (const auto& a : building_array_fields())
      for (int b = 0; b < nb; ++b) (out.*a.member)[static_cast<std::size_t>(b)] = a.source(sim, b);
    for (const auto& s : sim.sites) {
      const std::size_t i = static_cast<std::size_t>(s.pair * nl + s.floor - 1);
      out.peak_force[i] = s.peak_force;
      out.impacts[i] = s.impacts;
      out.approach_free[i] = s.approach_free;
      out.peak_column_shear[i] = s.column_shear_pounding;
      out.crush[i] = s.crush;
      if (!std::isfinite(s.approach_free))
        throw NumericalError("non-finite approach of the free run");
    }
  } catch (const NumericalError& e) {
    out.status = SampleStatus::numerical_failure;
    out.message = "sample " + std::to_string(id) + ": " + e.what();
  } catch (const InputError& e) {
    out.status = SampleStatus::input_failure;
    out.message = "sample " + std::to_string(id) + ": " + e.what();
  }
  if (out.status != SampleStatus::ok) {
    // A failed sample carries no response numbers.
    for (const auto& a : floor_array_fields()) (out.*a.member).assign((out.*a.member).size(), kNaN);
    for (const auto& a : building_array_fields())
      (out.*a.member).assign((out.*a.member).size(), kNaN);
    for (auto* v : {&out.peak_force, &out.impacts, &out.approach_free, &out.peak_column_shear,
                    &out.crush, &out.ground_relative})
      v->assign(v->size(), kNaN);
  }
  out.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace pound
