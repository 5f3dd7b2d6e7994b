// pound campaign: the Monte Carlo campaign over MPI ranks (mpirun -np N pound campaign ...).
#include <mpi.h>
#include <sys/stat.h>
#include <sysexits.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "app/commands.hpp"
#include "campaign/campaign_study.hpp"
#include "campaign/mpi_campaign.hpp"
#include "campaign/output_lock.hpp"
#include "ground/coherency.hpp"
#include "io/options.hpp"

namespace pound::app {
namespace {

// The exit status of `pound campaign`, for scripts and job chains (README, docs/campaign.md,
// slurm/README.md).
enum CampaignExit : int {
  kFinished = 0,           ///< RUN.h5 complete (or already complete), every sample ok
  kBadInput = 2,           ///< bad input, or a file that cannot be written for another reason
  kFailedSamples = 4,      ///< RUN.h5 complete, some samples failed (their messages are in it)
  kStopped = EX_TEMPFAIL,  ///< 75: stopped early (signal, full disk), journal kept: resume;
                           ///< or another campaign writes the same output: nothing changed
};
/// Not an exit status: claim_output() found the output free and ready, the run goes on.
constexpr int kRun = -1;

const char* const kExitStatusHelp =
    "\nExit status: 0 finished (RUN.h5 complete, or already complete); 2 bad input, or a file\n"
    "that cannot be written (read-only, no permission: the journal is kept); 4 finished with\n"
    "failed samples (their messages are in RUN.h5); 75 (EX_TEMPFAIL) stopped early by\n"
    "SIGTERM, SIGUSR1, SIGINT or a full disk, the journal kept: run again with --resume.\n"
    "75 also when another campaign is writing the same RUN.h5 (it holds RUN.h5.lock):\n"
    "nothing was changed; run again once it has ended, or wait for it with --wait-lock.\n"
    "Under mpirun the status is mpirun's: it passes 75 on when the ranks are signalled, or\n"
    "when mpirun gets SIGUSR1 (which it forwards); Ctrl-C or SIGTERM to mpirun itself stops\n"
    "the ranks the same way, journal kept, but mpirun then exits 1.\n";

bool exists(const std::string& p) {
  struct stat s;
  return ::stat(p.c_str(), &s) == 0;
}

// "A<sep>B" of two whole numbers (--sample-range LO:HI, --chunk K/C); {-1, -1} when the text
// has no separator or a part is not a whole number, which the callers' range checks reject
// with the message saying what is valid.
std::pair<long, long> whole_number_pair(const Options& opt, const std::string& key, char sep) {
  const std::string r = opt.get_string(key);
  const auto at = r.find(sep);
  if (at == std::string::npos) return {-1, -1};
  double a = 0.0, b = 0.0;
  try {
    a = parse_number(r.substr(0, at), opt.where(key));
    b = parse_number(r.substr(at + 1), opt.where(key));
  } catch (const InputError&) {
    return {-1, -1};
  }
  if (a != std::floor(a) || b != std::floor(b) || std::fabs(a) > 1e15 || std::fabs(b) > 1e15)
    return {-1, -1};
  return {static_cast<long>(a), static_cast<long>(b)};
}

// Checks of the output file made by rank 0 before anything runs. Returns "" or an error;
// *complete when --resume finds RUN.h5 complete already.
std::string check_output(const std::string& out, bool resume, bool force, bool* complete) {
  const std::string journal = out + ".journal";
  *complete = false;
  if (resume && force) return "--resume and --force exclude each other";
  if (resume) {
    if (exists(journal)) return "";
    if (exists(out)) {
      *complete = true;
      return "";
    }
    return out + ": nothing to resume (no " + journal + "); run without --resume";
  }
  if (!force && exists(out))
    return out + ": exists; use --force to overwrite it or --resume to complete it";
  if (!force && exists(journal))
    return journal +
           ": an interrupted run of this output exists; use --resume to complete it "
           "or --force to start again";
  if (force) {
    std::remove(out.c_str());
    std::remove(journal.c_str());
  }
  // The folder must be writable: try the journal name.
  std::FILE* f = std::fopen(journal.c_str(), "wb");
  if (!f) return out + ": cannot write in this folder";
  std::fclose(f);
  std::remove(journal.c_str());
  return "";
}

// The command that resumes this run (without --force and --resume).
std::string resume_command(int argc, const char* const* argv, int ranks) {
  std::string cmd = "mpirun -np " + std::to_string(ranks) + " pound campaign";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--force" || a == "--resume") continue;
    cmd += " " + a;
  }
  return cmd;
}

// --started-file: every rank has passed MPI start-up with its stop handlers (installed before
// MPI_Init), so a stop signal from now on is honoured. The file says so to job scripts.
void announce_start(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  const bool ok = f && std::fputs("started\n", f) >= 0;
  if (!(f && std::fclose(f) == 0 && ok))
    std::fprintf(stderr, "campaign: warning: cannot create the started file %s\n", path.c_str());
}

// Every option of pound campaign: the study's keys and the run's own.
std::vector<OptionSpec> campaign_command_specs() {
  auto specs = campaign_option_specs();
  specs.push_back({"out", "", "", "result file (HDF5); its journal is OUT.journal"});
  specs.push_back({"samples", "-", "", "number of samples (overrides campaign.samples)"});
  specs.push_back({"seed", "-", "", "study seed (overrides campaign.seed)"});
  specs.push_back({"sample-range", "", "",
                   "LO:HI: simulate only sample ids LO..HI-1 (one part of a split campaign; "
                   "join the parts with pound merge)"});
  specs.push_back(
      {"chunk", "", "", "K/C: the K-th of C equal sample ranges, K = 0..C-1 (Slurm array tasks)"});
  specs.push_back({"resume", "", "", "complete an interrupted campaign from its journal", true});
  specs.push_back({"force", "", "", "overwrite an existing result file", true});
  specs.push_back({"quiet", "", "", "no progress lines", true});
  specs.push_back({"started-file", "", "",
                   "FILE that rank 0 creates once every rank runs and honours stop signals (job "
                   "scripts wait for it before passing a signal on)"});
  specs.push_back({"wait-lock", "s", "0",
                   "while another campaign writes the same --out (holds OUT.lock), wait up to "
                   "this long for it to end instead of stopping at once (exit status 75)"});
  return specs;
}

// --sample-range LO:HI or --chunk K/C: the ids this run simulates.
void read_sample_range(const Options& opt, CampaignStudy& study) {
  if (opt.given("sample-range")) {
    const auto [lo, hi] = whole_number_pair(opt, "sample-range", ':');
    if (!(lo >= 0 && hi > lo && hi <= study.samples))
      throw opt.invalid("sample-range", "valid: LO:HI with 0 <= LO < HI <= " +
                                            std::to_string(study.samples) + " (the sample count)");
    study.range_lo = lo;
    study.range_hi = hi;
  }
  if (opt.given("chunk")) {
    if (opt.given("sample-range")) throw opt.invalid("chunk", "give --chunk or --sample-range");
    const auto [k, c] = whole_number_pair(opt, "chunk", '/');
    if (!(c >= 1 && c <= study.samples && k >= 0 && k < c))
      throw opt.invalid("chunk", "valid: K/C with C chunks, 1 <= C <= samples, 0 <= K < C");
    study.range_lo = k * study.samples / c;
    study.range_hi = (k + 1) * study.samples / c;
  }
}

// The study of a parsed command line (not --help): --out, --samples, --seed, the study keys
// and the sample range. Throws InputError naming the key.
CampaignStudy read_study(const Options& opt) {
  if (!opt.given("out")) throw InputError("command line: --out RUN.h5 is required");
  const long samples = opt.given("samples") ? opt.get_int("samples") : 0;
  if (opt.given("samples") && samples < 1) throw opt.invalid("samples", "valid: >= 1");
  const long seed = opt.given("seed") ? opt.get_int("seed") : -1;
  if (opt.given("seed") && seed < 0) throw opt.invalid("seed", "valid: >= 0");
  CampaignStudy study = campaign_from_options(opt, samples, seed);
  read_sample_range(opt, study);
  opt.get_nonnegative("wait-lock");  // checked on every rank, as the other run options
  return study;
}

// Rank 0, before anything about the output is looked at or changed: takes the output's lock,
// held in `lock` for the whole run (output_lock.hpp), then checks the output (check_output).
// Prints what ends the run here and returns its exit status, or kRun.
int claim_output(const Options& opt, const std::string& out, OutputLock& lock) {
  const double wait = opt.get_double("wait-lock");
  bool told = false;
  const auto got = lock.acquire(out, wait, [&](const LockHolder& holder) {
    if (!told)
      std::fprintf(stderr, "campaign: another campaign is writing %s (%s); waiting up to %g s\n",
                   out.c_str(), holder.text().c_str(), wait);
    told = true;
    return !stop_requested();  // SIGTERM, SIGUSR1, SIGINT end the wait
  });
  if (got == OutputLock::Outcome::busy) {
    if (stop_requested())
      std::fprintf(stderr,
                   "campaign: stopped by a signal while waiting for another campaign writing %s "
                   "to end; nothing was changed\n",
                   out.c_str());
    else
      std::fprintf(stderr, "%s\n", busy_output_message(out, lock, wait).c_str());
    return kStopped;
  }
  if (got == OutputLock::Outcome::unsupported)
    std::fprintf(stderr,
                 "campaign: warning: %s: cannot lock it (%s): this file system has no locks, so "
                 "make sure that no other campaign writes %s\n",
                 lock.path().c_str(), lock.reason().c_str(), out.c_str());
  bool complete = false;
  const std::string error = check_output(out, opt.flag("resume"), opt.flag("force"), &complete);
  if (!error.empty()) {
    std::cerr << "pound campaign: error: " << error << "\n";
    return kBadInput;
  }
  if (complete) {
    std::cerr << "campaign: " << out << " is already complete\n";
    return kFinished;
  }
  return kRun;
}

// Rank 0's `decision` on every rank. The others wait for it without spinning (rank 0 may wait
// minutes for the lock, --wait-lock): a non-blocking broadcast, tested every 10 ms.
int share_decision(int decision) {
  MPI_Request request;
  MPI_Ibcast(&decision, 1, MPI_INT, 0, MPI_COMM_WORLD, &request);
  int done = 0;
  MPI_Test(&request, &done, MPI_STATUS_IGNORE);
  while (!done) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
  }
  return decision;
}

