// The command line's side of the graphics module: it is loaded the first
// time a command draws, from where UNFURL_GRAPHICS_MODULE says (and nowhere
// else when it is set), or else beside the binary that holds this code (the
// build tree's command), in ../lib/unfurl from it (an install), in the
// build tree (its tests and Python module) or in the installed library
// directory. Every candidate is an absolute path: nothing is looked up
// relative to the working directory.
#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "commands.hpp"
#include "graphics_functions.hpp"
#include "study_plots.hpp"

namespace unfurl::app {

namespace {

#ifdef UNFURL_WITH_RENDER
constexpr const char* kModuleFile = "libunfurl_graphics.so";

// The directory of the binary that holds this code: the executable's
// through /proc (dladdr gives only argv[0] for it), a shared object's as
// dladdr names it.
std::filesystem::path binary_directory() {
  std::error_code ec;
  const std::filesystem::path executable = std::filesystem::canonical("/proc/self/exe", ec);
  Dl_info self{};
  if (dladdr(reinterpret_cast<void*>(&binary_directory), &self) && self.dli_fname &&
      std::string(self.dli_fname).find('/') != std::string::npos) {
    const std::filesystem::path object = std::filesystem::canonical(self.dli_fname, ec);
    if (!object.empty() && object != executable) return object.parent_path();
  }
  return executable.empty() ? executable : executable.parent_path();
}

std::vector<std::string> module_candidates() {
  if (const char* chosen = std::getenv("UNFURL_GRAPHICS_MODULE")) return {chosen};
  std::vector<std::string> paths;
  if (const std::filesystem::path here = binary_directory(); !here.empty()) {
    paths.push_back((here / kModuleFile).string());
    paths.push_back((here.parent_path() / "lib" / "unfurl" / kModuleFile).string());
  }
  paths.emplace_back(UNFURL_GRAPHICS_BUILT);
  paths.emplace_back(UNFURL_GRAPHICS_INSTALLED);
  return paths;
}

struct Loaded {
  const GraphicsFunctions* functions = nullptr;
  std::string failure;  // why not, when functions is null
};

// Loaded once and never closed: types the module made (exceptions, plots'
// strings) may outlive any call.
Loaded load() {
  Loaded out;
  std::string looked;
  for (const std::string& path : module_candidates()) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
      looked += "\n  " + path;
      continue;
    }
    void* handle = dlopen(std::filesystem::absolute(path, ec).c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      out.failure = std::string("the graphics module could not be loaded: ") + dlerror();
      return out;
    }
    auto entry = reinterpret_cast<const GraphicsFunctions* (*)()>(dlsym(handle, kGraphicsEntry));
    if (!entry) {
      out.failure = path + " is not unfurl's graphics module (no " + kGraphicsEntry + ")";
      return out;
    }
    out.functions = entry();
    return out;
  }
  out.failure = std::string("the graphics module ") + kModuleFile + " was not found; looked in:" + looked +
                "\n(set UNFURL_GRAPHICS_MODULE to its path)";
  return out;
}

const Loaded& module() {
  static const Loaded loaded = load();
  return loaded;
}
#endif

int not_built(const char* command, const char* option) {
  std::fprintf(stderr,
               "unfurl %s: this unfurl was built without it (configure with -D%s=ON on a machine that has what it "
               "needs; the configure message names what was missing)\n",
               command, option);
  return 69;
}

// The graphics table, or null after saying why on standard error.
const GraphicsFunctions* graphics(const char* command) {
#ifdef UNFURL_WITH_RENDER
  if (module().functions) return module().functions;
  std::fprintf(stderr, "unfurl %s: %s\n", command, module().failure.c_str());
#else
  (void)command;
#endif
  return nullptr;
}

// Without the module the report or study still has its tables and
// markdown; graphics() has said why there are no plots, or this does.
std::vector<std::string> no_plots() {
#ifndef UNFURL_WITH_RENDER
  static bool said = false;
  if (!said) std::fprintf(stderr, "unfurl: no plots: this unfurl was built without the renderer\n");
  said = true;
#endif
  return {};
}

}  // namespace

int command_render(const std::vector<std::string>& args) {
#ifdef UNFURL_WITH_RENDER
  const GraphicsFunctions* g = graphics("render");
  return g ? g->render(args) : 69;
#else
  (void)args;
  return not_built("render", "UNFURL_BUILD_RENDER");
#endif
}

int command_gui(const std::vector<std::string>& args) {
#ifdef UNFURL_WITH_GUI
  const GraphicsFunctions* g = graphics("gui");
  if (!g) return 69;
  if (g->gui) return g->gui(args);
#else
  (void)args;
#endif
  return not_built("gui", "UNFURL_BUILD_GUI");
}

std::vector<std::string> write_work_precision_plots(const sim::Scene& scene, const studies::WorkPrecision& report,
                                                    const std::string& dir) {
  const GraphicsFunctions* g = graphics("report");
  return g ? g->work_precision_plots(scene, report, dir) : no_plots();
}

std::vector<std::string> write_scaling_plots(const ScalingReport& report, const std::string& dir) {
  const GraphicsFunctions* g = graphics("report");
  return g ? g->scaling_plots(report, dir) : no_plots();
}

std::vector<std::string> write_compliance_plots(const ComplianceReport& report, const std::string& dir) {
  const GraphicsFunctions* g = graphics("report");
  return g ? g->compliance_plots(report, dir) : no_plots();
}

std::vector<std::string> write_stability_plots(const StabilityReport& report, const std::string& dir) {
  const GraphicsFunctions* g = graphics("report");
  return g ? g->stability_plots(report, dir) : no_plots();
}

std::vector<std::string> write_study_plots(const io::StudyReport& report, const std::string& dir) {
  const GraphicsFunctions* g = graphics("study");
  return g ? g->study_plots(report, dir) : no_plots();
}

}  // namespace unfurl::app
