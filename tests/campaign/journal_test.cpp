#include "campaign/journal.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "../support/scratch_dir.hpp"
#include "campaign/building_arrays.hpp"
#include "campaign/floor_arrays.hpp"
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
  // Every per-floor array with values of its own, which a mixed-up order would swap.
  double x = 0.25 * id;
  for (const auto& a : floor_array_fields()) {
    auto& v = o.*a.member;
    v.assign(bf, 0.0);
    for (double& y : v) y = (x += 0.1) / 3.0;
  }
  o.disp_pounding[1] = std::nan("");       // building 1 has one floor
  o.ductility_free[0] = std::nan("");      // a building without yield_shears
  o.hysteretic_energy_pounding[2] = -0.0;  // sign of zero kept
  o.residual_drift_free[3] = 4.9e-324;     // denormal kept
  // The per-building collapse arrays: a flag, a time, NaN where standing.
  o.collapsed_pounding = {id % 2 ? 1.0 : 0.0, 0.0};
  o.collapsed_free = {1.0, std::nan("")};
  o.collapse_time_pounding = {id % 2 ? 3.25 + id : std::nan(""), std::nan("")};
  o.collapse_time_free = {2.5 + 0.125 * id, std::nan("")};
  // The column-shear ratios (issue 36): NaN where a building is not struck.
  o.column_shear_ratio_pounding = {std::nan(""), 0.75 + 0.5 * id};
  o.column_shear_ratio_free = {std::nan(""), 0.5 + 0.0625 * id};
  o.peak_force.assign(pl, 1000.0 * id);
  o.impacts.assign(pl, 3.0);
  o.approach_free.assign(pl, 0.0125 + 0.001 * id);
  o.peak_column_shear.assign(pl, std::nan(""));  // a slab site
  o.crush.assign(pl, 1e-4 * id);
  o.ground_relative.assign(1, 0.0025 * id);  // one pair
  return o;
}

TEST(Journal, RecordsRoundTripAndATornTailIsDropped) {
  const CampaignStudy st = tiny_study();
  const RecordLayout layout(st);
  // im, scale, e, 12 per-floor arrays of 2 x 2, 6 per-building arrays of 2, peak force,
  // impacts, approach, column shear and crush of 1 x 1, the relative ground displacement of 1
  // pair, wall, rank.
  EXPECT_EQ(floor_array_fields().size(), 12u);
  EXPECT_EQ(building_array_fields().size(), 6u);
  EXPECT_EQ(layout.values(), 2u + 1u + 12u * 2u * 2u + 6u * 2u + 5u * 1u * 1u + 1u + 2u);
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
  EXPECT_EQ(got[2].approach_free[0], 0.0125 + 0.002);
  EXPECT_EQ(got[2].ground_relative[0], 0.0025 * 2);
  EXPECT_EQ(got[2].crush[0], 1e-4 * 2);
  EXPECT_TRUE(std::isnan(got[2].peak_column_shear[0]));
  EXPECT_TRUE(std::isnan(got[1].disp_pounding[1]));
  // Every per-floor array comes back bit for bit (NaN, -0 and denormals included).
  for (long id : {0L, 1L, 2L}) {
    const SampleOutcome want = outcome(st, id);
    for (const auto& a : floor_array_fields()) {
      const auto &w = want.*a.member, &g = got[std::size_t(id)].*a.member;
      ASSERT_EQ(g.size(), w.size()) << a.name;
      EXPECT_EQ(std::memcmp(g.data(), w.data(), w.size() * sizeof(double)), 0)
          << a.name << " of sample " << id;
    }
  }
  for (long id : {0L, 1L, 2L})
    for (const auto& a : building_array_fields()) {
      const SampleOutcome want = outcome(st, id);
      const auto &w = want.*a.member, &g = got[std::size_t(id)].*a.member;
      ASSERT_EQ(g.size(), 2u) << a.name;
      EXPECT_EQ(std::memcmp(g.data(), w.data(), w.size() * sizeof(double)), 0)
          << a.name << " of sample " << id;
    }
  EXPECT_TRUE(std::signbit(got[1].hysteretic_energy_pounding[2]));
  EXPECT_EQ(got[1].residual_drift_free[3], 4.9e-324);
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

TEST(Journal, AJournalOfTheOldFormatSaysSo) {
  // A journal written before the residual drift, ductility and energy arrays (POUNDJ01),
  // before the free-run approach (POUNDJ02) or before the collapse arrays (POUNDJ03) has shorter
  // records: it is refused with one line saying why and what to do.
  const CampaignStudy st = tiny_study();
  const std::string path = test::process_scratch_dir() / "journal-old";
  for (const char* magic : {"POUNDJ01", "POUNDJ02", "POUNDJ03"})
    for (const bool append : {false, true}) {
      { JournalWriter w(path, st, false); }
      {
        std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
        f.write(magic, 8);
      }
      try {
        if (append) {
          JournalWriter w(path, st, true);
        } else {
          read_journal(path, st);
        }
        ADD_FAILURE() << "an old journal was accepted";
      } catch (const InputError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find(path), std::string::npos) << m;
        EXPECT_NE(m.find("older pound"), std::string::npos) << m;
        EXPECT_NE(m.find(magic), std::string::npos) << m;
        EXPECT_NE(m.find("--force"), std::string::npos) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
      }
    }
  std::remove(path.c_str());
}

