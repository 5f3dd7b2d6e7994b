#include "io/options.hpp"

#include <algorithm>
#include <boost/program_options.hpp>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "io/ini.hpp"
#include "io/number.hpp"

namespace po = boost::program_options;

namespace pound {
namespace {

// Matches a key against a declared pattern in which '#' stands for a positive integer.
bool key_matches(const std::string& pattern, const std::string& key) {
  std::size_t i = 0, j = 0;
  while (i < pattern.size() && j < key.size()) {
    if (pattern[i] == '#') {
      std::size_t k = j;
      while (k < key.size() && std::isdigit(static_cast<unsigned char>(key[k]))) ++k;
      if (k == j || key[j] == '0') return false;
      j = k;
      ++i;
    } else {
      if (pattern[i] != key[j]) return false;
      ++i;
      ++j;
    }
  }
  return i == pattern.size() && j == key.size();
}

// The names to register on the command line for a pattern: the pattern itself when it has no
// '#', else every "--name" or "--name=value" in argv that matches it (building12.masses too).
std::vector<std::string> command_line_names(const std::string& pattern, int argc,
                                            const char* const* argv) {
  if (pattern.find('#') == std::string::npos) return {pattern};
  std::vector<std::string> out;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.size() < 3 || a.compare(0, 2, "--") != 0) continue;
    const std::string name =
        a.substr(2, a.find('=') == std::string::npos ? std::string::npos : a.find('=') - 2);
    if (key_matches(pattern, name) && std::find(out.begin(), out.end(), name) == out.end())
      out.push_back(name);
  }
  return out;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

}  // namespace

double parse_number(const std::string& text, const std::string& where) {
  const std::string t = trim(text);
  double v = 0.0;
  if (!read_decimal(t, &v))
    throw InputError(where + ": '" + t + "' is not a finite number (valid: " + kNumberForm + ")");
  return v;
}

std::vector<double> parse_number_list(const std::string& text, const std::string& where) {
  std::string s = text;
  std::replace(s.begin(), s.end(), ',', ' ');
  std::istringstream in(s);
  std::vector<double> out;
  std::string tok;
  while (in >> tok) out.push_back(parse_number(tok, where));
  if (out.empty()) throw InputError(where + ": expected a list of numbers, got nothing");
  return out;
}

Options::Options(std::string command, std::string summary, std::vector<OptionSpec> specs)
    : command_(std::move(command)), summary_(std::move(summary)), specs_(std::move(specs)) {}

const OptionSpec* Options::find_spec(const std::string& key) const {
  for (const auto& s : specs_)
    if (key_matches(s.key, key)) return &s;
  return nullptr;
}

std::string Options::valid_keys_hint(const std::string& key) const {
  // List declared keys of the same section, or all when the section is unknown.
  const auto dot = key.rfind('.');
  const std::string section = dot == std::string::npos ? "" : key.substr(0, dot);
  std::string list;
  for (const auto& s : specs_) {
    if (s.flag) continue;
    const auto sd = s.key.rfind('.');
    const std::string ssec = sd == std::string::npos ? "" : s.key.substr(0, sd);
    if (!section.empty() && !key_matches(ssec, section)) continue;
    if (section.empty() && !ssec.empty()) continue;
    list += (list.empty() ? "" : ", ") + s.key;
  }
  if (list.empty())
    for (const auto& s : specs_)
      if (!s.flag) list += (list.empty() ? "" : ", ") + s.key;
  return list;
}

void Options::parse(int argc, const char* const* argv) {
  po::options_description desc;
  desc.add_options()("help,h", "")("config", po::value<std::string>(), "");
  for (const auto& s : specs_) {
    for (const auto& name : command_line_names(s.key, argc, argv)) {
      if (s.flag)
        desc.add_options()(name.c_str(), po::bool_switch(), "");
      else
        desc.add_options()(name.c_str(), po::value<std::string>(), "");
    }
  }
  po::variables_map vm;
  try {
    po::store(
        po::command_line_parser(argc, argv)
            .options(desc)
            .style(po::command_line_style::unix_style ^ po::command_line_style::allow_guessing)
            .run(),
        vm);
  } catch (const po::unknown_option& e) {
    // Name the keys that would be valid there, as for an unknown key in a study file.
    std::string key = e.get_option_name();
    key.erase(0, key.find_first_not_of('-'));
    throw InputError("command line: unknown option '--" + key + "' for 'pound " + command_ +
                     "'; valid keys: " + valid_keys_hint(key));
  } catch (const po::error& e) {
    throw InputError(std::string("command line: ") + e.what() + " (see 'pound " + command_ +
                     " --help')");
  }
  help_ = vm.count("help") > 0;
  for (const auto& kv : vm) {
    if (kv.first == "help" || kv.first == "config") continue;
    const auto* spec = find_spec(kv.first);
    if (spec && spec->flag) {
      if (kv.second.as<bool>()) values_[kv.first] = Value{"true", "", 0};
    } else if (!kv.second.defaulted()) {
      values_[kv.first] = Value{kv.second.as<std::string>(), "", 0};
    }
  }
  if (vm.count("config")) {
    config_path_ = vm["config"].as<std::string>();
    add_entries(read_ini(config_path_));
  }
}

