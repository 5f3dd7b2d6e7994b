// Issue 13: what one sample costs the campaign master. Rank 0 runs the real master loop
// (src/campaign/campaign_master.cpp: receive a message of outcomes, append it to the journal and
// flush, book each outcome, hand out the next batch) in schedule-only mode, while every other
// rank answers each sample at once with a ready-made outcome of the study (the real record
// size), so the master is driven as fast as it can take outcomes. For each batch size it
// prints the master's busy time per sample (serving messages, without waiting for them), the
// message sizes, and from the sample costs of the default study measured here on one core
// (process CPU time) how many workers one master keeps busy; docs/scaling.md quotes them.
// Usage: mpirun -np R bench_master [study.ini [samples [batch,batch,...]]]
#include <mpi.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <sstream>
#include <string>
#include <vector>

#include "campaign/campaign_study.hpp"
#include "campaign/journal.hpp"
#include "campaign/mpi_campaign.hpp"
#include "campaign/sample.hpp"
#include "contact/registry.hpp"
#include "io/options.hpp"

namespace {

using namespace pound;

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
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
  std::vector<int> batches;
  {
    std::stringstream in(argc > 3 ? argv[3] : "1,4,16,64");
    for (std::string b; std::getline(in, b, ',');) batches.push_back(std::atoi(b.c_str()));
  }
  Options opt("campaign", "master benchmark", campaign_option_specs());
  opt.parse({"--config", study_file});
  CampaignStudy st = campaign_from_options(opt, samples, -1);

  // A real outcome of the study (sample 0), reused for every id: the record has its real size.
  SampleRunner runner(st);
  const SampleOutcome canned = runner.run(0);

  // Sample costs on one core (process CPU time), per contact model, as the study is (rank 0).
  double t_lumped = 0, t_sears = 0;
  int n_lumped = 0, n_sears = 0;
  if (rank == 0) {
    for (long id = 0; id < 48; ++id) {
      const bool sears = is_sears_model(runner.draw(id).model);
      const double c0 = cpu_seconds();
      runner.run(id);
      (sears ? t_sears : t_lumped) += cpu_seconds() - c0;
      ++(sears ? n_sears : n_lumped);
    }
  }
  const double tl = n_lumped ? t_lumped / n_lumped : 0.0, ts = n_sears ? t_sears / n_sears : 0.0;

  char dir[] = "/tmp/pound_master_benchXXXXXX";
  if (rank == 0 && !mkdtemp(dir)) MPI_Abort(MPI_COMM_WORLD, 1);
  MPI_Bcast(dir, sizeof dir, MPI_CHAR, 0, MPI_COMM_WORLD);
  const RecordLayout layout(st);
  if (rank == 0) {
    double load[3] = {0, 0, 0};
    getloadavg(load, 3);
    std::printf(
        "master benchmark: %s, %ld samples per run, %d worker ranks answering at once (%d cores "
        "here, load average %.2f)\n",
        study_file.c_str(), samples, size - 1, static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN)),
        load[0]);
    std::printf(
        "  sample costs on one core (48 samples, CPU time): lumped %.4f s, sears %.4f s; "
        "outcome record %zu bytes\n",
        tl, ts, layout.record_bytes());
    std::printf("%6s %10s %12s %12s %14s %12s %14s %14s\n", "batch", "messages", "busy[us/smp]",
                "loop[us/smp]", "bytes/msg in", "reply bytes", "workers lumped", "workers sears");
  }
  for (int batch : batches) {
    st.batch = batch;
    CampaignRunOptions ro;
    ro.out = std::string(dir) + "/run.h5";
    ro.progress = false;
    ro.write_result = false;
    ro.master_work = CampaignRunOptions::MasterWork::schedule_only;
    ro.simulate = [&](long id) {
      SampleOutcome o = canned;
      o.id = id;
      return o;
    };
    const CampaignSummary sum = run_campaign(st, ro, MPI_COMM_WORLD);
    if (rank == 0) {
      const double busy = sum.busy_seconds / static_cast<double>(sum.done);
      const double loop = sum.loop_seconds / static_cast<double>(sum.done);
      // A worker finishes one sample per sample cost; the master serves one per `busy`.
      std::printf("%6d %10ld %12.2f %12.2f %14.0f %12zu %14.0f %14.0f\n", sum.batch, sum.messages,
                  1e6 * busy, 1e6 * loop,
                  double(sum.done) * double(layout.record_bytes()) / double(sum.messages),
                  sizeof(long) * static_cast<std::size_t>(sum.batch), tl / busy, ts / busy);
      std::remove((ro.out + ".journal").c_str());
    }
    MPI_Barrier(MPI_COMM_WORLD);
  }
  if (rank == 0) rmdir(dir);
  MPI_Finalize();
  return 0;
}
