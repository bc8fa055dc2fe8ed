// The status bar: simulated and wall time, steps, right-hand sides,
// real-time factor.
#include "gui_panels.hpp"

#include <cstdio>

#include "panel_widgets.hpp"
#include "unfurl/io/output_file.hpp"
#include "unfurl/render/trajectory_plots.hpp"
#include "unfurl/sim/number_text.hpp"

namespace unfurl::app {

void status_bar(const GuiState& state) {
  const RunProgress& p = state.progress;
  const double factor = p.wall_time_s > 0 ? p.t_reached / p.wall_time_s : 0;
  const sim::RunSettings& run = state.scene.run;
  ImGui::Text(
      "simulated %.3f / %.3g s | wall %.3f s | %ld steps | %ld RHS | %.1fx real time | %s rtol %.0e | %s | UI %.0f fps",
      p.t_reached, run.t_end, p.wall_time_s, p.steps, p.rhs_calls, factor, sim::integrator_name(run.integrator),
      run.rtol, p.running ? "running" : sim::run_status_name(p.status), state.fps);
  if (!state.notice.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("| %s", state.notice.c_str());
  }
}

}  // namespace unfurl::app
