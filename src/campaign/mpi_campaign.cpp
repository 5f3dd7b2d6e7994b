#include "campaign/mpi_campaign.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <deque>
#include <memory>
#include <vector>

#include "campaign/journal.hpp"
#include "campaign/result_file.hpp"
#include "campaign/sample.hpp"
#include "campaign/sample_schedule.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/h5.hpp"

namespace pound {
namespace {

volatile std::sig_atomic_t g_stop = 0;
extern "C" void on_stop_signal(int) {
  g_stop = 1;
}

// The first failed write of the journal in one run (master): the campaign stops as on
// SIGTERM. Kept per run, apart from the signals' flag: a later run in the same process
// (tests, bench_master) is not stopped by it, and a signal that came meanwhile is not lost.
struct WriteFailure {
  std::string message;   ///< the WriteError's text ("" while none failed)
  int error_number = 0;  ///< its errno
  bool happened() const { return !message.empty(); }
  void note(const WriteError& e) {
    if (happened()) return;
    message = e.what();
    error_number = e.error_number();
  }
};

// The samples a journal holds. After a failed write the master's own count may include
// records that never reached the disk; the journal is what a resume will find.
void count_journal(const CampaignStudy& st, const std::string& path, CampaignSummary& sum) {
  sum.done = sum.failed = 0;
  SampleSchedule held(st.range_lo, st.range_hi);
  try {
    for_each_record(path, st, [&](const SampleOutcome& o) {
      if (held.mark_done(o.id)) {
        ++sum.done;
        if (o.status != SampleStatus::ok) ++sum.failed;
      }
    });
  } catch (const InputError&) {  // no journal (it could not be created)
  }
}

// Work requests each worker keeps in flight: with several, a worker always holds queued work
// while the master is busy with its own sample and cannot answer at once. Eight, not four: on
// two ranks of the default study a master's `sears` sample (up to about 60 ms) outlasted four
// queued lumped samples (about 7 ms each) and the worker waited; two ranks made 85.7 samples/s
// with four and 92.8-93.9 with eight (docs/speed.md, "Two ranks").
constexpr int kRequestsInFlight = 8;

enum Tag : int {
  kRequest = 1,  // worker -> master: finished records (0..n), asks for one more batch
  kWork = 2,     // master -> worker: ids of a batch
  kStopEnd = 3,  // master -> worker: no more work; finish the queue
  kStopNow = 4,  // master -> worker: interrupted; drop the queue
  kDone = 5,     // worker -> master: finished, nothing outstanding
};

// Non-blocking sends whose buffers live until the send completes. A blocking MPI_Send may
// wait for the receiver to post its receive (rendezvous), and both master and workers spend
// most of their time simulating, so a blocking send would idle the sender for up to one
// sample's time.
class PendingSends {
 public:
  PendingSends() = default;
  PendingSends(const PendingSends&) = delete;
  PendingSends& operator=(const PendingSends&) = delete;
  // Also when a failure unwinds: MPI reads the buffers until the sends complete (the receivers
  // always take their messages, so this ends).
  ~PendingSends() { wait_all(); }
  void send(std::vector<char> bytes, int dest, int tag, MPI_Comm comm) {
    items_.push_back({std::move(bytes), MPI_REQUEST_NULL});
    auto& it = items_.back();
    MPI_Isend(it.bytes.data(), static_cast<int>(it.bytes.size()), MPI_BYTE, dest, tag, comm,
              &it.request);
    reap();
  }
  void reap() {
    while (!items_.empty()) {
      int done = 0;
      MPI_Test(&items_.front().request, &done, MPI_STATUS_IGNORE);
      if (!done) break;
      items_.pop_front();
    }
  }
  void wait_all() {
    for (auto& it : items_) MPI_Wait(&it.request, MPI_STATUS_IGNORE);
    items_.clear();
  }

