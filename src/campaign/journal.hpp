#pragma once
// The campaign's crash-safe record: an append-only binary journal of finished samples,
// written by the master rank beside the result file (RUN.h5.journal). Each record is fixed
// size and ends with a checksum; it is flushed to the operating system as soon as it is
// written, so a run killed at any moment (SIGKILL included) loses at most the record being
// written, which the reader recognises by its size or checksum and drops. `--resume` reads
// the journal, skips the samples it holds and appends; the HDF5 result file is built from the
// journal, in sample order, when every sample is done.
//
// Layout (little-endian, native doubles): header = "POUNDJ04", study hash (u64), values per
// record (u64), message bytes (u64), samples (u64); record = id (i64), status (i64),
// values (f64 x values: im, scale, the sampled parameters, the per-floor arrays of
// floor_arrays.hpp in its order, the per-building arrays of building_arrays.hpp in its order,
// peak force, impacts, free-run approach (each pairs x levels), wall seconds, rank), message
// (bytes, NUL padded), FNV-1a checksum of the preceding bytes of the record (u64). Journals of
// the earlier formats "POUNDJ01" (six per-floor arrays, no approach), "POUNDJ02" (no approach)
// and "POUNDJ03" (no collapse arrays) are refused with a message saying so.
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "campaign/sample.hpp"
#include "core/error.hpp"

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
  /// checking its header and cutting a torn last record (a journal cut short inside its header,
  /// as a full disk leaves it, is written anew). Without `on_write_error`, a failed write
  /// throws; with it, the first failure of append, sync or close is handed to it and the
  /// journal takes no more records (the campaign stops as on SIGTERM).
  JournalWriter(const std::string& path, const CampaignStudy& st, bool append,
                std::function<void(const WriteError&)> on_write_error = {});
  ~JournalWriter();
  JournalWriter(const JournalWriter&) = delete;
  JournalWriter& operator=(const JournalWriter&) = delete;
  /// Appends whole records (a multiple of the record size) and flushes. Every call into the
  /// system is checked: a failed write, flush, sync or close throws WriteError naming the
  /// journal and the system's reason ("No space left on device"), with its errno (whether the
  /// campaign stops to resume or fails depends on it); the records appended before
  /// stay whole, a torn last one is cut when the campaign resumes.
  void append(const char* bytes, std::size_t n);
  void sync();   ///< flush and fsync (at the end of a run)
  void close();  ///< sync and close; the destructor closes without reporting (error paths)

 private:
  [[noreturn]] void fail(const char* what) const;
  /// Runs a write step; a WriteError goes to on_write_error_ when there is one.
  template <class Step>
  void guarded(Step step);
  // Closes without reporting (error paths). A unique_ptr, so that the file is closed when the
  // constructor throws after opening it (writing the header failed): the destructor of a
  // half-built object does not run, the destructors of its built members do.
  struct CloseFile {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::unique_ptr<std::FILE, CloseFile> f_;
  std::string path_;
  std::function<void(const WriteError&)> on_write_error_;
  bool failed_ = false;  ///< a write failed and was handed on: no more records
};

/// Reads the valid records of a journal, validating the header against the study. Returns
/// the byte offset after the last valid record in `valid_end` (a torn tail is not counted; 0
/// for a journal cut short inside its header, which holds no record).
std::vector<SampleOutcome> read_journal(const std::string& path, const CampaignStudy& st,
                                        long* valid_end = nullptr);

/// Streams the valid records to `fn` one at a time (memory independent of the sample count).
/// Returns the byte offset after the last valid record.
long for_each_record(const std::string& path, const CampaignStudy& st,
                     const std::function<void(const SampleOutcome&)>& fn);

}  // namespace pound
