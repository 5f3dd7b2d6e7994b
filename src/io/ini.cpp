#include "io/ini.hpp"

#include <sys/stat.h>

#include <fstream>
#include <set>
#include <sstream>

#include "core/error.hpp"
#include "io/utf8_bom.hpp"

namespace pound {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

bool valid_name(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '-' || c == '_' || c == '.';
    if (!ok) return false;
  }
  return true;
}

std::string strip_comment(const std::string& s) {
  // A comment starts at '#' or ';' at the line start or after white space.
  for (std::size_t i = 0; i < s.size(); ++i) {
    if ((s[i] == '#' || s[i] == ';') && (i == 0 || s[i - 1] == ' ' || s[i - 1] == '\t'))
      return s.substr(0, i);
  }
  return s;
}

}  // namespace

std::vector<IniEntry> parse_ini(const std::string& text, const std::string& name) {
  std::vector<IniEntry> out;
  std::set<std::string> seen;
  // A UTF-8 byte-order mark, as Windows editors save "UTF-8" files, is not part of the text.
  std::string body = text;
  strip_utf8_bom(body);
  std::istringstream in(body);
  std::string raw, section;
  int lineno = 0;
  while (std::getline(in, raw)) {
    ++lineno;
    const std::string line = trim(strip_comment(raw));
    if (line.empty()) continue;
    const std::string where = name + ":" + std::to_string(lineno) + ": ";
    if (line.front() == '[') {
      if (line.back() != ']')
        throw InputError(where + "section header '" + line + "' lacks a closing ']'");
      section = trim(line.substr(1, line.size() - 2));
      if (!valid_name(section))
        throw InputError(where + "invalid section name '" + section +
                         "' (letters, digits, '-', '_' and '.')");
      continue;
    }
    const auto eq = line.find('=');
    if (eq == std::string::npos)
      throw InputError(where + "expected 'key = value', got '" + line + "'");
    const std::string key = trim(line.substr(0, eq));
    if (!valid_name(key))
      throw InputError(where + "invalid key '" + key + "' (letters, digits, '-', '_' and '.')");
    IniEntry e;
    e.key = section.empty() ? key : section + "." + key;
    e.value = trim(line.substr(eq + 1));
    e.file = name;
    e.line = lineno;
    if (!seen.insert(e.key).second) throw InputError(where + "key '" + e.key + "' is given twice");
    out.push_back(std::move(e));
  }
  return out;
}

std::vector<IniEntry> read_ini(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw InputError(path + ": is a directory, not a study file; give the study file (INI)");
  std::ifstream f(path);
  if (!f) throw InputError(path + ": cannot open the study file (does it exist?)");
  std::ostringstream ss;
  ss << f.rdbuf();
  return parse_ini(ss.str(), path);
}

}  // namespace pound
