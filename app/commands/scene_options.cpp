#include "scene_options.hpp"

#include <cstdio>
#include <filesystem>

#include "unfurl/io/study_files.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/scene_validation.hpp"

namespace unfurl::app {

const std::set<std::string>& scene_flags() {
  static const std::set<std::string> flags{"--set",  "--t-end", "--integrator", "--linear-solver",
                                           "--rtol", "--atol",  "--dt",         "--sample"};
  return flags;
}

const char* scene_flags_help() {
  return "  SCENE                 a scene file (.yaml) or a built-in scene name; default: pantograph\n"
         "  --set KEY=VALUE       override any value of the scene by its path in the file, e.g.\n"
         "                        --set springs.j1.free_position=1.2 or --set regulator.v_max=1000;\n"
         "                        list elements by index or by name/joint/body; repeatable\n"
         "  --t-end T             simulate from 0 to T seconds (run.t_end)\n"
         "  --integrator NAME     cvode-bdf (default), cvode-adams, arkode-erk, arkode-dirk, rk4\n"
         "  --linear-solver NAME  Newton systems of cvode-bdf and arkode-dirk: dense (finite-difference\n"
         "                        Jacobian, LU), krylov (GMRES, O(N) preconditioner), auto (dense up\n"
         "                        to 100 states; run.linear_solver)\n"
         "  --rtol X              relative tolerance of the adaptive integrators (run.rtol)\n"
         "  --atol X              absolute tolerance of the joint angles (run.atol); lengths, momenta\n"
         "                        and regulator states in the mechanism's own sizes\n"
         "  --dt X                step of the fixed-step rk4 (run.dt)\n"
         "  --sample DT           output interval in seconds (run.sample, default 0.01)\n";
}

sim::SceneFile read_scene(const std::optional<std::string>& argument, const Args& args) {
  sim::SceneFile file = read_scene_named(argument.value_or("pantograph"), overrides_from(args));
  for (const std::string& warning : sim::scene_warnings(file.scene))
    std::fprintf(stderr, "unfurl: warning: %s: %s\n", file.scene.source.c_str(), warning.c_str());
  return file;
}

sim::Scene load_scene(const std::optional<std::string>& argument, const Args& args) {
  return read_scene(argument, args).scene;
}

std::vector<sim::Override> overrides_from(const Args& args) {
  std::vector<sim::Override> overrides;
  for (const std::string& s : args.all("--set")) overrides.push_back(sim::parse_override(s));
  // The run flags are overrides of the run section, validated like the file.
  const std::pair<const char*, const char*> run_flags[] = {{"--t-end", "t_end"},
                                                           {"--integrator", "integrator"},
                                                           {"--linear-solver", "linear_solver"},
                                                           {"--rtol", "rtol"},
                                                           {"--atol", "atol"},
                                                           {"--dt", "dt"},
                                                           {"--sample", "sample"}};
  for (const auto& [flag, key] : run_flags)
    if (const auto value = args.get(flag)) overrides.push_back({std::string("run.") + key, *value});
  return overrides;
}

std::string scene_text_named(const std::string& name) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(name, ec)) return io::read_text_file(name);
  return sim::builtin_scene_text(name);
}

sim::SceneFile read_scene_named(const std::string& name, const std::vector<sim::Override>& overrides) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(name, ec)) return sim::read_scene_file(name, overrides);
  const auto builtins = sim::builtin_scene_names();
  if (std::find(builtins.begin(), builtins.end(), name) != builtins.end())
    return sim::read_builtin_scene(name, overrides);
  std::string known;
  for (const auto& n : builtins) known += (known.empty() ? "" : ", ") + n;
  throw input::InputError(name + ": no such scene file, and no built-in scene of that name (built in: " + known + ")");
}

}  // namespace unfurl::app
