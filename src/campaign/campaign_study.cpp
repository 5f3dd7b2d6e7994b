#include "campaign/campaign_study.hpp"

#include <algorithm>
#include <sstream>

#include "contact/registry.hpp"
#include "motion/motion_processing.hpp"
#include "motion/motion_reader.hpp"
#include "motion/spectrum_factory.hpp"
#include "structure/building_on_base.hpp"
#include "study/row_options.hpp"
#include "study/sears_row_options.hpp"

namespace pound {
namespace {

std::vector<OptionSpec> prefixed(const std::string& prefix, std::vector<OptionSpec> specs) {
  for (auto& s : specs) s.key = prefix + "." + s.key;
  return specs;
}

// [generator]: the target spectrum's keys plus the generator's own.
std::vector<OptionSpec> generator_specs() {
  std::vector<OptionSpec> s = design_spectrum_option_specs();
  const std::vector<OptionSpec> own = {
      {"duration", "s", "20", "duration of generated motions"},
      {"dt", "s", "0.01", "time step of generated motions"},
      {"envelope", "", "jennings", "intensity envelope: jennings or saragoni-hart"},
      {"iterations", "-", "25", "spectrum-matching iterations at most"},
  };
  s.insert(s.end(), own.begin(), own.end());
  const std::vector<OptionSpec> var = variability_option_specs('_');
  s.insert(s.end(), var.begin(), var.end());
  return s;
}

}  // namespace

int CampaignStudy::max_floors() const {
  int m = 0;
  for (const auto& b : row.buildings) m = std::max(m, b.floors());
  return m;
}

int CampaignStudy::max_levels() const {
  int m = 0;
  for (int p = 0; p < pairs(); ++p) m = std::max(m, colliding_levels(row, p));
  return m;
}

std::vector<OptionSpec> campaign_option_specs() {
  std::vector<OptionSpec> s = row_and_sears_option_specs();
  const std::vector<OptionSpec> own = {
      {"campaign.samples", "-", "100", "number of samples"},
      {"campaign.seed", "-", "1", "study seed (every draw derives from it and the sample id)"},
      {"campaign.sampling", "", "lhs", "lhs (Latin hypercube) or mc (plain Monte Carlo)"},
      {"campaign.batch", "-", "auto",
       "samples handed to a worker at a time and outcomes it returns per message (auto: by the "
       "number of ranks)"},
      {"motion.source", "", "generated",
       "generated (spectrum-compatible, one per sample) or records (motion.records)"},
      {"motion.records", "", "", "record files drawn uniformly per sample (comma separated)"},
      {"intensity.measure", "", "pga", "pga or sa (Sa(T1) of intensity.building, 5 %)"},
      {"intensity.building", "", "1",
       "building (number from the left, or name) whose first period defines Sa(T1)"},
      {"intensity.levels", "g", "",
       "stripe levels (multiple-stripe analysis); samples cycle through them"},
      {"fragility.drift_limits", "-", "",
       "damage limits of the peak drift ratio for pound fragility (list)"},
      {"fragility.disp_limits", "m", "", "limits of the peak floor displacement (list)"},
      {"fragility.accel_limits", "m/s^2", "", "limits of the peak absolute floor acceleration"},
      {"fragility.force_limits", "N", "", "limits of the peak pounding force (list)"},
      {"fragility.residual_drift_limits", "-", "",
       "limits of the residual inter-storey drift ratio at the end of the run (list)"},
      {"fragility.ductility_limits", "-", "",
       "limits of the storey ductility demand, peak drift / yield drift (list)"},
      {"intensity.scale", "-", "",
       "sampled scale factor on the motion instead of levels (distribution)"},
  };
  s.insert(s.end(), own.begin(), own.end());
  auto spec = prefixed("generator", generator_specs());
  s.insert(s.end(), spec.begin(), spec.end());
  auto smp = prefixed("sample", sampled_option_specs());
  s.insert(s.end(), smp.begin(), smp.end());
  return s;
}

namespace {

// campaign.batch: "auto" (0) or a whole number from 1 to 10^6.
int read_batch(const Options& opt) {
  const std::string b = opt.get_string("campaign.batch");
  std::size_t used = 0;
  long v = 0;
  try {
    v = b == "auto" ? 0 : std::stol(b, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (b != "auto" && (used != b.size() || v < 1 || v > 1000000))
    throw opt.invalid("campaign.batch", "valid: auto or a whole number from 1 to 10^6");
  return static_cast<int>(v);
}

// [campaign]: the sample count and range, the seed, the sampling method and the batch.
void read_sampling(const Options& opt, long samples_override, long seed_override,
                   CampaignStudy& st) {
  st.samples = samples_override > 0 ? samples_override : opt.get_int("campaign.samples");
  if (st.samples < 1) throw opt.invalid("campaign.samples", "valid: a whole number >= 1");
  st.range_lo = 0;
  st.range_hi = st.samples;
  if (seed_override >= 0) {
    st.seed = static_cast<std::uint64_t>(seed_override);
  } else {
    const long seed = opt.get_int("campaign.seed");
    if (seed < 0) throw opt.invalid("campaign.seed", "valid: a whole number >= 0");
    st.seed = static_cast<std::uint64_t>(seed);
  }
  const std::string m = opt.get_string("campaign.sampling");
  if (m == "lhs")
    st.sampling = SamplingMethod::latin_hypercube;
  else if (m == "mc")
    st.sampling = SamplingMethod::monte_carlo;
  else
    throw opt.invalid("campaign.sampling", "valid: lhs or mc");
  st.batch = read_batch(opt);
}

// The contact models a campaign uses: the fixed contact.model, or the labels of a sampled
// model; and whether a sampled parameter gives the lumped models their stiffness.
ContactUse campaign_contact_use(const Options& opt, const std::vector<SampledParameter>& params) {
  ContactUse use = single_model_use(opt);
  for (const auto& p : params) {
    if (p.is_contact_model()) use.models = p.distribution.labels();
    use.k_sampled = use.k_sampled || p.spec->sets_contact_k;
  }
  use.k_alternative = "a sampled sample.k / sample.k_factor";
  return use;
}

// motion.source = generated: the target spectrum and the generator ([generator]).
void read_generated_motions(const Options& opt, CampaignStudy& st) {
  st.source = MotionSource::generated;
  // A record, or how to read or process one, named for a campaign of generated motions would
  // be ignored without a word (motion_file_spec and process_record use these keys for records
  // only).
  for (const char* key :
       {"motion.file", "motion.records", "motion.format", "motion.units", "motion.dt",
        "motion.scale", "motion.baseline", "motion.check_pga", "motion.duration"})
    if (opt.given(key))
      throw InputError(opt.where(key) +
                       ": not used: motion.source is 'generated' (every sample generates its "
                       "own motion, set by the generator.* keys); set motion.source = records "
                       "to simulate record files");
  const Options gen = opt.section("generator", generator_specs());
  if (!gen.given("spectrum"))
    throw InputError(opt.where("generator.spectrum") +
                     ": missing; generated motions need a target spectrum: ec8, nzs1170, "
                     "asce7, japan or table");
  st.spectrum = std::shared_ptr<const DesignSpectrum>(make_design_spectrum(gen));
  st.motion_duration = gen.get_positive("duration");
  st.generator.dt = gen.get_positive("dt");
  if (!(st.motion_duration > 20 * st.generator.dt))
    throw gen.invalid("duration", "valid: longer than 20 time steps");
  const std::string env = gen.get_string("envelope");
  if (env == "jennings")
    st.generator.envelope.shape = EnvelopeShape::jennings;
  else if (env == "saragoni-hart")
    st.generator.envelope.shape = EnvelopeShape::saragoni_hart;
  else
    throw gen.invalid("envelope", "valid: jennings or saragoni-hart");
  st.generator.max_iterations = static_cast<int>(gen.get_int("iterations"));
  if (st.generator.max_iterations < 0) throw gen.invalid("iterations", "valid: >= 0");
  st.variability = variability_from_options(gen, '_');
}

// motion.source = records: every record file (motion.records, or motion.file for one), read
// and processed as pound simulate does (a relative path of the study file is taken from its
// folder).
void read_records(const Options& opt, CampaignStudy& st) {
  st.source = MotionSource::records;
  std::vector<std::string> files;
  if (opt.given("motion.records") && opt.given("motion.file"))
    throw InputError(opt.where("motion.file") +
                     ": not used beside motion.records; give the records in one of them");
  if (opt.given("motion.records")) {
    std::string list = opt.get_string("motion.records");
    std::replace(list.begin(), list.end(), ',', ' ');
    std::istringstream in(list);
    std::string f;
    while (in >> f) files.push_back(f);
  } else if (opt.given("motion.file")) {
    files.push_back(opt.get_string("motion.file"));
  }
  if (files.empty()) throw InputError(opt.where("motion.records") + ": missing; give record files");
  const auto& dir = opt.config_path();
  const auto slash = dir.rfind('/');
  for (const auto& f : files) {
    const std::string path =
        (f[0] == '/' || slash == std::string::npos || !opt.given("motion.records") ||
         opt.where("motion.records").rfind("command line", 0) == 0)
            ? f
            : dir.substr(0, slash + 1) + f;
    st.records.push_back(process_record(opt, read_motion(motion_file_spec(opt, path))));
  }
}

// [intensity]: the measure, the building whose T1 defines Sa(T1), and the stripes or the
// sampled scale factor.
void read_intensity(const Options& opt, CampaignStudy& st) {
  const std::string im = opt.get_string("intensity.measure");
  if (im == "pga")
    st.measure = IntensityMeasure::pga;
  else if (im == "sa")
    st.measure = IntensityMeasure::sa;
  else
    throw opt.invalid("intensity.measure", "valid: pga or sa");
  // The building whose T1 defines Sa(T1): its number (1 = leftmost) or its name.
  const std::string ibs = opt.get_string("intensity.building");
  st.im_building = -1;
  for (int b = 0; b < st.buildings(); ++b)
    if (st.row.buildings[b].name == ibs || std::to_string(b + 1) == ibs) st.im_building = b;
  if (st.im_building < 0) {
    std::string names;
    for (const auto& b : st.row.buildings) names += ", " + b.name;
    throw opt.invalid("intensity.building",
                      "valid: 1.." + std::to_string(st.buildings()) + " or a name" + names);
  }
  st.im_period = assemble_on_base(st.row.buildings[st.im_building]).periods(0);
  if (opt.given("intensity.levels") == opt.given("intensity.scale"))
    throw InputError(opt.where("intensity.levels") +
                     ": give either intensity.levels (stripes, in g) or intensity.scale (a "
                     "distribution of scale factors), not both or neither");
  if (opt.given("intensity.levels")) {
    for (double l : opt.get_doubles("intensity.levels")) {
      if (!(l > 0)) throw opt.invalid("intensity.levels", "every level must be > 0 g");
      st.levels.push_back(l * kGravity);
    }
  } else {
    st.has_scale = true;
    st.scale = Distribution::parse(opt.get_string("intensity.scale"), opt.where("intensity.scale"));
    if (!(st.scale.lower() > 0)) throw opt.invalid("intensity.scale", "scale factors must be > 0");
  }
}

}  // namespace

CampaignStudy campaign_from_options(const Options& opt, long samples_override, long seed_override) {
  CampaignStudy st;
  // The row as `pound simulate` reads it; the sampled parameters, in a fixed (sorted) order
  // (sampled_parameters.hpp), say which contact models the campaign uses.
  std::vector<SampledParameter> params;
  static_cast<RowStudy&>(st) = read_row_study(opt, [&](const BuildingRow& row) {
    params = read_sampled_parameters(opt, row);
    StudyUse use;
    use.contact = campaign_contact_use(opt, params);
    for (const auto& p : params) use.sampled_velocity |= p.spec->sets_ground_velocity;
    return use;
  });
  st.parameters = std::move(params);
  read_sampling(opt, samples_override, seed_override, st);
  const std::string src = opt.get_string("motion.source");
  if (src == "generated")
    read_generated_motions(opt, st);
  else if (src == "records")
    read_records(opt, st);
  else
    throw opt.invalid("motion.source", "valid: generated or records");
  // The ground under each building (issue 28): a campaign draws its motions, so a building's
  // own record file is for `pound simulate`; coherency loss needs generated motions.
  for (std::size_t b = 0; b < st.ground.motion_files.size(); ++b)
    if (!st.ground.motion_files[b].empty())
      throw opt.invalid("building" + std::to_string(b + 1) + ".motion_file",
                        "no record per building in a campaign, which draws its motions "
                        "(motion.source); give it to pound simulate");
  if (st.source == MotionSource::records) refuse_coherency_with_records(opt, st.ground);
  read_intensity(opt, st);
  // The study as resolved; run-control options (output, resume, ...) are not part of it, the
  // sample count and seed are stored on their own.
  st.resolved =
      opt.resolved_text({"out", "resume", "force", "quiet", "started-file", "wait-lock", "samples",
                         "seed", "sample-range", "chunk", "campaign.samples", "campaign.seed"});
  return st;
}

}  // namespace pound
