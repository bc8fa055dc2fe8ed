#include "unfurl/io/output_file.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace unfurl::io {

OutputFile::OutputFile(std::string path)
    : path_(std::move(path)), temp_(path_ + ".partial-" + std::to_string(::getpid())), out_(temp_) {
  if (!out_) throw OutputError(path_ + ": cannot write (" + temp_ + ")");
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
    throw OutputError(path_ + ": writing failed");
  }
  committed_ = true;
}

void make_directory(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw OutputError(dir + ": cannot create the output directory (" + ec.message() + ")");
  if (!fs::is_directory(dir, ec)) throw OutputError(dir + ": not a directory (a file is in its place)");
  // Before any work: a directory that exists but cannot be written would
  // otherwise fail only when the results are ready.
  const fs::path probe = fs::path(dir) / (".unfurl_write_check." + std::to_string(::getpid()));
  {
    std::ofstream test(probe);
    if (!test) throw OutputError(dir + ": cannot write into the output directory");
  }
  fs::remove(probe, ec);
}

}  // namespace unfurl::io
