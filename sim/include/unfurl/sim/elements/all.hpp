// Every kind of force element, for code that names kinds (the scene file's
// reader and writer, the MJCF export).
#pragma once

#include "unfurl/sim/elements/applied_force.hpp"
#include "unfurl/sim/elements/bushing.hpp"
#include "unfurl/sim/elements/gravity.hpp"
#include "unfurl/sim/elements/joint_compliance.hpp"
#include "unfurl/sim/elements/joint_damper.hpp"
#include "unfurl/sim/elements/joint_driver.hpp"
#include "unfurl/sim/elements/joint_friction.hpp"
#include "unfurl/sim/elements/joint_limit.hpp"
#include "unfurl/sim/elements/joint_spring.hpp"
#include "unfurl/sim/elements/joint_stop.hpp"
#include "unfurl/sim/elements/latch.hpp"
#include "unfurl/sim/elements/point_spring.hpp"
