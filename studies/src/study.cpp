#include "unfurl/studies/study.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "unfurl/input/yaml_fields.hpp"
#include "unfurl/sim/elements/joint_spring.hpp"

namespace unfurl::studies {

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::string short_number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

std::string percent(double fraction) { return short_number(100 * fraction); }

std::string scalar_text(const input::YamlFields& fields, const YAML::Node& node, const std::string& field) {
  if (!node.IsScalar()) fields.fail(node, field, "expected a single value");
  return node.Scalar();
}

class StudyReader {
 public:
  StudyReader(std::string source, std::string directory)
      : fields_(std::move(source)), directory_(std::move(directory)) {}

  Study read(const std::string& text) {
    const YAML::Node root = fields_.load_document(text);
    fields_.check_map(root, "study");
    fields_.check_keys(root, {"scene", "set", "vary", "combine", "seed", "runs", "failures", "overlay"}, "");
    Study study;
    study.source = fields_.source();
    read_scene(fields_.require(root, "scene", "scene"), study);
    if (root["set"]) read_settings(root["set"], study);
    try {
      nominal_ = nominal_scene(study).scene;
    } catch (const input::InputError& e) {
      if (!root["set"]) throw;
      fields_.fail(root["set"], "set", std::string("the scene does not accept it: ") + e.what());
    }
    if (root["vary"]) read_variables(root["vary"], study);
    if (root["combine"]) read_combine(root["combine"], study);
    if (root["seed"]) study.seed = static_cast<unsigned long>(fields_.count(root["seed"], "seed", 0, 1L << 62));
    read_runs(root, study);
    if (root["failures"]) read_failures(root["failures"], study);
    read_overlay(root["overlay"], study);
    return study;
  }