// slurm/pound_parts.py reads journals on its own (the Slurm scripts' checks): it must read the
// engine's layout (with Debian's python3-numpy, which scripts/install-deps.sh installs), count the
// valid records and report the torn tail, so that a change of the format fails here and not only in
// the Slurm test.
TEST(Journal, TheSlurmCheckerReadsTheEnginesLayout) {
  const CampaignStudy st = tiny_study();
  const RecordLayout layout(st);
  const std::string path = test::process_scratch_dir() / "journal-py";
  {
    JournalWriter w(path, st, false);
    for (long id : {4L, 0L, 2L}) {
      const auto rec = encode_record(outcome(st, id), layout);
      w.append(rec.data(), rec.size());
    }
  }
  {
    const auto rec = encode_record(outcome(st, 1), layout);
    std::ofstream(path, std::ios::app | std::ios::binary).write(rec.data(), 17);
  }
  const std::string cmd =
      "/usr/bin/python3 " POUND_SOURCE_DIR "/slurm/pound_parts.py journal " + path + " 2>&1";
  std::string out;
  if (std::FILE* p = popen(cmd.c_str(), "r")) {
    char buf[512];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    EXPECT_EQ(pclose(p), 0) << out;
  }
  EXPECT_NE(out.find("3 of 5 samples in 3 valid records, 0 duplicate(s), torn tail of 17 bytes"),
            std::string::npos)
      << out;
  std::remove(path.c_str());
}

TEST(Journal, ADifferentStudyIsNotResumed) {
  const CampaignStudy st = tiny_study(5), other = tiny_study(6);
  const std::string path = test::process_scratch_dir() / "journal2";
  { JournalWriter w(path, st, false); }
  EXPECT_THROW(read_journal(path, other), InputError);
  std::remove(path.c_str());
}

// Issue 14: every write, flush, sync and close of the journal is checked, and says why it
// failed in the system's words.
TEST(Journal, AWriteThatFailsNamesTheJournalAndTheSystemsReason) {
  const CampaignStudy st = tiny_study();
  try {
    JournalWriter w("/dev/full", st, false);  // every write: ENOSPC
    FAIL() << "the header was written to /dev/full";
  } catch (const WriteError& e) {
    EXPECT_STREQ(e.what(),
                 "/dev/full: cannot write the campaign journal (No space left on device)");
    EXPECT_EQ(e.error_number(), ENOSPC);  // a stop to resume once there is space
    EXPECT_TRUE(out_of_space(e.error_number()));
  }
  // A directory in the journal's place (EISDIR, met as root too): no want of space, which the
  // campaign reports as an error rather than a stop.
  const std::string d = test::process_scratch_dir() / "a-directory";
  std::filesystem::create_directories(d);
  try {
    JournalWriter w(d, st, false);
    FAIL() << "a directory was opened as the journal";
  } catch (const WriteError& e) {
    EXPECT_EQ(std::string(e.what()), d + ": cannot write the campaign journal (Is a directory)");
    EXPECT_EQ(e.error_number(), EISDIR);
    EXPECT_FALSE(out_of_space(e.error_number()));
  }
}

// The open file descriptors of this process (the listing's own one included, every time).
long open_descriptors() {
  long n = 0;
  for (const auto& e : std::filesystem::directory_iterator("/proc/self/fd")) n += !e.path().empty();
  return n;
}

// A header that cannot be written throws from the constructor, whose destructor then does not
// run: the file it opened is closed all the same (it leaked before).
TEST(Journal, AConstructorThatThrowsClosesTheFileItOpened) {
  const CampaignStudy st = tiny_study();
  const long before = open_descriptors();
  for (int i = 0; i < 3; ++i) EXPECT_THROW(JournalWriter("/dev/full", st, false), WriteError);
  EXPECT_EQ(open_descriptors(), before);
}

