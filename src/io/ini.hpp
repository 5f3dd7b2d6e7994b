#pragma once
// A small INI reader that remembers where every key came from, so that errors can name the
// file and line. Format:
//   # or ; starts a comment (also after a value, when preceded by white space)
//   [section]          keys below are named section.key
//   key = value
// A UTF-8 byte-order mark at the start is skipped. Repeated keys are an error. Keys and
// section names are lower-case letters, digits, '-', '_' and '.'.
#include <string>
#include <vector>

namespace pound {

struct IniEntry {
  std::string key;    ///< full key, "section.key" or "key" before any section
  std::string value;  ///< trimmed value text
  std::string file;   ///< file it was read from
  int line = 0;       ///< 1-based line number
};

/// Reads an INI file. Throws InputError naming file and line on a syntax error, a repeated
/// key, or a file that cannot be opened.
std::vector<IniEntry> read_ini(const std::string& path);

/// Parses INI text; `name` is used in error messages.
std::vector<IniEntry> parse_ini(const std::string& text, const std::string& name);

}  // namespace pound
