// A one-line progress bar with an ETA on a terminal (stderr); silent when
// stderr is not a terminal.
#pragma once

#include <chrono>
#include <string>

namespace unfurl::app {

class Progress {
 public:
  Progress(std::string label, double total);
  ~Progress();
  // Redraws at most ten times a second; `detail` follows the ETA.
  void update(double done, const std::string& detail = "");
  void finish();

 private:
  std::string label_;
  double total_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace unfurl::app
