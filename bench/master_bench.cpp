// Issue 13: what one sample costs the campaign master. Rank 0 runs the real master loop
// (src/campaign/mpi_campaign.cpp: receive an outcome, decode it, append it to the journal and
// flush, hand out the next sample) in schedule-only mode, while every other rank answers each
// sample at once with a ready-made outcome of the study (the real record size), so the master is
// driven as fast as it can take outcomes. It prints the master's time per sample, the message
// sizes, and the sample costs of the default study measured here on one core, from which
// docs/scaling.md derives how many workers one master keeps busy.
// Usage: mpirun -np R bench_master [study.ini [samples]]
#include <mpi.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "campaign/campaign_study.hpp"
#include "campaign/journal.hpp"
#include "campaign/mpi_campaign.hpp"
#include "campaign/sample.hpp"
#include "io/options.hpp"

namespace {

using namespace pound;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const std::string study_file =
      argc > 1 ? argv[1] : std::string(POUND_SOURCE_DIR) + "/studies/fragility-default.ini";
  const long samples = argc > 2 ? std::atol(argv[2]) : 200000;
  Options opt("campaign", "master benchmark", campaign_option_specs());
  opt.parse({"--config", study_file});
  const CampaignStudy st = campaign_from_options(opt, samples, -1);

  // A real outcome of the study (sample 0), reused for every id: the record has its real size.
  SampleRunner runner(st);
  const SampleOutcome canned = runner.run(0);

  // Sample costs on one core, per contact model and with elastic storeys (rank 0 only).
  double t_lumped = 0, t_sears = 0, t_elastic_lumped = 0, t_elastic_sears = 0;
  int n_lumped = 0, n_sears = 0;
  if (rank == 0) {
    CampaignStudy elastic = st;
    for (auto& b : elastic.row.buildings) b.hysteresis = "elastic";
    SampleRunner run_elastic(elastic);
    for (long id = 0; id < 24; ++id) {
      const bool sears = runner.draw(id).model == "sears";
      auto t0 = std::chrono::steady_clock::now();
      runner.run(id);
      const double t = seconds_since(t0);
      t0 = std::chrono::steady_clock::now();
      run_elastic.run(id);
      const double te = seconds_since(t0);
      (sears ? t_sears : t_lumped) += t;
      (sears ? t_elastic_sears : t_elastic_lumped) += te;
      ++(sears ? n_sears : n_lumped);
    }
  }

  char dir[] = "/tmp/pound_master_benchXXXXXX";
  if (rank == 0 && !mkdtemp(dir)) MPI_Abort(MPI_COMM_WORLD, 1);
  MPI_Bcast(dir, sizeof dir, MPI_CHAR, 0, MPI_COMM_WORLD);
  CampaignRunOptions ro;
  ro.out = std::string(dir) + "/run.h5";
  ro.progress = false;
  ro.master_work = CampaignRunOptions::MasterWork::schedule_only;
  ro.simulate = [&](long id) {
    SampleOutcome o = canned;
    o.id = id;
    return o;
  };
  const CampaignSummary sum = run_campaign(st, ro, MPI_COMM_WORLD);
  if (rank == 0) {
    const RecordLayout layout(st);
    const double per = sum.loop_seconds / static_cast<double>(sum.done);
    std::printf(
        "master benchmark: %s, %ld samples, %d worker ranks answering at once (%d cores here)\n",
        study_file.c_str(), sum.done, size - 1, static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN)));
    std::printf("  master loop %.3f s: %.2f us per sample (%.0f samples/s)\n", sum.loop_seconds,
                1e6 * per, 1.0 / per);
    std::printf(
        "  messages per sample: outcome %zu bytes (worker -> master), reply %d bytes (ids of a "
        "batch of %d)\n",
        layout.record_bytes(), static_cast<int>(sizeof(long)) * st.batch, st.batch);
    const double tl = t_lumped / n_lumped, ts = t_sears / n_sears;
    std::printf(
        "  sample costs on one core (24 samples): lumped %.4f s (elastic %.4f s), sears %.4f s "
        "(elastic %.4f s)\n",
        tl, t_elastic_lumped / n_lumped, ts, t_elastic_sears / n_sears);
    std::printf(
        "  workers one master keeps busy (sample cost / master cost): lumped %.0f, sears %.0f, "
        "elastic lumped %.0f\n",
        tl / per, ts / per, (t_elastic_lumped / n_lumped) / per);
    std::remove((ro.out).c_str());
    std::remove((std::string(dir) + "/run.h5.journal").c_str());
    rmdir(dir);
  }
  MPI_Finalize();
  return 0;
}