void Options::add_entries(const std::vector<IniEntry>& entries) {
  for (const auto& e : entries) {
    const auto* spec = find_spec(e.key);
    if (!spec || spec->flag) {
      throw InputError(e.file + ":" + std::to_string(e.line) + ": unknown key '" + e.key +
                       "' for 'pound " + command_ + "'; valid keys: " + valid_keys_hint(e.key));
    }
    values_.emplace(e.key, Value{e.value, e.file, e.line});  // command line wins
  }
}

void Options::parse_text(const std::string& text, const std::string& name) {
  add_entries(parse_ini(text, name));
}

void Options::parse(const std::vector<std::string>& args) {
  std::vector<const char*> argv = {command_.c_str()};
  for (const auto& a : args) argv.push_back(a.c_str());
  parse(static_cast<int>(argv.size()), argv.data());
}

const Options::Value* Options::lookup(const std::string& key) const {
  const auto it = values_.find(key);
  return it == values_.end() ? nullptr : &it->second;
}

bool Options::given(const std::string& key) const {
  return lookup(key) != nullptr;
}

bool Options::has(const std::string& key) const {
  if (given(key)) return true;
  const auto* s = find_spec(key);
  return s && !s->default_value.empty();
}

bool Options::flag(const std::string& key) const {
  const auto* v = lookup(key);
  return v && v->text == "true";
}

std::string Options::where(const std::string& key) const {
  const auto* v = lookup(key);
  const std::string full = prefix_ + key;
  if (v && !v->file.empty())
    return v->file + ":" + std::to_string(v->line) + ": key '" + full + "'";
  if (v) return "command line: --" + full;
  return (config_path_.empty() ? std::string("command line") : config_path_) + ": key '" + full +
         "'";
}

InputError Options::invalid(const std::string& key, const std::string& valid) const {
  const auto* v = lookup(key);
  std::string msg = where(key);
  if (v) msg += " = '" + v->text + "'";
  return InputError(msg + ": " + valid);
}

std::string Options::meaning(const OptionSpec& s, const std::string& key) {
  std::string help = s.help;
  // The number standing for the pattern's only '#', read from the key.
  const auto p = s.key.find('#');
  if (p != std::string::npos && s.key.find('#', p + 1) == std::string::npos &&
      key.compare(0, p, s.key, 0, p) == 0) {
    std::size_t end = p;
    while (end < key.size() && std::isdigit(static_cast<unsigned char>(key[end]))) ++end;
    if (end > p && end - p < 9) {
      const long n = std::stol(key.substr(p, end - p));
      std::string out;
      for (std::size_t i = 0; i < help.size(); ++i) {
        if (help[i] != '#') {
          out += help[i];
        } else if (help.compare(i, 3, "#+1") == 0) {
          out += std::to_string(n + 1);
          i += 2;
        } else {
          out += std::to_string(n);
        }
      }
      help = out;
    }
  }
  return help + (s.unit.empty() || s.unit == "-" ? "" : " [" + s.unit + "]");
}

std::string Options::get_string(const std::string& key) const {
  if (const auto* v = lookup(key)) return v->text;
  const auto* s = find_spec(key);
  if (!s) throw std::logic_error("option '" + key + "' was never declared");
  if (s->default_value.empty()) throw InputError(where(key) + ": missing; " + meaning(*s, key));
  return s->default_value;
}

std::string Options::get_path(const std::string& key) const {
  const std::string p = get_string(key);
  const auto* v = lookup(key);
  if (p.empty() || p[0] == '/' || !v || v->file.empty()) return p;
  const auto slash = v->file.rfind('/');
  return slash == std::string::npos ? p : v->file.substr(0, slash + 1) + p;
}

double Options::get_double(const std::string& key) const {
  const std::string text = get_string(key);  // its own "missing" error already says what
  return with_expectation(key, [&] { return parse_number(text, where(key)); });
}

long Options::get_int(const std::string& key) const {
  const double v = get_double(key);
  if (v != std::floor(v) || std::fabs(v) > 1e15) throw invalid(key, "must be a whole number");
  return static_cast<long>(v);
}

