#include "unfurl/sim/loads.hpp"

namespace unfurl {

const char* wrench_component_name(int axis) {
  static const char* names[] = {"fx", "fy", "fz", "mx", "my", "mz"};
  return axis >= 0 && axis < 6 ? names[axis] : "?";
}

}  // namespace unfurl
