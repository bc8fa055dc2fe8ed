// Export of the frame, of frames or video of a range, and of the
// trajectory.
#include "gui_panels.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "panel_widgets.hpp"
#include "unfurl/io/output_file.hpp"
#include "unfurl/render/trajectory_plots.hpp"
#include "unfurl/sim/number_text.hpp"

namespace unfurl::app {

void export_panel(GuiState& state, Requests& requests) {
  ExportForm& f = state.export_form;
  char* frame_path = f.frame_path;
  char* csv_path = f.csv_path;
  char* dir = f.dir;
  char* video = f.video;
  float& from = f.from;
  float& to = f.to;
  float& fps = f.fps;
  int* size = f.size;
  bool& with_video = f.with_video;
  bool& frames = f.frames;
  if (to <= 0) to = static_cast<float>(state.scene.run.t_end);

  ImGui::SetNextItemWidth(em(200));
  ImGui::InputInt2("size [px]", size);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("of a saved frame and of exported frames and video");
  ImGui::SetNextItemWidth(em(260));
  ImGui::InputText("##frame", frame_path, sizeof f.frame_path);
  browse_button(state, FileField::frame, "...##frame");
  ImGui::SameLine();
  if (ImGui::Button("Save frame (PNG)")) requests.save_frame = std::string(frame_path);

  ImGui::SetNextItemWidth(em(260));
  ImGui::InputText("##csv", csv_path, sizeof f.csv_path);
  browse_button(state, FileField::trajectory, "...##csv");
  ImGui::SameLine();
  if (ImGui::Button("Save trajectory (CSV)")) requests.save_trajectory = std::string(csv_path);

  ImGui::Separator();
  ImGui::TextUnformatted("Frames or video of a time range");
  ImGui::SetNextItemWidth(em(200));
  ImGui::InputFloat("from [s]", &from, 0.1f, 1.0f, "%.3f");
  ImGui::SetNextItemWidth(em(200));
  ImGui::InputFloat("to [s]", &to, 0.1f, 1.0f, "%.3f");
  ImGui::SetNextItemWidth(em(200));
  ImGui::InputFloat("fps", &fps, 1, 10, "%.1f");
  ImGui::SetNextItemWidth(em(260));
  ImGui::InputText("##directory", dir, sizeof f.dir);
  browse_button(state, FileField::export_dir, "...##dir");
  ImGui::SameLine();
  ImGui::TextUnformatted("directory");
  ImGui::Checkbox("PNG frames", &frames);
  ImGui::SameLine();
  ImGui::Checkbox("video", &with_video);
  if (with_video) {
    ImGui::SetNextItemWidth(em(260));
    ImGui::InputText("##video", video, sizeof f.video);
    browse_button(state, FileField::video, "...##video");
    ImGui::SameLine();
    ImGui::TextUnformatted("video file");
  }
  const ExportProgress& ex = state.export_progress;
  if (ex.active) {
    ImGui::ProgressBar(ex.total ? float(ex.done) / ex.total : 0.0f, ImVec2(-em(90), 0));
    ImGui::SameLine();
    if (ImGui::Button("Cancel##export")) requests.cancel_export = true;
  } else if (ImGui::Button("Export")) {
    ExportRequest r;
    r.dir = dir;
    r.frames = frames;
    r.options.from = from;
    r.options.to = to;
    r.options.fps = std::max(1.0f, fps);
    r.options.width = std::clamp(size[0], 16, 8192);
    r.options.height = std::clamp(size[1], 16, 8192);
    if (with_video) r.options.video = std::string(video);
    requests.export_range = r;
  }
  if (!ex.message.empty()) ImGui::TextWrapped("%s", ex.message.c_str());
}

}  // namespace unfurl::app
