#pragma once
// A minimal JSON writer for the programs' --json output (numbers with 17 significant digits,
// non-finite numbers as null).
#include <sstream>
#include <string>
#include <vector>

namespace pound {

class JsonWriter {
 public:
  JsonWriter& begin_object();
  JsonWriter& end_object();
  JsonWriter& begin_array();
  JsonWriter& end_array();
  JsonWriter& key(const std::string& k);
  JsonWriter& value(double v);
  JsonWriter& value(long v);
  JsonWriter& value(int v) { return value(static_cast<long>(v)); }
  JsonWriter& value(bool v);
  JsonWriter& value(const std::string& v);
  JsonWriter& value(const char* v) { return value(std::string(v)); }
  JsonWriter& null();
  JsonWriter& array(const std::vector<double>& v);
  JsonWriter& array(const std::vector<std::string>& v);
  template <class T>
  JsonWriter& field(const std::string& k, const T& v) {
    key(k);
    return value(v);
  }
  std::string str() const { return out_.str(); }

 private:
  void comma();
  std::ostringstream out_;
  std::vector<bool> first_;  // per open container: nothing written yet
  bool after_key_ = false;
};

}  // namespace pound
