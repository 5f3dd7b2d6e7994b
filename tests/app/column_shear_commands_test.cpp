// The column_shear limit state through the commands (issue 36): a campaign of the smoke study
// with the right building 1.5 m up a slope (the left one's floor strikes its columns at mid
// height) and a column shear strength; pound summary's shares against the campaign file's
// ratios counted here, and pound fragility's column_shear curve.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "../support/campaign_process.hpp"
#include "../support/scratch_dir.hpp"
#include "../support/shell.hpp"

namespace {

const std::string& dir() {
  static const std::string d = pound::test::process_scratch_subdir("column_shear");
  return d;
}

TEST(ColumnShearCommands, SummarySharesAndFragilityCurves) {
  const std::string run = pound::test::make_smoke_campaign(
      dir() + "/offset.h5", 40,
      "--building2.base_elevation 1.5 --building2.column_shear_strength 300");
  ASSERT_FALSE(::testing::Test::HasFailure());
  const std::string summary = dir() + "/summary.json", frag = dir() + "/fragility.json";
  ASSERT_EQ(pound::test::run_command(std::string(POUND_BINARY) + " summary --input " + run +
                                     " --json > " + summary),
            0);
  ASSERT_EQ(pound::test::run_command(std::string(POUND_BINARY) + " fragility --input " + run +
                                     " --json > " + frag),
            0);
  // Counted from /response here: building 2 (index 1) is struck, building 1 has no ratio.
  std::ofstream(dir() + "/check.py")
      << "import h5py, json, math, sys\n"
         "f = h5py.File(sys.argv[1], 'r')\n"
         "rp = f['response/column_shear_ratio_pounding'][()]\n"
         "rf = f['response/column_shear_ratio_free'][()]\n"
         "assert all(math.isnan(x) for x in rp[:, 0]), 'building 1 is never struck'\n"
         "n = sum(1 for a, b in zip(rp[:, 1], rf[:, 1]) if math.isfinite(a) and math.isfinite(b))\n"
         "wp = sum(1 for a in rp[:, 1] if a >= 1)\n"
         "wf = sum(1 for a in rf[:, 1] if a >= 1)\n"
         "assert n == 40, n\n"
         "assert 0 < wp < 40, wp\n"
         "vs = f['response/peak_column_shear'][()]\n"
         "assert vs.shape == (40, 1, 1), vs.shape\n"
         "for v, r in zip(vs[:, 0, 0], rp[:, 1]):\n"
         "    assert abs(v / 300 - r) <= 1e-12 * r, (v, r)  # the one site: storey 1 of 2\n"
         "assert (f['response/crush'][()] == 0).all()  # no force_cap\n"
         "s = json.load(open(sys.argv[2]))\n"
         "cs = [c for g in s['groups'] for c in g['column_shear'] if c['building'] == 1]\n"
         "assert sum(c['count'] for c in cs) == n\n"
         "assert round(sum(c['count'] * c['failed_pounding'] for c in cs)) == wp\n"
         "assert round(sum(c['count'] * c['failed_free'] for c in cs)) == wf\n"
         "fr = json.load(open(sys.argv[3]))\n"
         "cur = [c for c in fr['curves'] if c['edp'] == 'column_shear']\n"
         "assert any(c['building'] == 1 and c['limit'] == 1 for c in cur), cur\n"
         "print('ok', n, wp, wf)\n";
  const std::string log = dir() + "/check.log";
  EXPECT_EQ(pound::test::run_command("/usr/bin/python3 " + dir() + "/check.py " + run + " " +
                                     summary + " " + frag + " > " + log + " 2>&1"),
            0)
      << pound::test::slurp(log);
}

}  // namespace

namespace {

// With the force P on the struck point, the two shears V + P (1 - s) and V - P s differ by P,
// so the larger magnitude is at least |P| / 2: at every recorded step, and so at the peaks,
// demand >= peak force / 2. For the damped Sears model and a lumped law alike.
TEST(ColumnShearCommands, EveryColumnSiteCarriesAtLeastHalfItsPeakForce) {
  for (const std::string model : {"sears", "hc-linear --contact.k 1e9"}) {
    const std::string out = dir() + "/sites.json", log = dir() + "/sites.log";
    ASSERT_EQ(pound::test::run_command(std::string(POUND_BINARY) + " simulate --config " +
                                       POUND_SOURCE_DIR +
                                       "/studies/ch8-five-three.ini --building2.storey_heights "
                                       "3.6 --contact.model " +
                                       model + " --json > " + out + " 2> " + log),
              0)
        << pound::test::slurp(log);
    std::ofstream(dir() + "/sites.py")
        << "import json, sys\n"
           "d = json.load(open(sys.argv[1]))\n"
           "c = [x for x in d['contacts'] if x['kind'] == 'column']\n"
           "assert len(c) == 6, len(c)\n"
           "assert sum(x['impacts'] for x in c) > 0\n"
           "for x in c:\n"
           "    assert x['peak_column_shear_N'] >= 0.5 * x['peak_force_N'], x\n"
           "    assert x['peak_column_shear_free_N'] > 0, x\n"
           "print('ok')\n";
    EXPECT_EQ(pound::test::run_command("/usr/bin/python3 " + dir() + "/sites.py " + out + " > " +
                                       log + " 2>&1"),
              0)
        << model << ": " << pound::test::slurp(log);
  }
}

}  // namespace