// Rank 0, before the run: the sample count, ranks, seed, range and the resolved study.
void echo_start(const CampaignStudy& study, const Options& opt, int size) {
  std::fprintf(stderr, "campaign: %ld samples on %d rank%s, seed %llu, %zu sampled parameter%s%s\n",
               study.samples, size, size == 1 ? "" : "s",
               static_cast<unsigned long long>(study.seed), study.parameters.size(),
               study.parameters.size() == 1 ? "" : "s", opt.flag("resume") ? " (resuming)" : "");
  if (opt.given("chunk"))
    std::fprintf(stderr, "campaign: chunk %s = samples [%ld, %ld) of %ld\n",
                 opt.get_string("chunk").c_str(), study.range_lo, study.range_hi, study.samples);
  else if (opt.given("sample-range"))
    std::fprintf(stderr, "campaign: samples [%ld, %ld) of %ld\n", study.range_lo, study.range_hi,
                 study.samples);
  if (study.source == MotionSource::generated) {
    const std::string note =
        fitted_range_note(study.ground.coherency, smallest_separation(study.ground.positions));
    if (!note.empty()) std::fprintf(stderr, "campaign: note: %s\n", note.c_str());
  }
  std::fprintf(stderr, "campaign: resolved study:\n");
  const std::string& text = study.resolved;
  std::size_t p = 0;
  while (p < text.size()) {
    const auto e = text.find('\n', p);
    std::fprintf(stderr, "  %s\n", text.substr(p, e - p).c_str());
    p = e == std::string::npos ? text.size() : e + 1;
  }
}

