#pragma once
// Timers for the components of the time step (thesis §3.4, timing.out): the wall clock
// and the process's CPU time of each phase (on a shared machine the CPU time is the work
// done; the wall clock also counts waiting for a core).
#include <array>
#include <chrono>
#include <string>

namespace pdq {

enum class Phase { Setup, Force, Integrate, Communication, Shuffle, Output, Other, Count };
const char* phaseName(Phase p);

// CPU seconds of this process (every thread).
double processCpuSeconds();

class Timers;
// "force=F integrate=I communication=C shuffle=S output=O other=R" in CPU seconds, R the
// part of `loopCpu` (the CPU time of the steps) outside the phases: reductions, checks.
std::string cpuBreakdown(const Timers& t, double loopCpu);

class Timers {
 public:
  double& operator[](Phase p) { return t_[static_cast<int>(p)]; }
  double operator[](Phase p) const { return t_[static_cast<int>(p)]; }
  double cpu(Phase p) const { return cpu_[static_cast<int>(p)]; }

  class Scope {
   public:
    Scope(Timers& t, Phase p)
        : t_(t), p_(p), start_(std::chrono::steady_clock::now()), cpu0_(processCpuSeconds()) {}
    ~Scope() {
      t_[p_] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
      t_.cpu_[static_cast<int>(p_)] += processCpuSeconds() - cpu0_;
    }

   private:
    Timers& t_;
    Phase p_;
    std::chrono::steady_clock::time_point start_;
    double cpu0_;
  };

 private:
  std::array<double, static_cast<int>(Phase::Count)> t_{}, cpu_{};
};

}  // namespace pdq
