#include "progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace unfurl::app {

Progress::Progress(std::string label, double total)
    : label_(std::move(label)),
      total_(total),
      enabled_(::isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

Progress::~Progress() { finish(); }

void Progress::update(double done, const std::string& detail) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  drawn_ = true;
  const double fraction = total_ > 0 ? std::min(1.0, done / total_) : 1.0;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const int width = 30, filled = static_cast<int>(fraction * width);
  std::string bar(filled, '#');
  bar.resize(width, '.');
  if (fraction > 0.001)
    std::fprintf(stderr, "\r%s [%s] %5.1f%%  %.1f s, ETA %.1f s  %-28.28s", label_.c_str(), bar.c_str(), 100 * fraction,
                 elapsed, elapsed * (1 - fraction) / fraction, detail.c_str());
  else
    std::fprintf(stderr, "\r%s [%s] %5.1f%%  %.1f s  %-28.28s", label_.c_str(), bar.c_str(), 100 * fraction, elapsed,
                 detail.c_str());
  std::fflush(stderr);
}

void Progress::finish() {
  if (!enabled_ || !drawn_) return;
  std::fprintf(stderr, "\r%*s\r", 120, "");
  std::fflush(stderr);
  drawn_ = false;
}

}  // namespace unfurl::app
