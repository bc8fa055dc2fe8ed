// A study's PNG plots, drawn by the graphics module (none without it).
#pragma once

#include <string>
#include <vector>

#include "unfurl/io/study_files.hpp"

namespace unfurl::app {

// Writes them into dir; returns their file names.
std::vector<std::string> write_study_plots(const io::StudyReport& report, const std::string& dir);

}  // namespace unfurl::app
