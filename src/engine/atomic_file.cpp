#include "engine/atomic_file.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "engine/error.hpp"

namespace pdq {

AtomicFile::AtomicFile(std::string path)
    : path_(std::move(path)), tmp_(path_ + ".tmp." + std::to_string(::getpid())) {
  out_.open(tmp_, std::ios::binary | std::ios::trunc);
  if (!out_) throw Error("cannot write " + path_ + ": cannot create " + tmp_);
}

AtomicFile::~AtomicFile() {
  if (!done_) {
    out_.close();
    std::remove(tmp_.c_str());
  }
}

void AtomicFile::commit() {
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok) {
    std::remove(tmp_.c_str());
    done_ = true;
    throw Error("error while writing " + path_);
  }
  std::error_code ec;
  std::filesystem::rename(tmp_, path_, ec);
  done_ = true;
  if (ec) {
    std::remove(tmp_.c_str());
    throw Error("cannot rename " + tmp_ + " to " + path_ + ": " + ec.message());
  }
}

void writeFileAtomically(const std::string& path, const std::string& content) {
  AtomicFile f(path);
  f.stream() << content;
  f.commit();
}

}  // namespace pdq
