#pragma once
// The messages between the master (rank 0) and the workers of a campaign: their tags, how
// many requests a worker keeps in flight, and the non-blocking sends both sides use. A
// request carries a worker's finished journal records (0..batch of them) and asks for more
// sample ids; the master answers with ids, or with a stop.
#include <mpi.h>

#include <deque>
#include <vector>

namespace pound {

enum class CampaignTag : int {
  request = 1,   ///< worker -> master: finished records (0..n), asks for one more batch
  work = 2,      ///< master -> worker: ids of a batch
  stop_end = 3,  ///< master -> worker: no more work; finish the queue
  stop_now = 4,  ///< master -> worker: interrupted; drop the queue
  done = 5,      ///< worker -> master: finished, nothing outstanding
};

/// The MPI tag of a message kind.
inline int mpi_tag(CampaignTag t) {
  return static_cast<int>(t);
}

/// Work requests each worker keeps in flight: with several, a worker always holds queued work
/// while the master is busy with its own sample and cannot answer at once. Eight, not four: on
/// two ranks of the default study a master's `sears` sample (up to about 60 ms) outlasted four
/// queued lumped samples (about 7 ms each) and the worker waited; two ranks made 85.7
/// samples/s with four and 92.8-93.9 with eight (docs/speed.md, "Two ranks").
inline constexpr int kRequestsInFlight = 8;

/// Non-blocking sends whose buffers live until the send completes. A blocking MPI_Send may
/// wait for the receiver to post its receive (rendezvous), and both master and workers spend
/// most of their time simulating, so a blocking send would idle the sender for up to one
/// sample's time.
class PendingSends {
 public:
  PendingSends() = default;
  PendingSends(const PendingSends&) = delete;
  PendingSends& operator=(const PendingSends&) = delete;
  /// Also when a failure unwinds: MPI reads the buffers until the sends complete (the
  /// receivers always take their messages, so this ends).
  ~PendingSends() { wait_all(); }
  void send(std::vector<char> bytes, int dest, CampaignTag tag, MPI_Comm comm);
  /// Forgets the sends that completed, oldest first.
  void reap();
  void wait_all();

 private:
  struct Item {
    std::vector<char> bytes;
    MPI_Request request;
  };
  std::deque<Item> items_;  // deque: element addresses stay valid as it grows
};

/// Sample ids as the bytes of a work message (the worker receives them into longs).
std::vector<char> id_bytes(const std::vector<long>& ids);

}  // namespace pound