 private:
  struct Item {
    std::vector<char> bytes;
    MPI_Request request;
  };
  std::deque<Item> items_;  // deque: element addresses stay valid as it grows
};

std::vector<char> id_bytes(const std::vector<long>& ids) {
  const char* p = reinterpret_cast<const char*>(ids.data());
  return std::vector<char>(p, p + ids.size() * sizeof(long));
}

std::string now_text() {
  char buf[64];
  const std::time_t t = std::time(nullptr);
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S%z", std::localtime(&t));
  return buf;
}

// ---------------------------------------------------------------- worker
void worker(const CampaignStudy& st, const CampaignRunOptions& opt, MPI_Comm comm, int rank,
            int batch) {
  const RecordLayout layout(st);
  SampleRunner runner(st);
  std::deque<long> queue;
  int outstanding = 0;
  PendingSends sends;
  auto request = [&](std::vector<char> records) {
    sends.send(std::move(records), 0, kRequest, comm);
    ++outstanding;
  };
  auto receive = [&](bool block) {
    while (outstanding > 0) {
      MPI_Status s;
      int flag = 1;
      if (block)
        MPI_Probe(0, MPI_ANY_TAG, comm, &s);
      else
        MPI_Iprobe(0, MPI_ANY_TAG, comm, &flag, &s);
      if (!flag) return;
      int count = 0;
      MPI_Get_count(&s, MPI_BYTE, &count);
      std::vector<long> ids(static_cast<std::size_t>(count) / sizeof(long));
      MPI_Recv(ids.data(), count, MPI_BYTE, 0, s.MPI_TAG, comm, MPI_STATUS_IGNORE);
      --outstanding;
      if (s.MPI_TAG == kWork)
        queue.insert(queue.end(), ids.begin(), ids.end());
      else if (s.MPI_TAG == kStopNow)
        queue.clear();
      block = false;
    }
  };
  // Several requests in flight: a batch is always queued while the master is busy.
  for (int i = 0; i < kRequestsInFlight; ++i) request({});
  std::vector<char> records;  // finished, not yet sent
  int held = 0;
  // Delivers the held results with a request for more work (after a stop the master answers
  // every request with a stop).
  auto deliver = [&] {
    request(std::move(records));
    records.clear();
    held = 0;
  };
  while (true) {
    receive(queue.empty() && held == 0 && outstanding > 0);
    if (queue.empty()) {
      if (held > 0) {
        deliver();  // the queue ran dry (or was dropped after a stop): send what is finished
        continue;
      }
      if (outstanding == 0) break;
      continue;
    }
    const long id = queue.front();
    queue.pop_front();
    SampleOutcome o = opt.simulate ? opt.simulate(id) : runner.run(id);
    o.rank = rank;
    const std::vector<char> rec = encode_record(o, layout);
    records.insert(records.end(), rec.begin(), rec.end());
    if (++held >= batch) deliver();
    sends.reap();
  }
  sends.wait_all();
  MPI_Send(nullptr, 0, MPI_BYTE, 0, kDone, comm);
}

// ---------------------------------------------------------------- master
struct Progress {
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now(), last = start;
  long at_start = 0;
};

// Answers every remaining worker request with an immediate stop until all workers are done
// (used when the master fails, so that no rank is left waiting).
void drain_workers(MPI_Comm comm, int active) {
  while (active > 0) {
    MPI_Status s;
    MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, comm, &s);
    int count = 0;
    MPI_Get_count(&s, MPI_BYTE, &count);
    std::vector<char> buf(static_cast<std::size_t>(count));
    MPI_Recv(buf.data(), count, MPI_BYTE, s.MPI_SOURCE, s.MPI_TAG, comm, MPI_STATUS_IGNORE);
    if (s.MPI_TAG == kDone)
      --active;
    else
      MPI_Send(nullptr, 0, MPI_BYTE, s.MPI_SOURCE, kStopNow, comm);
  }
}

CampaignSummary master_loop(const CampaignStudy& st, const CampaignRunOptions& opt, MPI_Comm comm,
                            int size, int batch, int& active, WriteFailure& failure);

// A journal that cannot be written for want of space (disk full, quota, file size limit) is a
// stop, resumed once there is space; any other failure (a read-only file system, no
// permission, an I/O error) would fail again on resume: an error naming the journal, the
// system's reason and the samples the journal keeps for a resume once it can be written.
CampaignSummary master(const CampaignStudy& st, const CampaignRunOptions& opt, MPI_Comm comm,
                       int size, int batch) {
  int active = size - 1;
  CampaignSummary sum;
  WriteFailure failure;
  try {
    sum = master_loop(st, opt, comm, size, batch, active, failure);
  } catch (const WriteError& e) {  // the journal could not be created or opened
    drain_workers(comm, active);
    failure.note(e);
  } catch (...) {
    drain_workers(comm, active);
    throw;
  }
  if (failure.happened()) {
    sum.total = st.range_size();
    count_journal(st, opt.out + ".journal", sum);
    if (!out_of_space(failure.error_number)) {
      std::string text = failure.message;
      if (sum.done > 0)
        text += "; the journal keeps " + std::to_string(sum.done) + " of " +
                std::to_string(sum.total) + " samples: run again with --resume once " + opt.out +
                ".journal can be written";
      throw WriteError(text, failure.error_number);
    }
    sum.interrupted = true;
    sum.stop_reason = failure.message;
  }
  return sum;
}

CampaignSummary master_loop(const CampaignStudy& st, const CampaignRunOptions& opt, MPI_Comm comm,
                            int size, int batch, int& active, WriteFailure& failure) {
  const RecordLayout layout(st);
  const std::string journal_path = opt.out + ".journal";
  CampaignSummary sum;
  sum.total = st.range_size();
  // Which samples are done, in flight or to run, in memory independent of the sample count.
  SampleSchedule schedule(st.range_lo, st.range_hi);
  if (opt.resume) {
    for_each_record(journal_path, st, [&](const SampleOutcome& o) {
      if (schedule.mark_done(o.id)) {
        ++sum.done;
        if (o.status != SampleStatus::ok) ++sum.failed;
      }
    });
  }
  JournalWriter journal(journal_path, st, opt.resume, [&failure](const WriteError& e) {
    failure.note(e);
    std::fprintf(stderr, "campaign: %s; stopping (samples in flight are not kept)\n", e.what());
  });
  Progress prog;
  prog.at_start = sum.done;
  std::unique_ptr<SampleRunner> runner;  // built when the master simulates
  using MasterWork = CampaignRunOptions::MasterWork;
  const bool simulates =
      opt.master_work == MasterWork::simulate ||
      (opt.master_work == MasterWork::automatic && size <= kMasterSimulatesUpTo) || size == 1;

  // Journals the records of one message (one write and flush) and books them. Only a failed
  // record is decoded (its message is listed); the others need their id and status alone
  // (the checksum is tested by every reader of the journal).
  auto record = [&](const char* bytes, std::size_t n) {
    if (n % layout.record_bytes() != 0)
      throw std::runtime_error("a message of " + std::to_string(n) +
                               " bytes from a worker is not a whole number of records");
    journal.append(bytes, n);
    for (std::size_t off = 0; off < n; off += layout.record_bytes()) {
      long id = 0;
      SampleStatus status = SampleStatus::ok;
      record_key(bytes + off, id, status);
      if (schedule.complete(id)) {
        ++sum.done;
        if (status != SampleStatus::ok) {
          SampleOutcome o;
          if (!decode_record(bytes + off, layout, o))
            throw std::runtime_error("corrupt record from a worker");
          // The first failures are listed; a study failing by the thousand must not bury the
          // progress lines. Every message stays in the result file.
          constexpr long kListedFailures = 20;
          if (++sum.failed <= kListedFailures)
            std::fprintf(stderr, "campaign: %s\n", o.message.c_str());
          if (sum.failed == kListedFailures + 1)
            std::fprintf(stderr,
                         "campaign: further failed samples are not listed here; every "
                         "message is in %s (/samples/message)\n",
                         opt.out.c_str());
        }
      }
    }
  };
  auto report = [&](bool final) {
    const auto t = std::chrono::steady_clock::now();
    if (!opt.progress || (!final && t - prog.last < std::chrono::seconds(2))) return;
    prog.last = t;
    const double el = std::chrono::duration<double>(t - prog.start).count();
    const double rate = el > 0 ? (sum.done - prog.at_start) / el : 0.0;
    const double left = rate > 0 ? (sum.total - sum.done) / rate : 0.0;
    std::fprintf(stderr,
                 "campaign: %ld/%ld samples done, %ld failed, %.2f samples/s, ~%.0f s left\n",
                 sum.done, sum.total, sum.failed, rate, left);
  };

  bool stopping = false;
  PendingSends replies;
  std::unique_ptr<char[]> buf;
  std::size_t capacity = 0;
  while (true) {
    if ((g_stop || failure.happened()) && !stopping) {
      stopping = true;
      sum.interrupted = !schedule.exhausted();
      std::fprintf(stderr, "campaign: stop requested; finishing samples in flight\n");
    }
    // Serve every waiting message.
    int flag = 1;
    bool served = false;
    while (active > 0) {
      MPI_Status s;
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, comm, &flag, &s);
      if (!flag) break;
      served = true;
      const auto t0 = std::chrono::steady_clock::now();
      int count = 0;
      MPI_Get_count(&s, MPI_BYTE, &count);
      // One receive buffer, grown as needed and never cleared (a message fills what it uses).
      if (static_cast<std::size_t>(count) > capacity) {
        capacity = static_cast<std::size_t>(count);
        buf.reset(new char[capacity]);
      }
      MPI_Recv(buf.get(), count, MPI_BYTE, s.MPI_SOURCE, s.MPI_TAG, comm, MPI_STATUS_IGNORE);
      if (s.MPI_TAG == kDone) {
        --active;
        continue;
      }
      if (count > 0) ++sum.messages;
      try {
        record(buf.get(), static_cast<std::size_t>(count));
      } catch (...) {
        // This request gets no other answer: without one its worker would wait for it for
        // ever and never report done to drain_workers.
        MPI_Send(nullptr, 0, MPI_BYTE, s.MPI_SOURCE, kStopNow, comm);
        throw;
      }
      std::vector<long> ids;
      long id = 0;
      while (!stopping && ids.size() < static_cast<std::size_t>(batch) && schedule.take(id))
        ids.push_back(id);
      const int tag = !ids.empty() ? kWork : (stopping ? kStopNow : kStopEnd);
      replies.send(id_bytes(ids), s.MPI_SOURCE, tag, comm);
      sum.busy_seconds +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    report(false);
    long own = 0;
    if (simulates && !stopping && schedule.take(own)) {
      // The master simulates too (both ranks busy on a two-core machine).
      if (!runner && !opt.simulate) runner = std::make_unique<SampleRunner>(st);
      SampleOutcome o = opt.simulate ? opt.simulate(own) : runner->run(own);
      o.rank = 0;
      const auto rec = encode_record(o, layout);
      record(rec.data(), rec.size());
      continue;
    }
    if (active == 0) break;
    if (!served) {
      MPI_Status s;
      MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, comm, &s);  // wait for the next message
    }
  }
  replies.wait_all();
  journal.close();
  sum.loop_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - prog.start).count();
  if (stopping && sum.done < sum.total) sum.interrupted = true;
  report(true);
  return sum;
}

