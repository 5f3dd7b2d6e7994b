#include "campaign/journal.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "campaign/building_arrays.hpp"
#include "campaign/floor_arrays.hpp"
#include "core/error.hpp"
#include "sampling/counter_rng.hpp"

namespace pound {
namespace {

constexpr char kMagic[8] = {'P', 'O', 'U', 'N', 'D', 'J', '0', '4'};
// Journals of earlier formats: recognised to say so (their records are laid out differently).
struct OldFormat {
  char magic[8];
  const char* lacks;  ///< what its records do not hold
};
constexpr OldFormat kOldFormats[] = {
    {{'P', 'O', 'U', 'N', 'D', 'J', '0', '1'},
     "the residual drift, ductility, hysteretic energy and free-run approach"},
    {{'P', 'O', 'U', 'N', 'D', 'J', '0', '2'}, "the free-run approach of the facing floors"},
    {{'P', 'O', 'U', 'N', 'D', 'J', '0', '3'}, "the collapse of each building"},
};
constexpr std::size_t kHeaderBytes = 8 + 4 * 8;

std::uint64_t fnv(const char* p, std::size_t n) {
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t i = 0; i < n; ++i) {
    h ^= static_cast<unsigned char>(p[i]);
    h *= 1099511628211ull;
  }
  return h;
}

template <class T>
void put(std::vector<char>& b, const T& v) {
  const char* p = reinterpret_cast<const char*>(&v);
  b.insert(b.end(), p, p + sizeof(T));
}

template <class T>
T get(const char*& p) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  p += sizeof(T);
  return v;
}

std::vector<char> header(const CampaignStudy& st, const RecordLayout& l) {
  std::vector<char> h(kMagic, kMagic + 8);
  put<std::uint64_t>(h, study_hash(st));
  put<std::uint64_t>(h, l.values());
  put<std::uint64_t>(h, RecordLayout::kMessageBytes);
  put<std::uint64_t>(h, static_cast<std::uint64_t>(st.samples));
  return h;
}

}  // namespace

RecordLayout::RecordLayout(const CampaignStudy& st)
    : parameters(static_cast<int>(st.parameters.size())),
      buildings(st.buildings()),
      floors(st.max_floors()),
      pairs(st.pairs()),
      levels(st.max_levels()) {}

std::size_t RecordLayout::values() const {
  // im, scale, parameters, the floor arrays, the building arrays, 5 contact arrays, the pairs'
  // relative ground displacement, wall seconds, rank
  return 2 + parameters + floor_array_fields().size() * buildings * floors +
         building_array_fields().size() * buildings + 5 * pairs * levels + pairs + 2;
}

std::size_t RecordLayout::record_bytes() const {
  return 16 + 8 * values() + kMessageBytes + 8;
}

std::uint64_t study_hash(const CampaignStudy& st) {
  std::string s =
      st.resolved + "\nsamples=" + std::to_string(st.samples) + "\nseed=" + std::to_string(st.seed);
  if (st.range_lo != 0 || st.range_hi != st.samples)
    s += "\nrange=" + std::to_string(st.range_lo) + ":" + std::to_string(st.range_hi);
  return fnv(s.data(), s.size());
}

std::vector<char> encode_record(const SampleOutcome& o, const RecordLayout& l) {
  std::vector<char> b;
  b.reserve(l.record_bytes());
  put<std::int64_t>(b, o.id);
  put<std::int64_t>(b, static_cast<std::int64_t>(o.status));
  put(b, o.im);
  put(b, o.scale);
  for (int i = 0; i < l.parameters; ++i) put(b, o.values.at(i));
  for (const auto& a : floor_array_fields())
    for (double x : o.*a.member) put(b, x);
  for (const auto& a : building_array_fields())
    for (double x : o.*a.member) put(b, x);
  for (const auto* v :
       {&o.peak_force, &o.impacts, &o.approach_free, &o.peak_column_shear, &o.crush})
    for (double x : *v) put(b, x);
  for (double x : o.ground_relative) put(b, x);
  put(b, o.wall_seconds);
  put(b, static_cast<double>(o.rank));
  char msg[RecordLayout::kMessageBytes] = {};
  std::strncpy(msg, o.message.c_str(), sizeof msg - 1);
  b.insert(b.end(), msg, msg + sizeof msg);
  put<std::uint64_t>(b, fnv(b.data(), b.size()));
  if (b.size() != l.record_bytes()) throw std::logic_error("record size mismatch");
  return b;
}

void record_key(const char* bytes, long& id, SampleStatus& status) {
  const char* p = bytes;
  id = static_cast<long>(get<std::int64_t>(p));
  status = static_cast<SampleStatus>(get<std::int64_t>(p));
}