std::vector<double> Options::get_doubles(const std::string& key) const {
  const std::string text = get_string(key);
  return with_expectation(key, [&] { return parse_number_list(text, where(key)); });
}

std::vector<double> Options::get_per_floor(const std::string& key, std::size_t n,
                                           const std::string& what,
                                           const std::function<bool(double)>& valid) const {
  std::vector<double> v = get_doubles(key);
  if (v.size() == 1 && n > 1) v.assign(n, v[0]);
  if (v.size() != n)
    throw invalid(key, "expected " + std::to_string(n) + " values (one per floor), got " +
                           std::to_string(v.size()));
  for (double x : v)
    if (!valid(x)) throw invalid(key, what);
  return v;
}

double Options::get_positive(const std::string& key) const {
  const double v = get_double(key);
  if (!(v > 0)) throw invalid(key, "must be > 0");
  return v;
}

double Options::get_nonnegative(const std::string& key) const {
  const double v = get_double(key);
  if (!(v >= 0)) throw invalid(key, "must be >= 0");
  return v;
}

Options Options::section(const std::string& prefix, std::vector<OptionSpec> specs) const {
  Options sub(command_, summary_, std::move(specs));
  sub.prefix_ = prefix_ + prefix + ".";
  sub.config_path_ = config_path_;
  const std::string pre = prefix + ".";
  for (const auto& kv : values_) {
    if (kv.first.compare(0, pre.size(), pre) != 0) continue;
    const std::string key = kv.first.substr(pre.size());
    if (!sub.find_spec(key)) {
      const std::string loc = kv.second.file.empty()
                                  ? "command line: --" + kv.first
                                  : kv.second.file + ":" + std::to_string(kv.second.line);
      throw InputError(loc + ": unknown key '" + kv.first + "'; valid keys in [" + prefix +
                       "]: " + sub.valid_keys_hint(key));
    }
    sub.values_[key] = kv.second;
  }
  return sub;
}

std::vector<std::string> Options::given_keys() const {
  std::vector<std::string> keys;
  for (const auto& kv : values_) keys.push_back(kv.first);
  return keys;
}

bool Options::matches(const std::string& pattern, const std::string& key) {
  return key_matches(pattern, key);
}

std::map<long, std::string> Options::numbered_sections(const std::string& prefix) const {
  std::map<long, std::string> out;
  constexpr long kMax = std::numeric_limits<long>::max();
  for (const auto& kv : values_) {
    const std::string& key = kv.first;
    if (key.compare(0, prefix.size(), prefix) != 0) continue;
    std::size_t k = prefix.size();
    // Found by fuzz_study: building2000000000000.masses overflowed an int (undefined
    // behaviour); a number past the range of a long is held at its largest value.
    long num = 0;
    while (k < key.size() && std::isdigit(static_cast<unsigned char>(key[k]))) {
      const int digit = key[k++] - '0';
      num = num > (kMax - digit) / 10 ? kMax : num * 10 + digit;
    }
    if (k > prefix.size() && k < key.size() && key[k] == '.') out.emplace(num, key);
  }
  return out;
}

std::string Options::resolved_text(const std::vector<std::string>& exclude) const {
  std::map<std::string, std::string> all;
  for (const auto& s : specs_)
    if (s.key.find('#') == std::string::npos && !s.default_value.empty() && !s.flag)
      all[s.key] = s.default_value;
  for (const auto& kv : values_) all[kv.first] = kv.second.text;
  for (const auto& k : exclude) all.erase(k);
  std::string out;
  for (const auto& kv : all) out += kv.first + " = " + kv.second + "\n";
  return out;
}

std::string Options::help_text() const {
  std::ostringstream out;
  out << "Usage: pound " << command_ << " [--config STUDY.ini] [options]\n" << summary_ << "\n\n";
  out << "Every option can also be given as 'key = value' in the study file; INI sections\n"
         "give the part before the dot ([building1] masses = ... is building1.masses).\n"
         "The command line wins over the file. '#' stands for 1, 2, 3, ...\n\n";
  out << "  --config FILE                study file (INI)\n";
  for (const auto& s : specs_) {
    std::string lhs = "  --" + s.key;
    if (!s.flag) lhs += " ARG";
    if (lhs.size() < 31) lhs.resize(31, ' ');
    out << lhs << " " << s.help;
    if (!s.unit.empty() && s.unit != "-") out << " [" << s.unit << "]";
    if (!s.default_value.empty()) out << " (default " << s.default_value << ")";
    out << "\n";
  }
  return out.str();
}

}  // namespace pound
