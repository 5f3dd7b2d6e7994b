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
  /// "k": [ {...}, ... ], one object per item, whose members `write(item)` writes.
  template <class Items, class Write>
  JsonWriter& objects(const std::string& k, const Items& items, Write write) {
    key(k).begin_array();
    for (const auto& item : items) {
      begin_object();
      write(item);
      end_object();
    }
    return end_array();
  }
  std::string str() const { return out_.str(); }

 private:
  void comma();
  JsonWriter& open(char bracket);
  JsonWriter& close(char bracket);
  std::ostringstream out_;
  std::vector<bool> first_;  // per open container: nothing written yet
  bool after_key_ = false;
};

}  // namespace pound
