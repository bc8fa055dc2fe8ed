// The layers, one way (docs/ARCHITECTURE.md): read off the sources. The
// solver's public headers show Eigen's core and the standard library only;
// no header of a lower layer includes a higher one; the renderer reads the
// solver's description and trajectory types and never its dynamics.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace unfurl {
namespace {

namespace fs = std::filesystem;

struct Include {
  std::string file, target;
};

std::vector<Include> includes_under(const std::string& relative, bool headers_only) {
  std::vector<Include> out;
  const fs::path root = fs::path(UNFURL_SOURCE_DIR) / relative;
  const std::regex include(R"(^\s*#\s*include\s*[<"]([^>"]+)[>"])");
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".hpp" && (headers_only || ext != ".cpp")) continue;
    std::ifstream in(entry.path());
    for (std::string line; std::getline(in, line);) {
      std::smatch m;
      if (std::regex_search(line, m, include)) out.push_back({entry.path().string(), m[1]});
    }
  }
  EXPECT_FALSE(out.empty()) << "nothing found under " << root;
  return out;
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

bool standard_header(const std::string& target) {
  return target.find('/') == std::string::npos && target.find('.') == std::string::npos;
}

TEST(Layers, SolverPublicHeadersShowOnlyEigensCoreAndTheStandardLibrary) {
  for (const Include& i : includes_under("sim/include", true)) {
    const bool allowed = standard_header(i.target) || starts_with(i.target, "unfurl/sim/") ||
                         i.target == "unfurl/input/input_error.hpp" || i.target == "Eigen/Core" ||
                         i.target == "Eigen/Geometry";
    EXPECT_TRUE(allowed) << i.file << " includes " << i.target;
  }
}

TEST(Layers, SolverIncludesNoHigherLayer) {
  for (const Include& i : includes_under("sim", false))
    EXPECT_FALSE(starts_with(i.target, "unfurl/studies/") || starts_with(i.target, "unfurl/render/"))
        << i.file << " includes " << i.target;
}

TEST(Layers, StudiesIncludeNoRendererOrApplication) {
  for (const Include& i : includes_under("studies", false)) {
    EXPECT_FALSE(starts_with(i.target, "unfurl/render/")) << i.file << " includes " << i.target;
    if (i.target.find('/') == std::string::npos && i.target.find(".hpp") != std::string::npos)
      ADD_FAILURE() << i.file << " includes an application header " << i.target;
  }
}

TEST(Layers, RendererReadsTheSolversDescriptionsNeverItsDynamics) {
  // What the renderer may know of the solver: the mechanism's description
  // (a flexible body's mode shapes, to draw it bent, among it), poses and
  // recorded runs.
  const std::set<std::string> readable{"spatial",      "joint",      "model",       "kinematics", "loop",
                                       "loads",        "scene",      "visuals",     "energy",     "state_layout",
                                       "run_settings", "trajectory", "number_text", "momentum",   "regulator_settings",
                                       "force_element", "elements/latch", "torque_margin_result",
                                       "torque_margin_factors", "flexible/flexible_body"};
  for (const Include& i : includes_under("render", false)) {
    EXPECT_FALSE(starts_with(i.target, "unfurl/studies/")) << i.file << " includes " << i.target;
    if (!starts_with(i.target, "unfurl/sim/")) continue;
    const std::string name = i.target.substr(11, i.target.size() - 11 - 4);
    EXPECT_TRUE(readable.count(name)) << i.file << " includes the solver's " << i.target;
  }
}

TEST(Layers, FilesIncludeNoHigherLayer) {
  // unfurl::io sits above the solver, the studies and the renderer, below
  // the application; the renderer knows no files.
  for (const Include& i : includes_under("io", false))
    if (i.target.find('/') == std::string::npos && i.target.find(".hpp") != std::string::npos)
      ADD_FAILURE() << i.file << " includes an application header " << i.target;
  for (const Include& i : includes_under("render", false))
    EXPECT_FALSE(starts_with(i.target, "unfurl/io/")) << i.file << " includes " << i.target;
}

// Each layer's code is in its own namespace: unfurl::sim, unfurl::studies,
// unfurl::render, unfurl::io, unfurl::app (unfurl::input below them all).
TEST(Layers, EachLayerHasItsNamespace) {
  const std::regex opening(R"(^namespace (unfurl[a-z_:]*) \{)");
  for (const std::string layer : {"input", "sim", "studies", "render", "io", "app"}) {
    const fs::path root = fs::path(UNFURL_SOURCE_DIR) / layer;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".hpp" && ext != ".cpp") continue;
      std::ifstream in(entry.path());
      for (std::string line; std::getline(in, line);) {
        std::smatch m;
        if (!std::regex_search(line, m, opening)) continue;
        EXPECT_TRUE(starts_with(m[1].str(), "unfurl::" + layer)) << entry.path() << " opens " << m[1];
      }
    }
  }
}

}  // namespace
}  // namespace unfurl
