#include "unfurl/studies/pin_stiffness.hpp"

#include <cmath>

#include "unfurl/sim/elements/bushing.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/summary.hpp"
#include "unfurl/sim/number_text.hpp"

namespace unfurl::studies {

namespace {

PinLoads loads_of(const sim::Scene& scene, const sim::RunResult& run) {
  const sim::RunSummary s = sim::summarize(scene, run);
  PinLoads p;
  p.status = run.status;
  if (run.status == sim::RunStatus::failed) p.failure = sim::describe(run.failure);
  if (s.unlatched.empty())
    for (const auto& [joint, t] : s.latch_times) p.deployment_time = std::max(p.deployment_time, t);
  for (const auto& h : s.peak_hinge_force)
    if (!std::isnan(h.peak.t) && h.peak.value > p.peak_hinge_force)
      p.peak_hinge_force = h.peak.value, p.peak_hinge_joint = h.joint;
  for (const auto& h : s.peak_hinge_force_indeterminate)
    if (!std::isnan(h.peak.t)) p.peak_hinge_force_indeterminate = std::max(p.peak_hinge_force_indeterminate, h.peak.value);
  for (const auto& e : s.element_peaks)
    if (e.quantity == "peak_bushing_force") p.peak_pin_force = std::max(p.peak_pin_force, e.peak.value);
  p.loads_determinate = s.loads_determinate;
  p.steps = run.stats.steps;
  p.wall_time_s = run.wall_time_s;
  return p;
}

PinStiffnessCase run(const std::string& scene_name, int deployment, double k, double rtol, double t_end) {
  std::vector<sim::Override> overrides;
  const std::vector<PinStiffnessDeployment> deployments = pin_stiffness_deployments();
  for (const auto& [path, value] : deployments[deployment].overrides)
    overrides.push_back({path, value});
  overrides.push_back({"run.t_end", sim::format_number(t_end)});
  overrides.push_back({"run.rtol", sim::format_number(rtol)});
  overrides.push_back({"run.atol", sim::format_number(rtol / 100)});
  if (k > 0) {
    const sim::Scene nominal = sim::load_builtin_scene(scene_name);
    for (const sim::Bushing* pin : nominal.elements_of<sim::Bushing>())
      for (int a = 0; a < 3; ++a)
        overrides.push_back({"bushings." + pin->name + ".stiffness." + std::to_string(a), sim::format_number(k)});
  }
  const sim::Scene scene = sim::load_builtin_scene(scene_name, overrides);
  const sim::RunResult result = sim::simulate(scene, scene.run);
  return {deployment, k, loads_of(scene, result)};
}

}  // namespace

std::vector<PinStiffnessDeployment> pin_stiffness_deployments() {
  return {{"nominal", {}}, {"off-nominal (j1 spring +2 %)", {{"springs.j1.stiffness", "0.102"}}}};
}

PinStiffnessCase run_compliant_pins(int deployment, double k, double rtol, double t_end) {
  return run("pantograph_compliant", deployment, k, rtol, t_end);
}

PinStiffnessCase run_rigid_pins(int deployment, double rtol, double t_end) {
  return run("pantograph", deployment, 0, rtol, t_end);
}

}  // namespace unfurl::studies
