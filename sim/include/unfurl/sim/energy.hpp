// The mechanism's energy at one instant, by where it is stored.
#pragma once

namespace unfurl::sim {

struct EnergyParts {
  double kinetic = 0;
  double springs = 0;
  double latches = 0;
  double gravity = 0;
  double regulator = 0;
  double unattributed = 0;  // energy known only as a total (a trajectory read back from a file)
  // Work the dampers, friction and latches have taken out since t = 0: not
  // part of the total; total() + dissipated is what the run conserves
  // (without external loads).
  double dissipated = 0;
  // Work the drivers have put in since t = 0 (joint_driver.hpp): total() +
  // dissipated - driven is what a driven run conserves.
  double driven = 0;
  double total() const { return kinetic + springs + latches + gravity + regulator + unattributed; }
  double balance() const { return total() + dissipated - driven; }
};

}  // namespace unfurl::sim
