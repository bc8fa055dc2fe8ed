#include "output_file.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace unfurl::app {

OutputFile::OutputFile(std::string path)
    : path_(std::move(path)), temp_(path_ + ".partial-" + std::to_string(::getpid())), out_(temp_) {
  if (!out_) throw std::runtime_error(path_ + ": cannot write (" + temp_ + ")");
  out_.precision(17);
}

OutputFile::~OutputFile() {
  if (!committed_) {
    out_.close();
    std::remove(temp_.c_str());
  }
}

void OutputFile::commit() {
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok || std::rename(temp_.c_str(), path_.c_str()) != 0) {
    std::remove(temp_.c_str());
    throw std::runtime_error(path_ + ": writing failed");
  }
  committed_ = true;
}

void make_directory(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error(dir + ": cannot create the directory (" + ec.message() + ")");
}

}  // namespace unfurl::app
