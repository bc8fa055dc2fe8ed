#include "unfurl/sim/number_text.hpp"

#include <charconv>

namespace unfurl::sim {

std::string format_number(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

}  // namespace unfurl::sim
