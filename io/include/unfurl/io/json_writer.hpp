// A small streaming JSON writer for the reports (summary.json): objects,
// arrays, strings, numbers (non-finite ones as null) and booleans.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace unfurl::io {

class JsonWriter {
 public:
  explicit JsonWriter(std::ostream& out) : out_(out) {}

  JsonWriter& begin_object(const std::string& key = "");
  JsonWriter& end_object();
  JsonWriter& begin_array(const std::string& key = "");
  JsonWriter& end_array();
  JsonWriter& value(const std::string& key, double x);
  JsonWriter& value(const std::string& key, long x);
  JsonWriter& value(const std::string& key, int x) { return value(key, static_cast<long>(x)); }
  JsonWriter& value(const std::string& key, bool x);
  JsonWriter& value(const std::string& key, const std::string& x);
  JsonWriter& value(const std::string& key, const char* x) { return value(key, std::string(x)); }
  JsonWriter& null(const std::string& key);

 private:
  void key(const std::string& k);
  void quoted(const std::string& s);

  std::ostream& out_;
  std::vector<bool> first_{true};
};

}  // namespace unfurl::io
