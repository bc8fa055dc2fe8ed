// An MP4 (H.264) encoded by piping raw RGB frames to ffmpeg. The file
// appears only when encoding finished.
#pragma once

#include <cstdio>
#include <string>

#include "unfurl/render/framebuffer.hpp"

namespace unfurl::io {

class VideoPipe {
 public:
  // Throws std::runtime_error when ffmpeg is not installed or cannot start.
  VideoPipe(const std::string& path, int width, int height, double fps);
  ~VideoPipe();  // abandons an unfinished video
  VideoPipe(const VideoPipe&) = delete;
  VideoPipe& operator=(const VideoPipe&) = delete;

  void add(const render::Image& frame);
  // Waits for ffmpeg and moves the video into place; throws on failure.
  void finish();
  // What the caller should tell the user about the video ("" or the padding
  // of an odd size).
  const std::string& note() const { return note_; }

 private:
  std::string encoder_log() const;

  std::string path_, temp_, log_, note_;
  FILE* pipe_ = nullptr;
};

// Whether an executable is on the PATH.
bool on_path(const std::string& program);

}  // namespace unfurl::io
