// Numbers as text for files another program reads back: scene overrides,
// generated scenes, CSV and JSON.
#pragma once

#include <string>

namespace unfurl::sim {

// The shortest text that reads back as the same double; "nan"/"inf" kept.
std::string format_number(double x);

}  // namespace unfurl::sim
