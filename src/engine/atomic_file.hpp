#pragma once
// Output files are written whole or not at all: content goes to a temporary file beside
// the target, which is renamed over it only when complete. Files that grow during a run
// (time histories, debug.txt) are appended to with one write call per chunk of whole
// lines, so a run killed at any moment leaves every chunk it wrote, and whole.
#include <fstream>
#include <string>

namespace pdq {

class AtomicFile {
 public:
  explicit AtomicFile(std::string path);
  ~AtomicFile();  // removes the temporary if commit() was never called
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return out_; }
  void commit();  // flushes, checks for write errors, renames into place
  const std::string& path() const { return path_; }

 private:
  std::string path_, tmp_;
  std::ofstream out_;
  bool done_ = false;
};

void writeFileAtomically(const std::string& path, const std::string& content);

class AppendFile {
 public:
  AppendFile() = default;
  ~AppendFile();
  AppendFile(const AppendFile&) = delete;
  AppendFile& operator=(const AppendFile&) = delete;

  void open(const std::string& path);  // for appending (created if missing)
  bool isOpen() const { return fd_ >= 0; }
  // Straight to the file (no buffer in this process): what was written survives a kill.
  void write(const std::string& text);

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace pdq
