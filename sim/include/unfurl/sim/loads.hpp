// The loads an engineer sizes hardware with, at one instant: what each force
// element reports (its load columns: a spring's torque, a cable's tension),
// the wrench the parent transmits to the child through each joint, and per
// loop component the regulator's constraint force.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "unfurl/sim/spatial.hpp"

namespace unfurl::sim {

// A column of loads.csv (and of the GUI's loads): what a force element
// reports at each sample. Elements that report the same name share the
// column and their values add (two springs on one hinge give one spring
// torque).
struct LoadColumn {
  std::string name;   // "spring_torque.j1"
  std::string unit;   // "N m"
  std::string frame;  // "" for a scalar (a torque about its joint's axis)
  int joint = -1;     // the joint it is listed with, or -1 (after the joints)
};

// The index of the column called `name`, or -1.
int find_load_column(const std::vector<LoadColumn>& columns, const std::string& name);

// A peak the run keeps of an element's loads (or a sensor's readings)
// over every step: the magnitude of `count` of its columns from `first` (a
// bushing's force, x..z), in summary.json under `quantity`, by the
// element's handle (the sensor's name).
struct ElementPeak {
  std::string quantity;  // "peak_bushing_force"
  int first = 0, count = 1;
};

// Such a peak placed among a run's columns: the magnitude of some load
// columns (or sensor columns).
struct TrackedPeak {
  std::string quantity, name, unit;  // "peak_bushing_force", the element's handle, "N"
  std::vector<int> columns;          // of the run's load columns
};

// Loads of a mechanism without loops are always determinate; a step where
// the sparse analysis could not factor the closure system is not assessed
// (closure_rank.hpp, sparse_closure_rank.hpp in the sources).
enum class Determinacy { determinate, indeterminate, not_assessed };

struct Loads {
  // Per load column of the run (Dynamics::load_columns, Trajectory::load_columns).
  std::vector<double> element;
  // Per joint (every joint, fixed ones too): the wrench from the parent on
  // the child, force (N) and moment (N m) about the hinge point, in the
  // child body's frame. Its component along a hinge's axis is the sum of
  // the torques its elements apply.
  std::vector<Vec6> reaction;
  // Per active loop component: the force on the split body from its image
  // (its negative acts on the image), at the body's origin, in its frame.
  std::vector<double> loop_force;
  // The sensors' readings (Dynamics::sensor_columns).
  std::vector<double> sensor;
  // Whether the motion determines the loop forces, and with them the
  // reactions inside the loops (closure_rank.hpp). Where it does not, the
  // reactions and loop forces are the minimum-norm ones.
  Determinacy determinacy = Determinacy::determinate;
  // The loops' independent equations here (ClosureRank::rank); -1 where
  // not counted (no loops, or the sparse analysis).
  int closure_rank = -1;
};

// The largest magnitude a quantity took and when.
struct Peak {
  double value = 0;
  double t = std::numeric_limits<double>::quiet_NaN();
  void update(double x, double at) {
    if (x > value || std::isnan(t)) value = x, t = at;
  }
};

// Peaks over every step the integrator took (not only the samples: a latch's
// shock lasts milliseconds), and the largest geometric loop gap. The
// reactions' peaks are kept apart where the loads are determinate and where
// they are not (Loads::determinacy): there they are the minimum-norm ones,
// with the rigid loads running into and out of those spans, which the rigid
// model does not bound (determinate_peak.hpp in the sources).
struct RunPeaks {
  std::vector<Peak> latch_torque;   // per latch, |tau_L|
  std::vector<Peak> hinge_force;    // per joint, |f| of the reaction, maxima over determinate steps
  std::vector<Peak> hinge_moment;   // per joint, |m| about the hinge point, likewise
  std::vector<Peak> hinge_force_indeterminate;  // the same over the indeterminate steps and run-ups
  std::vector<Peak> hinge_moment_indeterminate;
  // [t0, t1]: from the first to the last step of each run of indeterminate
  // steps.
  std::vector<std::array<double, 2>> indeterminate_spans;
  bool loads_assessed = true;  // false if some step's were not (Determinacy::not_assessed)
  // The closure system's rank at the start and its lowest over the steps
  // (a branch point), with when; -1 where not assessed.
  int closure_rank_at_start = -1;
  int lowest_closure_rank = -1;
  double lowest_closure_rank_t = std::numeric_limits<double>::quiet_NaN();
  std::vector<Peak> element;        // per Scene::element_peaks()
  std::vector<Peak> sensor;         // per Scene::sensor_peaks()
  Peak gap_m, gap_rad;              // over all loops
  Peak gap_m_before_latch, gap_rad_before_latch;
};

// The time inside spans [t0, t1] (RunPeaks::indeterminate_spans).
double total_time(const std::vector<std::array<double, 2>>& spans);

// The name of loop component axis a: fx, fy, fz, mx, my, mz.
const char* wrench_component_name(int axis);

}  // namespace unfurl::sim
