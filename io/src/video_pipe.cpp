#include "unfurl/io/video_pipe.hpp"

#include "unfurl/io/output_file.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace unfurl::io {

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && ::access((dir + "/" + program).c_str(), X_OK) == 0) return true;
  return false;
}

namespace {
std::string shell_quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}
}  // namespace

VideoPipe::VideoPipe(const std::string& path, int width, int height, double fps)
    : path_(path), temp_(path + ".partial-" + std::to_string(::getpid()) + ".mp4"), log_(temp_ + ".log") {
  if (!on_path("ffmpeg"))
    throw std::runtime_error("cannot encode " + path + ": ffmpeg is not installed (Debian package ffmpeg)");
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (!folder.empty()) make_directory(folder.string());
  // H.264 in yuv420p needs even sizes: an odd one gets a black row or
  // column of padding, and the caller says so (note()).
  if (width % 2 || height % 2)
    note_ = "the video is " + std::to_string(width + width % 2) + "x" + std::to_string(height + height % 2) +
            " (H.264 needs even sizes: padded with black by one pixel)";
  std::ostringstream command;
  command << "ffmpeg -y -loglevel error -f rawvideo -pix_fmt rgb24 -s " << width << "x" << height << " -r " << fps
          << " -i - -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' -c:v libx264 -preset medium -crf 20 -pix_fmt yuv420p "
          << "-movflags +faststart " << shell_quoted(temp_) << " 2>" << shell_quoted(log_);
  pipe_ = ::popen(command.str().c_str(), "w");
  if (!pipe_) throw std::runtime_error("cannot start ffmpeg for " + path);
}

VideoPipe::~VideoPipe() {
  if (pipe_) ::pclose(pipe_);
  std::remove(temp_.c_str());
  std::remove(log_.c_str());
}

// The encoder's own words, for an error message.
std::string VideoPipe::encoder_log() const {
  std::ifstream log(log_);
  std::stringstream text;
  text << log.rdbuf();
  std::string words = text.str();
  while (!words.empty() && words.back() == '\n') words.pop_back();
  return words.empty() ? "(ffmpeg said nothing)" : words;
}

void VideoPipe::add(const render::Image& frame) {
  // A pipe whose reader is gone fails the write with EPIPE rather than
  // killing the process: main() ignores SIGPIPE.
  if (std::fwrite(frame.rgb.data(), 1, frame.rgb.size(), pipe_) != frame.rgb.size() || std::fflush(pipe_) != 0) {
    ::pclose(pipe_);
    pipe_ = nullptr;
    throw std::runtime_error("ffmpeg stopped taking frames for " + path_ + ": " + encoder_log());
  }
}

void VideoPipe::finish() {
  const int status = ::pclose(pipe_);
  pipe_ = nullptr;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("ffmpeg failed to encode " + path_ + ": " + encoder_log());
  if (std::rename(temp_.c_str(), path_.c_str()) != 0) throw std::runtime_error("cannot move the video to " + path_);
}

}  // namespace unfurl::io
