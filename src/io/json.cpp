#include "io/json.hpp"

#include <cmath>
#include <cstdio>

namespace pound {

void JsonWriter::comma() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (!first_.empty()) {
    if (!first_.back()) out_ << ",";
    first_.back() = false;
  }
}

JsonWriter& JsonWriter::open(char bracket) {
  comma();
  out_ << bracket;
  first_.push_back(true);
  return *this;
}
JsonWriter& JsonWriter::close(char bracket) {
  out_ << bracket;
  first_.pop_back();
  return *this;
}
JsonWriter& JsonWriter::begin_object() {
  return open('{');
}
JsonWriter& JsonWriter::end_object() {
  return close('}');
}
JsonWriter& JsonWriter::begin_array() {
  return open('[');
}
JsonWriter& JsonWriter::end_array() {
  return close(']');
}
JsonWriter& JsonWriter::key(const std::string& k) {
  comma();
  after_key_ = true;  // the key itself takes no comma
  value(k);
  out_ << ":";
  after_key_ = true;
  return *this;
}
JsonWriter& JsonWriter::value(double v) {
  comma();
  if (!std::isfinite(v)) {
    out_ << "null";
  } else {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    out_ << buf;
  }
  return *this;
}
JsonWriter& JsonWriter::value(long v) {
  comma();
  out_ << v;
  return *this;
}
JsonWriter& JsonWriter::value(bool v) {
  comma();
  out_ << (v ? "true" : "false");
  return *this;
}
JsonWriter& JsonWriter::null() {
  comma();
  out_ << "null";
  return *this;
}
JsonWriter& JsonWriter::value(const std::string& v) {
  comma();
  out_ << '"';
  for (char c : v) {
    switch (c) {
      case '"':
        out_ << "\\\"";
        break;
      case '\\':
        out_ << "\\\\";
        break;
      case '\n':
        out_ << "\\n";
        break;
      case '\t':
        out_ << "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out_ << buf;
        } else {
          out_ << c;
        }
    }
  }
  out_ << '"';
  return *this;
}
JsonWriter& JsonWriter::array(const std::vector<double>& v) {
  begin_array();
  for (double x : v) value(x);
  return end_array();
}

JsonWriter& JsonWriter::array(const std::vector<std::string>& v) {
  begin_array();
  for (const auto& x : v) value(x);
  return end_array();
}

}  // namespace pound
