// The files a run writes and reads back: loads.csv has the columns the
// scene has and reads back beside trajectory.csv into the same loads.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "support.hpp"
#include "unfurl/io/run_columns.hpp"
#include "unfurl/io/run_files.hpp"

namespace unfurl {
namespace {

// Every header cell of every file, for every built-in scene (with a sensor
// of every quantity): no comma, so any CSV reader splits it as the rows.
TEST(RunFiles, NoHeaderCellHoldsAComma) {
  for (const std::string& name : sim::builtin_scene_names()) {
    // The last rigid body carries the sensor (flexible bodies carry none yet).
    const sim::Model model = sim::load_builtin_scene(name).model;
    std::string body;
    for (const sim::Body& b : model.bodies)
      if (!b.flexible) body = b.name;
    sim::Scene scene = sim::load_builtin_scene(
        name, {{"run.t_end", "0.02"},
               {"sensors", "[{name: s, body: " + body +
                               ", frame: inertial, measure: [position, velocity, acceleration, angular_rate, "
                               "angular_acceleration]}]"}});
    const sim::RunResult run = sim::simulate(scene, scene.run);
    for (const auto& columns : {io::trajectory_columns(scene, run.trajectory),
                                io::load_file_columns(scene, run.trajectory),
                                io::sensor_file_columns(run.trajectory)})
      for (const io::RunColumn& c : columns)
        EXPECT_EQ(io::header_cell(c).find(','), std::string::npos) << name << ": " << io::header_cell(c);
  }
}

TEST(LoadsFile, HasTheColumnsTheSceneHasAndReadsBack) {
  // The pantograph: springs and latches on j1..j8 only, reactions on every
  // joint, nine loop-force components.
  namespace fs = std::filesystem;
  const sim::Scene scene = test::scene_file("pantograph", {{"run.t_end", "0.2"}, {"run.sample", "0.05"}});
  const sim::RunResult run = sim::simulate(scene, scene.run);
  const fs::path dir = fs::temp_directory_path() / ("unfurl_loads_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  io::write_trajectory_csv(scene, run.trajectory, (dir / "trajectory.csv").string());
  io::write_loads_csv(scene, run.trajectory, (dir / "loads.csv").string());
  std::ifstream in(dir / "loads.csv");
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header.find("t [s],determinate,spring_torque.j1 [N m],damper_torque.j1 [N m],latch_torque.j1 [N m],"
                        "hinge_force.j1.x [N; child body frame],"),
            0u)
      << header;
  EXPECT_EQ(header.find("spring_torque.j9"), std::string::npos) << "no spring on a cross pivot";
  EXPECT_NE(header.find(",hinge_moment.j9.z [N m; child body frame about the hinge point],"), std::string::npos);
  EXPECT_NE(header.find(",loop_force.A1.y [N; split body frame],loop_force.A1.z [N; split body frame],"
                        "loop_moment.A1.x [N m; split body frame],"),
            std::string::npos)
      << header;
  const sim::Trajectory back = io::read_trajectory_csv(scene, (dir / "trajectory.csv").string());
  ASSERT_EQ(back.samples.size(), run.trajectory.samples.size());
  EXPECT_EQ(back.loop_components.size(), 9u);
  for (std::size_t k = 0; k < back.samples.size(); ++k) {
    EXPECT_EQ(back.samples[k].loads.determinacy, run.trajectory.samples[k].loads.determinacy);
    for (int j = 0; j < scene.model.size(); ++j) {
      EXPECT_EQ(back.samples[k].loads.reaction[j], run.trajectory.samples[k].loads.reaction[j]);
      const std::string spring = "spring_torque." + scene.model.joints[j].name;
      if (sim::find_load_column(run.trajectory.load_columns, spring) < 0) continue;
      EXPECT_EQ(test::load_of(back.load_columns, back.samples[k].loads, spring),
                test::load_of(run.trajectory.load_columns, run.trajectory.samples[k].loads, spring));
    }
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace unfurl
