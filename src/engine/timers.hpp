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
  // The clocks of `other` start (a run's set-up).
  void start();
  // The wall clock and CPU time since start() outside every phase's scope, as the phase
  // `other` (reductions, checks, work no phase names).
  void settleOther();

  // A phase's scope. Scopes nest: the time of an inner scope is its phase's alone, not the
  // enclosing one's (the quasi-static relaxation, timed as integrate, calls the force).
  class Scope {
   public:
    Scope(Timers& t, Phase p) : t_(t), p_(p), outer_(t.top_) {
      const Time now = std::chrono::steady_clock::now();
      const double cpu = processCpuSeconds();
      if (outer_) outer_->charge(now, cpu);
      t_.top_ = this;
      start_ = now, cpu0_ = cpu;
    }
    ~Scope() {
      const Time now = std::chrono::steady_clock::now();
      const double cpu = processCpuSeconds();
      charge(now, cpu);
      t_.top_ = outer_;
      if (outer_) outer_->start_ = now, outer_->cpu0_ = cpu;
    }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    using Time = std::chrono::steady_clock::time_point;
    void charge(Time now, double cpu) {
      t_[p_] += std::chrono::duration<double>(now - start_).count();
      t_.cpu_[static_cast<int>(p_)] += cpu - cpu0_;
    }
    Timers& t_;
    Phase p_;
    Scope* outer_;
    Time start_;
    double cpu0_ = 0;
  };

 private:
  std::array<double, static_cast<int>(Phase::Count)> t_{}, cpu_{};
  Scope* top_ = nullptr;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  double startedCpu_ = processCpuSeconds();
};

}  // namespace pdq
