// A scene: the mechanism (tree, force elements, loops, regulator), its
// initial state and how to run it. What the renderer draws is apart
// (visuals.hpp).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "unfurl/sim/elements/latch.hpp"
#include "unfurl/sim/force_element.hpp"
#include "unfurl/sim/loop.hpp"
#include "unfurl/sim/model.hpp"
#include "unfurl/sim/regulator_settings.hpp"
#include "unfurl/sim/run_settings.hpp"
#include "unfurl/sim/sensor.hpp"
#include "unfurl/sim/torque_margin_factors.hpp"

namespace unfurl::sim {

struct Scene {
  std::string name;
  std::string description;
  std::string source;  // the file it came from, or "built-in"
  Model model;
  // Everything that applies force, in the order their forces add up.
  std::vector<std::shared_ptr<const ForceElement>> elements;
  std::vector<Loop> loops;
  // What the run measures at points of bodies, besides the loads.
  std::vector<Sensor> sensors;
  RegulatorSettings regulator;
  std::vector<double> q0;     // per position coordinate
  std::vector<double> dq0;    // per velocity coordinate (used when p0 is empty)
  std::vector<double> p0;     // per velocity coordinate, optional
  // How far the initial loops may be open: rad, and for a distance times
  // the mechanism's length (MechanismScales).
  double closure_tolerance = 1e-6;
  RunSettings run;
  // How the driven joints' torque margins are weighed (torque_margin.hpp).
  TorqueMarginFactors torque_margin;

  // The elements of one kind, in scene order.
  template <class Element>
  std::vector<const Element*> elements_of() const {
    std::vector<const Element*> out;
    for (const auto& e : elements)
      if (const auto* x = dynamic_cast<const Element*>(e.get())) out.push_back(x);
    return out;
  }
  // The latches, in the order of their events (LatchEvent::latch).
  std::vector<const Latch*> latches() const { return elements_of<Latch>(); }
  // Uniform gravity (base frame), zero without it.
  Vec3 gravity() const;
  // The load columns of the elements (loads.hpp), one per name in the
  // order first named; with `of_element`, which columns each element writes.
  std::vector<LoadColumn> load_columns(std::vector<std::vector<int>>* of_element = nullptr) const;
  // The peaks its elements ask a run to keep, on load_columns()' columns.
  std::vector<TrackedPeak> element_peaks() const;
  // The peaks of the sensors' readings, on sensor_columns(sensors).
  std::vector<TrackedPeak> sensor_peaks() const;
  // The --set path of element k ("springs.j1", or "springs.3" where its
  // handle is shared or missing), and every path that names it (by index,
  // and by handle where no other element of its list shares it).
  std::string element_path(std::size_t k) const { return element_paths(k).back(); }
  std::vector<std::string> element_paths(std::size_t k) const;
};

}  // namespace unfurl::sim
