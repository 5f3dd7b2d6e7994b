#pragma once
// Options of one subcommand, from the command line and an INI study file (--config FILE), the
// command line winning. Every option is declared once with its unit, default and meaning;
// the declarations drive --help, the unknown-key check and the error messages, which name the
// file and line (or the command-line flag), the key and what would be valid.
//
// A key may contain '#', standing for a positive integer: "building#.masses" declares
// building1.masses, building2.masses, ...
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace pound {

struct IniEntry;  // io/ini.hpp

struct OptionSpec {
  std::string key;            ///< dotted key; section "a" and key "b" in INI give "a.b"
  std::string unit;           ///< SI unit or "-" for dimensionless, "" for text and flags
  std::string default_value;  ///< "" means no default (optional unless required)
  std::string help;           ///< one line: what it means and what is valid
  bool flag = false;          ///< a switch without value (command line only, e.g. --json)
};

class Options {
 public:
  Options(std::string command, std::string summary, std::vector<OptionSpec> specs);

  /// Parses argv (after the subcommand name). Reads --config FILE when given. Throws
  /// InputError on unknown options or keys, repeated keys and syntax errors.
  void parse(int argc, const char* const* argv);
  /// The same from the arguments after the program name ({"--config", "study.ini", ...}).
  void parse(const std::vector<std::string>& args);
  /// The keys of a study given as INI text (a study stored in a result file), as --config reads
  /// a file; `name` stands for the file in messages. Throws InputError as parse() does.
  void parse_text(const std::string& text, const std::string& name);

  bool help_requested() const { return help_; }
  std::string help_text() const;

  /// True when the key was given (command line or file) or has a default.
  bool has(const std::string& key) const;
  /// True when the key was given by the user.
  bool given(const std::string& key) const;
  bool flag(const std::string& key) const;

  std::string get_string(const std::string& key) const;
  double get_double(const std::string& key) const;
  long get_int(const std::string& key) const;
  /// A file path; a relative path given in the study file is taken relative to the study
  /// file's folder, one given on the command line relative to the working directory.
  std::string get_path(const std::string& key) const;
  std::vector<double> get_doubles(const std::string& key) const;
  /// A list of one value for each of n floors (or storeys), or one value for all; each must
  /// pass `valid`, else invalid(key, what); a list of another length names n and its length.
  std::vector<double> get_per_floor(const std::string& key, std::size_t n, const std::string& what,
                                    const std::function<bool(double)>& valid) const;

  /// Doubles with a check: lo < x (or lo <= x) and x <= hi; `what` names the quantity.
  double get_positive(const std::string& key) const;
  double get_nonnegative(const std::string& key) const;

  /// The keys "prefix.X" of this object as a new Options over `specs` (declared without the
  /// prefix), keeping where each value came from; errors name the full key. Keys under the
  /// prefix that `specs` does not declare are an error.
  Options section(const std::string& prefix, std::vector<OptionSpec> specs) const;

  /// The keys given by the user (command line or file), sorted.
  std::vector<std::string> given_keys() const;
  /// True when `key` is an instance of the declared pattern ("building2.E" of "building#.E").
  static bool matches(const std::string& pattern, const std::string& key);

  /// The numbers N of the "prefixN." keys given (building1.masses, building12.E: 1 and 12),
  /// ascending, each with the alphabetically first key given under it (the keys are kept
  /// sorted, not in the order given), in one walk over the given keys. A
  /// number too large for a long (building2000000000000000000000.masses) counts as the
  /// largest long: past any count of buildings or pairs, and its key names it.
  std::map<long, std::string> numbered_sections(const std::string& prefix) const;

  /// Where a value came from: "study.ini:12: key 'gap'" or "command line: --gap".
  std::string where(const std::string& key) const;
  /// An InputError saying that the key's value is invalid and what is valid.
  InputError invalid(const std::string& key, const std::string& valid) const;

  /// The resolved configuration (given keys and defaults), as INI-like "key = value" lines,
  /// sorted by key. Stored in result files and echoed at start.
  std::string resolved_text(const std::vector<std::string>& exclude = {}) const;
  const std::string& config_path() const { return config_path_; }

 private:
  struct Value {
    std::string text;
    std::string file;  // "" for the command line
    int line = 0;
  };
  const OptionSpec* find_spec(const std::string& key) const;
  /// Takes the entries of a study file; keys already given (the command line) win.
  void add_entries(const std::vector<IniEntry>& entries);
  const Value* lookup(const std::string& key) const;
  /// Runs a parse; a failure gets the key's meaning and unit appended ("expected ...").
  template <class Parse>
  auto with_expectation(const std::string& key, Parse parse) const -> decltype(parse()) {
    try {
      return parse();
    } catch (const InputError& e) {
      const auto* s = find_spec(key);
      if (!s) throw;
      throw InputError(std::string(e.what()) + "; expected " + meaning(*s, key));
    }
  }
  std::string valid_keys_hint(const std::string& key) const;
  /// The spec's help and unit for this key, '#' in the help replaced by the key's number
  /// ("gap between building # and #+1" for pair2.gap reads "building 2 and 3").
  static std::string meaning(const OptionSpec& s, const std::string& key);

  std::string command_, summary_, prefix_;
  std::vector<OptionSpec> specs_;
  std::map<std::string, Value> values_;
  std::string config_path_;
  bool help_ = false;
};

/// Parses a list of numbers separated by commas and/or white space. Throws InputError with
/// `where` in the message on a non-number.
std::vector<double> parse_number_list(const std::string& text, const std::string& where);
/// Parses one finite number; throws InputError naming `where`.
double parse_number(const std::string& text, const std::string& where);

}  // namespace pound
