// Latches: a stop that catches a joint the first time it reaches its
// deployed position and from then on holds it with a stiff spring-damper.
// A latch never lets go.
#pragma once

#include <vector>

namespace unfurl {

struct Latch {
  int joint = 0;
  double position = 0;   // the deployed angle (or length)
  double stiffness = 0;  // k_L
  double damping = 0;    // c_L

  // tau_L = -k_L (q - position) - c_L dq, once engaged.
  double torque(double q, double dq) const {
    return -stiffness * (q - position) - damping * dq;
  }
  double energy(double q) const { return 0.5 * stiffness * (q - position) * (q - position); }
};

// The engagement state of a scene's latches along one run.
class LatchState {
 public:
  // `side` of each latch: the sign of q(0) - position, the side the joint
  // starts on; a latch whose joint starts at its position starts engaged.
  LatchState(const std::vector<Latch>& latches, const std::vector<double>& q0_of_latch);

  // The root function of latch l: s (q - position), crossing zero downwards
  // when the joint reaches the deployed position; +1 once engaged.
  double switching_value(int l, double q) const;
  // Its rate for a joint rate dq (0 once engaged).
  double switching_rate(int l, double dq) const { return engaged_[l] ? 0.0 : side_[l] * dq; }
  bool engaged(int l) const { return engaged_[l] != 0; }
  void engage(int l) { engaged_[l] = 1; }
  int size() const { return static_cast<int>(side_.size()); }
  int engaged_count() const;

 private:
  std::vector<double> side_;
  std::vector<double> position_;
  std::vector<char> engaged_;
};

}  // namespace unfurl
