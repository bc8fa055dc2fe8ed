// The `unfurl` subcommands. Each returns the process exit code:
// 0 done, 1 the run failed (results so far are written), 2 a bad scene,
// 64 bad usage.
#pragma once

#include <string>
#include <vector>

namespace unfurl::app {

int command_simulate(const std::vector<std::string>& args);
int command_render(const std::vector<std::string>& args);
int command_gui(const std::vector<std::string>& args);
int command_generate(const std::vector<std::string>& args);
int command_report(const std::vector<std::string>& args);
int command_export(const std::vector<std::string>& args);
int command_study(const std::vector<std::string>& args);
int command_modes(const std::vector<std::string>& args);

}  // namespace unfurl::app
