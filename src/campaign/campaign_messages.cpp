#include "campaign/campaign_messages.hpp"

namespace pound {

void PendingSends::send(std::vector<char> bytes, int dest, CampaignTag tag, MPI_Comm comm) {
  items_.push_back({std::move(bytes), MPI_REQUEST_NULL});
  auto& it = items_.back();
  MPI_Isend(it.bytes.data(), static_cast<int>(it.bytes.size()), MPI_BYTE, dest, mpi_tag(tag), comm,
            &it.request);
  reap();
}

void PendingSends::reap() {
  while (!items_.empty()) {
    int done = 0;
    MPI_Test(&items_.front().request, &done, MPI_STATUS_IGNORE);
    if (!done) break;
    items_.pop_front();
  }
}

void PendingSends::wait_all() {
  for (auto& it : items_) MPI_Wait(&it.request, MPI_STATUS_IGNORE);
  items_.clear();
}

std::vector<char> id_bytes(const std::vector<long>& ids) {
  const char* p = reinterpret_cast<const char*>(ids.data());
  return std::vector<char>(p, p + ids.size() * sizeof(long));
}

}  // namespace pound
