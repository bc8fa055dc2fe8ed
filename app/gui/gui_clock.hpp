// Clock and file times for the workbench's loop, hot reload and playback.
#pragma once

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>

namespace unfurl::app {

// Seconds on a steady clock.
inline double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// When a file was last written, or nothing for a file that is not there.
inline std::optional<std::filesystem::file_time_type> modification_time(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  const auto t = std::filesystem::last_write_time(path, ec);
  return ec ? std::nullopt : std::optional(t);
}

}  // namespace unfurl::app
