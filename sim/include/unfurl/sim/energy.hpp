// The mechanism's energy at one instant, by where it is stored.
#pragma once

namespace unfurl {

struct EnergyParts {
  double kinetic = 0;
  double springs = 0;
  double latches = 0;
  double gravity = 0;
  double regulator = 0;
  double unattributed = 0;  // energy known only as a total (a trajectory read back from a file)
  double total() const { return kinetic + springs + latches + gravity + regulator + unattributed; }
};

}  // namespace unfurl
