#include "campaign/journal.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "campaign/floor_arrays.hpp"
#include "core/error.hpp"
#include "sampling/counter_rng.hpp"

namespace pound {
namespace {

constexpr char kMagic[8] = {'P', 'O', 'U', 'N', 'D', 'J', '0', '2'};
// Journals of earlier formats: recognised to say so (their records are laid out differently).
constexpr char kOldMagic[8] = {'P', 'O', 'U', 'N', 'D', 'J', '0', '1'};
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
  // im, scale, parameters, the floor arrays, 2 contact arrays, wall seconds, rank
  return 2 + parameters + floor_array_fields().size() * buildings * floors + 2 * pairs * levels + 2;
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
  for (const auto* v : {&o.peak_force, &o.impacts})
    for (double x : *v) put(b, x);
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
  for (auto* v : {&o.peak_force, &o.impacts}) {
    v->resize(pl);
    for (auto& x : *v) x = get<double>(p);
  }
  o.wall_seconds = get<double>(p);
  o.rank = static_cast<int>(get<double>(p));
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
  const bool whole = std::fread(h.data(), 1, h.size(), f) == h.size();
  if (whole && std::memcmp(h.data(), kOldMagic, 8) == 0) {
    std::fclose(f);
    throw InputError(
        path +
        ": a campaign journal written by an older pound (format POUNDJ01, without the "
        "residual drift, ductility and hysteretic energy); it cannot be resumed, start "
        "again with --force");
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

JournalWriter::JournalWriter(const std::string& path, const CampaignStudy& st, bool append)
    : path_(path) {
  if (append) {
    const long end = for_each_record(path, st, [](const SampleOutcome&) {});
    if (::truncate(path.c_str(), end) != 0)
      throw InputError(path + ": cannot cut the torn tail of the journal (" + std::strerror(errno) +
                       ")");
    f_ = std::fopen(path.c_str(), "ab");
  } else {
    f_ = std::fopen(path.c_str(), "wb");
    if (f_) {
      const auto h = header(st, RecordLayout(st));
      std::fwrite(h.data(), 1, h.size(), f_);
      std::fflush(f_);
    }
  }
  if (!f_)
    throw InputError(path + ": cannot write the campaign journal (" + std::strerror(errno) + ")");
}

JournalWriter::~JournalWriter() {
  if (f_) {
    std::fflush(f_);
    ::fsync(fileno(f_));
    std::fclose(f_);
  }
}

void JournalWriter::append(const char* bytes, std::size_t n) {
  if (n && std::fwrite(bytes, 1, n, f_) != n)
    throw InputError(path_ + ": write failed (" + std::strerror(errno) + ")");
  std::fflush(f_);  // in the kernel from here on: survives the process being killed
}

void JournalWriter::sync() {
  std::fflush(f_);
  ::fsync(fileno(f_));
}

}  // namespace pound
