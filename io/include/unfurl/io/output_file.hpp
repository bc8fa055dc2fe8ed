// Output files are written completely or not at all: text goes to a
// temporary file beside the target, renamed over it on commit().
#pragma once

#include <fstream>
#include <stdexcept>
#include <string>

namespace unfurl::io {

// An output file or directory that cannot be written (exit status 73).
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class OutputFile {
 public:
  explicit OutputFile(std::string path);
  ~OutputFile();  // removes the temporary file unless committed
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  std::ostream& stream() { return out_; }
  // Flushes and renames into place; throws OutputError on failure.
  void commit();

 private:
  std::string path_, temp_;
  std::ofstream out_;
  bool committed_ = false;
};

// Creates the directory (and its parents); throws on failure.
void make_directory(const std::string& dir);

}  // namespace unfurl::io
