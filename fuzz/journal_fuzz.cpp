// libFuzzer harness: the campaign journal reader (read_journal, and the resume path that cuts
// a torn tail and appends). The first input byte chooses the file: even, the rest of the
// input as it is; odd, a valid header of the harness's study followed by the rest of the
// input with the FNV-1a checksum of every whole record put right (campaign/journal.hpp), so
// that the record decoder sees arbitrary contents and not only checksum failures.
// Invariants: the reader accepts whole records after the header and stops at the first torn
// or corrupt one; after a resume has appended a record, the journal holds one more.
#include <sys/stat.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "campaign/journal.hpp"
#include "campaign/sample.hpp"
#include "core/error.hpp"
#include "fuzz_support.hpp"

namespace {

using namespace pound;

constexpr std::size_t kHeaderBytes = 40;  // the magic and four u64 (campaign/journal.hpp)

const CampaignStudy& study() {
  static const CampaignStudy st = fuzz::smoke_study();
  return st;
}

const SampleOutcome& real_outcome(long id) {
  static std::vector<SampleOutcome> cache;
  static SampleRunner runner(study());
  while (static_cast<long>(cache.size()) <= id)
    cache.push_back(runner.run(static_cast<long>(cache.size())));
  return cache[static_cast<std::size_t>(id)];
}

// FNV-1a over the bytes of a record before its checksum (campaign/journal.hpp).
std::uint64_t fnv(const char* p, std::size_t n) {
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t i = 0; i < n; ++i) {
    h ^= static_cast<unsigned char>(p[i]);
    h *= 1099511628211ull;
  }
  return h;
}

long file_size(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 ? static_cast<long>(st.st_size) : -1;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  const std::string dir = fuzz::prepare_dir(*argc, *argv);
  if (dir.empty()) return 0;
  // Seeds: a journal of three real samples (as written by a campaign), the same with a torn
  // last record, and its records after the "valid header" byte.
  const std::string path = fuzz::scratch() + "/seed.journal";
  {
    JournalWriter w(path, study(), false);
    for (long id = 0; id < 3; ++id) {
      const auto rec = encode_record(real_outcome(id), RecordLayout(study()));
      w.append(rec.data(), rec.size());
    }
  }
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  fuzz::write_prepared(dir, "seeds/journal", std::string(1, '\0') + bytes);
  fuzz::write_prepared(dir, "seeds/torn", std::string(1, '\0') + bytes.substr(0, bytes.size() - 9));
  fuzz::write_prepared(dir, "seeds/records", std::string(1, '\1') + bytes.substr(kHeaderBytes));
  fuzz::write_prepared(dir, "dict",
                       fuzz::dict_entry("POUNDJ03") + fuzz::dict_entry("POUNDJ02") +
                           fuzz::dict_entry("POUNDJ01") + fuzz::dict_entry(std::string(8, '\0')) +
                           fuzz::dict_entry(std::string(8, '\xff')));
  std::exit(0);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const CampaignStudy& st = study();
  const RecordLayout layout(st);
  const std::size_t rb = layout.record_bytes();
  const std::string path = fuzz::scratch() + "/run.h5.journal";
  std::size_t whole = 0;  // records with a put-right checksum (odd first byte)
  if (data[0] & 1) {
    { JournalWriter header_only(path, st, false); }
    std::vector<char> body(data + 1, data + size);
    for (std::size_t off = 0; off + rb <= body.size(); off += rb, ++whole) {
      const std::uint64_t sum = fnv(body.data() + off, rb - 8);
      std::memcpy(body.data() + off + rb - 8, &sum, 8);
    }
    std::FILE* f = std::fopen(path.c_str(), "ab");
    if (!f || std::fwrite(body.data(), 1, body.size(), f) != body.size() || std::fclose(f) != 0)
      fuzz::fail("cannot write " + path);
  } else {
    fuzz::write_file("run.h5.journal", data + 1, size - 1);
  }
  const long bytes = file_size(path);
  long end = -1;
  std::vector<SampleOutcome> records;
  try {
    records = read_journal(path, st, &end);
  } catch (const InputError&) {
    return 0;  // not a journal of this study
  }
  const long n = static_cast<long>(records.size());
  const bool cut_in_header = end == 0 && n == 0 && bytes < static_cast<long>(kHeaderBytes);
  if ((!cut_in_header && end != static_cast<long>(kHeaderBytes + n * rb)) || end > bytes)
    fuzz::fail("valid end " + std::to_string(end) + " for " + std::to_string(n) + " records in " +
               std::to_string(bytes) + " bytes");
  if ((data[0] & 1) && n != static_cast<long>(whole))
    fuzz::fail(std::to_string(n) + " of " + std::to_string(whole) + " checksummed records read");
  for (const auto& o : records)
    if (o.values.size() != static_cast<std::size_t>(layout.parameters) ||
        o.peak_force.size() != static_cast<std::size_t>(layout.pairs * layout.levels))
      fuzz::fail("a record decoded to arrays of the wrong size");
  // Resume: the torn tail is cut and a record appended.
  const SampleOutcome& next = real_outcome(1);
  {
    JournalWriter w(path, st, true);
    const auto rec = encode_record(next, layout);
    w.append(rec.data(), rec.size());
    w.sync();
  }
  const auto after = read_journal(path, st);
  if (static_cast<long>(after.size()) != n + 1 || after.back().id != next.id ||
      file_size(path) != std::max(end, static_cast<long>(kHeaderBytes)) + static_cast<long>(rb))
    fuzz::fail("after a resume appended one record the journal holds " +
               std::to_string(after.size()) + " records (had " + std::to_string(n) + ")");
  return 0;
}
