#include "panel_widgets.hpp"

#include <algorithm>

#include "unfurl/sim/number_text.hpp"

namespace unfurl::app {

void value_field(const char* label, const std::string& path, double value, double step, Requests& requests, double lo,
                 double hi, const char* format, const char* help) {
  double v = value;
  ImGui::SetNextItemWidth(em(190));
  const bool stepped = ImGui::InputScalar(label, ImGuiDataType_Double, &v, &step, nullptr, format);
  if (help && ImGui::IsItemHovered()) ImGui::SetTooltip("%s\n%s", help, path.c_str());
  const bool commit = ImGui::IsItemDeactivatedAfterEdit() || (stepped && !ImGui::IsItemActive());
  if (lo < hi) v = std::clamp(v, lo, hi);
  if (commit && v != value) requests.edit = sim::Override{path, sim::format_number(v)};
}

}  // namespace unfurl::app
