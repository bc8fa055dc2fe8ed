// libunfurl_graphics.so's entry: the table the command line calls through.
#include "graphics_functions.hpp"

namespace unfurl::app {
namespace {

const GraphicsFunctions kFunctions{
    render_command,
#ifdef UNFURL_WITH_GUI
    gui_command,
#else
    nullptr,
#endif
    work_precision_plot_files,
    scaling_plot_files,
    compliance_plot_files,
    stability_plot_files,
    study_plot_files,
};

}  // namespace
}  // namespace unfurl::app

extern "C" __attribute__((visibility("default"))) const unfurl::app::GraphicsFunctions* unfurl_graphics_functions() {
  return &unfurl::app::kFunctions;
}
