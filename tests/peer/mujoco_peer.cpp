// The MuJoCo side of the peer tests (mujoco_runner.hpp does the running):
//
//   unfurl_mujoco_peer MODEL.xml T_END DT SAMPLE OUT_PREFIX
//
// writes OUT_PREFIX.csv (t, q.JOINT..., energy) and OUT_PREFIX_events.csv
// (t, joint). Exits 1 when the model loads with an error or a warning, or
// MuJoCo warns while it runs.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>

#include "mujoco_runner.hpp"

int main(int argc, char** argv) {
  if (argc != 6) {
    std::fprintf(stderr, "usage: unfurl_mujoco_peer MODEL.xml T_END DT SAMPLE OUT_PREFIX\n");
    return 64;
  }
  const std::string prefix = argv[5];
  unfurl::peer::MujocoRun run;
  try {
    run = unfurl::peer::run_mujoco(argv[1], std::atof(argv[2]), std::atof(argv[3]), std::atof(argv[4]));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "unfurl_mujoco_peer: %s\n", e.what());
    return 1;
  }
  std::ofstream csv(prefix + ".csv");
  csv.precision(17);
  csv << "t";
  for (const std::string& joint : run.joints) csv << ",q." << joint;
  csv << ",energy\n";
  for (std::size_t k = 0; k < run.t.size(); ++k) {
    csv << run.t[k];
    for (double q : run.q[k]) csv << ',' << q;
    csv << ',' << run.energy[k] << '\n';
  }
  std::ofstream events(prefix + "_events.csv");
  events.precision(17);
  events << "t,joint\n";
  for (const auto& [t, joint] : run.latches) events << t << ',' << joint << '\n';
  if (run.warnings) {
    std::fprintf(stderr, "unfurl_mujoco_peer: MuJoCo warned %d times while running\n", run.warnings);
    return 1;
  }
  return 0;
}
