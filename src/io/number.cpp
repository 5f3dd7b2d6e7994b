#include "io/number.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace pound {

const char* const kNumberForm = "a decimal number such as 16, -0.5 or 2.1e9";

namespace {

bool digit(char c) {
  return c >= '0' && c <= '9';
}

// Length of the longest prefix of s matching [+-]? (D+ (. D*)? | . D+) ([eE] [+-]? D+)?,
// or 0 when none does.
std::size_t decimal_length(const std::string& s) {
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t mantissa = 0;
  while (i < s.size() && digit(s[i])) ++i, ++mantissa;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && digit(s[i])) ++i, ++mantissa;
  }
  if (mantissa == 0) return 0;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
    const std::size_t first = j;
    while (j < s.size() && digit(s[j])) ++j;
    if (j == first) return 0;  // "1e", "2e+": an exponent without digits
    i = j;
  }
  return i;
}

}  // namespace

bool read_decimal(const std::string& text, double* value) {
  if (text.empty() || decimal_length(text) != text.size()) return false;
  // The grammar above is a subset of strtod's decimal form, so strtod reads all of it.
  const double v = std::strtod(text.c_str(), nullptr);
  if (!std::isfinite(v)) return false;  // beyond the range of a double (1e999)
  *value = v;
  return true;
}

bool read_decimal_at(const std::string& text, std::size_t pos, double* value) {
  while (pos < text.size() && (text[pos] == ' ' || text[pos] == '\t')) ++pos;
  if (pos >= text.size()) return false;
  const std::string rest = text.substr(pos);
  const std::size_t n = decimal_length(rest);
  if (n == 0) return false;
  if (n < rest.size()) {
    const unsigned char next = static_cast<unsigned char>(rest[n]);
    if (std::isdigit(next) || next == '.' || next == 'x' || next == 'X') return false;
  }
  return read_decimal(rest.substr(0, n), value);
}

bool names_non_finite(const std::string& text) {
  std::string s;
  for (char c : text) s += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) s.erase(0, 1);
  return s == "nan" || s == "inf" || s == "infinity" || s.rfind("nan(", 0) == 0;
}

}  // namespace pound
