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

#include "../support/campaign_process.hpp"
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
  const std::string run = pound::test::make_smoke_campaign(dir() + "/sum.h5", 40);
  ASSERT_FALSE(::testing::Test::HasFailure());
  const std::string log = dir() + "/sum.log";
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

// A campaign of two contact models whose buildings collapse at the stronger stripes: the
// collapse shares and each model's table in the JSON against counts and medians done here from
// the file's own datasets; without the collapse arrays (a file older than issue 23) the same
// output without them; a group written before them is completed in memory.
TEST(CmdSummary, CollapseSharesAndPerModelTables) {
  const std::string run = pound::test::make_smoke_campaign(
      dir() + "/models.h5", 40,
      "--sample.model 'discrete(hc-linear: 1, lve: 1)' --simulation.collapse_drift_ratio 0.01");
  ASSERT_FALSE(::testing::Test::HasFailure());
  const std::string log = dir() + "/models.log";
  const std::string a = dir() + "/models-a.json", b = dir() + "/models-b.json";
  const std::string c = dir() + "/models-c.json";
  const std::string older = dir() + "/models-older.h5", partial = dir() + "/models-partial.h5";
  ASSERT_EQ(sh(std::string(POUND_BINARY) + " summary --input " + run + " --json > " + a), 0);
  // A file without the collapse arrays nor /amplification, and one whose /amplification lacks
  // the collapse shares and the models (as an older pound wrote it).
  fs::copy_file(run, older, fs::copy_options::overwrite_existing);
  fs::copy_file(run, partial, fs::copy_options::overwrite_existing);
  std::ofstream(dir() + "/older.py")
      << "import h5py, sys\n"
         "f = h5py.File(sys.argv[1], 'a')\n"
         "for k in ('amplification', 'response/collapsed_pounding', 'response/collapsed_free',\n"
         "          'response/collapse_time_pounding', 'response/collapse_time_free'):\n"
         "    del f[k]\n"
         "g = h5py.File(sys.argv[2], 'a')\n"
         "del g['amplification/collapse'], g['amplification/models']\n";
  ASSERT_EQ(sh("/usr/bin/python3 " + dir() + "/older.py " + older + " " + partial + " 2>" + log), 0)
      << slurp(log);
  ASSERT_EQ(sh(std::string(POUND_BINARY) + " summary --input " + older + " --json > " + b), 0);
  ASSERT_EQ(sh(std::string(POUND_BINARY) + " summary --input " + partial + " --json > " + c), 0);
  const std::string check =
      "import json, sys, h5py, numpy as np\n"
      "a, b, c = (json.load(open(p)) for p in sys.argv[1:4])\n"
      "f = h5py.File(sys.argv[4], 'r')\n"
      "ok = f['samples/status'][:] == 0\n"
      "stripe = f['samples/id'][:] % 4\n"
      "label = np.array([x.decode() for x in f['samples/model'][:]])\n"
      "cp, cf = f['response/collapsed_pounding'][:], f['response/collapsed_free'][:]\n"
      "ap, af = f['response/peak_accel_pounding'][:], f['response/peak_accel_free'][:]\n"
      "assert not a['computed_now'] and b['computed_now'] and c['computed_now']\n"
      "assert [m['model'] for m in a['models']] == ['hc-linear', 'lve'], a['models']\n"
      "st_all = np.stack([(cp[:, b] == 0) & (cp[:, 1 - b] == 1) for b in range(2)], axis=1)\n"
      "assert st_all.any(), 'no pounding run was stopped: the censoring is not tested'\n"
      "def check(groups, keep, censor=True):\n"
      "    shares = []\n"
      "    for g, grp in enumerate(groups):\n"
      "        use = ok & keep & (stripe == g)\n"
      "        assert grp['samples'] == int((keep & (stripe == g)).sum())\n"
      "        for bd in range(2):\n"
      "            e = grp['collapse'][bd]\n"
      "            n = int(use.sum())\n"
      "            assert e['building'] == bd and e['count'] == n, (e, n)\n"
      "            assert e['collapsed_pounding'] == cp[use, bd].sum() / n, (e, cp[use, bd])\n"
      "            assert e['collapsed_free'] == cf[use, bd].sum() / n, (e, cf[use, bd])\n"
      "            st = (cp[use, bd] == 0) & (cp[use, 1 - bd] == 1)\n"
      "            assert e['stopped_pounding'] == st.sum() / n, (e, st.sum())\n"
      "            shares += [e['collapsed_pounding'], e['collapsed_free']]\n"
      "            # amplification: without the samples whose pounding run another building's\n"
      "            # collapse stopped while this one stood (when the file has the flags)\n"
      "            sel = use & ~st_all[:, bd] if censor else use\n"
      "            r = ap[sel, bd, 0] / af[sel, bd, 0]\n"
      "            assert grp['buildings'][bd]['floors'][0]['accel']['count'] == int(sel.sum())\n"
      "            med = grp['buildings'][bd]['floors'][0]['accel']['median']\n"
      "            if not sel.any():\n"
      "                assert med is None, med  # no sample left: no statistics\n"
      "                continue\n"
      "            assert abs(med - np.median(r)) <= 1e-12 * med, (med, np.median(r))\n"
      "    return shares\n"
      "shares = check(a['groups'], np.ones(len(ok), bool))\n"
      "assert min(shares) < 0.5 and max(shares) > 0.5, shares\n"
      "for m in a['models']:\n"
      "    check(m['groups'], label == m['model'])\n"
      "    assert m['groups'] != a['groups']\n"
      "# Without the collapse arrays: the same output without the collapse shares.\n"
      "strip = lambda gs: [{k: v for k, v in g.items() if k != 'collapse'} for g in gs]\n"
      "assert all('collapse' not in g for g in b['groups'])\n"
      "# (and, not knowing which pounding runs stopped, the amplification of every sample)\n"
      "amp = lambda gs: [{k: v for k, v in g.items() if k not in ('collapse', 'buildings')}\n"
      "                  for g in gs]\n"
      "assert amp(b['groups']) == amp(a['groups'])\n"
      "assert [amp(m['groups']) for m in b['models']] == [amp(m['groups']) for m in a['models']]\n"
      "def uncensored(groups, keep):\n"
      "    for g, grp in enumerate(groups):\n"
      "        use = ok & keep & (stripe == g)\n"
      "        for bd in range(2):\n"
      "            r = ap[use, bd, 0] / af[use, bd, 0]\n"
      "            med = grp['buildings'][bd]['floors'][0]['accel']['median']\n"
      "            assert abs(med - np.median(r)) <= 1e-12 * med, (med, np.median(r))\n"
      "uncensored(b['groups'], np.ones(len(ok), bool))\n"
      "for m in b['models']:\n"
      "    uncensored(m['groups'], label == m['model'])\n"
      "# A group without the shares and models: computed now, the same numbers.\n"
      "assert c['groups'] == a['groups'] and c['models'] == a['models']\n";
  std::ofstream(dir() + "/models.py") << check;
  EXPECT_EQ(sh("/usr/bin/python3 " + dir() + "/models.py " + a + " " + b + " " + c + " " + run +
               " 2>" + log),
            0)
      << slurp(log);
  // The text: the collapse table, each model's tables after the pooled ones; none without the
  // collapse arrays.
  ASSERT_EQ(sh(std::string(POUND_BINARY) + " summary --input " + run + " > " + dir() + "/m.txt"),
            0);
  ASSERT_EQ(sh(std::string(POUND_BINARY) + " summary --input " + older + " > " + dir() + "/o.txt"),
            0);
  const std::string t = slurp(dir() + "/m.txt"), o = slurp(dir() + "/o.txt");
  const auto collapse = t.find("\nCollapse: share of the successful samples");
  const auto lve = t.find("\n== Contact model lve (/samples/model): ");
  ASSERT_NE(collapse, std::string::npos) << t;
  ASSERT_NE(lve, std::string::npos) << t;
  EXPECT_LT(t.find("\n== Contact model hc-linear"), lve);
  EXPECT_LT(collapse, t.find("\n== Contact model hc-linear"));
  EXPECT_EQ(o.find("Collapse:"), std::string::npos) << o;
  EXPECT_NE(o.find("\n== Contact model lve"), std::string::npos) << o;
}

}  // namespace