 private:
  void read_scene(const YAML::Node& node, Study& study) {
    study.scene = fields_.text(node, "scene");
    std::filesystem::path path = study.scene;
    if (path.is_relative() && !directory_.empty()) path = std::filesystem::path(directory_) / path;
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec)) {
      std::ifstream in(path);
      std::stringstream text;
      text << in.rdbuf();
      study.scene_text = text.str();
      study.scene_source = path.string();
      return;
    }
    const auto names = sim::builtin_scene_names();
    if (std::find(names.begin(), names.end(), study.scene) == names.end())
      fields_.fail(node, "scene", "no scene file '" + path.string() + "' and no built-in scene of that name");
    study.scene_text = sim::builtin_scene_text(study.scene);
    study.scene_source = "built-in:" + study.scene;
  }

  void read_settings(const YAML::Node& node, Study& study) {
    fields_.check_map(node, "set");
    for (const auto& item : node) {
      const std::string path = fields_.text(item.first, "set");
      study.settings.push_back({path, scalar_text(fields_, item.second, "set." + path)});
    }
  }

  void read_variables(const YAML::Node& list, Study& study) {
    if (!list.IsSequence()) fields_.fail(list, "vary", "expected a list of {path, values | grid | uniform | normal | lognormal}");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const YAML::Node item = list[i];
      const std::string field = input::index_field("vary", i);
      fields_.check_map(item, field);
      fields_.check_keys(item, {"path", "scale", "values", "grid", "uniform", "normal", "lognormal"}, field);
      StudyVariable v;
      read_values(item, field, v);
      v.scale = item["scale"] && fields_.flag(item["scale"], field + ".scale");
      const YAML::Node path = fields_.require(item, "path", field + ".path");
      for (const std::string& concrete : concrete_paths(path, field + ".path", study)) {
        v.path = concrete;
        if (std::any_of(study.settings.begin(), study.settings.end(),
                        [&](const sim::Override& o) { return o.path == concrete; }))
          fields_.fail(path, field + ".path", concrete + " is also fixed under `set`");
        for (const StudyVariable& other : study.variables)
          if (other.path == concrete) fields_.fail(path, field + ".path", concrete + " varies twice");
        v.nominal = v.is_preload() ? 1.0 : sim::scene_number(study.scene_text, study.scene_source, concrete);
        if (v.is_preload() && v.scale) fields_.fail(item["scale"], field + ".scale", "a preload is already a factor");
        check_values(item, field, v, study);
        study.variables.push_back(v);
      }
    }
  }

  // The paths a pattern stands for; springs.J.preload stands for itself.
  std::vector<std::string> concrete_paths(const YAML::Node& node, const std::string& field, const Study& study) {
    const std::string pattern = fields_.text(node, field);
    const bool preload = ends_with(pattern, ".preload");
    const std::string probe = preload ? pattern.substr(0, pattern.size() - 8) + ".free_position" : pattern;
    if (preload && pattern.rfind("springs.", 0) != 0)
      fields_.fail(node, field, "a preload factor is set on a spring: springs.JOINT.preload");
    std::vector<std::string> paths;
    try {
      paths = sim::expand_scene_path(study.scene_text, study.scene_source, probe);
    } catch (const input::InputError&) {
      fields_.fail(node, field, "the scene has no value at " + probe);
    }
    if (preload)
      for (std::string& p : paths) p = p.substr(0, p.size() - 14) + ".preload";
    return paths;
  }

  void read_values(const YAML::Node& item, const std::string& field, StudyVariable& v) {
    int kinds = 0;
    if (const YAML::Node n = item["values"]) {
      ++kinds;
      v.kind = StudyVariable::Kind::values;
      v.values = fields_.numbers(n, field + ".values");
      if (v.values.empty()) fields_.fail(n, field + ".values", "give at least one value");
    }
    if (const YAML::Node n = item["grid"]) {
      ++kinds;
      v.kind = StudyVariable::Kind::grid;
      fields_.check_keys(n, {"from", "to", "steps"}, field + ".grid");
      const double from = fields_.number(fields_.require(n, "from", field + ".grid.from"), field + ".grid.from");
      const double to = fields_.number(fields_.require(n, "to", field + ".grid.to"), field + ".grid.to");
      const long steps = fields_.count(fields_.require(n, "steps", field + ".grid.steps"), field + ".grid.steps", 2, 100000);
      for (long k = 0; k < steps; ++k) v.values.push_back(from + (to - from) * static_cast<double>(k) / static_cast<double>(steps - 1));
    }
    if (const YAML::Node n = item["uniform"]) {
      ++kinds;
      v.kind = StudyVariable::Kind::uniform;
      fields_.check_keys(n, {"min", "max"}, field + ".uniform");
      v.a = fields_.number(fields_.require(n, "min", field + ".uniform.min"), field + ".uniform.min");
      v.b = fields_.number(fields_.require(n, "max", field + ".uniform.max"), field + ".uniform.max");
      if (!(v.a < v.b)) fields_.fail(n, field + ".uniform", "min must be below max");
    }
    for (const char* key : {"normal", "lognormal"})
      if (const YAML::Node n = item[key]) {
        ++kinds;
        const bool log = std::string(key) == "lognormal";
        const std::string f = field + "." + key;
        v.kind = log ? StudyVariable::Kind::lognormal : StudyVariable::Kind::normal;
        fields_.check_keys(n, {log ? "mu" : "mean", "sigma", "min", "max"}, f);
        v.a = fields_.number(fields_.require(n, log ? "mu" : "mean", f), f + (log ? ".mu" : ".mean"));
        v.b = fields_.positive(fields_.require(n, "sigma", f + ".sigma"), f + ".sigma");
        v.lo = fields_.number_or(n, "min", v.lo, f + ".min");
        v.hi = fields_.number_or(n, "max", v.hi, f + ".max");
        const double centre = log ? std::exp(v.a) : v.a;
        if (!(v.lo < centre && centre < v.hi))
          fields_.fail(n, f, "the bounds must enclose the " + std::string(log ? "median" : "mean"));
      }
    if (kinds != 1)
      fields_.fail(item, field, "give exactly one of values, grid, uniform, normal, lognormal");
  }

  // Every value the variable can take must be one the scene accepts: the
  // nominal scene is read once with the extremes.
  void check_values(const YAML::Node& item, const std::string& field, const StudyVariable& v, const Study& study) {
    std::vector<double> extremes = v.values;
    if (v.kind == StudyVariable::Kind::uniform) extremes = {v.a, v.b};
    if (v.random() && std::isfinite(v.lo)) extremes.push_back(v.lo);
    if (v.random() && std::isfinite(v.hi)) extremes.push_back(v.hi);
    for (double x : extremes) {
      if (v.is_preload()) {
        if (x < 0) fields_.fail(item, field, "a preload factor is not negative");
        continue;
      }
      if (v.scale) x *= v.nominal;
      char text[64];
      std::snprintf(text, sizeof text, "%.17g", x);
      try {
        std::vector<sim::Override> overrides = study.settings;
        overrides.push_back({v.path, text});
        (void)sim::load_scene_text(study.scene_text, study.scene_source, overrides);
      } catch (const input::InputError& e) {
        fields_.fail(item, field, std::string(v.path) + " = " + text + " is not a valid scene: " + e.what());
      }
    }
  }

  void read_combine(const YAML::Node& node, Study& study) {
    const std::string how = fields_.text(node, "combine");
    if (how != "product" && how != "zip") fields_.fail(node, "combine", "expected product or zip");
    study.zip = how == "zip";
    if (!study.zip) return;
    std::size_t n = 0;
    for (const StudyVariable& v : study.variables)
      if (!v.random()) {
        if (n && v.values.size() != n) fields_.fail(node, "combine", "zip needs lists and grids of one length");
        n = v.values.size();
      }
  }

  void read_runs(const YAML::Node& root, Study& study) {
    const bool random = std::any_of(study.variables.begin(), study.variables.end(), [](auto& v) { return v.random(); });
    const bool listed = std::any_of(study.variables.begin(), study.variables.end(), [](auto& v) { return !v.random(); });
    if (random && listed)
      fields_.fail(root["vary"], "vary", "a study either draws values (uniform, normal, lognormal) or lists them (values, grid), not both");
    if (root["runs"]) {
      if (!random) fields_.fail(root["runs"], "runs", "runs sets the number of random draws; this study draws nothing");
      study.runs = fields_.count(root["runs"], "runs", 1, 1000000);
    } else if (random) {
      fields_.fail(root, "runs", "a study that draws values needs runs (the number of draws)");
    }
  }

  void read_failures(const YAML::Node& list, Study& study) {
    if (!list.IsSequence()) fields_.fail(list, "failures", "expected a list");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const YAML::Node item = list[i];
      const std::string field = input::index_field("failures", i);
      fields_.check_map(item, field);
      fields_.check_keys(item,
                         {"latch_fails", "spring_breaks", "preload_loss", "stuck", "extra_friction", "fraction",
                          "coulomb", "viscous"},
                         field);
      StudyFailure f;
      const char* key = nullptr;
      for (const auto& [name, kind] : {std::pair{"latch_fails", StudyFailure::Kind::latch_fails},
                                       std::pair{"spring_breaks", StudyFailure::Kind::spring_breaks},
                                       std::pair{"preload_loss", StudyFailure::Kind::preload_loss},
                                       std::pair{"stuck", StudyFailure::Kind::stuck},
                                       std::pair{"extra_friction", StudyFailure::Kind::extra_friction}})
        if (item[name]) {
          if (key) fields_.fail(item, field, "one failure per entry");
          key = name;
          f.kind = kind;
        }
      if (!key)
        fields_.fail(item, field, "expected latch_fails, spring_breaks, preload_loss, stuck or extra_friction");
      if (f.kind == StudyFailure::Kind::preload_loss) {
        const YAML::Node fraction = fields_.require(item, "fraction", field + ".fraction");
        f.fraction = fields_.number(fraction, field + ".fraction");
        if (!(f.fraction > 0 && f.fraction <= 1)) fields_.fail(fraction, field + ".fraction", "expected a fraction in (0, 1]");
      } else if (item["fraction"]) {
        fields_.fail(item["fraction"], field + ".fraction", "only a preload_loss has a fraction");
      }
      read_friction(item, field, f);
      const YAML::Node joint = item[key];
      for (const std::string& name : failure_joints(joint, field + "." + key, f.kind)) {
        f.joint = name;
        study.failures.push_back(f);
      }
    }
  }

  // extra_friction's coulomb and viscous: at least one, both non-negative.
  void read_friction(const YAML::Node& item, const std::string& field, StudyFailure& f) {
    const bool friction = f.kind == StudyFailure::Kind::extra_friction;
    for (const char* key : {"coulomb", "viscous"}) {
      const YAML::Node value = item[key];
      if (!value) continue;
      const std::string where = field + "." + key;
      if (!friction) fields_.fail(value, where, "only an extra_friction has a " + std::string(key));
      (key[0] == 'c' ? f.coulomb : f.viscous) = fields_.non_negative(value, where);
    }
    if (friction && !item["coulomb"] && !item["viscous"])
      fields_.fail(item, field, "an extra_friction needs coulomb (N m), viscous (N m s/rad) or both");
  }

  // The joints a failure names; "*" is every joint it can apply to.
  std::vector<std::string> failure_joints(const YAML::Node& node, const std::string& field, StudyFailure::Kind kind) {
    std::vector<std::string> candidates;
    const sim::Model& m = nominal_.model;
    if (kind == StudyFailure::Kind::latch_fails)
      for (const sim::Latch* l : nominal_.latches()) candidates.push_back(m.joints[l->joint].name);
    else if (kind == StudyFailure::Kind::stuck || kind == StudyFailure::Kind::extra_friction)
      for (const sim::Joint& j : m.joints) {
        // What a stop or friction acts on: a hinge's or a slider's coordinate
        // (not a free bus, as the scene loader has it).
        if (j.has_free_coordinate()) candidates.push_back(j.name);
      }
    else
      for (const sim::JointSpring* s : nominal_.elements_of<sim::JointSpring>())
        candidates.push_back(m.joints[s->joint].name);
    const std::string name = fields_.text(node, field);
    if (name == "*") return candidates;
    if (std::find(candidates.begin(), candidates.end(), name) == candidates.end()) {
      const char* what = kind == StudyFailure::Kind::latch_fails ? "a latch"
                         : kind == StudyFailure::Kind::stuck || kind == StudyFailure::Kind::extra_friction
                             ? "a hinge or slider (revolute or prismatic)"
                                                                 : "a spring";
      fields_.fail(node, field, "'" + name + "' is not a joint with " + what + " (or \"*\" for every one)");
    }
    return {name};
  }

  void read_overlay(const YAML::Node& node, Study& study) {
    const sim::Model& m = nominal_.model;
    if (!node) {
      const std::vector<const sim::Latch*> latches = nominal_.latches();
      study.overlay_joint = latches.empty() ? m.joints.front().name : m.joints[latches.front()->joint].name;
      return;
    }
    study.overlay_joint = fields_.text(node, "overlay");
    for (const sim::Joint& j : m.joints)
      if (j.name == study.overlay_joint && j.dof() > 0) return;
    fields_.fail(node, "overlay", "'" + study.overlay_joint + "' is not a moving joint of the scene");
  }

  input::YamlFields fields_;
  std::string directory_;
  sim::Scene nominal_;
};

}  // namespace

