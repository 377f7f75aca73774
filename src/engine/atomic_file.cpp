#include "engine/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>

#include "engine/error.hpp"

namespace pdq {

AtomicFile::AtomicFile(std::string path)
    : path_(std::move(path)), tmp_(path_ + ".tmp." + std::to_string(::getpid())) {
  errno = 0;
  out_.open(tmp_, std::ios::binary | std::ios::trunc);
  if (!out_)
    throw Error("cannot write " + path_ + ": cannot create " + tmp_ +
                (errno ? std::string(": ") + std::strerror(errno) : std::string()));
}

AtomicFile::~AtomicFile() {
  if (!done_) {
    out_.close();
    std::remove(tmp_.c_str());
  }
}

static bool syncPath(const std::string& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = ::fsync(fd) == 0;
  ::close(fd);
  return ok;
}

void AtomicFile::commit(bool durable) {
  errno = 0;  // so that a reason given is this write's
  out_.flush();
  bool ok = static_cast<bool>(out_);
  out_.close();
  if (ok && durable && !syncPath(tmp_, O_RDONLY)) ok = false;
  if (!ok) {
    const std::string why = errno ? std::string(": ") + std::strerror(errno) : "";
    std::remove(tmp_.c_str());
    done_ = true;
    throw Error("error while writing " + path_ + why);
  }
  std::error_code ec;
  std::filesystem::rename(tmp_, path_, ec);
  done_ = true;
  if (ec) {
    std::remove(tmp_.c_str());
    throw Error("cannot rename " + tmp_ + " to " + path_ + ": " + ec.message());
  }
  if (durable) {
    std::string dir = std::filesystem::path(path_).parent_path().string();
    if (!syncPath(dir.empty() ? "." : dir, O_RDONLY | O_DIRECTORY))
      throw Error("cannot sync the folder of " + path_ + ": " + std::strerror(errno));
  }
}

void removeStepFiles(const std::string& dir, const std::string& prefix, const std::string& suffix,
                     long step) {
  std::vector<std::filesystem::path> stale;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() <= prefix.size() + suffix.size() || name.rfind(prefix, 0) != 0 ||
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
      continue;
    const std::string digits =
        name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    if (digits.size() > 18 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    if (step < 0 || std::stol(digits) > step) stale.push_back(it->path());
  }
  for (const auto& p : stale) std::filesystem::remove(p, ec);
}

std::vector<std::string> removeStrayTemporaries(const std::string& dir) {
  std::vector<std::string> removed;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    const auto at = name.rfind(".tmp.");
    if (at == std::string::npos || at + 5 == name.size()) continue;
    const std::string pid = name.substr(at + 5);
    if (pid.find_first_not_of("0123456789") != std::string::npos || pid.size() > 10) continue;
    // Only a process that no longer exists left it (kill 0 tests without signalling).
    const long id = std::stol(pid);
    if (id <= 0 || id > std::numeric_limits<pid_t>::max()) continue;
    if (::kill(static_cast<pid_t>(id), 0) == 0 || errno != ESRCH) continue;
    std::error_code rm;
    if (std::filesystem::remove(it->path(), rm)) removed.push_back(name);
  }
  return removed;
}

void writeFileAtomically(const std::string& path, const std::string& content) {
  AtomicFile f(path);
  f.stream() << content;
  f.commit();
}

void createFolder(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(dir, ec)) return;
  fs::create_directories(dir, ec);
  if (!ec) return;
  // A part of the path that exists but is no folder is the likely cause.
  for (fs::path p = fs::path(dir).lexically_normal(); !p.empty() && p != p.parent_path();
       p = p.parent_path()) {
    std::error_code e;
    if (fs::exists(p, e) && !fs::is_directory(p, e))
      throw Error("cannot create the folder " + dir + ": " + p.string() +
                  " is a file, not a folder");
  }
  throw Error("cannot create the folder " + dir + ": " + std::strerror(ec.value()));
}

AppendFile::~AppendFile() {
  if (fd_ >= 0) ::close(fd_);
}

void AppendFile::open(const std::string& path) {
  if (fd_ >= 0) ::close(fd_);
  path_ = path;
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0) throw Error("cannot write " + path + ": " + std::strerror(errno));
}

void AppendFile::write(const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd_, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw Error("error while writing " + path_ + ": " + std::strerror(errno));
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace pdq
