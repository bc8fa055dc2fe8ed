#include "file_dialog.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace unfurl::app {

namespace fs = std::filesystem;

std::vector<DirectoryEntry> directory_entries(const fs::path& dir, const std::vector<std::string>& extensions) {
  std::vector<DirectoryEntry> folders, files;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, fs::directory_options::skip_permission_denied)) {
    const std::string name = e.path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    std::error_code ec;
    if (e.is_directory(ec)) {
      folders.push_back({name, true});
      continue;
    }
    const bool wanted = extensions.empty() || std::any_of(extensions.begin(), extensions.end(), [&](const std::string& x) {
                          return name.size() >= x.size() && name.compare(name.size() - x.size(), x.size(), x) == 0;
                        });
    if (wanted) files.push_back({name, false});
  }
  const auto by_name = [](const DirectoryEntry& a, const DirectoryEntry& b) { return a.name < b.name; };
  std::sort(folders.begin(), folders.end(), by_name);
  std::sort(files.begin(), files.end(), by_name);
  folders.insert(folders.end(), files.begin(), files.end());
  return folders;
}

void FileDialog::show(const std::string& title, Mode mode, const std::string& start, std::vector<std::string> extensions) {
  title_ = title;
  mode_ = mode;
  extensions_ = std::move(extensions);
  std::error_code ec;
  fs::path path = start.empty() ? fs::current_path(ec) : fs::absolute(start, ec);
  fs::path dir = fs::is_directory(path, ec) ? path : path.parent_path();
  if (!fs::is_directory(dir, ec)) dir = fs::current_path(ec);
  std::snprintf(name_field_, sizeof name_field_, "%s",
                mode == Mode::save_file && !fs::is_directory(path, ec) ? path.filename().string().c_str() : "");
  enter(dir);
  visible_ = open_popup_ = focus_name_ = true;
}

void FileDialog::enter(const fs::path& dir) {
  dir_ = dir.lexically_normal();
  std::snprintf(dir_field_, sizeof dir_field_, "%s", dir_.string().c_str());
  try {
    entries_ = directory_entries(dir_, extensions_);
    if (mode_ == Mode::choose_directory)
      entries_.erase(std::remove_if(entries_.begin(), entries_.end(), [](const DirectoryEntry& e) { return !e.directory; }),
                     entries_.end());
    error_.clear();
  } catch (const fs::filesystem_error& e) {
    entries_.clear();
    error_ = e.what();
  }
}

std::optional<std::string> FileDialog::draw() {
  if (!visible_) return std::nullopt;
  if (open_popup_) ImGui::OpenPopup(title_.c_str()), open_popup_ = false;
  std::optional<std::string> chosen;
  const float font = ImGui::GetFontSize();
  ImGui::SetNextWindowSize(ImVec2(40 * font, 28 * font), ImGuiCond_Appearing);
  bool keep = true;
  if (!ImGui::BeginPopupModal(title_.c_str(), &keep)) {
    visible_ = keep && ImGui::IsPopupOpen(title_.c_str());
    return std::nullopt;
  }
  if (ImGui::Button("Up")) enter(dir_.parent_path());
  ImGui::SameLine();
  if (ImGui::Button("Home")) {
    const char* home = std::getenv("HOME");
    enter(home ? fs::path(home) : dir_);
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1);
  if (ImGui::InputText("##dir", dir_field_, sizeof dir_field_, ImGuiInputTextFlags_EnterReturnsTrue))
    enter(fs::path(dir_field_));
  if (!error_.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", error_.c_str());
  const float footer = 2.4f * ImGui::GetFrameHeightWithSpacing();
  ImGui::BeginChild("entries", ImVec2(0, -footer), true);
  for (const DirectoryEntry& e : entries_) {
    const std::string label = e.directory ? e.name + "/" : e.name;
    const bool selected = !e.directory && e.name == name_field_;
    if (ImGui::Selectable(label.c_str(), selected, ImGuiSelectableFlags_AllowDoubleClick)) {
      if (e.directory && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
        enter(dir_ / e.name);
        break;  // the list just changed under the loop
      }
      if (!e.directory) {
        std::snprintf(name_field_, sizeof name_field_, "%s", e.name.c_str());
        if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) chosen = (dir_ / e.name).string();
      }
    }
  }
  if (entries_.empty() && error_.empty()) ImGui::TextDisabled("(nothing here)");
  ImGui::EndChild();
  if (mode_ != Mode::choose_directory) {
    // Typing a name works at once: the field has the keyboard when the dialog opens.
    // (Not on the popup's first frame: opening it takes the focus then.)
    if (focus_name_ && !ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere(), focus_name_ = false;
    ImGui::SetNextItemWidth(-1);
    if (ImGui::InputText("##name", name_field_, sizeof name_field_, ImGuiInputTextFlags_EnterReturnsTrue) &&
        name_field_[0] != 0)
      chosen = (dir_ / name_field_).string();
  }
  const char* action = mode_ == Mode::open_file ? "Open" : mode_ == Mode::save_file ? "Save" : "Choose this folder";
  const bool ready = mode_ == Mode::choose_directory || name_field_[0] != 0;
  ImGui::BeginDisabled(!ready);
  if (ImGui::Button(action))
    chosen = mode_ == Mode::choose_directory ? dir_.string() : (dir_ / name_field_).string();
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) keep = false;
  if (chosen || !keep) {
    visible_ = false;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
  return chosen;
}

}  // namespace unfurl::app
