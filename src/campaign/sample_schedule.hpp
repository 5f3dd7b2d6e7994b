#pragma once
// The master's record of which samples of [lo, hi) are done, handed out or still to run, in
// memory independent of the sample count (issue 13): samples are handed out in increasing id
// order from a cursor, the ones in flight are kept in a set (bounded by ranks x requests x
// batch), and the samples a resumed run found in its journal are kept as disjoint intervals
// (a journal holds whole runs of ids, broken only where samples were in flight when the run
// stopped).
#include <map>
#include <unordered_set>

namespace pound {

class SampleSchedule {
 public:
  /// The samples lo..hi-1 (hi > lo), none done.
  SampleSchedule(long lo, long hi);
  /// Marks sample id done before the run (from the journal). Returns false when it is outside
  /// [lo, hi) or was already marked.
  bool mark_done(long id);
  /// The next sample neither done nor handed out, in increasing order; false when none is left.
  bool take(long& id);
  /// A handed-out sample finished. Returns false when it was not in flight (a duplicate).
  bool complete(long id);
  /// Samples neither done before the run nor handed out yet.
  bool exhausted() const { return cursor_ >= hi_; }
  long in_flight() const { return static_cast<long>(in_flight_.size()); }
  /// Disjoint intervals of done-before-the-run samples (their number bounds the memory).
  std::size_t intervals() const { return done_.size(); }

 private:
  void skip_done();
  long lo_, hi_, cursor_;
  std::map<long, long> done_;  // start -> end (exclusive), disjoint, not adjacent
  std::unordered_set<long> in_flight_;
};

}  // namespace pound
