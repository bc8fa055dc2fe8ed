// The commands a build left out: they say so and how to build them.
#include <cstdio>

#include "commands.hpp"

namespace unfurl::app {

namespace {

int not_built(const char* command, const char* option) {
  std::fprintf(stderr,
               "unfurl %s: this unfurl was built without it (configure with -D%s=ON on a machine that has what it "
               "needs; the configure message names what was missing)\n",
               command, option);
  return 69;
}

}  // namespace

#ifndef UNFURL_WITH_RENDER
int command_render(const std::vector<std::string>&) { return not_built("render", "UNFURL_BUILD_RENDER"); }
#endif
#ifndef UNFURL_WITH_GUI
int command_gui(const std::vector<std::string>&) { return not_built("gui", "UNFURL_BUILD_GUI"); }
#endif

}  // namespace unfurl::app
