#include "unfurl/studies/scene_generators.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "unfurl/sim/elements/all.hpp"
#include "unfurl/sim/flexible/flexible_body.hpp"
#include "unfurl/sim/mechanism_scales.hpp"
#include "unfurl/sim/regulator.hpp"
#include "unfurl/sim/scene_builder.hpp"

namespace unfurl::studies {

namespace {

// The geometry and loads of SCENES.md, shared by the pantograph and z-fold.
constexpr double kFrameHalf = 0.30, kPanelHalf = 0.60, kChainX = 0.45, kPitch = 0.03;
constexpr double kFrameMass = 1.2, kPanelMass = 4.0;
const sim::Vec3 kFrameInertia(0.03606, 0.08106, 0.11700);
const sim::Vec3 kPanelInertia(0.4802, 0.2702, 0.7500);
constexpr double kSpring = 0.10, kSpringDamping = 0.02, kLatch = 1000, kLatchDamping = 10;
const double kOpen = M_PI / 2 - 0.01;  // a(0): 0.01 rad off the stowed stack

// Pivot-line offset of panel k (1-based) of chain A; chain B mirrors it.
double pivot_offset(int k) { return (k % 2 == 1 ? 1 : -1) * kPitch * k; }

sim::Body box(const std::string& name, double mass, const sim::Vec3& inertia, double share) {
  sim::Body b;
  b.name = name;
  b.mass = mass * share;
  b.inertia_com = (inertia * share).asDiagonal();
  return b;
}

sim::Visual mesh(const std::string& name) {
  sim::Visual v;
  v.mesh = name;
  return v;
}

void bus(sim::SceneBuilder& b) {
  sim::Visual v = mesh("bus");
  v.scale = sim::Vec3(1.6, 1.2, 1.2);
  b.fixed_base("bus", sim::Vec6::Zero(), v);
}

std::string joint_name(int j) { return "j" + std::to_string(j); }

// Panel k (1-based) of a chain, by its name: its body and its drawing.
using PanelMaker = std::function<std::pair<sim::Body, sim::Visual>(const std::string& name, int k)>;

PanelMaker rigid_panels(double share) {
  return [share](const std::string& name, int) {
    return std::pair(box(name, kPanelMass, kPanelInertia, share), mesh("panel"));
  };
}

// One chain of a frame and `panels` panels at x; joints named j<first>...
// mirror = +1 for chain A, -1 for chain B.
void chain(sim::SceneBuilder& b, const std::string& label, double x, double mirror, int panels, int first_joint,
           const PanelMaker& panel) {
  const std::string frame = "frame_" + label;
  b.body(box(frame, kFrameMass, kFrameInertia, 1.0), "bus",
         sim::joints::revolute(joint_name(first_joint), sim::Vec3::UnitX(), sim::Vec3(x, 0.75, 0),
                               sim::Vec3(0, -kFrameHalf, 0)),
         mesh("yoke"));
  std::string parent = frame;
  double parent_half = kFrameHalf, parent_p = 0;
  for (int k = 1; k <= panels; ++k) {
    const double p = mirror * pivot_offset(k);
    const std::string name = "panel_" + label + std::to_string(k);
    const auto [body, visual] = panel(name, k);
    b.body(body, parent,
           sim::joints::revolute(joint_name(first_joint + k), sim::Vec3::UnitX(), sim::Vec3(0, parent_half, parent_p),
                                 sim::Vec3(0, -kPanelHalf, p)),
           visual);
    parent = name;
    parent_half = kPanelHalf;
    parent_p = p;
  }
}

// Larger arrays deploy in about the reference's time (SCENES.md's 3-stage
// pantograph: 7.4 s): the lazy-tongs' inertia along its one motion grows as
// N^3 and the number of springs as N, so every spring and latch is (N / 3)^2
// as stiff and as damped as the reference's (one at N = 3). Each latch then
// stops as much energy per joint as the reference's does, at its angle.
double size_factor(int stages) { return (stages / 3.0) * (stages / 3.0); }

// Springs of joints j<first>..j<first + count - 1>, the first starting on
// the side first_sign, the rest alternating: each spring's free angle is
// pi/2 past the deployed angle 0, where its latch catches it.
void chain_forces(sim::SceneBuilder& b, int first, int count, double first_sign, double factor) {
  for (int j = 0; j < count; ++j) {
    const double s = j == 0 ? first_sign : (j % 2 == 1 ? -first_sign : first_sign);
    auto spring = std::make_shared<sim::JointSpring>(b.joint_index(joint_name(first + j), "springs"));
    spring->stiffness = factor * kSpring;
    spring->free_position = -s * M_PI / 2;
    spring->damping = factor * kSpringDamping;
    b.element(spring);
  }
}

void chain_latches(sim::SceneBuilder& b, int first, int count, double factor) {
  for (int j = 0; j < count; ++j) {
    auto latch = std::make_shared<sim::Latch>(b.joint_index(joint_name(first + j), "latches"));
    latch->stiffness = factor * kLatch;
    latch->damping = factor * kLatchDamping;
    b.element(latch);
  }
}

// The reference pantograph's bandwidth (SCENES.md). Other sizes, whose
// latches ring at other rates, take the automatic bandwidth from their own.
// Every size takes the automatic regularization (Regulator), which for the
// arrays released next to the lazy-tongs' branch point is finer than the
// reference's.
sim::RegulatorSettings cross_link_regulator(int stages) {
  sim::RegulatorSettings regulator;
  if (stages == 3) regulator.v_max = 2000;
  return regulator;
}

// The flexible arrays' loops close at the rigid array's bandwidth (the
// reference's at 3 stages). The automatic rule would take the tree's
// fastest rate, a pin half's tilt on its compliant hinge (10 g, 1e5 rad/s at
// 10 stages), which the loop's weld removes; measured at 10 stages, 25 times
// that rate took 14 times the steps and ended 8.7e-4 rad from a tight
// reference, where the rigid array's 4403 rad/s ended within 1e-8 rad.
// Their panels' loop forces follow the panels' vibration, which the
// regulator lags by delta's share even where W(0) has no weak mode (the
// 10-stage array's weakest lies at 1.3e-3 of its largest, where the
// automatic rule keeps 2e-6): its first 0.2 s at rtol 1e-10 ended 2.3e-6
// rad from a run at 2e-11 at 2e-6, 2.1e-9 rad at 2e-9 (at rtol 1e-7:
// 3,528 and 1,838 steps), so sizes other than the reference's take the finest.
sim::RegulatorSettings flexible_cross_link_regulator(int stages) {
  sim::RegulatorSettings regulator = cross_link_regulator(stages);
  if (!regulator.v_max) {
    regulator.regularization = sim::Regulator::kFinestRegularization;
    const sim::Scene rigid = generate_pantograph(stages).scene;
    sim::Sweep sweep(rigid.model);
    regulator.v_max = sim::Regulator::automatic_bandwidth(sim::mechanism_scales(rigid, sweep).rate);
  }
  return regulator;
}

// The rigid cross-links: each chain A panel's other half, its image, turns
// on the chain B panel at the pivot, and a loop closes it on the panel.
void cross_loops(sim::SceneBuilder& b, int stages) {
  const int N = stages;
  for (int k = 1; k <= N; ++k) {
    const double p_child = pivot_offset(k), p_parent = -p_child;
    b.body(box("image_A" + std::to_string(k), kPanelMass, kPanelInertia, 0.5), "panel_B" + std::to_string(k),
           sim::joints::revolute(joint_name(2 * N + 2 + k), sim::Vec3::UnitX(), sim::Vec3(-kChainX, 0, p_parent),
                                 sim::Vec3(kChainX, 0, p_child)));
  }
  for (int k = 1; k <= N; ++k)
    b.loop("A" + std::to_string(k), "panel_A" + std::to_string(k), "image_A" + std::to_string(k));
  b.regulator(cross_link_regulator(N));
}

// The compliant cross-link pins of pantograph_compliant.yaml: a bushing at
// each pivot, from panel A_k to panel B_k, stiff along x, y, z and in the
// two tilts, free about the hinge axis x. Like the springs and latches they
// scale with the size, so that every size's pins deflect as the reference's.
void cross_pins(sim::SceneBuilder& b, int stages, double factor) {
  const sim::Vec6 stiffness = factor * (sim::Vec6() << 1e6, 1e6, 1e6, 0, 1e4, 1e4).finished();
  const sim::Vec6 damping = factor * (sim::Vec6() << 100, 100, 100, 0, 3, 3).finished();
  for (int k = 1; k <= stages; ++k) {
    auto pin = std::make_shared<sim::Bushing>();
    pin->name = "A" + std::to_string(k);
    pin->a.body = b.body_index("panel_A" + std::to_string(k), "bushings");
    pin->a.point = sim::Vec3(kChainX, 0, pivot_offset(k));
    pin->b.body = b.body_index("panel_B" + std::to_string(k), "bushings");
    pin->b.point = sim::Vec3(-kChainX, 0, -pivot_offset(k));
    pin->stiffness = stiffness.asDiagonal();
    pin->damping = damping.asDiagonal();
    b.element(pin);
  }
}

// Joint j (1-based) of an N-stage pantograph 0.01 rad off the stowed stack,
// on the lazy-tongs path: chain A (-a, 2a, -2a, ...), chain B its negative,
// images (2a, -2a, ...), at a = kOpen.
double stowed_angle(int N, int j) {
  if (j == 1) return -kOpen;
  if (j <= N + 1) return (j % 2 == 0 ? 2 : -2) * kOpen;
  if (j == N + 2) return kOpen;
  if (j <= 2 * N + 2) return ((j - N - 1) % 2 == 0 ? -2 : 2) * kOpen;
  return ((j - 2 * N - 2) % 2 == 1 ? 2 : -2) * kOpen;
}

// A snubber under each hinge of an N-stage array's two chains: it stops
// the hinge at its stowed angle, on the side the hinge folds, as stiff as
// its latch.
void stowed_snubbers(sim::SceneBuilder& b, int N) {
  for (int j = 1; j <= 2 * N + 2; ++j) {
    const double stowed = stowed_angle(N, j);
    auto snubber = std::make_shared<sim::JointLimit>(b.joint_index(joint_name(j), "limits"));
    (stowed > 0 ? snubber->upper : snubber->lower) = stowed;
    snubber->stiffness = size_factor(N) * kLatch;
    snubber->damping = size_factor(N) * kLatchDamping;
    b.element(snubber);
  }
}

// Each half of a cross pivot's pin (a chain A panel's plate is as much
// lighter as the pin weighs, so that with it the panel weighs kPanelMass).
constexpr double kPinHalfMass = 0.01;
const sim::Vec3 kPinHalfInertia(1e-5, 1e-5, 1e-5);
// The tip sensor on the outer chain A panel: a plate node, so an attachment.
const sim::Vec3 kTipSensorPoint(0, kPanelHalf, 0);

// The flexible panels of pantograph_flexible.yaml: zfold_plates.yaml's
// aluminium honeycomb plate (0.9 x 1.2 m, D = 7435 N m, nu = 0.33, meshed
// 6 x 8), held along its inboard hinge line with its outboard one tied
// rigid, four fixed-interface modes, damped by Adams' bands. Panel k of a
// chain carries its next panel's hinge (k < N) and its cross pivot, a node
// at the middle of its edge toward the other chain (x = +-kChainX) on a
// bracket off the mid-plane; the outer chain A panel carries the tip sensor.
PanelMaker plate_panels(int stages, double mirror, double mass) {
  return [=](const std::string& name, int k) {
    namespace flex = sim::flexible;
    flex::PlateBodySpec spec;
    spec.plate.length_x = 2 * kChainX;
    spec.plate.length_y = 2 * kPanelHalf;
    spec.plate.bending_stiffness = 7435;
    spec.plate.poisson = 0.33;
    spec.plate.mass_per_area = mass / (spec.plate.length_x * spec.plate.length_y);
    spec.plate.elements_x = 6;
    spec.plate.elements_y = 8;
    spec.corner = sim::Vec3(-kChainX, -kPanelHalf, 0);
    spec.root_edge = flex::PlateEdge::y0;
    spec.hinge_lines = {flex::PlateEdge::y1};
    spec.normal_modes = 4;
    spec.damping.bands = {{100, 0.005}, {1000, 0.1}, {std::numeric_limits<double>::infinity(), 0.5}};
    const double p = mirror * pivot_offset(k);
    if (mirror > 0 && k == stages) spec.attachments.push_back(kTipSensorPoint);
    if (k < stages) spec.attachments.emplace_back(0, kPanelHalf, p);
    spec.attachments.emplace_back(mirror * kChainX, 0, p);
    sim::Body body;
    body.name = name;
    body.flexible = std::make_shared<const flex::FlexibleBody>(flex::plate_body(spec));
    return std::pair(body, mesh("flexible_panel"));
  };
}

// The flexible array's cross pivots: each pin's half on chain A's panel
// (fixed at its node) and its image turning on chain B's panel on a
// compliant hinge (pantograph_compliant.yaml's pins, scaled with the size
// like the springs), a loop closing the two through the plates' bending.
void flexible_cross_pivots(sim::SceneBuilder& b, int stages, double factor) {
  const int N = stages;
  for (int k = 1; k <= N; ++k) {
    sim::Joint hinge = sim::joints::revolute(joint_name(2 * N + 2 + k), sim::Vec3::UnitX(),
                                             sim::Vec3(-kChainX, 0, -pivot_offset(k)), sim::Vec3::Zero());
    hinge.compliant = true;
    b.body(box("image_A" + std::to_string(k), kPinHalfMass, kPinHalfInertia, 1.0), "panel_B" + std::to_string(k),
           hinge);
    auto pin = std::make_shared<sim::JointCompliance>();
    pin->joint = b.joint_index(hinge.name, "compliance");
    pin->radial = pin->axial = factor * 1e6;
    pin->tilt = factor * 1e4;
    pin->radial_damping = pin->axial_damping = factor * 100;
    pin->tilt_damping = factor * 3;
    b.element(pin);
  }
  for (int k = 1; k <= N; ++k) {
    sim::Joint fixed;
    fixed.name = "p" + std::to_string(k);
    fixed.type = sim::JointType::fixed;
    fixed.parent_point = sim::Vec3(kChainX, 0, pivot_offset(k));
    b.body(box("pivot_A" + std::to_string(k), kPinHalfMass, kPinHalfInertia, 1.0), "panel_A" + std::to_string(k),
           fixed);
  }
  for (int k = 1; k <= N; ++k)
    b.loop("A" + std::to_string(k), "pivot_A" + std::to_string(k), "image_A" + std::to_string(k));
}

sim::RunSettings run(double t_end, double rtol, double atol) {
  sim::RunSettings r;
  r.t_end = t_end;
  r.rtol = rtol;
  r.atol = atol;
  r.sample = 0.01;
  return r;
}

// The reference pantograph's run (SCENES.md), and for other sizes the same
// with BDF's stability-limit detection: a latched array rings down lightly
// damped, where orders 3 to 5 are unstable, and without it the 30-stage
// array's whole 20 s took 97,948 steps at rtol 1e-7 against 16,683 with it
// (the compliant one's 84,211 against 61,519).
sim::RunSettings array_run(int stages, double rtol, double atol) {
  sim::RunSettings r = run(20, rtol, atol);
  if (stages != 3) r.stability_limit_detection = sim::StabilityLimitDetection::on;
  return r;
}

void check_count(int n, const char* what) {
  if (n < 1) throw std::invalid_argument(std::string(what) + " must be at least 1");
}

}  // namespace

sim::SceneFile generate_pantograph(int stages, CrossPivots pivots, Snubbers snubbers) {
  check_count(stages, "the number of stages");
  const int N = stages;
  const bool compliant = pivots == CrossPivots::compliant;
  const std::string count = std::to_string(N);
  sim::SceneBuilder b(
      compliant ? "pantograph_compliant_" + count : "pantograph_" + count,
      compliant ? "The pantograph solar array with " + count + " panel pairs cross-linked on compliant pins."
                : "The pantograph solar array with " + count + " panel pairs (" + count + " loops).");
  b.source("generated");
  bus(b);
  chain(b, "A", -kChainX, 1, N, 1, rigid_panels(compliant ? 1.0 : 0.5));
  chain(b, "B", kChainX, -1, N, N + 2, rigid_panels(1.0));
  chain_forces(b, 1, N + 1, -1, size_factor(N));
  chain_forces(b, N + 2, N + 1, 1, size_factor(N));
  chain_latches(b, 1, N + 1, size_factor(N));
  chain_latches(b, N + 2, N + 1, size_factor(N));
  if (compliant)
    cross_pins(b, N, size_factor(N));
  else
    cross_loops(b, N);
  for (int j = 1; j <= (compliant ? 2 : 3) * N + 2; ++j) b.initial_position(joint_name(j), {stowed_angle(N, j)});
  if (compliant && snubbers == Snubbers::stowed) stowed_snubbers(b, N);
  b.run(array_run(N, 1e-10, 1e-12));
  return b.build();
}

sim::SceneFile generate_flexible_pantograph(int stages, Snubbers snubbers) {
  check_count(stages, "the number of stages");
  const int N = stages;
  const std::string count = std::to_string(N);
  sim::SceneBuilder b("pantograph_flexible_" + count, "The pantograph solar array with " + count +
                                                          " pairs of flexible plate panels, its loops closing "
                                                          "through their bending at compliant cross pivots.");
  b.source("generated");
  bus(b);
  chain(b, "A", -kChainX, 1, N, 1, plate_panels(N, 1, kPanelMass - 2 * kPinHalfMass));
  chain(b, "B", kChainX, -1, N, N + 2, plate_panels(N, -1, kPanelMass));
  flexible_cross_pivots(b, N, size_factor(N));
  chain_forces(b, 1, N + 1, -1, size_factor(N));
  chain_forces(b, N + 2, N + 1, 1, size_factor(N));
  chain_latches(b, 1, N + 1, size_factor(N));
  chain_latches(b, N + 2, N + 1, size_factor(N));
  sim::Sensor tip;
  tip.name = "tip";
  tip.point = kTipSensorPoint;
  b.sensor(tip, "panel_A" + count);
  b.regulator(flexible_cross_link_regulator(N));
  for (int j = 1; j <= 3 * N + 2; ++j) b.initial_position(joint_name(j), {stowed_angle(N, j)});
  if (snubbers == Snubbers::stowed) stowed_snubbers(b, N);
  sim::RunSettings r = array_run(N, 1e-8, 1e-10);
  // pantograph_flexible's: its deployment as without the detection.
  if (N == 3) r.stability_limit_detection = sim::StabilityLimitDetection::after_latch;
  b.run(r);
  return b.build();
}

sim::SceneFile generate_scene(const std::string& kind, int size, const ArrayOptions& options) {
  if ((options.compliant || options.flexible || !options.snubbers) && kind != "pantograph")
    throw std::invalid_argument("the compliant, flexible and snubber options (--compliant, --flexible, "
                                "--no-snubbers) apply to a pantograph only");
  if (options.compliant && options.flexible)
    throw std::invalid_argument("compliant and flexible (--compliant, --flexible) are two different arrays: give one");
  if (!options.snubbers && !options.compliant && !options.flexible)
    throw std::invalid_argument(
        "leaving the snubbers out (--no-snubbers, snubbers=False) applies to a compliant or flexible pantograph only");
  const Snubbers snubbers = options.snubbers ? Snubbers::stowed : Snubbers::none;
  if (kind == "pantograph" && options.flexible) return generate_flexible_pantograph(size, snubbers);
  if (kind == "pantograph")
    return generate_pantograph(size, options.compliant ? CrossPivots::compliant : CrossPivots::rigid, snubbers);
  if (kind == "zfold") return generate_zfold(size);
  if (kind == "chain") return generate_chain(size);
  if (kind == "rods") return generate_parallel_rods(size);
  if (kind == "beam") return generate_beam(size);
  throw std::invalid_argument("'" + kind + "' is not a generated scene: pantograph, zfold, chain, rods or beam");
}

sim::SceneFile generate_zfold(int panels) {
  check_count(panels, "the number of panels");
  const int N = panels;
  sim::SceneBuilder b("zfold_" + std::to_string(N), "A Z-folded wing of a frame and " + std::to_string(N) + " panels.");
  b.source("generated");
  bus(b);
  chain(b, "A", -kChainX, 1, N, 1, rigid_panels(1.0));
  chain_forces(b, 1, N + 1, -1, 1.0);
  chain_latches(b, 1, N + 1, 1.0);
  b.initial_position("j1", {-M_PI / 2});
  for (int j = 2; j <= N + 1; ++j) b.initial_position(joint_name(j), {(j % 2 == 0 ? 1 : -1) * M_PI});
  b.run(run(20, 1e-8, 1e-10));
  return b.build();
}

sim::SceneFile generate_chain(int links) {
  check_count(links, "the number of links");
  const int N = links;
  const double length = 1.0 / N, mass = 1.0 / N;
  const double I = mass * length * length / 12;
  sim::SceneBuilder b("chain_" + std::to_string(N), "A hanging chain of " + std::to_string(N) + " links.");
  b.source("generated");
  b.fixed_base("ground").gravity(sim::Vec3(0, 0, -9.81));
  // A thin rod: about its own axis a thousandth of I (the radius a
  // hundredth of the length), which keeps the principal moments a rigid
  // body can have at any N (a floor of 1e-12 did not, from 10,000 links).
  const sim::Vec3 inertia(I, I, 1e-3 * I);
  for (int i = 1; i <= N; ++i) {
    const std::string parent = i == 1 ? "ground" : "link" + std::to_string(i - 1);
    b.body(
        box("link" + std::to_string(i), mass, inertia, 1.0), parent,
        sim::joints::revolute(joint_name(i), sim::Vec3::UnitX(),
                              i == 1 ? sim::Vec3::Zero() : sim::Vec3(0, 0, -length / 2), sim::Vec3(0, 0, length / 2)));
  }
  for (int i = 1; i <= N; ++i) {
    auto damper = std::make_shared<sim::JointDamper>(b.joint_index(joint_name(i), "dampers"));
    damper->damping = 1e-4 * mass;
    b.element(damper);
  }
  for (int i = 1; i <= N; ++i) b.initial_position(joint_name(i), {i == 1 ? 1.0 : 0.5 / N});
  b.run(run(5, 1e-8, 1e-10));
  return b.build();
}

sim::SceneFile generate_beam(int segments, const BeamSpec& spec) {
  check_count(segments, "the number of segments");
  const int N = segments;
  const double l = spec.length / N, m = spec.mass_per_length * l;
  const double I = m * l * l / 12;
  sim::SceneBuilder b("beam_" + std::to_string(N),
                      "A uniform beam of " + std::to_string(N) +
                          " rigid segments and bending springs on a hub spun up about z (Simo and Vu-Quoc).");
  b.source("generated");
  b.fixed_base("ground");
  sim::Body hub = box("hub", 1.0, sim::Vec3(1, 1, 1), 1.0);
  sim::Visual hub_visual = mesh("rod");
  hub_visual.scale = sim::Vec3(0.4, 0.4, 0.4);
  b.body(hub, "ground", sim::joints::revolute("hub", sim::Vec3::UnitZ(), sim::Vec3::Zero(), sim::Vec3::Zero()),
         hub_visual);
  for (int i = 1; i <= N; ++i) {
    sim::Body segment = box("s" + std::to_string(i), m, sim::Vec3(1e-3 * I, I, I), 1.0);
    segment.com = sim::Vec3(l / 2, 0, 0);
    sim::Visual v = mesh("rod");  // a unit cylinder along z, laid along x
    v.scale = sim::Vec3(0.05, 0.05, l);
    v.rotation_axis = sim::Vec3::UnitY();
    v.rotation_deg = 90;
    v.offset = sim::Vec3(l / 2, 0, 0);
    v.collision = std::vector<sim::CollisionShape>{};  // the beam's own segments do not collide
    b.body(segment, i == 1 ? "hub" : "s" + std::to_string(i - 1),
           sim::joints::revolute("b" + std::to_string(i), sim::Vec3::UnitZ(),
                                 i == 1 ? sim::Vec3::Zero() : sim::Vec3(l, 0, 0), sim::Vec3::Zero()),
           v);
  }
  for (int i = 1; i <= N; ++i) {
    auto spring = std::make_shared<sim::JointSpring>(b.joint_index("b" + std::to_string(i), "springs"));
    spring->stiffness = (i == 1 ? 2 : 1) * spec.bending_stiffness / l;
    b.element(spring);
  }
  auto driver = std::make_shared<sim::JointDriver>(b.joint_index("hub", "drivers"));
  driver->profile = sim::JointDriver::Profile::spin_up;
  driver->amount = spec.spin_rate;
  driver->duration = spec.spin_up_time;
  b.element(driver);
  // The tip, in the inertial frame: its deflection is its offset across the
  // hub's turned axis.
  sim::Sensor tip;
  tip.name = "tip";
  tip.point = sim::Vec3(l, 0, 0);
  tip.frame = sim::SensorFrame::inertial;
  tip.measures = {sim::SensorQuantity::position, sim::SensorQuantity::acceleration};
  b.sensor(tip, "s" + std::to_string(N));
  b.run(run(30, 1e-8, 1e-10));
  return b.build();
}

namespace {

// The rods' crank spring: theta'' = -(k / I) (theta - free) from theta(0) = start at rest.
constexpr double kRodsSpring = 1.0, kRodsFree = 0.0, kRodsStart = 0.8;

}  // namespace

sim::SceneFile generate_parallel_rods(int rods) {
  check_count(rods, "the number of rods");
  constexpr double kCrank = 0.5, kBase = 1.0, kCrankMass = 1.0, kRodMass = 0.4;
  sim::SceneBuilder b("rods_" + std::to_string(rods),
                      "Two cranks joined by " + std::to_string(rods) + " parallel rods, swung through their flat position.");
  b.source("generated");
  b.fixed_base("ground");
  // A crank of length a (its frame at its pivot, along +y at q = 0); the two
  // pivots kBase apart along y.
  const auto crank = [&](const std::string& name, const sim::Vec3& pivot) {
    sim::Body c = box(name, kCrankMass, sim::Vec3(kCrankMass * kCrank * kCrank / 12, 1e-4, kCrankMass * kCrank * kCrank / 12), 1.0);
    c.com = sim::Vec3(0, kCrank / 2, 0);
    b.body(c, "ground", sim::joints::revolute(name, sim::Vec3::UnitX(), pivot, sim::Vec3::Zero()));
  };
  crank("crank_A", sim::Vec3::Zero());
  crank("crank_B", sim::Vec3(0, kBase, 0));
  // Rod k pinned at radius a k / N on both cranks: split into the rod on
  // crank A (its frame at that pin) and its image on crank B, half the mass
  // each.
  const sim::Vec3 rod_inertia(kRodMass * kBase * kBase / 12, 1e-4, kRodMass * kBase * kBase / 12);
  for (int k = 1; k <= rods; ++k) {
    const double r = kCrank * k / rods;
    const std::string name = "rod" + std::to_string(k);
    sim::Body rod = box(name, kRodMass, rod_inertia, 0.5);
    rod.com = sim::Vec3(0, kBase / 2, 0);
    b.body(rod, "crank_A", sim::joints::revolute("a" + std::to_string(k), sim::Vec3::UnitX(), sim::Vec3(0, r, 0), sim::Vec3::Zero()));
    sim::Body image = rod;
    image.name = name + "_image";
    b.body(image, "crank_B",
           sim::joints::revolute("b" + std::to_string(k), sim::Vec3::UnitX(), sim::Vec3(0, r, 0), sim::Vec3(0, kBase, 0)));
    b.loop(name, name, name + "_image");
  }
  auto spring = std::make_shared<sim::JointSpring>(0);
  spring->stiffness = kRodsSpring;
  spring->free_position = kRodsFree;
  b.element(spring);
  b.regulator(sim::RegulatorSettings{});
  const sim::SceneFile shape = b.build();
  const std::vector<double> q0 = parallel_rods_angles(shape.scene, 0);
  for (int j = 0; j < shape.scene.model.size(); ++j) b.initial_position(shape.scene.model.joints[j].name, {q0[j]});
  sim::RunSettings settings;
  settings.t_end = 10;
  settings.sample = 0.01;
  b.run(settings);
  return b.build();
}

std::vector<double> parallel_rods_angles(const sim::Scene& scene, double t) {
  // The cranks turn about their pivots and every rod translates: the
  // kinetic energy is (I_A + I_B + sum m_rod r^2) theta'^2 / 2.
  const sim::Model& m = scene.model;
  double inertia = 0;
  for (int i = 0; i < m.size(); ++i) {
    const sim::Body& body = m.bodies[i];
    if (i < 2)
      inertia += body.inertia_com(0, 0) + body.mass * body.com.tail<2>().squaredNorm();
    else
      inertia += body.mass * m.joints[i].parent_point.squaredNorm();
  }
  const double theta = kRodsFree + (kRodsStart - kRodsFree) * std::cos(std::sqrt(kRodsSpring / inertia) * t);
  std::vector<double> q(m.size());
  for (int j = 0; j < m.size(); ++j) q[j] = j < 2 ? theta : -theta;
  return q;
}

}  // namespace unfurl::studies
