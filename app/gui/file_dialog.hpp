// A small file browser for the workbench's open, save and export fields: a
// modal popup listing a directory (folders first, then the files with the
// wanted extensions), a path field to type or paste into, up and home.
// Debian packages no ImGui file dialog, so this is the project's own.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace unfurl::app {

struct DirectoryEntry {
  std::string name;
  bool directory = false;
};

// The entries of `dir`: folders, then files whose name ends with one of
// `extensions` (all files when empty), each group sorted by name; hidden
// ones (a leading dot) left out. Throws std::filesystem::filesystem_error
// when the directory cannot be read.
std::vector<DirectoryEntry> directory_entries(const std::filesystem::path& dir,
                                              const std::vector<std::string>& extensions);

class FileDialog {
 public:
  enum class Mode { open_file, save_file, choose_directory };

  // Shows the dialog from the next frame, in the folder of `start` (a file
  // or a folder; the working directory when empty or missing); a save
  // dialog offers start's file name.
  void show(const std::string& title, Mode mode, const std::string& start, std::vector<std::string> extensions);

  // Draws the dialog while it is shown. Returns the chosen path once, when
  // the user picks one (double click, or Open/Save/Choose).
  std::optional<std::string> draw();

  bool shown() const { return visible_; }
  const std::string& title() const { return title_; }

 private:
  void enter(const std::filesystem::path& dir);

  std::string title_;
  Mode mode_ = Mode::open_file;
  std::vector<std::string> extensions_;
  std::filesystem::path dir_;
  std::vector<DirectoryEntry> entries_;
  std::string error_;  // why the folder could not be listed
  char dir_field_[512] = "";
  char name_field_[256] = "";
  bool visible_ = false, open_popup_ = false, focus_name_ = false;
};

}  // namespace unfurl::app
