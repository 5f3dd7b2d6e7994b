#include "campaign/campaign_worker.hpp"

#include <deque>
#include <vector>

#include "campaign/campaign_messages.hpp"
#include "campaign/journal.hpp"
#include "campaign/sample.hpp"

namespace pound {
namespace {

class Worker {
 public:
  Worker(const CampaignStudy& st, const CampaignRunOptions& opt, MPI_Comm comm, int rank, int batch)
      : opt_(opt), comm_(comm), rank_(rank), batch_(batch), layout_(st), runner_(st) {}

  void run() {
    // Several requests in flight: a batch is always queued while the master is busy.
    for (int i = 0; i < kRequestsInFlight; ++i) request({});
    while (true) {
      receive(queue_.empty() && held_ == 0 && outstanding_ > 0);
      if (queue_.empty()) {
        if (held_ > 0) {
          deliver();  // the queue ran dry (or was dropped after a stop): send what is finished
          continue;
        }
        if (outstanding_ == 0) break;
        continue;
      }
      simulate_next();
    }
    sends_.wait_all();
    MPI_Send(nullptr, 0, MPI_BYTE, 0, mpi_tag(CampaignTag::done), comm_);
  }

 private:
  void request(std::vector<char> records) {
    sends_.send(std::move(records), 0, CampaignTag::request, comm_);
    ++outstanding_;
  }

  // Takes the master's answers: waits for the first when `block`, then takes whatever else
  // has come. Work goes to the queue; a stop drops it.
  void receive(bool block) {
    while (outstanding_ > 0) {
      MPI_Status s;
      int flag = 1;
      if (block)
        MPI_Probe(0, MPI_ANY_TAG, comm_, &s);
      else
        MPI_Iprobe(0, MPI_ANY_TAG, comm_, &flag, &s);
      if (!flag) return;
      int count = 0;
      MPI_Get_count(&s, MPI_BYTE, &count);
      std::vector<long> ids(static_cast<std::size_t>(count) / sizeof(long));
      MPI_Recv(ids.data(), count, MPI_BYTE, 0, s.MPI_TAG, comm_, MPI_STATUS_IGNORE);
      --outstanding_;
      if (s.MPI_TAG == mpi_tag(CampaignTag::work))
        queue_.insert(queue_.end(), ids.begin(), ids.end());
      else if (s.MPI_TAG == mpi_tag(CampaignTag::stop_now))
        queue_.clear();
      block = false;
    }
  }

  // Delivers the held results with a request for more work (after a stop the master answers
  // every request with a stop).
  void deliver() {
    request(std::move(records_));
    records_.clear();
    held_ = 0;
  }

  void simulate_next() {
    const long id = queue_.front();
    queue_.pop_front();
    SampleOutcome o = opt_.simulate ? opt_.simulate(id) : runner_.run(id);
    o.rank = rank_;
    const std::vector<char> rec = encode_record(o, layout_);
    records_.insert(records_.end(), rec.begin(), rec.end());
    if (++held_ >= batch_) deliver();
    sends_.reap();
  }

  const CampaignRunOptions& opt_;
  MPI_Comm comm_;
  int rank_, batch_;
  const RecordLayout layout_;
  SampleRunner runner_;
  std::deque<long> queue_;  // ids given, not yet simulated
  int outstanding_ = 0;     // requests not yet answered
  PendingSends sends_;
  std::vector<char> records_;  // finished, not yet sent
  int held_ = 0;               // records in records_
};

}  // namespace

void run_worker(const CampaignStudy& st, const CampaignRunOptions& opt, MPI_Comm comm, int rank,
                int batch) {
  Worker(st, opt, comm, rank, batch).run();
}

}  // namespace pound
