#include "unfurl/sim/loads.hpp"

namespace unfurl::sim {

double total_time(const std::vector<std::array<double, 2>>& spans) {
  double time = 0;
  for (const auto& span : spans) time += span[1] - span[0];
  return time;
}

const char* wrench_component_name(int axis) {
  static const char* names[] = {"fx", "fy", "fz", "mx", "my", "mz"};
  return axis >= 0 && axis < 6 ? names[axis] : "?";
}

int find_load_column(const std::vector<LoadColumn>& columns, const std::string& name) {
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c].name == name) return static_cast<int>(c);
  return -1;
}

}  // namespace unfurl::sim
