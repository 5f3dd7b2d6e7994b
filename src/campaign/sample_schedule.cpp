#include "campaign/sample_schedule.hpp"

#include <iterator>

namespace pound {

SampleSchedule::SampleSchedule(long lo, long hi) : lo_(lo), hi_(hi), cursor_(lo) {}

bool SampleSchedule::mark_done(long id) {
  if (id < lo_ || id >= hi_) return false;
  // The interval starting at or before id.
  auto it = done_.upper_bound(id);
  if (it != done_.begin()) {
    auto prev = std::prev(it);
    if (id < prev->second) return false;  // inside: already done
    if (id == prev->second) {             // extends prev at its end
      prev->second = id + 1;
      if (it != done_.end() && it->first == id + 1) {  // and joins the next one
        prev->second = it->second;
        done_.erase(it);
      }
      skip_done();
      return true;
    }
  }
  if (it != done_.end() && it->first == id + 1) {  // extends the next one at its start
    const long end = it->second;
    done_.erase(it);
    done_.emplace(id, end);
  } else {
    done_.emplace(id, id + 1);
  }
  skip_done();
  return true;
}

// Moves the cursor past done intervals.
void SampleSchedule::skip_done() {
  for (auto it = done_.upper_bound(cursor_); it != done_.begin();) {
    const auto prev = std::prev(it);
    if (cursor_ < prev->first || cursor_ >= prev->second) break;
    cursor_ = prev->second;
    it = done_.upper_bound(cursor_);
  }
}

bool SampleSchedule::take(long& id) {
  skip_done();
  if (cursor_ >= hi_) return false;
  id = cursor_++;
  in_flight_.insert(id);
  return true;
}

bool SampleSchedule::complete(long id) {
  return in_flight_.erase(id) > 0;
}

}  // namespace pound
