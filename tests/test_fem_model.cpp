// Flexible bodies from a reduced finite-element model (MBDyn's modal data
// file, fem_model.hpp): the example boom (examples/fem/boom.fem, assembled
// and reduced by examples/fem/boom_fem.py in numpy) against unfurl's own
// beam of the same section, which is the same model computed another way;
// the deployment it drives; the file's and the scene's errors.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <sstream>
#include <string>

#include "support.hpp"
#include "unfurl/sim/flexible/fem_model.hpp"
#include "unfurl/sim/flexible/flexible_body.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"
#include "unfurl/sim/summary.hpp"

namespace unfurl::sim {
namespace {

const std::string kScene = std::string(UNFURL_SOURCE_DIR) + "/examples/fem/magnetometer_boom.yaml";
const std::string kFem = std::string(UNFURL_SOURCE_DIR) + "/examples/fem/boom.fem";

// boom_fem.py's tube: 3 m, 40 mm across, 1 mm wall; E 70 GPa, G 5 GPa,
// 1600 kg/m^3; 16 elements.
struct Tube {
  double L = 3, E = 70e9, G = 5e9, rho = 1600;
  double A = M_PI / 4 * (0.04 * 0.04 - 0.038 * 0.038);
  double I = M_PI / 64 * (std::pow(0.04, 4) - std::pow(0.038, 4));
};

// The example scene with the boom as unfurl's own beam, the same section,
// elements and normal modes.
SceneFile beam_boom(const std::vector<Override>& overrides = {}) {
  const Tube t;
  std::ostringstream beam;
  beam.precision(17);
  beam << "beam: {length: 3, axial_stiffness: " << t.E * t.A << ", bending_stiffness: [" << t.E * t.I << ", "
       << t.E * t.I << "], torsional_stiffness: " << t.G * 2 * t.I << ", mass_per_length: " << t.rho * t.A
       << ", polar_inertia_per_length: " << t.rho * 2 * t.I << ", elements: 16}\n      modes: 4";
  std::string text = test::text_of(kScene);
  const std::string fem = "fem: boom.fem";
  text.replace(text.find(fem), fem.size(), beam.str());
  return read_scene_text(text, "beam boom", overrides);
}

const flexible::FlexibleBody& boom_of(const SceneFile& f) { return *f.scene.model.bodies[0].flexible; }

// The tip's static compliance, 6 x 6: Phi_tip K^-1 Phi_tip^T, whatever
// basis the coordinates are in.
Eigen::MatrixXd tip_compliance(const flexible::FlexibleBody& b) {
  const int tip = b.node_of(Eigen::Vector3d(3, 0, 0));
  const Eigen::MatrixXd& phi = b.nodes.at(tip).shape;
  return phi * b.stiffness.cwiseInverse().asDiagonal() * phi.transpose();
}

// The file's model and unfurl's beam are the same Euler-Bernoulli elements
// and the same Craig-Bampton reduction (root held, tip the interface, 4
// normal modes), assembled and reduced independently: the file's modal
// mass and stiffness have the beam's frequencies to round-off, the first
// the cantilever's closed form (beta_1 L = 1.8751) within the mesh's
// error, and the tip's static compliance is the beam's. The body's inertia
// is summed from the file's lumped masses (its modal mass too, so that the
// kinetic energy is one body's): its frequencies are the lumped model's,
// under the consistent one's by the lumping's O(h^2): 0.18 %, 0.62 % and
// 1.09 % in the first three bending modes at 16 elements (the constraint
// modes above 100 Hz by up to 10 %), and its rigid inertia within the
// trapezoid rule's (h / L)^2 / 2 = 2e-3 of the beam's.
TEST(FemModel, TheExampleBoomIsUnfurlsBeamComputedAnotherWay) {
  const SceneFile fem = read_scene_file(kScene), beam = beam_boom();
  const flexible::FlexibleBody &f = boom_of(fem), &b = boom_of(beam);
  ASSERT_TRUE(f.fem);
  ASSERT_EQ(f.modes(), 10);
  ASSERT_EQ(b.modes(), 10);
  const flexible::FemModel& file = *f.fem->model;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> consistent(file.stiffness, file.mass);
  const Eigen::VectorXd file_hz = consistent.eigenvalues().cwiseSqrt() / (2 * M_PI);
  for (int k = 0; k < 10; ++k) {
    EXPECT_NEAR(file_hz[k], b.frequency_hz[k], 1e-9 * b.frequency_hz[k]) << k;
    if (b.frequency_hz[k] < 100) {
      EXPECT_NEAR(f.frequency_hz[k], b.frequency_hz[k], 1.2e-2 * b.frequency_hz[k]) << k;
    }
    EXPECT_LE(f.frequency_hz[k], b.frequency_hz[k]) << k;
  }
  const Tube t;
  const double closed_form = 1.8751 * 1.8751 / (2 * M_PI * t.L * t.L) * std::sqrt(t.E * t.I / (t.rho * t.A));
  EXPECT_NEAR(file_hz[0], closed_form, 1e-4 * closed_form);
  const Eigen::MatrixXd cf = tip_compliance(f), cb = tip_compliance(b);
  EXPECT_LT((cf - cb).norm(), 1e-8 * cb.norm());
  EXPECT_NEAR(cf(1, 1), std::pow(t.L, 3) / (3 * t.E * t.I), 1e-8 * cf(1, 1)) << "a tip force's deflection, L^3 / 3EI";
  const Eigen::MatrixXd Mf = f.inertia.mass_matrix(Eigen::VectorXd::Zero(10)).topLeftCorner(6, 6);
  const Eigen::MatrixXd Mb = b.inertia.mass_matrix(Eigen::VectorXd::Zero(10)).topLeftCorner(6, 6);
  EXPECT_NEAR(f.inertia.mass(), t.rho * t.A * t.L, 1e-12 * f.inertia.mass());
  EXPECT_LT((Mf - Mb).norm(), 2e-3 * Mb.norm());
}

struct Deployment {
  double latched_at = NAN, latch_torque = NAN, deflection = NAN;
};

Deployment deploy(const SceneFile& file) {
  const RunResult run = simulate(file.scene, file.scene.run);
  EXPECT_EQ(run.status, RunStatus::finished) << describe(run.failure);
  Deployment d;
  if (!run.trajectory.events.empty()) d.latched_at = run.trajectory.events.front().t;
  const RunSummary s = summarize(file.scene, run);
  if (!s.peak_latch_torque.empty()) d.latch_torque = s.peak_latch_torque.front().peak.value;
  const int column = find_load_column(run.trajectory.load_columns, "deflection.boom");
  d.deflection = 0;
  for (const Sample& sample : run.trajectory.samples) d.deflection = std::max(d.deflection, sample.loads.element[column]);
  return d;
}

// The deployment: the boom latches at the same time either way (its swing
// is the rigid body's); the latch-up, which bends it, differs by the
// lumped masses' inertia: within 1 %.
TEST(FemModel, TheExampleBoomDeploysAsTheBeamOne) {
  const Deployment f = deploy(read_scene_file(kScene)), b = deploy(beam_boom());
  EXPECT_NEAR(f.latched_at, b.latched_at, 1e-3 * b.latched_at);
  EXPECT_NEAR(f.latch_torque, b.latch_torque, 1e-2 * b.latch_torque);
  EXPECT_NEAR(f.deflection, b.deflection, 1e-2 * b.deflection);
  EXPECT_GT(f.deflection, 1e-2) << "the latch-up bends it";
}

// Written back, the scene names the file by its full path and reads to
// the same body.
TEST(FemModel, TheSceneWritesBack) {
  const SceneFile file = read_scene_file(kScene);
  const SceneFile again = read_scene_text(write_scene_text(file), "/somewhere/else.yaml");
  ASSERT_TRUE(again.scene.model.bodies[0].flexible && again.scene.model.bodies[0].flexible->fem);
  EXPECT_EQ(again.scene.model.bodies[0].flexible->fem->file, boom_of(file).fem->file);
  EXPECT_EQ(again.scene.model.bodies[0].flexible->frequency_hz, boom_of(file).frequency_hz);
}

// The file's errors name its line and what belongs there.
std::string fem_error(const std::string& text) {
  try {
    flexible::read_fem_text(text, "bad.fem");
  } catch (const flexible::FemFileError& e) {
    return e.what();
  }
  return "";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(FemModel, ABadFileIsRefusedAtItsLine) {
  const std::string good = test::text_of(kFem);
  EXPECT_EQ(fem_error(good), "");
  EXPECT_NE(fem_error(replaced(good, "** RECORD GROUP 10", "** RECORD GROUP 99")).find("no RECORD GROUP 10"),
            std::string::npos);
  EXPECT_NE(fem_error(replaced(good, "REV0 17 4 0 6 0", "REV0 17 4 0 x 0")).find("bad.fem:5: RECORD GROUP 1: 'x'"),
            std::string::npos)
      << fem_error(replaced(good, "REV0 17 4 0 6 0", "REV0 17 4 0 x 0"));
  EXPECT_NE(fem_error(replaced(good, "REV0 17 4 0 6 0", "REV0 17 4 0 7 0")).find("ends after"), std::string::npos);
  EXPECT_NE(fem_error(replaced(good, "1 2 3 4 5", "1 2 3 4 5 6")).find("holds more than its 17"), std::string::npos);
  EXPECT_NE(fem_error(replaced(good, "** RECORD GROUP 6", "1.0e0 nan\n** RECORD GROUP 6")).find("holds more"),
            std::string::npos);
  EXPECT_NE(fem_error(replaced(good, "0.0000000000000000e+00", "abc")).find("bad.fem:11: RECORD GROUP 3: 'abc' is not"),
            std::string::npos)
      << fem_error(replaced(good, "0.0000000000000000e+00", "abc"));
  EXPECT_NE(fem_error(replaced(good, "** END OF FILE", "** RECORD GROUP 9\n1\n")).find("appears twice"),
            std::string::npos);
  EXPECT_NE(fem_error("1 2 3\n" + good).find("bad.fem:1: '1' before the first RECORD GROUP"), std::string::npos);
  EXPECT_NE(fem_error(replaced(good, "REV0 17 4 0 6 0", "REV0 17 4 0 6 10")).find("10 of its 10 modes rejected"),
            std::string::npos);
  // Node 1's lumped masses (the first line of group 11) made unequal, and
  // the rigid body's mass (group 12's first line) off by 10 %.
  const std::size_t lumped = good.find('\n', good.find("** RECORD GROUP 11")) + 1;
  std::string unequal = good;
  unequal.replace(good.find(' ', lumped), 0, "1");
  EXPECT_NE(fem_error(unequal).find("RECORD GROUP 11: node 1's masses along x, y and z differ"), std::string::npos)
      << fem_error(unequal);
  const std::size_t rigid = good.find('\n', good.find("** RECORD GROUP 12")) + 1;
  std::string heavier = good;
  heavier.replace(rigid, good.find('\n', rigid) - rigid, "0.65");
  EXPECT_NE(fem_error(heavier).find("RECORD GROUP 12: the rigid body's mass is 0.65"), std::string::npos)
      << fem_error(heavier);
}

// Rejected modes come first in the mode shapes and are skipped: a file
// with one more, rejected, reads to the same model.
TEST(FemModel, RejectedModesAreSkipped) {
  const std::string good = test::text_of(kFem);
  std::string with_rejected = replaced(good, "REV0 17 4 0 6 0", "REV0 17 4 0 7 1");
  const std::string shapes = "** RECORD GROUP 8, MODE SHAPES\n";
  std::string rejected = "**    REJECTED MODE SHAPE # 1\n";
  for (int k = 0; k < 17; ++k) rejected += "9 9 9 9 9 9\n";
  with_rejected.replace(with_rejected.find(shapes) + shapes.size(), 0, rejected);
  const flexible::FemModel a = flexible::read_fem_text(good, "good.fem"),
                           b = flexible::read_fem_text(with_rejected, "rejected.fem");
  EXPECT_EQ(a.shapes, b.shapes);
  EXPECT_EQ(a.stiffness, b.stiffness);
}

TEST(FemModel, ABadModelOrAttachmentIsRefusedAtItsField) {
  const auto error = [](const std::vector<Override>& overrides) {
    try {
      read_scene_file(kScene, overrides);
    } catch (const input::InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string off_node = error({{"bodies.magnetometer.joint.parent_point", "[2.9, 0, 0]"}});
  EXPECT_NE(off_node.find("bodies[1].joint.parent_point"), std::string::npos) << off_node;
  EXPECT_NE(off_node.find("at a node of the FE model"), std::string::npos) << off_node;
  const std::string missing = error({{"bodies.boom.flexible.fem", "nowhere.fem"}});
  EXPECT_NE(missing.find("bodies[0] (boom).flexible.fem"), std::string::npos) << missing;
  EXPECT_NE(missing.find("cannot open"), std::string::npos) << missing;
  const std::string too_many = error({{"bodies.boom.flexible.modes", "11"}});
  EXPECT_NE(too_many.find("11 modes asked, the file has 10"), std::string::npos) << too_many;

  // Free-free modes (the root's constraint modes instead of it held): a
  // rigid motion among them.
  flexible::FemModel free = flexible::read_fem(kFem);
  free.stiffness.row(4).setZero();
  free.stiffness.col(4).setZero();
  flexible::FemBodySpec spec;
  spec.model = std::make_shared<const flexible::FemModel>(free);
  try {
    flexible::fem_body(spec);
    ADD_FAILURE() << "a rigid motion among the modes is refused";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no stiffness"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace unfurl::sim