std::string StudyVariable::label() const { return is_preload() ? path + "_factor" : path; }

bool StudyVariable::is_preload() const { return ends_with(path, ".preload"); }

std::string StudyFailure::id() const {
  switch (kind) {
    case Kind::latch_fails: return "latch-" + joint + "-fails";
    case Kind::spring_breaks: return "spring-" + joint + "-breaks";
    case Kind::preload_loss: return "spring-" + joint + "-loses-" + percent(fraction) + "pc";
    case Kind::stuck: return "hinge-" + joint + "-stuck";
    case Kind::extra_friction:
      return "hinge-" + joint + "-friction" + (coulomb > 0 ? "-" + short_number(coulomb) + "Nm" : "") +
             (viscous > 0 ? "-" + short_number(viscous) + "Nms" : "");
  }
  return "";
}

std::vector<std::string> StudyFailure::removed_latches() const {
  if (kind == Kind::latch_fails) return {joint};
  return {};
}

std::string StudyFailure::describe() const {
  switch (kind) {
    case Kind::latch_fails: return "latch " + joint + " never engages";
    case Kind::spring_breaks: return "spring " + joint + " broken";
    case Kind::preload_loss: return "spring " + joint + " loses " + percent(fraction) + " % of its preload";
    case Kind::stuck: return "hinge " + joint + " stuck";
    case Kind::extra_friction: {
      std::string what = "hinge " + joint + " with extra friction:";
      if (coulomb > 0) what += " Coulomb " + short_number(coulomb) + " N m";
      if (coulomb > 0 && viscous > 0) what += " +";
      if (viscous > 0) what += " viscous " + short_number(viscous) + " N m s/rad";
      return what;
    }
  }
  return "";
}

sim::SceneFile nominal_scene(const Study& study) {
  return sim::read_scene_text(study.scene_text, study.scene_source, study.settings);
}

Study read_study_text(const std::string& text, const std::string& source, const std::string& directory) {
  return StudyReader(source, directory).read(text);
}

Study read_study_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw input::InputError(path + ": cannot open the study file");
  std::stringstream text;
  text << in.rdbuf();
  return read_study_text(text.str(), path, std::filesystem::path(path).parent_path().string());
}

}  // namespace unfurl::studies