TEST(Journal, AfterAFailedAppendTheHandlerIsToldOnceAndTheResumeCutsTheTornRecord) {
  const CampaignStudy st = tiny_study();
  const RecordLayout layout(st);
  const std::string path = test::process_scratch_dir() / "limited.journal";
  // In a child whose files may not grow past two records and 10 bytes (RLIMIT_FSIZE: the
  // kernel refuses the rest of the third record's write with EFBIG, as a full disk does
  // with ENOSPC).
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::signal(SIGXFSZ, SIG_IGN);
    const rlim_t limit = 40 + 2 * layout.record_bytes() + 10;
    const struct rlimit r = {limit, limit};
    ::setrlimit(RLIMIT_FSIZE, &r);
    int calls = 0;
    bool named = false;
    {
      JournalWriter w(path, st, false, [&](const WriteError& e) {
        ++calls;
        named = std::string(e.what()) ==
                    path + ": cannot write the campaign journal (File too large)" &&
                e.error_number() == EFBIG && out_of_space(e.error_number());
      });
      for (long id : {0L, 1L, 2L, 3L}) {
        const auto rec = encode_record(outcome(st, id), layout);
        w.append(rec.data(), rec.size());  // 2 and 3 fail: the handler hears of the first only
      }
      w.close();  // no second report
    }
    ::_exit(calls == 1 && named ? 0 : 10 + calls);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  ASSERT_EQ(WEXITSTATUS(status), 0) << "10 + the number of reports, or a wrong message";
  long end = 0;
  EXPECT_EQ(read_journal(path, st, &end).size(), 2u);  // the torn third is not read
  EXPECT_EQ(end, static_cast<long>(40 + 2 * layout.record_bytes()));
  {
    JournalWriter w(path, st, true);  // resume: the 10 bytes are cut, then appended to
    const auto rec = encode_record(outcome(st, 2), layout);
    w.append(rec.data(), rec.size());
    w.close();
  }
  const auto got = read_journal(path, st);
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(got[2].id, 2);
  std::remove(path.c_str());
}

TEST(Journal, AJournalCutInsideItsHeaderIsWrittenAnewOnResume) {
  // A disk that filled up while the header was written leaves a few of its 40 bytes.
  const CampaignStudy st = tiny_study();
  const std::string path = test::process_scratch_dir() / "short.journal";
  { JournalWriter w(path, st, false); }
  ASSERT_EQ(::truncate(path.c_str(), 13), 0);
  long end = -1;
  EXPECT_TRUE(read_journal(path, st, &end).empty());
  EXPECT_EQ(end, 0);
  {
    JournalWriter w(path, st, true);
    const auto rec = encode_record(outcome(st, 4), RecordLayout(st));
    w.append(rec.data(), rec.size());
  }
  const auto got = read_journal(path, st);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].id, 4);
  // Thirteen bytes that are not the start of this study's header are no journal of it.
  { JournalWriter w(path, tiny_study(6), false); }
  ASSERT_EQ(::truncate(path.c_str(), 13), 0);
  EXPECT_THROW(read_journal(path, st), InputError);
  std::remove(path.c_str());
}

// Found by fuzz_journal (issue 14): a record with a right checksum whose rank field no int
// holds (-2.16e242 in the fuzzer's input) was converted with undefined behaviour.
TEST(Journal, ARankNoIntHoldsReadsMinusOne) {
  const CampaignStudy st = tiny_study();
  const RecordLayout layout(st);
  std::vector<char> rec = encode_record(outcome(st, 1), layout);
  const std::size_t rank_at = rec.size() - 8 - RecordLayout::kMessageBytes - 8;
  for (const double bad : {-2.16153e242, 1e300, std::nan(""), -1.0, 3e9}) {
    std::memcpy(rec.data() + rank_at, &bad, 8);
    std::uint64_t h = 14695981039346656037ull;  // FNV-1a of the record before its checksum
    for (std::size_t i = 0; i + 8 < rec.size(); ++i) {
      h ^= static_cast<unsigned char>(rec[i]);
      h *= 1099511628211ull;
    }
    std::memcpy(rec.data() + rec.size() - 8, &h, 8);
    SampleOutcome o;
    ASSERT_TRUE(decode_record(rec.data(), layout, o)) << bad;
    EXPECT_EQ(o.rank, -1) << bad;
    EXPECT_EQ(o.id, 1);
  }
}

}  // namespace
}  // namespace pound