// Writes the result file from the complete journal and removes the journal (rank 0). A write
// that fails for want of space (disk full, quota, file size limit) stops the campaign as
// SIGTERM does: the journal stays and `--resume` writes the file. Returns another failure's
// message (the journal stays too), or "".
std::string write_result(const CampaignStudy& st, const CampaignRunOptions& opt, RunInfo info,
                         CampaignSummary& sum) {
  try {
    char host[256] = {};
    ::gethostname(host, sizeof host - 1);
    info.host = host;
    AtomicPath out(opt.out);
    write_result_file(out.temp(), st, opt.out + ".journal", info);
    out.commit();
    std::remove((opt.out + ".journal").c_str());
    return "";
  } catch (const std::exception& e) {
    const auto* write = dynamic_cast<const WriteError*>(&e);
    const bool system = write || !h5::system_error().empty();
    if (!system) return e.what();
    const std::string reason = !h5::system_error().empty() && !write
                                   ? std::string(e.what()) + " (" + h5::system_error() + ")"
                                   : e.what();
    const int error_number =
        write && write->error_number() != 0 ? write->error_number() : h5::system_errno();
    if (!out_of_space(error_number))
      return reason + "; the journal " + opt.out + ".journal keeps every sample: run again with " +
             "--resume once " + opt.out + " can be written";
    sum.interrupted = true;
    sum.stop_reason = reason;
    return "";
  }
}

}  // namespace