// Rank 0, after the run: how it ended, and how to resume a stopped one.
void report_end(const CampaignSummary& sum, const std::string& out, const std::string& resume) {
  if (sum.interrupted && !sum.stop_reason.empty()) {
    std::fprintf(stderr,
                 "campaign: stopped after %ld of %ld samples (%ld failed): %s. The journal "
                 "%s.journal keeps them; free some space (or raise the file size limit) and "
                 "resume with: %s --resume\n",
                 sum.done, sum.total, sum.failed, sum.stop_reason.c_str(), out.c_str(),
                 resume.c_str());
  } else if (sum.interrupted) {
    std::fprintf(stderr,
                 "campaign: interrupted after %ld of %ld samples (%ld failed); the journal "
                 "%s.journal keeps them. Resume with: %s --resume\n",
                 sum.done, sum.total, sum.failed, out.c_str(), resume.c_str());
  } else {
    std::fprintf(stderr,
                 "campaign: done: %ld samples, %ld failed, written to %s (peak memory per "
                 "rank %.1f MB)\n",
                 sum.done, sum.failed, out.c_str(), sum.peak_rss_mb);
  }
}

// Every rank returns the same status (the summary is shared): a stop before the end is 75
// whatever failed so far, since the run is not finished.
int exit_status(const CampaignSummary& sum) {
  return sum.interrupted ? kStopped : sum.failed > 0 ? kFailedSamples : kFinished;
}

}  // namespace

