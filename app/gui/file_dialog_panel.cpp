// The file browser behind every path field.
#include "gui_panels.hpp"

#include <filesystem>

#include "panel_widgets.hpp"
#include "unfurl/io/output_file.hpp"
#include "unfurl/render/trajectory_plots.hpp"
#include "unfurl/sim/number_text.hpp"

namespace unfurl::app {

namespace {

// The text field a file field is, and what its dialog looks like.
struct FileFieldSpec {
  char* text;
  std::size_t size;
  const char* title;
  FileDialog::Mode mode;
  std::vector<std::string> extensions;
};

FileFieldSpec file_field_spec(GuiState& state, FileField field) {
  ExportForm& f = state.export_form;
  using Mode = FileDialog::Mode;
  switch (field) {
    case FileField::open_scene:
      return {state.scene_path, sizeof state.scene_path, "Open a scene", Mode::open_file, {".yaml", ".yml"}};
    case FileField::save_scene:
      return {state.save_path, sizeof state.save_path, "Save the scene as", Mode::save_file, {".yaml", ".yml"}};
    case FileField::frame:
      return {f.frame_path, sizeof f.frame_path, "Save the frame as", Mode::save_file, {".png"}};
    case FileField::trajectory:
      return {f.csv_path, sizeof f.csv_path, "Save the trajectory as", Mode::save_file, {".csv"}};
    case FileField::export_dir:
      return {f.dir, sizeof f.dir, "Export frames to", Mode::choose_directory, {}};
    case FileField::video:
      return {f.video, sizeof f.video, "Save the video as", Mode::save_file, {".mp4"}};
    case FileField::none:
      break;
  }
  return {nullptr, 0, "", Mode::open_file, {}};
}

}  // namespace

void open_file_dialog(GuiState& state, FileField field) {
  const FileFieldSpec spec = file_field_spec(state, field);
  if (!spec.text) return;
  state.file_field = field;
  state.file_dialog.show(spec.title, spec.mode, spec.text, spec.extensions);
}

void browse_button(GuiState& state, FileField field, const char* id) {
  ImGui::SameLine();
  if (ImGui::Button(id)) open_file_dialog(state, field);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("choose with a file browser");
}

void file_dialog_panel(GuiState& state, Requests& requests) {
  const std::optional<std::string> chosen = state.file_dialog.draw();
  if (!chosen) return;
  // Relative to the working directory when inside it: shorter, and what
  // the user typed before.
  std::error_code ec;
  const std::filesystem::path relative = std::filesystem::relative(*chosen, std::filesystem::current_path(ec), ec);
  const std::string path =
      !ec && !relative.empty() && relative.string().rfind("..", 0) != 0 ? relative.string() : *chosen;
  const FileFieldSpec spec = file_field_spec(state, state.file_field);
  if (spec.text) std::snprintf(spec.text, spec.size, "%s", path.c_str());
  if (state.file_field == FileField::open_scene) requests.open = path;
  state.file_field = FileField::none;
}

}  // namespace unfurl::app
