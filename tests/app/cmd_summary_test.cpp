// pound summary end to end: the /amplification a campaign writes, printed as JSON, equals what
// the command computes itself for a file without the group (written by an older pound); bad
// input is one line and exit 2.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../support/scratch_dir.hpp"
#include "../support/shell.hpp"

namespace {

namespace fs = std::filesystem;

// The files of this test file, apart from the other command tests of tests/app.
const std::string& dir() {
  static const std::string d = pound::test::process_scratch_subdir("summary");
  return d;
}

using pound::test::slurp;
int sh(const std::string& cmd) {
  return pound::test::run_command(cmd);
}

TEST(CmdSummary, StoredAndRecomputedStatisticsAgree) {
  const std::string run = dir() + "/sum.h5", log = dir() + "/sum.log";
  ASSERT_EQ(sh(std::string(POUND_BINARY) + " campaign --config " + POUND_SOURCE_DIR +
               "/studies/campaign-smoke.ini --samples 40 --quiet --out " + run + " 2>" + log),
            0)
      << slurp(log);
  const std::string a = dir() + "/a.json", b = dir() + "/b.json", old = dir() + "/old.h5";
  ASSERT_EQ(sh(std::string(POUND_BINARY) + " summary --input " + run + " --json > " + a), 0);
  fs::copy_file(run, old, fs::copy_options::overwrite_existing);
  ASSERT_EQ(sh("/usr/bin/python3 -c \"import h5py; f = h5py.File('" + old +
               "', 'a'); del f['amplification']\""),
            0);
  ASSERT_EQ(sh(std::string(POUND_BINARY) + " summary --input " + old + " --json > " + b), 0);
  // The same numbers (only the input name and computed_now differ), and their structure: four
  // stripes of ten samples, two one-storey buildings, one contact level; the displacement and
  // drift ratios of a one-storey building are the same numbers (to the rounding of the drift
  // ratio's division by the storey height).
  const std::string check =
      "import json, sys\n"
      "a, b = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))\n"
      "assert not a['computed_now'] and b['computed_now']\n"
      "assert a['groups'] == b['groups']\n"
      "assert a['design'] == 'stripes' and len(a['groups']) == 4\n"
      "for g in a['groups']:\n"
      "    assert g['samples'] == 10 and g['failed'] == 0\n"
      "    assert len(g['buildings']) == 2 and len(g['contacts']) == 1\n"
      "    for bd in g['buildings']:\n"
      "        f = bd['floors'][0]\n"
      "        assert f['disp']['count'] == 10, f\n"
      "        for k in ('mean', 'median', 'p16', 'p84'):\n"
      "            assert abs(f['disp'][k] - f['drift'][k]) < 1e-12 * f['disp'][k], f\n"
      "        assert f['disp']['p16'] <= f['disp']['median'] <= f['disp']['p84']\n"
      "    c = g['contacts'][0]\n"
      "    assert 0 <= c['pounded_fraction'] <= 1 and c['count'] == 10\n";
  std::ofstream(dir() + "/sum.py") << check;
  EXPECT_EQ(sh("/usr/bin/python3 " + dir() + "/sum.py " + a + " " + b + " 2>" + log), 0)
      << slurp(log);
  // The text table names the stripes and the contacts.
  ASSERT_EQ(sh(std::string(POUND_BINARY) + " summary --input " + run + " > " + dir() + "/t.txt"),
            0);
  const std::string t = slurp(dir() + "/t.txt");
  EXPECT_NE(t.find("Contacts"), std::string::npos);
  EXPECT_NE(t.find("T0.75"), std::string::npos);
  // Bad input: a missing file.
  EXPECT_EQ(sh(std::string(POUND_BINARY) + " summary --input " + dir() + "/none.h5 2>" + log), 2);
  EXPECT_NE(slurp(log).find("none.h5"), std::string::npos);
}

}  // namespace