int run_campaign(int argc, const char* const* argv) {
  // Before MPI start-up: a stop request that comes while the ranks start (srun passing on
  // Slurm's signal in the job's first second) is kept, and honoured once the campaign runs.
  install_stop_handlers();
  MPI_Init(nullptr, nullptr);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  Options opt("campaign",
              "Monte Carlo campaign: samples of buildings in a row with and without pounding, "
              "spread over MPI ranks (mpirun -np N pound campaign ...).",
              campaign_command_specs());
  // Everything is checked on every rank before any rank simulates; rank 0 reports.
  std::string error;
  CampaignStudy study;
  bool help = false;
  try {
    opt.parse(argc, argv);
    help = opt.help_requested();
    if (!help) study = read_study(opt);
  } catch (const std::exception& e) {
    error = e.what();
  }
  int bad = error.empty() ? 0 : 1, any_bad = 0;
  MPI_Allreduce(&bad, &any_bad, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  if (any_bad || help) {
    if (rank == 0 && help) std::cout << opt.help_text() << kExitStatusHelp;
    if (rank == 0 && !help)
      std::cerr << "pound campaign: error: "
                << (error.empty() ? "a rank failed to read the study" : error) << "\n";
    MPI_Finalize();
    return help ? kFinished : kBadInput;
  }
  const std::string out = opt.get_string("out");
  // Rank 0 decides; every rank ends here when the output is taken, in error or complete. The
  // lock is held until this function returns: after the result file and the journal's removal.
  OutputLock lock;
  const int decision = share_decision(rank == 0 ? claim_output(opt, out, lock) : kRun);
  if (decision != kRun) {
    MPI_Finalize();
    return decision;
  }
  if (rank == 0) echo_start(study, opt, size);
  if (rank == 0 && opt.given("started-file")) announce_start(opt.get_string("started-file"));
  CampaignRunOptions ro;
  ro.out = out;
  ro.resume = opt.flag("resume");
  ro.progress = !opt.flag("quiet");
  CampaignSummary sum;
  try {
    sum = pound::run_campaign(study, ro, MPI_COMM_WORLD);
  } catch (const std::exception& e) {
    if (rank == 0) std::cerr << "pound campaign: error: " << e.what() << "\n";
    MPI_Finalize();
    return kBadInput;
  }
  if (rank == 0) report_end(sum, out, resume_command(argc, argv, size));
  const int code = exit_status(sum);
  MPI_Finalize();
  return code;
}

}  // namespace pound::app
