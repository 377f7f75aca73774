#include "engine/timers.hpp"

#include <algorithm>
#include <cstdio>
#include <ctime>

namespace pdq {

double processCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

const char* phaseName(Phase p) {
  switch (p) {
    case Phase::Setup:
      return "setup";
    case Phase::Force:
      return "force";
    case Phase::Integrate:
      return "integrate";
    case Phase::Communication:
      return "communication";
    case Phase::Shuffle:
      return "shuffle";
    case Phase::Output:
      return "output";
    case Phase::Other:
      return "other";
    default:
      return "?";
  }
}

void Timers::start() {
  started_ = std::chrono::steady_clock::now();
  startedCpu_ = processCpuSeconds();
}

void Timers::settleOther() {
  const int other = static_cast<int>(Phase::Other);
  double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  double cpu = processCpuSeconds() - startedCpu_;
  for (int p = 0; p < static_cast<int>(Phase::Count); ++p)
    if (p != other) wall -= t_[p], cpu -= cpu_[p];
  t_[other] = std::max(0.0, wall);
  cpu_[other] = std::max(0.0, cpu);
}

std::string cpuBreakdown(const Timers& t, double loopCpu) {
  std::string s;
  double rest = loopCpu;
  char buf[64];
  for (Phase p :
       {Phase::Force, Phase::Integrate, Phase::Communication, Phase::Shuffle, Phase::Output}) {
    std::snprintf(buf, sizeof buf, "%s=%.3f ", phaseName(p), t.cpu(p));
    s += buf;
    rest -= t.cpu(p);
  }
  std::snprintf(buf, sizeof buf, "other=%.3f", rest);
  return s + buf;
}

}  // namespace pdq
