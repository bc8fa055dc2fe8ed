#include "study_browser.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <type_traits>

#include "unfurl/io/study_files.hpp"
#include "unfurl/sim/elements/all.hpp"

namespace unfurl::app {

StudyBrowser open_study(const std::string& study_path, const std::string& dir) {
  StudyBrowser b;
  b.study_path = study_path;
  b.dir = dir;
  b.study = studies::read_study_file(study_path);
  b.columns = studies::case_columns(b.study, studies::nominal_scene(b.study).scene);
  b.cases = studies::study_cases(b.study);
  for (const studies::StudyCase& c : b.cases)
    if (auto row = io::read_case_record(b.columns, dir, c.id)) b.rows.push_back(std::move(*row));
  if (b.rows.empty())
    throw std::runtime_error(dir + " holds no finished case of " + study_path + " (run: unfurl study " + study_path +
                             " --out " + dir + ")");
  const int n_inputs = static_cast<int>(b.columns.inputs.size());
  b.table_columns = {0, 1};
  for (const std::string& name : studies::CaseColumns::headline()) {
    const auto it = std::find(b.columns.outputs.begin(), b.columns.outputs.end(), name);
    if (it != b.columns.outputs.end()) b.table_columns.push_back(2 + n_inputs + static_cast<int>(it - b.columns.outputs.begin()));
  }
  for (int k = 0; k < n_inputs && b.table_columns.size() < 64; ++k) b.table_columns.push_back(2 + k);
  b.order.resize(b.rows.size());
  std::iota(b.order.begin(), b.order.end(), 0);
  return b;
}

const studies::StudyCase* StudyBrowser::find_case(const std::string& id) const {
  for (const studies::StudyCase& c : cases)
    if (c.id == id) return &c;
  return nullptr;
}

std::string StudyBrowser::column_name(int column) const {
  if (column == 0) return "case";
  if (column == 1) return "status";
  const std::size_t k = static_cast<std::size_t>(column - 2);
  return k < columns.inputs.size() ? columns.inputs[k] : columns.outputs[k - columns.inputs.size()];
}

double StudyBrowser::value(const studies::CaseResult& r, int column) const {
  if (column < 2) return std::nan("");
  const std::size_t k = static_cast<std::size_t>(column - 2);
  return k < r.inputs.size() ? r.inputs[k] : r.outputs[k - r.inputs.size()];
}

void StudyBrowser::sort(int column, bool ascending) {
  const auto less = [&](int a, int b) {
    const studies::CaseResult &ra = rows[a], &rb = rows[b];
    if (column == 0) return ascending ? a < b : b < a;  // case order
    if (column == 1) {
      if (ra.status != rb.status) return ascending ? ra.status < rb.status : rb.status < ra.status;
      return a < b;
    }
    const double x = value(ra, column), y = value(rb, column);
    if (std::isnan(x) || std::isnan(y)) return !std::isnan(x) && std::isnan(y);
    if (x != y) return ascending ? x < y : y < x;
    return a < b;
  };
  std::stable_sort(order.begin(), order.end(), less);
}

std::vector<std::string> failure_elements(const sim::Scene& scene, const studies::StudyFailure& failure) {
  std::vector<std::string> paths;
  const auto add = [&](std::size_t k) {
    for (const std::string& path : scene.element_paths(k)) paths.push_back(path);
  };
  // The last element of a kind on the failure's joint: a spring that
  // breaks or loses its preload, the stop of a stuck hinge, the added
  // friction (the last friction).
  const auto last_on_joint = [&](auto* of_kind) {
    using Kind = std::remove_pointer_t<decltype(of_kind)>;
    std::size_t found = scene.elements.size();
    for (std::size_t k = 0; k < scene.elements.size(); ++k)
      if (const auto* e = dynamic_cast<const Kind*>(scene.elements[k].get());
          e && scene.model.joints[e->joint].name == failure.joint)
        found = k;
    if (found < scene.elements.size()) add(found);
  };
  switch (failure.kind) {
    case studies::StudyFailure::Kind::latch_fails:
      break;  // nothing left to edit
    case studies::StudyFailure::Kind::spring_breaks:
    case studies::StudyFailure::Kind::preload_loss:
      for (std::size_t k = 0; k < scene.elements.size(); ++k)
        if (const auto* s = dynamic_cast<const sim::JointSpring*>(scene.elements[k].get());
            s && scene.model.joints[s->joint].name == failure.joint)
          add(k);
      break;
    case studies::StudyFailure::Kind::stuck:
      last_on_joint(static_cast<const sim::JointStop*>(nullptr));
      break;
    case studies::StudyFailure::Kind::extra_friction:
      last_on_joint(static_cast<const sim::JointFriction*>(nullptr));
      break;
  }
  return paths;
}

bool edits_element(const std::string& path, const std::vector<std::string>& elements) {
  return std::any_of(elements.begin(), elements.end(),
                     [&](const std::string& e) { return path.rfind(e + ".", 0) == 0; });
}

}  // namespace unfurl::app
