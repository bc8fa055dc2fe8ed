// The modes of a scene about the state its command-line flags ask for
// (`unfurl modes`, `unfurl render --mode`): where a run ends (settled to its
// static equilibrium), a run's state at --at T, or --q positions.
#pragma once

#include <set>
#include <string>

#include "cli.hpp"
#include "unfurl/sim/modes.hpp"

namespace unfurl::app {

// --at, --q; and --settle, --no-settle.
const std::set<std::string>& modes_state_flags();
const std::set<std::string>& modes_state_switches();
// Their help lines.
const char* modes_state_help();

// Computes the modes into `modes` and says how the state was chosen in
// `described`; returns 0, or the exit status of a failure it has reported
// (1: the run or the linearization failed; an interrupt's). Throws
// UsageError for bad flags.
int scene_modes(const sim::Scene& scene, const Args& args, sim::ModesResult& modes, std::string& described);

}  // namespace unfurl::app
