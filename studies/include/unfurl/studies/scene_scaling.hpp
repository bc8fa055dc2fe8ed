// A scene in other units: every length x L and every mass x M, time
// unchanged. By dimensional analysis the scaled mechanism's angles are the
// same functions of time; a solver whose answers depend on the units shows
// it here (the unit-invariance tests, docs/stability).
#pragma once

#include "unfurl/sim/scene_file.hpp"

namespace unfurl::studies {

// Bodies (masses, centres of mass, inertias; a flexible body's structure,
// reduced again, and its elastic coordinates, x L sqrt(M)), joints'
// points, the base's velocity, initial lengths and momenta, force elements
// (ForceElement::scaled) and the visuals; the regulator's and the run's
// settings are dimensionless or in time and stay.
sim::SceneFile scale_scene(const sim::SceneFile& file, double L, double M);

}  // namespace unfurl::studies
