// What `unfurl modes` writes: modes.csv (a row per mode: its kind,
// frequency, damping and shape per coordinate, units in the header) and
// modes.json (the state it linearized about and the same modes, each shape
// by coordinate name). Each file is complete or absent.
#pragma once

#include <string>

#include "unfurl/sim/modes.hpp"

namespace unfurl::io {

// `state`: how the state was chosen ("end of the run, settled", ...).
void write_modes_csv(const sim::Scene& scene, const sim::ModesResult& modes, const std::string& path);
void write_modes_json(const sim::Scene& scene, const sim::ModesResult& modes, const std::string& state,
                      const std::string& path);

}  // namespace unfurl::io