bool decode_record(const char* bytes, const RecordLayout& l, SampleOutcome& o) {
  const std::size_t n = l.record_bytes() - 8;
  std::uint64_t sum;
  std::memcpy(&sum, bytes + n, 8);
  if (sum != fnv(bytes, n)) return false;
  const char* p = bytes;
  o.id = static_cast<long>(get<std::int64_t>(p));
  o.status = static_cast<SampleStatus>(get<std::int64_t>(p));
  o.im = get<double>(p);
  o.scale = get<double>(p);
  o.values.resize(l.parameters);
  for (auto& v : o.values) v = get<double>(p);
  const std::size_t bf = static_cast<std::size_t>(l.buildings * l.floors);
  const std::size_t pl = static_cast<std::size_t>(l.pairs * l.levels);
  for (const auto& a : floor_array_fields()) {
    std::vector<double>& v = o.*a.member;
    v.resize(bf);
    for (auto& x : v) x = get<double>(p);
  }
  for (const auto& a : building_array_fields()) {
    std::vector<double>& v = o.*a.member;
    v.resize(static_cast<std::size_t>(l.buildings));
    for (auto& x : v) x = get<double>(p);
  }
  for (auto* v : {&o.peak_force, &o.impacts, &o.approach_free, &o.peak_column_shear, &o.crush}) {
    v->resize(pl);
    for (auto& x : *v) x = get<double>(p);
  }
  o.ground_relative.resize(static_cast<std::size_t>(l.pairs));
  for (auto& x : o.ground_relative) x = get<double>(p);
  o.wall_seconds = get<double>(p);
  // Found by fuzz_journal: a rank no int holds (in a record no pound writes, checksum right)
  // overflowed the conversion, undefined behaviour; it reads -1.
  const double rank = get<double>(p);
  o.rank = rank >= 0.0 && rank <= 2147483647.0 ? static_cast<int>(rank) : -1;
  o.message.assign(p, strnlen(p, RecordLayout::kMessageBytes));
  return true;
}

long for_each_record(const std::string& path, const CampaignStudy& st,
                     const std::function<void(const SampleOutcome&)>& fn) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw InputError(path + ": cannot open the campaign journal to resume");
  const RecordLayout l(st);
  const std::vector<char> want = header(st, l);
  std::vector<char> h(kHeaderBytes);
  const std::size_t got = std::fread(h.data(), 1, h.size(), f);
  const bool whole = got == h.size();
  if (!whole && std::equal(h.begin(), h.begin() + static_cast<long>(got), want.begin())) {
    std::fclose(f);
    return 0;  // cut short inside its header (a full disk at the start): no record yet
  }
  for (const auto& old : kOldFormats)
    if (whole && std::memcmp(h.data(), old.magic, 8) == 0) {
      std::fclose(f);
      throw InputError(path + ": a campaign journal written by an older pound (format " +
                       std::string(old.magic, 8) + ", without " + old.lacks +
                       "); it cannot be resumed, start again with --force");
    }
  if (!whole || std::memcmp(h.data(), kMagic, 8) != 0) {
    std::fclose(f);
    throw InputError(path + ": not a pound campaign journal");
  }
  if (h != want) {
    std::fclose(f);
    throw InputError(path +
                     ": the journal belongs to a different study, sample count or seed; "
                     "resume with the same study file and options, or start again with --force");
  }
  std::vector<char> rec(l.record_bytes());
  long end = static_cast<long>(kHeaderBytes);
  SampleOutcome o;
  while (std::fread(rec.data(), 1, rec.size(), f) == rec.size()) {
    if (!decode_record(rec.data(), l, o)) break;  // torn or corrupt tail
    fn(o);
    end += static_cast<long>(rec.size());
  }
  std::fclose(f);
  return end;
}

std::vector<SampleOutcome> read_journal(const std::string& path, const CampaignStudy& st,
                                        long* valid_end) {
  std::vector<SampleOutcome> out;
  const long end = for_each_record(path, st, [&](const SampleOutcome& o) { out.push_back(o); });
  if (valid_end) *valid_end = end;
  return out;
}

JournalWriter::JournalWriter(const std::string& path, const CampaignStudy& st, bool append,
                             std::function<void(const WriteError&)> on_write_error)
    : path_(path) {
  long end = 0;
  if (append) {
    end = for_each_record(path, st, [](const SampleOutcome&) {});
    if (::truncate(path.c_str(), end) != 0) fail("cannot cut the torn tail of the journal");
    f_.reset(std::fopen(path.c_str(), "ab"));
  } else {
    f_.reset(std::fopen(path.c_str(), "wb"));
  }
  if (!f_) fail("cannot write the campaign journal");
  if (end == 0) {  // new, or cut short inside its header
    const auto h = header(st, RecordLayout(st));
    this->append(h.data(), h.size());
  }
  on_write_error_ = std::move(on_write_error);
}

template <class Step>
void JournalWriter::guarded(Step step) {
  if (failed_) return;
  if (!on_write_error_) return step();
  try {
    step();
  } catch (const WriteError& e) {
    failed_ = true;
    on_write_error_(e);
  }
}

// After close() failed or an error elsewhere, f_ closes the file without reporting.
JournalWriter::~JournalWriter() = default;

void JournalWriter::fail(const char* what) const {
  const int e = errno;
  throw WriteError(path_ + ": " + what + " (" + std::strerror(e) + ")", e);
}

void JournalWriter::append(const char* bytes, std::size_t n) {
  // Every byte reaches the kernel before this returns (and so survives the process being
  // killed); a short write or a failed flush (disk full, file size limit) is an error at once.
  guarded([&] {
    if (n && std::fwrite(bytes, 1, n, f_.get()) != n) fail("cannot write the campaign journal");
    if (std::fflush(f_.get()) != 0) fail("cannot write the campaign journal");
  });
}

void JournalWriter::sync() {
  guarded([&] {
    if (std::fflush(f_.get()) != 0 || ::fsync(fileno(f_.get())) != 0)
      fail("cannot sync the campaign journal");
  });
}

void JournalWriter::close() {
  sync();
  guarded([&] {
    std::FILE* f = f_.release();
    if (std::fclose(f) != 0) fail("cannot close the campaign journal");
  });
}

}  // namespace pound
