// libFuzzer target for the scene loader and the --set parser. The input is
// a scene file; its lines that start with "#set " are also given as
// overrides (KEY=VALUE), as `unfurl simulate --set` would. Whatever the
// input, loading ends in a scene or a input::InputError: any other exception, a
// crash, a hang or a sanitizer report is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "unfurl/sim/scene_file.hpp"

namespace {

std::vector<unfurl::sim::Override> overrides_in(const std::string& text) {
  std::vector<unfurl::sim::Override> overrides;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("#set ", 0) == 0) overrides.push_back(unfurl::sim::parse_override(line.substr(5)));
  return overrides;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const unfurl::sim::SceneFile file = unfurl::sim::read_scene_text(text, "fuzz.yaml", overrides_in(text));
    if (file.scene.model.nq <= 0) std::abort();  // the loader promises something to integrate
  } catch (const unfurl::input::InputError&) {
    // The answer to bad input.
  } catch (const std::exception& e) {
    std::fprintf(stderr, "not a input::InputError: %s\n", e.what());
    std::abort();
  }
  return 0;
}
