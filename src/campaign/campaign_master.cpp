#include "campaign/campaign_master.hpp"

#include <chrono>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <vector>

#include "campaign/campaign_messages.hpp"
#include "campaign/campaign_progress.hpp"
#include "campaign/journal.hpp"
#include "campaign/sample.hpp"
#include "campaign/sample_schedule.hpp"
#include "campaign/stop_signals.hpp"
#include "campaign/write_failure.hpp"

namespace pound {
namespace {

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
    if (s.MPI_TAG == mpi_tag(CampaignTag::done))
      --active;
    else
      MPI_Send(nullptr, 0, MPI_BYTE, s.MPI_SOURCE, mpi_tag(CampaignTag::stop_now), comm);
  }
}

// The first failures are listed; a study failing by the thousand must not bury the progress
// lines. Every message stays in the result file.
constexpr long kListedFailures = 20;

class Master {
 public:
  // `active`: workers not yet done, kept up to date for drain_workers should run() throw.
  Master(const CampaignStudy& st, const CampaignRunOptions& opt, MPI_Comm comm, int size, int batch,
         int& active, WriteFailure& failure)
      : st_(st),
        opt_(opt),
        comm_(comm),
        batch_(batch),
        active_(active),
        failure_(failure),
        layout_(st),
        journal_path_(opt.out + ".journal"),
        schedule_(st.range_lo, st.range_hi),
        simulates_(master_simulates(opt.master_work, size)) {
    sum_.total = st.range_size();
  }

