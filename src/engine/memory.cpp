#include "engine/memory.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace pdq {

double availableMemory() {
  if (const char* limit = std::getenv("PDQ_MEMORY_LIMIT")) {
    char* end = nullptr;
    double v = std::strtod(limit, &end);
    const std::string unit = end ? end : "";
    const double scale = unit == "K"   ? 1e3
                         : unit == "M" ? 1e6
                         : unit == "G" ? 1e9
                         : unit == "T" ? 1e12
                                       : 1.0;
    if (std::isfinite(v) && v > 0) return v * scale;
  }
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0;
  std::string unit;
  while (in >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb * 1024;
  return HUGE_VAL;  // unknown: nothing is refused
}

std::string byteText(double bytes) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (bytes >= 1000 && u < 6) {
    bytes /= 1000;
    ++u;
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, bytes >= 1e4 ? "%.3g %s" : "%.3g %s", bytes, units[u]);
  return buf;
}

double tableBytes(const Schema& s, double local, double owned, double bondEntries) {
  return local * 8 * (1 + s.nFixed() + s.nAlter()) + owned * 8 * s.nInteg() +
         bondEntries * (8 + 4 + 1 + 8 * s.nBond()) + (owned + 1) * 8;
}

void checkParticleCount(double count, double bytesEach, const std::string& what) {
  const double need = count * bytesEach, have = availableMemory();
  if (!(need <= have)) {
    char n[32];
    std::snprintf(n, sizeof n, "%.3g", count);
    throw MemoryError(what + " would make about " + n + " particles, at least " + byteText(need) +
                      " for their attributes alone; this machine has " + byteText(have) +
                      " available (MemAvailable in /proc/meminfo, or PDQ_MEMORY_LIMIT): make "
                      "the lattice coarser or the specimen smaller, or run on more nodes");
  }
}

}  // namespace pdq
