#pragma once
// Wall-clock timers for the components of the time step (thesis §3.4, timing.out).
#include <array>
#include <chrono>
#include <string>

namespace pdq {

enum class Phase { Setup, Force, Integrate, Communication, Shuffle, Output, Other, Count };
const char* phaseName(Phase p);

class Timers {
 public:
  double& operator[](Phase p) { return t_[static_cast<int>(p)]; }
  double operator[](Phase p) const { return t_[static_cast<int>(p)]; }

  class Scope {
   public:
    Scope(Timers& t, Phase p) : t_(t), p_(p), start_(std::chrono::steady_clock::now()) {}
    ~Scope() {
      t_[p_] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }

   private:
    Timers& t_;
    Phase p_;
    std::chrono::steady_clock::time_point start_;
  };

 private:
  std::array<double, static_cast<int>(Phase::Count)> t_{};
};

}  // namespace pdq