  CampaignSummary run() {
    if (opt_.resume) count_resumed_samples();
    journal_ = std::make_unique<JournalWriter>(
        journal_path_, st_, opt_.resume, [this](const WriteError& e) {
          failure_.note(e);
          std::fprintf(stderr, "campaign: %s; stopping (samples in flight are not kept)\n",
                       e.what());
        });
    progress_ = std::make_unique<ProgressLine>(opt_.progress, sum_.done);
    while (true) {
      if ((stop_requested() || failure_.happened()) && !stopping_) begin_stop();
      const bool served = serve_waiting_messages();
      progress_->report(sum_, false);
      if (simulate_own_sample()) continue;
      if (active_ == 0) break;
      if (!served) {
        MPI_Status s;
        MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, comm_, &s);  // wait for the next message
      }
    }
    replies_.wait_all();
    journal_->close();
    sum_.loop_seconds = progress_->elapsed_seconds();
    if (stopping_ && sum_.done < sum_.total) sum_.interrupted = true;
    progress_->report(sum_, true);
    return sum_;
  }

 private:
  static bool master_simulates(CampaignRunOptions::MasterWork work, int size) {
    using MasterWork = CampaignRunOptions::MasterWork;
    return work == MasterWork::simulate ||
           (work == MasterWork::automatic && size <= kMasterSimulatesUpTo) || size == 1;
  }

  // A resumed run: the samples the journal holds are done.
  void count_resumed_samples() {
    for_each_record(journal_path_, st_, [&](const SampleOutcome& o) {
      if (schedule_.mark_done(o.id)) {
        ++sum_.done;
        if (o.status != SampleStatus::ok) ++sum_.failed;
      }
    });
  }

  void begin_stop() {
    stopping_ = true;
    sum_.interrupted = !schedule_.exhausted();
    std::fprintf(stderr, "campaign: stop requested; finishing samples in flight\n");
  }

  // Journals the records of one message (one write and flush) and books them. Only a failed
  // record is decoded (its message is listed); the others need their id and status alone
  // (the checksum is tested by every reader of the journal).
  void record(const char* bytes, std::size_t n) {
    if (n % layout_.record_bytes() != 0)
      throw std::runtime_error("a message of " + std::to_string(n) +
                               " bytes from a worker is not a whole number of records");
    journal_->append(bytes, n);
    for (std::size_t off = 0; off < n; off += layout_.record_bytes()) {
      long id = 0;
      SampleStatus status = SampleStatus::ok;
      record_key(bytes + off, id, status);
      if (!schedule_.complete(id)) continue;
      ++sum_.done;
      if (status != SampleStatus::ok) list_failure(bytes + off);
    }
  }

  void list_failure(const char* bytes) {
    SampleOutcome o;
    if (!decode_record(bytes, layout_, o)) throw std::runtime_error("corrupt record from a worker");
    if (++sum_.failed <= kListedFailures) std::fprintf(stderr, "campaign: %s\n", o.message.c_str());
    if (sum_.failed == kListedFailures + 1)
      std::fprintf(stderr,
                   "campaign: further failed samples are not listed here; every message is in %s "
                   "(/samples/message)\n",
                   opt_.out.c_str());
  }

  // Serves every waiting message; true when there was one.
  bool serve_waiting_messages() {
    bool served = false;
    while (active_ > 0) {
      MPI_Status s;
      int flag = 1;
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, comm_, &flag, &s);
      if (!flag) break;
      served = true;
      serve(s);
    }
    return served;
  }

  // Receives one message: a worker that is done, or a request with records to journal, which
  // gets the next batch of ids or a stop.
  void serve(const MPI_Status& s) {
    const auto t0 = std::chrono::steady_clock::now();
    int count = 0;
    MPI_Get_count(&s, MPI_BYTE, &count);
    // One receive buffer, grown as needed and never cleared (a message fills what it uses).
    if (static_cast<std::size_t>(count) > capacity_) {
      capacity_ = static_cast<std::size_t>(count);
      buf_.reset(new char[capacity_]);
    }
    MPI_Recv(buf_.get(), count, MPI_BYTE, s.MPI_SOURCE, s.MPI_TAG, comm_, MPI_STATUS_IGNORE);
    if (s.MPI_TAG == mpi_tag(CampaignTag::done)) {
      --active_;
      return;
    }
    if (count > 0) ++sum_.messages;
    try {
      record(buf_.get(), static_cast<std::size_t>(count));
    } catch (...) {
      // This request gets no other answer: without one its worker would wait for it for
      // ever and never report done to drain_workers.
      MPI_Send(nullptr, 0, MPI_BYTE, s.MPI_SOURCE, mpi_tag(CampaignTag::stop_now), comm_);
      throw;
    }
    reply(s.MPI_SOURCE);
    sum_.busy_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  // The next batch of ids for a worker, or a stop: at once (stopping) or at its queue's end.
  void reply(int worker) {
    std::vector<long> ids;
    long id = 0;
    while (!stopping_ && ids.size() < static_cast<std::size_t>(batch_) && schedule_.take(id))
      ids.push_back(id);
    const CampaignTag tag = !ids.empty()
                                ? CampaignTag::work
                                : (stopping_ ? CampaignTag::stop_now : CampaignTag::stop_end);
    replies_.send(id_bytes(ids), worker, tag, comm_);
  }

  // The master simulates too (both ranks busy on a two-core machine): one sample, when it
  // simulates at all, is not stopping and a sample is left. True when it ran one.
  bool simulate_own_sample() {
    long own = 0;
    if (!simulates_ || stopping_ || !schedule_.take(own)) return false;
    if (!runner_ && !opt_.simulate) runner_ = std::make_unique<SampleRunner>(st_);
    SampleOutcome o = opt_.simulate ? opt_.simulate(own) : runner_->run(own);
    o.rank = 0;
    const auto rec = encode_record(o, layout_);
    record(rec.data(), rec.size());
    return true;
  }

  const CampaignStudy& st_;
  const CampaignRunOptions& opt_;
  MPI_Comm comm_;
  int batch_;
  int& active_;
  WriteFailure& failure_;
  const RecordLayout layout_;
  const std::string journal_path_;
  CampaignSummary sum_;
  // Which samples are done, in flight or to run, in memory independent of the sample count.
  SampleSchedule schedule_;
  const bool simulates_;
  std::unique_ptr<JournalWriter> journal_;
  std::unique_ptr<ProgressLine> progress_;
  std::unique_ptr<SampleRunner> runner_;  // built when the master simulates
  bool stopping_ = false;
  PendingSends replies_;
  std::unique_ptr<char[]> buf_;
  std::size_t capacity_ = 0;
};

}  // namespace

CampaignSummary run_master(const CampaignStudy& st, const CampaignRunOptions& opt, MPI_Comm comm,
                           int size, int batch) {
  int active = size - 1;
  CampaignSummary sum;
  WriteFailure failure;
  try {
    sum = Master(st, opt, comm, size, batch, active, failure).run();
  } catch (const WriteError& e) {  // the journal could not be created or opened
    drain_workers(comm, active);
    failure.note(e);
  } catch (...) {
    drain_workers(comm, active);
    throw;
  }
  if (failure.happened()) settle_journal_failure(failure, st, opt.out, sum);
  return sum;
}

}  // namespace pound
