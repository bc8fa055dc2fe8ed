#include "unfurl/io/json_writer.hpp"

#include <cmath>
#include <cstdio>

#include "unfurl/sim/number_text.hpp"
#include "unfurl/io/output_file.hpp"

namespace unfurl::io {

void JsonWriter::quoted(const std::string& s) {
  out_ << '"';
  for (const char c : s) {
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
      case '\r':
        out_ << "\\r";
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
}

void JsonWriter::key(const std::string& k) {
  if (!first_.back()) out_ << ",";
  out_ << "\n" << std::string(2 * (first_.size() - 1), ' ');
  first_.back() = false;
  if (!k.empty()) {
    quoted(k);
    out_ << ": ";
  }
}

JsonWriter& JsonWriter::begin_object(const std::string& k) {
  if (first_.size() > 1 || !first_.back()) key(k);
  out_ << "{";
  first_.push_back(true);
  return *this;
}

JsonWriter& JsonWriter::end_object() {
  first_.pop_back();
  out_ << "\n" << std::string(2 * (first_.size() - 1), ' ') << "}";
  if (first_.size() == 1) out_ << "\n";
  return *this;
}

JsonWriter& JsonWriter::begin_array(const std::string& k) {
  key(k);
  out_ << "[";
  first_.push_back(true);
  return *this;
}

JsonWriter& JsonWriter::end_array() {
  first_.pop_back();
  out_ << "\n" << std::string(2 * (first_.size() - 1), ' ') << "]";
  return *this;
}

JsonWriter& JsonWriter::value(const std::string& k, double x) {
  key(k);
  if (std::isfinite(x))
    out_ << sim::format_number(x);
  else
    out_ << "null";
  return *this;
}

JsonWriter& JsonWriter::value(const std::string& k, long x) {
  key(k);
  out_ << x;
  return *this;
}

JsonWriter& JsonWriter::value(const std::string& k, bool x) {
  key(k);
  out_ << (x ? "true" : "false");
  return *this;
}

JsonWriter& JsonWriter::value(const std::string& k, const std::string& x) {
  key(k);
  quoted(x);
  return *this;
}

JsonWriter& JsonWriter::null(const std::string& k) {
  key(k);
  out_ << "null";
  return *this;
}

}  // namespace unfurl::io