void install_stop_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sa.sa_flags = SA_RESTART;  // MPI start-up and file calls are not interrupted by a stop request
  sigemptyset(&sa.sa_mask);
  for (int sig : {SIGTERM, SIGUSR1, SIGINT}) sigaction(sig, &sa, nullptr);
  // A file size limit (ulimit -f) makes writes fail with EFBIG, a stop like a full disk,
  // instead of killing the process.
  std::signal(SIGXFSZ, SIG_IGN);
}

bool stop_requested() {
  return g_stop != 0;
}

int campaign_batch(int batch, int ranks) {
  if (batch > 0) return batch;
  return std::min(32, std::max(1, (ranks + 63) / 64));
}

CampaignSummary run_campaign(const CampaignStudy& st, const CampaignRunOptions& opt,
                             MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  CampaignSummary sum;
  std::string error;
  RunInfo info;
  info.ranks = size;
  info.start_time = now_text();
  const int batch = campaign_batch(st.batch, size);
  if (rank == 0) {
    try {
      sum = master(st, opt, comm, size, batch);
    } catch (const std::exception& e) {
      error = e.what();
    }
  } else {
    worker(st, opt, comm, rank, batch);
  }
  // Share the outcome (and any master error) with every rank.
  const std::string stop_reason = sum.stop_reason;
  long buf[4] = {sum.total, sum.done, sum.failed, sum.interrupted ? 1L : 0L};
  MPI_Bcast(buf, 4, MPI_LONG, 0, comm);
  const CampaignSummary own = sum;  // the master's own figures
  sum = CampaignSummary{};
  sum.total = buf[0];
  sum.done = buf[1];
  sum.failed = buf[2];
  sum.interrupted = buf[3] != 0;
  sum.loop_seconds = own.loop_seconds;
  sum.busy_seconds = own.busy_seconds;
  sum.messages = own.messages;
  sum.batch = batch;
  int err_len = static_cast<int>(error.size());
  MPI_Bcast(&err_len, 1, MPI_INT, 0, comm);
  if (err_len) throw InputError(rank == 0 ? error : std::string("(reported by rank 0)"));
  if (rank == 0) sum.stop_reason = stop_reason;
  if (rank == 0 && sum.done == sum.total && stop_reason.empty() && opt.write_result) {
    info.end_time = now_text();
    error = write_result(st, opt, info, sum);
  }
  // A result file that cannot be written is a stop (the system's reason) or an error (any
  // other) on every rank, as above.
  int state[2] = {static_cast<int>(error.size()), sum.interrupted ? 1 : 0};
  MPI_Bcast(state, 2, MPI_INT, 0, comm);
  if (state[0]) throw InputError(rank == 0 ? error : std::string("(reported by rank 0)"));
  sum.interrupted = state[1] != 0;
  // Peak resident memory of the largest rank (ru_maxrss is in kB on Linux).
  struct rusage ru {};
  getrusage(RUSAGE_SELF, &ru);
  double mb = static_cast<double>(ru.ru_maxrss) / 1024.0, max_mb = 0.0;
  MPI_Allreduce(&mb, &max_mb, 1, MPI_DOUBLE, MPI_MAX, comm);
  sum.peak_rss_mb = max_mb;
  MPI_Barrier(comm);
  return sum;
}

}  // namespace pound
