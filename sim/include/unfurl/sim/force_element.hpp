// One interface for everything that pushes on the mechanism: joint springs
// (linear or a measured curve), dampers, latches, hinge friction, point
// springs and cables, applied forces and gravity, and what comes next. As in
// Drake's ForceElement, every kind answers the same questions, so the
// right-hand side, the energy balance and the dissipation meter, the loads
// and their peaks, the Newton preconditioner, the parameter panel and the
// renderer loop over elements without knowing their kinds. An element is
// immutable once made: a scene's copies share it, and what one run learns
// about it (its load columns, whether a latch has engaged) is kept by the
// run, not by the element.
#pragma once

#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "unfurl/sim/coordinates.hpp"
#include "unfurl/sim/kinematics.hpp"
#include "unfurl/sim/loads.hpp"
#include "unfurl/sim/model.hpp"

namespace unfurl::sim {

struct Scene;
class Sweep;

// Where an element's stored energy is counted (EnergyParts).
enum class EnergyStore { springs, latches, gravity };

// What an element reads at one state. poses and v are filled only when some
// element needs_poses(); v is then each body's velocity in its own frame,
// and base_velocity the base's. sweep, configured at q, carries the node
// frames of flexible bodies (elements/point_frame.hpp); null where no
// element reads them (the Newton preconditioner's stiffness estimate).
struct ElementState {
  const Model& model;
  Positions q;  // positions
  Rates w;      // velocity coordinates (a one-coordinate joint's q')
  const std::vector<Pose>& poses;
  const std::vector<Vec6>& v;
  Vec6 base_velocity = Vec6::Zero();
  // An event-driven element's discrete state: whether a latch has engaged.
  bool engaged = false;
  const Sweep* sweep = nullptr;
};

// Where an element's forces go: generalized forces on the velocity
// coordinates, and wrenches (f, m) on bodies at their origins, in their
// frames. Both accumulate.
struct ElementForces {
  RatesOut Q;
  std::vector<Vec6>& F;
};

// A number of an element that a --set path, the GUI or a study can change:
// path = the element's path + "." + key.
struct ElementParameter {
  std::string key;    // "stiffness"
  std::string label;  // "stiffness [N m/rad]"
  double value = 0;
  double step = 0;        // the GUI's - and + step
  double lo = 0, hi = 0;  // the GUI clamps to [lo, hi] when lo < hi
  std::string help;       // what it is, in the GUI's tooltip
};

// A line the renderer draws between two attachment points (kBase: a point
// fixed on the base), in the colour of its kind; a bushing is drawn as a
// sleeve at point a along its frame's x axis.
struct ElementLink {
  enum class Style { spring, cable, bushing };
  int body_a = kBase, body_b = kBase;
  Vec3 point_a = Vec3::Zero(), point_b = Vec3::Zero();  // each body's frame
  Style style = Style::spring;
  Vec3 axis_a = Vec3::UnitX();  // a bushing's x axis, in body a's frame
};

// The bodies of `ends` that are not the base, for ForceElement::bodies().
inline std::vector<int> bodies_off_base(std::initializer_list<int> ends) {
  std::vector<int> bodies;
  for (int b : ends)
    if (b != kBase) bodies.push_back(b);
  return bodies;
}

class ForceElement {
 public:
  virtual ~ForceElement() = default;

  // "spring", "latch", ...: what it is, in messages and the GUI.
  virtual std::string kind() const = 0;
  // The scene file's list it is written in ("springs"), and what names it
  // there (its joint's or its own name; "" if nothing does, and the element
  // is then addressed by its index in the list).
  virtual std::string list() const = 0;
  virtual std::string handle(const Model& model) const = 0;
  // Where it is written in the scene file when that is not its list's
  // entry (a joint's compliance: "bodies.panel_A1.joint.compliance"); ""
  // for an entry of list().
  virtual std::string file_path(const Scene&) const { return ""; }

  // Adds its forces at the state.
  virtual void add_forces(const ElementState& s, ElementForces& out) const = 0;
  // Whether it reads poses and body velocities (else they may be stale).
  virtual bool needs_poses() const { return false; }
  // The bodies it may put wrenches on (never kBase), so that an analysis
  // of a few joints can take one element's forces without a pass over
  // every body (torque_margin.cpp); nullopt: any body. An element that
  // lists bodies writes no generalized force on a joint's coordinate (at
  // most on its bodies' elastic ones); an empty list: generalized forces
  // only.
  virtual std::optional<std::vector<int>> bodies() const { return std::nullopt; }

  // Its stored energy, and the store it counts towards.
  virtual double potential_energy(const ElementState&) const { return 0.0; }
  virtual EnergyStore energy_store() const { return EnergyStore::springs; }
  // The power it takes out of the mechanism (>= 0 for a passive element);
  // dissipative() says whether it can take any (the meter skips the
  // quadrature where nothing can).
  virtual double dissipated_power(const ElementState&) const { return 0.0; }
  virtual bool dissipative() const { return false; }

  // Its stiffness -dQ/dq and damping -dQ/dw along velocity coordinates,
  // where it acts on them directly: the estimate the implicit integrators'
  // Newton preconditioner takes as armature (newton_preconditioner.hpp).
  virtual void add_joint_stiffness(const ElementState&, RatesOut /*stiffness*/, RatesOut /*damping*/) const {}

  // Its load columns, and their values at a state (one per column).
  virtual std::vector<LoadColumn> load_columns(const Model&) const { return {}; }
  virtual void load_values(const ElementState&, double* /*values*/) const {}
  // The peaks of its loads a run reports (for an element with a handle).
  virtual std::vector<ElementPeak> peaks() const { return {}; }

  // A copy for the mechanism scaled by lengths x L and masses x M with time
  // unchanged, by dimensional analysis (a hinge's torque and stiffness x M
  // L^2, a force x M L, a point x L): the same motion in other units.
  virtual std::shared_ptr<ForceElement> scaled(double L, double M, const Model& model) const = 0;

  // Throws SceneInvalid (scene_validation.hpp) at `field` + ".key" when a
  // value breaks the element's rules in the scene.
  virtual void validate(const Scene& /*scene*/, const std::string& /*field*/) const {}

  // Its editable values, labelled in the units they have in `model` (a
  // joint element's per metre on a slider, per radian on a hinge).
  virtual std::vector<ElementParameter> parameters(const Model& /*model*/) const { return {}; }
  // A line about it beyond its parameters (a measured curve's size), or "".
  virtual std::string note() const { return ""; }
  virtual std::vector<ElementLink> links() const { return {}; }
};

}  // namespace unfurl::sim
