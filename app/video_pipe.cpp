#include "video_pipe.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace unfurl::app {

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && ::access((dir + "/" + program).c_str(), X_OK) == 0) return true;
  return false;
}

namespace {
std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}
}  // namespace

VideoPipe::VideoPipe(const std::string& path, int width, int height, double fps)
    : path_(path), temp_(path + ".partial-" + std::to_string(::getpid()) + ".mp4"), log_(temp_ + ".log") {
  if (!on_path("ffmpeg"))
    throw std::runtime_error("cannot encode " + path + ": ffmpeg is not installed (Debian package ffmpeg)");
  std::ostringstream command;
  command << "ffmpeg -y -loglevel error -f rawvideo -pix_fmt rgb24 -s " << width << "x" << height << " -r " << fps
          << " -i - -c:v libx264 -preset medium -crf 20 -pix_fmt yuv420p -movflags +faststart " << quoted(temp_)
          << " 2>" << quoted(log_);
  pipe_ = ::popen(command.str().c_str(), "w");
  if (!pipe_) throw std::runtime_error("cannot start ffmpeg for " + path);
}

VideoPipe::~VideoPipe() {
  if (pipe_) ::pclose(pipe_);
  std::remove(temp_.c_str());
  std::remove(log_.c_str());
}

void VideoPipe::add(const render::Image& frame) {
  if (std::fwrite(frame.rgb.data(), 1, frame.rgb.size(), pipe_) != frame.rgb.size())
    throw std::runtime_error("ffmpeg stopped taking frames for " + path_);
}

void VideoPipe::finish() {
  const int status = ::pclose(pipe_);
  pipe_ = nullptr;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::ifstream log(log_);
    std::stringstream text;
    text << log.rdbuf();
    throw std::runtime_error("ffmpeg failed to encode " + path_ + ": " + text.str());
  }
  if (std::rename(temp_.c_str(), path_.c_str()) != 0) throw std::runtime_error("cannot move the video to " + path_);
}

}  // namespace unfurl::app
