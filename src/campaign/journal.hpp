#pragma once
// The campaign's crash-safe record: an append-only binary journal of finished samples,
// written by the master rank beside the result file (RUN.h5.journal). Each record is fixed
// size and ends with a checksum; it is flushed to the operating system as soon as it is
// written, so a run killed at any moment (SIGKILL included) loses at most the record being
// written, which the reader recognises by its size or checksum and drops. `--resume` reads
// the journal, skips the samples it holds and appends; the HDF5 result file is built from the
// journal, in sample order, when every sample is done.
//
// Layout (little-endian, native doubles): header = "POUNDJ02", study hash (u64), values per
// record (u64), message bytes (u64), samples (u64); record = id (i64), status (i64),
// values (f64 x values: im, scale, the sampled parameters, the per-floor arrays of
// floor_arrays.hpp in its order, peak force, impacts, wall seconds, rank), message (bytes, NUL
// padded), FNV-1a checksum of the preceding bytes of the record (u64). A journal of the
// earlier format "POUNDJ01" (six per-floor arrays) is refused with a message saying so.
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "campaign/sample.hpp"

namespace pound {

/// Sizes of the arrays in a record for one study.
struct RecordLayout {
  int parameters = 0, buildings = 0, floors = 0, pairs = 0, levels = 0;
  explicit RecordLayout(const CampaignStudy& st);
  RecordLayout() = default;
  std::size_t values() const;  ///< doubles per record
  std::size_t record_bytes() const;
  static constexpr std::size_t kMessageBytes = 232;
};

/// Serialises an outcome to one record (the bytes sent from workers and appended).
std::vector<char> encode_record(const SampleOutcome& o, const RecordLayout& layout);
/// The id and status at the start of an encoded record, read without the checksum test (the
/// master's bookkeeping of records from its workers; every reader of the journal tests it).
void record_key(const char* bytes, long& id, SampleStatus& status);
/// Decodes a record; false when the checksum does not match.
bool decode_record(const char* bytes, const RecordLayout& layout, SampleOutcome& o);

/// Hash identifying a study (resolved text, sample count, seed): a journal of another study
/// is never resumed.
std::uint64_t study_hash(const CampaignStudy& st);

class JournalWriter {
 public:
  /// Creates a new journal (truncating) or, with `append`, opens an existing one after
  /// checking its header and cutting a torn last record.
  JournalWriter(const std::string& path, const CampaignStudy& st, bool append);
  ~JournalWriter();
  JournalWriter(const JournalWriter&) = delete;
  JournalWriter& operator=(const JournalWriter&) = delete;
  /// Appends whole records (a multiple of the record size) and flushes.
  void append(const char* bytes, std::size_t n);
  void sync();  ///< fsync (called periodically and at the end)

 private:
  std::FILE* f_ = nullptr;
  std::string path_;
};

/// Reads the valid records of a journal, validating the header against the study. Returns
/// the byte offset after the last valid record in `valid_end` (a torn tail is not counted).
std::vector<SampleOutcome> read_journal(const std::string& path, const CampaignStudy& st,
                                        long* valid_end = nullptr);

/// Streams the valid records to `fn` one at a time (memory independent of the sample count).
/// Returns the byte offset after the last valid record.
long for_each_record(const std::string& path, const CampaignStudy& st,
                     const std::function<void(const SampleOutcome&)>& fn);

}  // namespace pound
