#pragma once
// Progress of a run, printed by rank 0: on a terminal one line rewritten in place
//     step 1200/5000 (24%)  t = 0.06  2.1e+06 particle-steps/s  1:12 to go
// and otherwise (a batch job's log) the same as plain lines, one per tenth of the run
// and at least one a minute.
#include <chrono>
#include <cstdio>
#include <string>

namespace pdq::cli {

enum class Verbosity { Quiet, Normal, Verbose };

class Progress {
 public:
  // `particles`: the problem's total; steps firstStep+1 .. lastStep will be run.
  Progress(bool show, bool terminal, double particles, long firstStep, long lastStep, double dt);
  void update(long step);  // after each step
  void finish(long step);  // ends the line (terminal) and prints the last one

  // The line for `step` after `seconds` of stepping (exposed for tests).
  static std::string line(long step, long firstStep, long lastStep, double dt, double particles,
                          double seconds);

 private:
  void print(long step, bool final);
  using Clock = std::chrono::steady_clock;
  bool show_, terminal_;
  double particles_, dt_;
  long first_, last_, nextLogStep_;
  Clock::time_point start_, lastPrint_;
  std::size_t width_ = 0;
};

// "1:02:03", "4:05" or "6 s".
std::string duration(double seconds);

}  // namespace pdq::cli
