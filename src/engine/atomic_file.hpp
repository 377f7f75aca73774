#pragma once
// Output files are written whole or not at all: content goes to a temporary file beside
// the target, which is renamed over it only when complete. Files that grow during a run
// (time histories, debug.txt) are appended to with one write call per chunk of whole
// lines, so a run killed at any moment leaves every chunk it wrote, and whole.
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace pdq {

class AtomicFile {
 public:
  explicit AtomicFile(std::string path);
  ~AtomicFile();  // removes the temporary if commit() was never called
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return out_; }
  // Flushes, checks for write errors, renames into place. `durable`: the content is on the
  // disk (fsync) before the rename, and the rename is (fsync of the folder) when it returns,
  // so a crash of the machine leaves the old file or the new one, never an empty one.
  void commit(bool durable = false);
  const std::string& path() const { return path_; }
  // Where the content is until commit(): to read back what was written (flush first).
  const std::string& temporaryPath() const { return tmp_; }

 private:
  std::string path_, tmp_;
  std::ofstream out_;
  bool done_ = false;
};

void writeFileAtomically(const std::string& path, const std::string& content);

// Removes the files in `dir` named `prefix<step>suffix` (the step a whole number, with
// or without leading zeros) whose step is after `step`, or every one when `step` < 0:
// outputs of an earlier run in a reused folder, which would look newer than this run's.
void removeStepFiles(const std::string& dir, const std::string& prefix, const std::string& suffix,
                     long step);

// Removes the temporaries (`NAME.tmp.PID`) in `dir` of processes no longer running on this
// machine, which a kill while writing leaves behind; returns their names.
std::vector<std::string> removeStrayTemporaries(const std::string& dir);

// Creates the folder `dir` and its parents (nothing if it exists); an Error naming the
// folder and the reason otherwise: "cannot create the folder a/out: a is a file, not a
// folder", or the system's reason ("Permission denied", "Read-only file system").
void createFolder(const std::string& dir);

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
