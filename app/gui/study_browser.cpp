#include "study_browser.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "study_files.hpp"

namespace unfurl::app {

StudyBrowser open_study(const std::string& study_path, const std::string& dir) {
  StudyBrowser b;
  b.study_path = study_path;
  b.dir = dir;
  b.study = read_study_file(study_path);
  b.columns = case_columns(b.study, nominal_scene(b.study).scene);
  b.cases = study_cases(b.study);
  for (const StudyCase& c : b.cases)
    if (auto row = read_case_record(b.columns, dir, c.id)) b.rows.push_back(std::move(*row));
  if (b.rows.empty())
    throw std::runtime_error(dir + " holds no finished case of " + study_path + " (run: unfurl sweep " + study_path +
                             " --out " + dir + ")");
  const int n_inputs = static_cast<int>(b.columns.inputs.size());
  b.table_columns = {0, 1};
  for (const std::string& name : CaseColumns::headline()) {
    const auto it = std::find(b.columns.outputs.begin(), b.columns.outputs.end(), name);
    if (it != b.columns.outputs.end()) b.table_columns.push_back(2 + n_inputs + static_cast<int>(it - b.columns.outputs.begin()));
  }
  for (int k = 0; k < n_inputs && b.table_columns.size() < 64; ++k) b.table_columns.push_back(2 + k);
  b.order.resize(b.rows.size());
  std::iota(b.order.begin(), b.order.end(), 0);
  return b;
}

const StudyCase* StudyBrowser::find_case(const std::string& id) const {
  for (const StudyCase& c : cases)
    if (c.id == id) return &c;
  return nullptr;
}

std::string StudyBrowser::column_name(int column) const {
  if (column == 0) return "case";
  if (column == 1) return "status";
  const std::size_t k = static_cast<std::size_t>(column - 2);
  return k < columns.inputs.size() ? columns.inputs[k] : columns.outputs[k - columns.inputs.size()];
}

double StudyBrowser::value(const CaseResult& r, int column) const {
  if (column < 2) return std::nan("");
  const std::size_t k = static_cast<std::size_t>(column - 2);
  return k < r.inputs.size() ? r.inputs[k] : r.outputs[k - r.inputs.size()];
}

void StudyBrowser::sort(int column, bool ascending) {
  const auto less = [&](int a, int b) {
    const CaseResult &ra = rows[a], &rb = rows[b];
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

namespace {

// Element k of a list as a path names it: by its joint when no other
// element of the list has that joint, and always by index.
template <class Element>
void name_element(const std::string& list, const std::vector<Element>& elements, std::size_t k, const Model& model,
                  std::vector<std::string>& out) {
  out.push_back(list + "." + std::to_string(k));
  const int joint = elements[k].joint;
  const auto shared = std::count_if(elements.begin(), elements.end(), [&](const Element& e) { return e.joint == joint; });
  if (shared == 1) out.push_back(list + "." + model.joints[joint].name);
}

}  // namespace

std::vector<std::string> failure_elements(const Scene& scene, const StudyFailure& failure) {
  std::vector<std::string> elements;
  const Model& model = scene.model;
  switch (failure.kind) {
    case StudyFailure::Kind::latch_fails: break;  // nothing left to edit
    case StudyFailure::Kind::spring_breaks:
    case StudyFailure::Kind::preload_loss: {
      const std::vector<JointSpring> springs(scene.springs.begin(),
                                             scene.springs.begin() + static_cast<long>(scene.dampers_from));
      for (std::size_t k = 0; k < springs.size(); ++k)
        if (model.joints[springs[k].joint].name == failure.joint) name_element("springs", springs, k, model, elements);
      break;
    }
    case StudyFailure::Kind::stuck:  // the stop is the last latch
      if (!scene.latches.empty()) name_element("latches", scene.latches, scene.latches.size() - 1, model, elements);
      break;
    case StudyFailure::Kind::extra_friction:  // the added friction is the last entry
      if (!scene.friction.empty()) name_element("friction", scene.friction, scene.friction.size() - 1, model, elements);
      break;
  }
  return elements;
}

bool edits_element(const std::string& path, const std::vector<std::string>& elements) {
  return std::any_of(elements.begin(), elements.end(),
                     [&](const std::string& e) { return path.rfind(e + ".", 0) == 0; });
}

}  // namespace unfurl::app
