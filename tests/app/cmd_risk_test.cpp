// pound risk end to end on a small campaign made here: the JSON fields the issue lists, the
// files, the campaign file byte for byte unchanged, and bad input: one line, exit 2, no file.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../support/campaign_process.hpp"
#include "../support/scratch_dir.hpp"
#include "../support/shell.hpp"

namespace {

namespace fs = std::filesystem;

// The files of this test file, apart from the other command tests of tests/app.
const std::string& dir() {
  static const std::string d = pound::test::process_scratch_subdir("risk");
  return d;
}

using pound::test::slurp;
int sh(const std::string& cmd) {
  return pound::test::run_command(cmd);
}

// A 48-sample campaign of the smoke study (stripes 0.1-0.4 g), made once.
const std::string& campaign() {
  static const std::string out = pound::test::make_smoke_campaign(dir() + "/run.h5", 48);
  return out;
}

// A power-law hazard, rate 1/475 at 0.3 g and slope 3, in the unit and measure of the header.
std::string hazard(const std::string& name, const std::string& header = "pga [g]",
                   double sign = 1.0, double slope = 3.0) {
  const std::string path = dir() + "/" + name;
  std::ofstream f(path);
  f << "# a test curve\n" << header << ", annual_rate [1/yr]\n";
  for (double x : {0.02, 0.05, 0.1, 0.2, 0.4, 0.8, 1.6})
    f << x << ", " << sign * std::pow(x / 0.3, -slope) / 475.0 << "\n";
  return path;
}

std::string risk(const std::string& args) {
  return std::string(POUND_BINARY) + " risk --input " + campaign() + " " + args;
}

TEST(CmdRisk, JsonFieldsFilesAndUntouchedCampaign) {
  const std::string before = slurp(campaign());
  ASSERT_FALSE(before.empty());
  const std::string out = dir() + "/risk", json = dir() + "/risk.json";
  ASSERT_EQ(sh(risk("--hazard " + hazard("h.csv") + " --out " + out + " --replicates 50 --json > " +
                    json + " 2>" + dir() + "/risk.log")),
            0)
      << slurp(dir() + "/risk.log");
  EXPECT_EQ(slurp(campaign()), before);  // the campaign file is byte for byte the same
  for (const char* f : {"risk_gaps.csv", "code_rules.csv", "damage_maf.csv", "risk.h5"})
    EXPECT_TRUE(fs::exists(out + "/" + f)) << f;
  for (const auto& e : fs::directory_iterator(out))
    EXPECT_EQ(e.path().string().find(".tmp."), std::string::npos) << e.path();
  // The fields of the issue, checked by Python's json module: years, target_probability, and
  // per pair its number, the gap grid (40 gaps from 0), nu and the probability per gap (null
  // where no finite fit), the gap for the target and its band (null or [lo, hi]), and the
  // three code rules with their gaps and probabilities.
  const std::string check =
      "import json, sys\n"
      "d = json.load(open(sys.argv[1]))\n"
      "assert d['years'] == 50 and d['target_probability'] == 0.02, d\n"
      "assert len(d['pairs']) == 1\n"
      "p = d['pairs'][0]\n"
      "assert p['pair'] == 1\n"
      "g = p['gaps_m']\n"
      "assert len(g) == 40 and g[0] == 0 and all(b > a for a, b in zip(g, g[1:]))\n"
      "assert len(p['maf_pounding']) == 40 and len(p['probability_pounding']) == 40\n"
      "for s, m, q in zip(p['status'], p['maf_pounding'], p['probability_pounding']):\n"
      "    assert (s == 'ok') == (m is not None) == (q is not None), (s, m, q)\n"
      "    assert q is None or 0 <= q <= 1\n"
      "assert p['gap_for_target_m'] is None or p['gap_for_target_m'] >= 0\n"
      "b = p['gap_for_target_band_m']\n"
      "assert b is None or (len(b) == 2 and b[0] <= b[1])\n"
      "assert [r['rule'] for r in p['code_rules']] == ['abs', 'srss', 'ddc', 'ec8']\n"
      "r = {x['rule']: x for x in p['code_rules']}\n"
      "assert r['abs']['gap_m'] > r['srss']['gap_m'] >= r['ddc']['gap_m'] > 0\n"
      "assert p['ec8_case'] == 'floors_coincide'  # one floor each at 3 m\n"
      "assert abs(r['ec8']['gap_m'] - 0.7 * r['srss']['gap_m']) < 1e-15\n"
      "for x in p['code_rules']:\n"
      "    q = x['probability_pounding']\n"
      "    assert q is None or 0 <= q <= 1\n"
      "assert len(d['files']) == 4 and len(d['damage']) == 10\n"
      "assert [x['edp'] for x in d['damage']][:1] == ['collapse']\n"
      "assert len(d['collapse']) == 2 and all(x['model'] == 'all' for x in d['collapse'])\n"
      "for x in d['collapse']:\n"
      "    assert x['cmr_pounding'] is None and x['cmr_free'] is None  # no --design-im\n"
      "# The bootstrap bands of the damage limits (50 replicates): [lo, hi] or null, the\n"
      "# probabilities' within [0, 1]; the CSV keeps its first columns and appends the bands,\n"
      "# the same numbers as the JSON.\n"
      "import csv\n"
      "rows = list(csv.DictReader(open(sys.argv[2])))\n"
      "head = open(sys.argv[2]).readline().strip().split(',')\n"
      "assert head[:21] == ['building', 'building_name', 'edp', 'unit', 'limit',\n"
      "    'status_pounding', 'theta_pounding_mps2', 'beta_pounding', 'status_free',\n"
      "    'theta_free_mps2', 'beta_free', 'maf_pounding_per_year', 'maf_free_per_year', 'ratio',\n"
      "    'maf_share_outside_campaign_pounding', 'maf_share_outside_campaign_free', 'model',\n"
      "    'free_same_analyses', 'theta_free_same_mps2', 'beta_free_same',\n"
      "    'maf_pounding_kept_per_year'], head\n"
      "assert len(rows) == len(d['damage'])\n"
      "def same(a, b):\n"
      "    return (a == '' and b is None) or abs(float(a) - b) <= 1e-9 * abs(b)\n"
      "banded = 0\n"
      "for x, row in zip(d['damage'], rows):\n"
      "    for k in ('maf_pounding', 'maf_free', 'ratio', 'probability_pounding',\n"
      "              'probability_free'):\n"
      "        b = x[k + '_band']\n"
      "        assert b is None or b[0] <= b[1], (k, b)\n"
      "        col = k.replace('maf_pounding', 'maf_pounding_ci90_{}_per_year').replace(\n"
      "            'maf_free', 'maf_free_ci90_{}_per_year') if k.startswith('maf') else k + "
      "'_ci90_{}'\n"
      "        assert same(row[col.format('lo')], b and b[0]), (col, row, b)\n"
      "        assert same(row[col.format('hi')], b and b[1]), (col, row, b)\n"
      "    for k in ('probability_pounding', 'probability_free'):\n"
      "        b = x[k + '_band']\n"
      "        assert b is None or 0 <= b[0] <= b[1] <= 1, (k, b)\n"
      "        assert same(row[k], x[k]), (k, row[k], x[k])\n"
      "    assert row['bootstrap_replicates'] == '50'\n"
      "    assert int(row['band_finite_pounding']) == x['band_finite_pounding'] <= 50\n"
      "    banded += x['probability_pounding_band'] is not None\n"
      "assert banded >= 2, banded  # at least the two collapse limits\n"
      "import h5py, math\n"
      "with h5py.File(sys.argv[3], 'r') as f:\n"
      "    g = f['risk/damage']\n"
      "    for i, x in enumerate(d['damage']):\n"
      "        for k in ('maf_pounding', 'ratio', 'probability_pounding', 'probability_free'):\n"
      "            for j, end in enumerate(('_lo', '_hi')):\n"
      "                v, b = float(g[k + end][i]), x[k + '_band']\n"
      "                assert (math.isnan(v) and b is None) or v == b[j], (k, end, v, b)\n"
      "        assert g['band_finite_free'][i] == x['band_finite_free']\n";
  std::ofstream(dir() + "/check.py") << check;
  EXPECT_EQ(sh("/usr/bin/python3 " + dir() + "/check.py " + json + " " + out + "/damage_maf.csv " +
               out + "/risk.h5 2>" + dir() + "/py.log"),
            0)
      << slurp(dir() + "/py.log") << slurp(json);
  // The table is printed first without --json.
  ASSERT_EQ(sh(risk("--hazard " + hazard("h.csv") + " --out " + out + " --replicates 20 > " +
                    dir() + "/risk.txt 2>&1")),
            0);
  const std::string text = slurp(dir() + "/risk.txt");
  EXPECT_LT(text.find("Gap needed for the target"), text.find("Code rules"));
  EXPECT_LT(text.find("Code rules"), text.find("Pounding at each gap"));
  EXPECT_NE(text.find("log-log"), std::string::npos);  // the rule beyond the ends is stated
  EXPECT_NE(text.find("P50 pound [band]"), std::string::npos) << text;       // the damage limits
  EXPECT_NE(text.find("P50 pound [90 % band]"), std::string::npos) << text;  // collapse
}

// EN 1998-1 4.4.2.7(3) from the campaign's floors: the smoke pair with the second storey 3.5 m
// high, so that the first building's slab (3 m) strikes the second one's column at xi 6/7 and
// the second one's slab stands above the first one's roof. The ec8 gap is then the SRSS gap,
// and the table, the CSV and the JSON say why.
TEST(CmdRisk, Ec8TakesNoReductionWhereASlabStrikesAColumn) {
  const std::string run =
      pound::test::make_smoke_campaign(dir() + "/offset.h5", 24, "--building2.storey_heights 3.5");
  const std::string out = dir() + "/offset-risk", json = dir() + "/offset.json";
  ASSERT_EQ(sh(std::string(POUND_BINARY) + " risk --input " + run + " --hazard " +
               hazard("h-offset.csv") + " --out " + out + " --replicates 10 --json > " + json +
               " 2>" + dir() + "/offset.log"),
            0)
      << slurp(dir() + "/offset.log");
  const std::string check =
      "import csv, json, sys\n"
      "p = json.load(open(sys.argv[1]))['pairs'][0]\n"
      "assert p['ec8_case'] == 'floors_offset', p['ec8_case']\n"
      "r = {x['rule']: x for x in p['code_rules']}\n"
      "assert r['ec8']['gap_m'] == r['srss']['gap_m'] > 0, r\n"
      "rows = list(csv.DictReader(open(sys.argv[2])))\n"
      "assert [x['rule'] for x in rows] == ['abs', 'srss', 'ddc', 'ec8'], rows\n"
      "assert [x['ec8_case'] for x in rows] == ['', '', '', 'floors_offset'], rows\n";
  std::ofstream(dir() + "/check-offset.py") << check;
  EXPECT_EQ(sh("/usr/bin/python3 " + dir() + "/check-offset.py " + json + " " + out +
               "/code_rules.csv 2>" + dir() + "/py-offset.log"),
            0)
      << slurp(dir() + "/py-offset.log");
  ASSERT_EQ(sh(std::string(POUND_BINARY) + " risk --input " + run + " --hazard " +
               hazard("h-offset.csv") + " --out " + out + " --replicates 10 > " + dir() +
               "/offset.txt 2>&1"),
            0)
      << slurp(dir() + "/offset.txt");
  EXPECT_NE(slurp(dir() + "/offset.txt").find("ec8 (EN 1998-1 4.4.2.7(3)): floors do not coincide"),
            std::string::npos)
      << slurp(dir() + "/offset.txt");
}

TEST(CmdRisk, BadInputIsOneLineExitTwoAndNoFile) {
  const struct {
    std::string args;
    const char* says;
  } cases[] = {
      {"--hazard " + hazard("rising.csv", "pga [g]", 1.0, -1.0), "must fall strictly"},
      {"--hazard " + hazard("negative.csv", "pga [g]", -1.0), "finite number > 0"},
      {"--hazard " + hazard("sa.csv", "sa(0.5) [g]"), "the campaign's intensity measure is PGA"},
      {"--hazard " + hazard("unit.csv", "pga [gal]"), "valid: g, m/s2"},
      {"--hazard " + hazard("h2.csv") + " --target-probability 1.5",
       "valid: a probability in (0, 1)"},
      {"--hazard " + hazard("h3.csv") + " --target-probability 0",
       "valid: a probability in (0, 1)"},
      {"--hazard " + dir() + "/missing.csv", "missing.csv"},
      {"--hazard " + hazard("h4.csv") + " --gaps 0.02,0.01", "increasing gaps"},
      {"--hazard " + hazard("h5.csv") + " --design-im 3", "outside the campaign's intensities"},
      {"--hazard " + hazard("h6.csv") + " --years -5", "years"},
      {"--hazard " + hazard("h7.csv") + " --no-such-option 1", "no-such-option"},
  };
  int k = 0;
  for (const auto& c : cases) {
    const std::string out = dir() + "/bad" + std::to_string(k++), log = out + ".log";
    EXPECT_EQ(sh(risk(c.args + " --out " + out + " 2>" + log + " >/dev/null")), 2) << c.args;
    const std::string m = slurp(log);
    EXPECT_NE(m.find(c.says), std::string::npos) << c.args << ": " << m;
    EXPECT_EQ(std::count(m.begin(), m.end(), '\n'), 1) << m;
    EXPECT_FALSE(fs::exists(out)) << c.args;
  }
  // A campaign file without the approach (written before it existed) says so.
  const std::string old = dir() + "/old.h5", log = dir() + "/old.log";
  fs::copy_file(campaign(), old, fs::copy_options::overwrite_existing);
  ASSERT_EQ(sh("/usr/bin/python3 -c \"import h5py; f = h5py.File('" + old +
               "', 'a'); del f['response/approach_free']\""),
            0);
  EXPECT_EQ(sh(std::string(POUND_BINARY) + " risk --input " + old + " --hazard " +
               hazard("h8.csv") + " --out " + dir() + "/old-risk 2>" + log),
            2);
  EXPECT_NE(slurp(log).find("approach_free"), std::string::npos) << slurp(log);
  EXPECT_FALSE(fs::exists(dir() + "/old-risk"));
}

}  // namespace
