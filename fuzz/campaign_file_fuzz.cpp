// libFuzzer harness: the campaign-file readers of `pound fragility` and `pound risk`
// (read_campaign), `pound merge` (merge_campaign_parts, which also computes the joined file's
// /amplification) and `pound summary` (read_amplification, or compute_amplification for a file
// without the group), given the input bytes as a file. Only InputError may
// leave them, and every HDF5 object they open (file, group, dataset, attribute) must be closed
// again. The HDF5 library itself (Debian's libhdf5 1.10.8) is not instrumented: the sanitizers
// watch pound's code, and a fault inside HDF5 still ends the run as a crash. LeakSanitizer is
// off for this harness (fuzz/run.sh): it reports blocks that libhdf5 allocates and loses across
// inputs (not input by input), outside pound's code.
#include <hdf5.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "campaign/amplification_file.hpp"
#include "campaign/journal.hpp"
#include "campaign/merge.hpp"
#include "campaign/result_file.hpp"
#include "campaign/sample.hpp"
#include "core/error.hpp"
#include "fragility/campaign_reader.hpp"
#include "fuzz_support.hpp"

namespace {

using namespace pound;

// The harness's study with two contact models and a collapse limit that the stronger stripes
// pass: its file has /samples/model, /response/collapsed_* and their /amplification groups.
CampaignStudy models_study() {
  const std::string path = fuzz::write_file("smoke.ini", fuzz::kSmokeStudy);
  Options opt("campaign", "", campaign_option_specs());
  opt.parse({"--config", path, "--sample.model", "discrete(hc-linear: 1, lve: 1)",
             "--simulation.collapse_drift_ratio", "0.01"});
  return campaign_from_options(opt, 0, -1);
}

// A result file of samples [lo, hi) of a study, as `pound campaign` writes it.
std::string result_file(CampaignStudy st, long lo, long hi) {
  st.range_lo = lo;
  st.range_hi = hi;
  const std::string journal = fuzz::scratch() + "/seed.journal";
  const std::string out = fuzz::scratch() + "/seed.h5";
  {
    JournalWriter w(journal, st, false);
    SampleRunner runner(st);
    for (long id = lo; id < hi; ++id) {
      const auto rec = encode_record(runner.run(id), RecordLayout(st));
      w.append(rec.data(), rec.size());
    }
  }
  RunInfo info;
  info.start_time = info.end_time = "2026-01-01T00:00:00+0000";
  info.host = "fuzz";
  write_result_file(out, st, journal, info);
  std::ifstream in(out, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const std::string dir = fuzz::prepare_dir(*argc, *argv);
  if (dir.empty()) return 0;
  fuzz::write_prepared(dir, "seeds/whole.h5", result_file(fuzz::smoke_study(), 0, 4));
  fuzz::write_prepared(dir, "seeds/part.h5", result_file(fuzz::smoke_study(), 1, 3));
  fuzz::write_prepared(dir, "seeds/models.h5", result_file(models_study(), 0, 4));
  std::string dict;
  for (const char* w : {"\x89HDF\r\n\x1a\n",
                        "/samples",
                        "/response",
                        "/run",
                        "status",
                        "im",
                        "scale",
                        "sample_range",
                        "study",
                        "seed",
                        "samples",
                        "peak_force",
                        "peak_drift_ratio_pounding",
                        "peak_drift_pounding",
                        "im_levels_mps2",
                        "building_names",
                        "0:4",
                        "1:3",
                        "/amplification",
                        "design",
                        "stripes",
                        "bins",
                        "count",
                        "median",
                        "approach_free",
                        "collapse",
                        "collapsed_pounding",
                        "collapsed_free",
                        "models",
                        "model",
                        "sears"})
    dict += fuzz::dict_entry(w);
  fuzz::write_prepared(dir, "dict", dict);
  std::exit(0);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = fuzz::write_file("part.h5", data, size);
  try {
    read_campaign(path);
  } catch (const InputError&) {
  }
  try {
    merge_campaign_parts({path}, fuzz::scratch() + "/merged.h5");
  } catch (const InputError&) {
  }
  if (H5Fis_hdf5(path.c_str()) > 0) {
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (f >= 0) {
      try {
        AmplificationTable t;
        if (read_amplification(f, path, &t)) {
          // What pound summary indexes: every array sized by the groups and shapes read.
          for (const auto& m : t.measures)
            if (m.median.size() != t.groups * t.buildings * t.floors)
              fuzz::fail("an amplification table of the wrong size was read");
          if (t.force_median.size() != t.groups * t.pairs * t.levels)
            fuzz::fail("a contact table of the wrong size was read");
          if (t.has_collapse && t.collapsed_free.size() != t.groups * t.buildings)
            fuzz::fail("a collapse table of the wrong size was read");
          for (const auto& m : t.models)
            if (m.groups != t.groups || m.buildings != t.buildings || m.floors != t.floors ||
                m.measures.size() != t.measures.size() ||
                m.force_median.size() != t.force_median.size() ||
                m.collapsed_free.size() != t.collapsed_free.size())
              fuzz::fail("a model's table of another shape than the pooled one was read");
        } else {
          compute_amplification(f, path);
        }
      } catch (const InputError&) {
      }
      H5Fclose(f);
    }
  }
  // Every HDF5 object the readers opened must be closed again: one left open would hold the
  // file (and its cached metadata) into the next input.
  const ssize_t open = H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL);
  if (open != 0) fuzz::fail(std::to_string(open) + " HDF5 objects left open");
  return 0;
}
