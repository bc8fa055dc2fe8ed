#include "unfurl/sim/scene.hpp"

#include <algorithm>
#include <unordered_map>

#include "unfurl/sim/elements/gravity.hpp"

namespace unfurl::sim {

Vec3 Scene::gravity() const {
  Vec3 g = Vec3::Zero();
  for (const Gravity* e : elements_of<Gravity>()) g += e->g;
  return g;
}

std::vector<LoadColumn> Scene::load_columns(std::vector<std::vector<int>>* of_element) const {
  std::vector<LoadColumn> columns;
  // Elements that share a column (a joint's spring and damper) are found by
  // name; a search of the list made this O(N^2) on large arrays.
  std::unordered_map<std::string, int> index;
  if (of_element) of_element->assign(elements.size(), {});
  for (std::size_t k = 0; k < elements.size(); ++k) {
    for (const LoadColumn& c : elements[k]->load_columns(model)) {
      const auto [at, added] = index.try_emplace(c.name, static_cast<int>(columns.size()));
      if (of_element) (*of_element)[k].push_back(at->second);
      if (added) columns.push_back(c);
    }
  }
  return columns;
}

std::vector<TrackedPeak> Scene::element_peaks() const {
  std::vector<std::vector<int>> of_element;
  const std::vector<LoadColumn> columns = load_columns(&of_element);
  std::vector<TrackedPeak> peaks;
  for (std::size_t k = 0; k < elements.size(); ++k) {
    for (const ElementPeak& peak : elements[k]->peaks()) {
      TrackedPeak tracked{peak.quantity, elements[k]->handle(model), columns[of_element[k][peak.first]].unit, {}};
      for (int c = 0; c < peak.count; ++c) tracked.columns.push_back(of_element[k][peak.first + c]);
      peaks.push_back(std::move(tracked));
    }
  }
  return peaks;
}

std::vector<TrackedPeak> Scene::sensor_peaks() const {
  std::vector<TrackedPeak> peaks;
  int first_column = 0;
  for (const Sensor& s : sensors) {
    for (const ElementPeak& peak : s.peaks()) {
      TrackedPeak tracked{peak.quantity, s.name, sensor_quantity_unit(s.measures[peak.first / 3]), {}};
      for (int c = 0; c < peak.count; ++c) tracked.columns.push_back(first_column + peak.first + c);
      peaks.push_back(std::move(tracked));
    }
    first_column += static_cast<int>(s.columns().size());
  }
  return peaks;
}

std::vector<std::string> Scene::element_paths(std::size_t k) const {
  const ForceElement& e = *elements[k];
  if (const std::string path = e.file_path(*this); !path.empty()) return {path};
  const std::string list = e.list(), handle = e.handle(model);
  // Its index among its list's elements, and whether another one there is
  // called the same (a --set path names the first it finds).
  std::size_t index = 0;
  bool shared = handle.empty();
  for (std::size_t j = 0; j < elements.size(); ++j) {
    if (elements[j]->list() != list) continue;
    if (j < k) ++index;
    if (j != k && elements[j]->handle(model) == handle) shared = true;
  }
  std::vector<std::string> paths{list + "." + std::to_string(index)};
  if (!shared) paths.push_back(list + "." + handle);
  return paths;
}

}  // namespace unfurl::sim
