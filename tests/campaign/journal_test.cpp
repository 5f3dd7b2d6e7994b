#include "campaign/journal.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "../support/scratch_dir.hpp"
#include "core/error.hpp"
#include "io/options.hpp"

namespace pound {
namespace {

CampaignStudy tiny_study(long samples = 5) {
  const char* argv[] = {"campaign",
                        "--building1.masses",
                        "100",
                        "--building1.stiffnesses",
                        "1e4",
                        "--building2.masses",
                        "100,100",
                        "--building2.stiffnesses",
                        "1e4,1e4",
                        "--contact.k",
                        "1e6",
                        "--sample.e",
                        "uniform(0.3, 0.9)",
                        "--motion.source",
                        "records",
                        "--motion.file",
                        POUND_SOURCE_DIR "/motions/elcentro-1940-ns.dat",
                        "--intensity.levels",
                        "0.1"};
  Options opt("campaign", "", campaign_option_specs());
  opt.parse(sizeof argv / sizeof *argv, argv);
  return campaign_from_options(opt, samples, 3);
}

SampleOutcome outcome(const CampaignStudy& st, long id) {
  SampleOutcome o;
  o.id = id;
  o.status = id == 2 ? SampleStatus::numerical_failure : SampleStatus::ok;
  o.message = id == 2 ? "sample 2: diverged" : "";
  o.im = 0.1 * id;
  o.scale = 2.0;
  o.values = {0.5 + 0.01 * id};
  const std::size_t bf = st.buildings() * st.max_floors(), pl = st.pairs() * st.max_levels();
  for (auto* v : {&o.disp_pounding, &o.disp_free, &o.drift_pounding, &o.drift_free,
                  &o.accel_pounding, &o.accel_free})
    v->assign(bf, 0.25 * id);
  o.disp_pounding[1] = std::nan("");  // building 1 has one floor
  o.peak_force.assign(pl, 1000.0 * id);
  o.impacts.assign(pl, 3.0);
  return o;
}

TEST(Journal, RecordsRoundTripAndATornTailIsDropped) {
  const CampaignStudy st = tiny_study();
  const RecordLayout layout(st);
  EXPECT_EQ(layout.values(), 2u + 1u + 6u * 2u * 2u + 2u * 1u * 1u + 2u);
  const std::string path = test::process_scratch_dir() / "journal";
  {
    JournalWriter w(path, st, false);
    for (long id : {0L, 1L, 2L}) {
      const auto rec = encode_record(outcome(st, id), layout);
      w.append(rec.data(), rec.size());
    }
  }
  // A kill in the middle of the fourth record leaves half of it.
  {
    const auto rec = encode_record(outcome(st, 3), layout);
    std::ofstream(path, std::ios::app | std::ios::binary).write(rec.data(), rec.size() / 2);
  }
  long end = 0;
  const auto got = read_journal(path, st, &end);
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(got[2].status, SampleStatus::numerical_failure);
  EXPECT_EQ(got[2].message, "sample 2: diverged");
  EXPECT_EQ(got[1].peak_force[0], 1000.0);
  EXPECT_TRUE(std::isnan(got[1].disp_pounding[1]));
  EXPECT_EQ(end, static_cast<long>(40 + 3 * layout.record_bytes()));
  // Appending after a resume cuts the torn tail first.
  {
    JournalWriter w(path, st, true);
    const auto rec = encode_record(outcome(st, 3), layout);
    w.append(rec.data(), rec.size());
  }
  EXPECT_EQ(read_journal(path, st).size(), 4u);
  std::remove(path.c_str());
}

TEST(Journal, ADifferentStudyIsNotResumed) {
  const CampaignStudy st = tiny_study(5), other = tiny_study(6);
  const std::string path = test::process_scratch_dir() / "journal2";
  { JournalWriter w(path, st, false); }
  EXPECT_THROW(read_journal(path, other), InputError);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace pound
