#include "unfurl/studies/scene_scaling.hpp"

#include <cmath>
#include <memory>
#include <string>

#include "unfurl/sim/flexible/flexible_body.hpp"
#include "unfurl/sim/scene_validation.hpp"

namespace unfurl::studies {

sim::SceneFile scale_scene(const sim::SceneFile& file, double L, double M) {
  sim::SceneFile out = file;
  sim::Scene& scene = out.scene;
  sim::Model& model = scene.model;
  for (sim::Body& b : model.bodies) {
    b.mass *= M;
    b.com *= L;
    b.inertia_com *= M * L * L;
    if (b.flexible) {
      const sim::flexible::FlexibleBody& f = *b.flexible;
      b.flexible = std::make_shared<const sim::flexible::FlexibleBody>(
          f.fem     ? sim::flexible::fem_body(sim::flexible::scaled(*f.fem, L, M))
          : f.plate ? sim::flexible::plate_body(sim::flexible::scaled(*f.plate, L, M))
                    : sim::flexible::beam_body(sim::flexible::scaled(f.beam, L, M)));
    }
  }
  for (sim::Joint& j : model.joints) {
    j.parent_point *= L;
    j.child_point *= L;
  }
  model.base_velocity.head<3>() *= L;
  for (auto& element : scene.elements) element = element->scaled(L, M, model);
  for (sim::Sensor& s : scene.sensors) s.point *= L;
  // Elastic coordinates (m kg^0.5, unit modal masses) and their rates and
  // momenta grow by L sqrt(M).
  const double modal = L * std::sqrt(M);
  for (int c = 0; c < model.nq; ++c) {
    const std::string unit = model.position_unit(c);
    if (unit == "m") scene.q0[c] *= L;
    if (unit == "m kg^0.5") scene.q0[c] *= modal;
  }
  for (int c = 0; c < model.nv; ++c) {
    const std::string unit = model.velocity_unit(c);
    const bool linear = unit == "m/s", elastic = unit == "m kg^0.5/s";
    if (linear) scene.dq0[c] *= L;
    if (elastic) scene.dq0[c] *= modal;
    if (!scene.p0.empty()) scene.p0[c] *= elastic ? modal : linear ? M * L : M * L * L;
  }
  const auto scale_visual = [L](sim::Visual& v) {
    v.scale *= L;
    v.offset *= L;
    if (v.collision)
      for (sim::CollisionShape& c : *v.collision) {
        c.size *= L;
        c.radius *= L;
        c.length *= L;
        c.scale *= L;
        c.offset *= L;
      }
  };
  scale_visual(out.visuals.base);
  for (sim::Visual& v : out.visuals.bodies) scale_visual(v);
  scene.name += "_scaled";
  sim::validate(scene);
  return out;
}

}  // namespace unfurl::studies
