#pragma once
// Output files are written whole or not at all: content goes to a temporary file beside
// the target, which is renamed over it only when complete.
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

}  // namespace pdq
