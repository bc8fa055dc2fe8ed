#include "unfurl/studies/study_cases.hpp"

#include <algorithm>
#include <cstdio>
#include <random>
#include <string>

#include "unfurl/sim/elements/joint_friction.hpp"
#include "unfurl/sim/elements/joint_spring.hpp"
#include "unfurl/sim/elements/joint_stop.hpp"

namespace unfurl::studies {

namespace {

std::string numbered_id(long k, long count) {
  const std::size_t width = std::max<std::size_t>(4, std::to_string(count).size());
  const std::string digits = std::to_string(k);
  return "case-" + std::string(width - std::min(width, digits.size()), '0') + digits;
}

std::vector<double> nominal_inputs(const Study& study) {
  std::vector<double> x;
  for (const StudyVariable& v : study.variables) x.push_back(v.nominal);
  return x;
}

// One draw of a random variable; a truncated one is drawn again until it
// falls within its bounds (the bounds enclose the centre, so this ends).
double draw(const StudyVariable& v, std::mt19937_64& engine) {
  double x = 0;
  for (int attempt = 0; attempt < 10000; ++attempt) {
    switch (v.kind) {
      case StudyVariable::Kind::uniform: x = std::uniform_real_distribution<double>(v.a, v.b)(engine); break;
      case StudyVariable::Kind::normal: x = std::normal_distribution<double>(v.a, v.b)(engine); break;
      case StudyVariable::Kind::lognormal: x = std::lognormal_distribution<double>(v.a, v.b)(engine); break;
      default: return v.nominal;
    }
    if (x >= v.lo && x <= v.hi) break;
  }
  x = std::clamp(x, v.lo, v.hi);
  return v.scale ? v.nominal * x : x;
}

void add_random_cases(const Study& study, std::vector<StudyCase>& cases) {
  for (long k = 1; k <= study.runs; ++k) {
    std::seed_seq seed{static_cast<unsigned long>(study.seed >> 32), static_cast<unsigned long>(study.seed & 0xffffffffUL),
                       static_cast<unsigned long>(k)};
    std::mt19937_64 engine(seed);
    StudyCase c{numbered_id(k, study.runs), {}, std::nullopt};
    for (const StudyVariable& v : study.variables) c.inputs.push_back(draw(v, engine));
    cases.push_back(std::move(c));
  }
}

double listed_value(const StudyVariable& v, std::size_t i) { return v.scale ? v.nominal * v.values[i] : v.values[i]; }

void add_listed_cases(const Study& study, std::vector<StudyCase>& cases) {
  const auto& vars = study.variables;
  if (vars.empty()) return;
  if (study.zip) {
    const long n = static_cast<long>(vars.front().values.size());
    for (long i = 0; i < n; ++i) {
      StudyCase c{numbered_id(i + 1, n), {}, std::nullopt};
      for (const StudyVariable& v : vars) c.inputs.push_back(listed_value(v, static_cast<std::size_t>(i)));
      cases.push_back(std::move(c));
    }
    return;
  }
  long n = 1;
  for (const StudyVariable& v : vars) n *= static_cast<long>(v.values.size());
  std::vector<std::size_t> digit(vars.size(), 0);  // the last variable turns fastest
  for (long k = 1; k <= n; ++k) {
    StudyCase c{numbered_id(k, n), {}, std::nullopt};
    for (std::size_t i = 0; i < vars.size(); ++i) c.inputs.push_back(listed_value(vars[i], digit[i]));
    cases.push_back(std::move(c));
    for (std::size_t i = vars.size(); i-- > 0;) {
      if (++digit[i] < vars[i].values.size()) break;
      digit[i] = 0;
    }
  }
}

int joint_named(const sim::Model& model, const std::string& name) {
  for (int j = 0; j < static_cast<int>(model.joints.size()); ++j)
    if (model.joints[j].name == name) return j;
  throw input::InputError("no joint " + name + " in the scene");
}

// The scene's (first) spring on the joint, to change: a copy that replaces
// it in the scene (elements are shared between a scene's copies).
sim::JointSpring& spring_of(sim::Scene& scene, int joint) {
  for (auto& e : scene.elements) {
    const auto* s = dynamic_cast<const sim::JointSpring*>(e.get());
    if (!s || s->joint != joint) continue;
    auto copy = std::make_shared<sim::JointSpring>(*s);
    e = copy;
    return *copy;
  }
  throw input::InputError("no spring on joint " + scene.model.joints[joint].name);
}

double initial_q(const sim::Scene& scene, int joint) { return scene.q0[scene.model.position_of(joint).value]; }

// The spring's twist at the start scaled by `factor`: the preload torque
// k (q_free - q(0)) scales with it at the same stiffness.
void scale_preload(sim::Scene& scene, int joint, double factor) {
  sim::JointSpring& s = spring_of(scene, joint);
  if (s.curve) {
    // A measured curve: its torque at every angle scales.
    std::vector<double> tau = s.curve->torques();
    for (double& t : tau) t *= factor;
    s.curve = std::make_shared<const sim::SpringCurve>(s.curve->angles(), tau);
    return;
  }
  const double q0 = initial_q(scene, joint);
  s.free_position = q0 + factor * (s.free_position - q0);
}

// A stuck hinge is held where it starts by a stop (not a latch: its latch
// stays unlatched) as stiff as the scene's stiffest latch.
void make_stuck(sim::Scene& scene, int joint) {
  auto stop = std::make_shared<sim::JointStop>(joint);
  stop->position = initial_q(scene, joint);
  stop->stiffness = 1000.0;
  stop->damping = 10.0;
  for (const sim::Latch* l : scene.latches())
    if (l->stiffness > stop->stiffness) stop->stiffness = l->stiffness, stop->damping = l->damping;
  scene.elements.push_back(stop);
}

void apply_failure(sim::Scene& scene, const StudyFailure& f) {
  const int joint = joint_named(scene.model, f.joint);
  switch (f.kind) {
    case StudyFailure::Kind::latch_fails:
      scene.elements.erase(std::remove_if(scene.elements.begin(), scene.elements.end(),
                                          [&](const auto& e) {
                                            const auto* l = dynamic_cast<const sim::Latch*>(e.get());
                                            return l && l->joint == joint;
                                          }),
                           scene.elements.end());
      break;
    case StudyFailure::Kind::spring_breaks: {
      sim::JointSpring& s = spring_of(scene, joint);
      s.stiffness = 0;
      s.curve.reset();
      break;
    }
    case StudyFailure::Kind::preload_loss: scale_preload(scene, joint, 1 - f.fraction); break;
    case StudyFailure::Kind::stuck: make_stuck(scene, joint); break;
    case StudyFailure::Kind::extra_friction: {
      auto friction = std::make_shared<sim::JointFriction>(joint);
      friction->coulomb = f.coulomb;
      friction->viscous = f.viscous;
      // With the scene's own friction, ahead of the latches.
      const auto first_latch = std::find_if(scene.elements.begin(), scene.elements.end(),
                                            [](const auto& e) { return dynamic_cast<const sim::Latch*>(e.get()); });
      scene.elements.insert(first_latch, friction);
      break;
    }
  }
}

std::string spring_joint_of_preload(const std::string& path) {
  // springs.J.preload
  return path.substr(8, path.size() - 8 - 8);
}

}  // namespace

std::vector<StudyCase> study_cases(const Study& study) {
  std::vector<StudyCase> cases{{"nominal", nominal_inputs(study), std::nullopt}};
  if (study.runs > 0)
    add_random_cases(study, cases);
  else
    add_listed_cases(study, cases);
  for (const StudyFailure& f : study.failures) cases.push_back({"fail-" + f.id(), nominal_inputs(study), f});
  return cases;
}

sim::Scene case_scene(const Study& study, const StudyCase& c) { return case_scene_file(study, c).scene; }

sim::SceneFile case_scene_file(const Study& study, const StudyCase& c, const std::vector<sim::Override>& edits) {
  const auto number = [](double x) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", x);
    return std::string(text);
  };
  std::vector<sim::Override> overrides = study.settings;
  for (std::size_t i = 0; i < study.variables.size(); ++i)
    if (!study.variables[i].is_preload()) overrides.push_back({study.variables[i].path, number(c.inputs[i])});
  const auto preload_joint = [&](const sim::Scene& scene, std::size_t i) {
    return joint_named(scene.model, spring_joint_of_preload(study.variables[i].path));
  };
  sim::SceneFile file = sim::read_scene_text(study.scene_text, study.scene_source, overrides);
  for (std::size_t i = 0; i < study.variables.size(); ++i)
    if (study.variables[i].is_preload()) scale_preload(file.scene, preload_joint(file.scene, i), c.inputs[i]);
  if (!edits.empty()) {
    // The edits go over the case's values: its scaled preloads become free
    // positions in the text ahead of them (a curve's, which has none, is
    // scaled again after).
    std::vector<bool> in_text(study.variables.size(), false);
    for (std::size_t i = 0; i < study.variables.size(); ++i) {
      if (!study.variables[i].is_preload()) continue;
      const int joint = preload_joint(file.scene, i);
      const sim::JointSpring& spring = spring_of(file.scene, joint);  // a copy in file.scene, read only
      if (spring.curve) continue;
      overrides.push_back({"springs." + file.scene.model.joints[joint].name + ".free_position",
                           number(spring.free_position)});
      in_text[i] = true;
    }
    overrides.insert(overrides.end(), edits.begin(), edits.end());
    file = sim::read_scene_text(study.scene_text, study.scene_source, overrides);
    for (std::size_t i = 0; i < study.variables.size(); ++i)
      if (study.variables[i].is_preload() && !in_text[i])
        scale_preload(file.scene, preload_joint(file.scene, i), c.inputs[i]);
  }
  if (c.failure) apply_failure(file.scene, *c.failure);
  return file;
}

}  // namespace unfurl::studies
