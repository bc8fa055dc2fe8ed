#include "gui_script.hpp"

#include "unfurl/render/camera_frame.hpp"

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace unfurl::app {

std::vector<ScriptCommand> read_gui_script(const std::string& path) {
  // Command -> (least, most) arguments.
  static const std::map<std::string, std::pair<int, int>> arity{
      {"wait", {1, 1}},   {"idle", {1, 1}},   {"wait_run", {0, 0}},   {"play", {0, 0}},       {"pause", {0, 0}},
      {"speed", {1, 1}},  {"loop", {1, 1}},       {"scrub", {1, 1}},      {"camera", {1, 1}},
      {"set", {2, 2}},    {"screenshot", {1, 1}}, {"save_frame", {1, 1}}, {"export", {4, 5}},
      {"wait_export", {0, 0}}, {"cancel_export", {0, 0}}, {"report", {1, 1}}, {"open", {1, 1}}, {"case", {1, 1}}, {"undo", {0, 0}}, {"redo", {0, 0}}, {"save_scene", {1, 1}}, {"plot", {1, 1}},
      {"pin", {0, 8}}, {"orthographic", {1, 1}}, {"loads", {1, 2}}, {"exaggerate", {1, 1}}, {"camera_frame", {1, 1}}, {"ui_scale", {1, 1}}, {"browse", {1, 1}}, {"unpin", {1, 1}}, {"zoom", {1, 2}}, {"curves", {1, 1000}}, {"modes", {0, 0}}, {"mode", {1, 1}}, {"quit", {0, 0}}};
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the script");
  std::vector<ScriptCommand> commands;
  std::string text;
  for (int n = 1; std::getline(in, text); ++n) {
    std::istringstream words(text);
    ScriptCommand c;
    c.line = n;
    if (!(words >> c.name) || c.name[0] == '#') continue;
    for (std::string w; words >> w;) c.args.push_back(w);
    const auto it = arity.find(c.name);
    if (it == arity.end()) throw std::runtime_error(path + ":" + std::to_string(n) + ": unknown command '" + c.name + "'");
    const int count = static_cast<int>(c.args.size());
    if (count < it->second.first || count > it->second.second)
      throw std::runtime_error(path + ":" + std::to_string(n) + ": wrong number of arguments for '" + c.name + "'");
    if (c.name == "loads" && ((c.args[0] != "on" && c.args[0] != "off") ||
                              (c.args.size() > 1 && !(std::strtod(c.args[1].c_str(), nullptr) > 0))))
      throw std::runtime_error(path + ":" + std::to_string(n) + ": loads: expected on or off and a scale > 0");
    if (c.name == "camera_frame" && !render::parse_camera_frame(c.args[0]))
      throw std::runtime_error(path + ":" + std::to_string(n) + ": camera_frame: expected bus or inertial");
    commands.push_back(c);
  }
  return commands;
}

}  // namespace unfurl::app
