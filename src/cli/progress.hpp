#pragma once
// Progress of a run, printed by rank 0: on a terminal one line rewritten in place
//     step 1200/5000 (24%)  t = 0.06  2.1e+06 particle-steps/s  1:12 to go
// and otherwise (a batch job's log) the same as plain lines, one per tenth of the run
// and at least one a minute. A quasi-static run tells its load steps instead,
//     load step 12  load factor 0.6 (60%)  load 1.2e+04  displacement 0.003  residual 8e-07  0:40
//     to go
// on a terminal rewritten in place, otherwise one line per load step.
#include <chrono>
#include <cstdio>
#include <functional>
#include <string>

namespace pdq::cli {

enum class Verbosity { Quiet, Normal, Verbose };

class Progress {
 public:
  // `particles`: the problem's total; steps firstStep+1 .. lastStep will be run.
  // `status` (quasi-static runs): what the last load step reached, asked for after each
  // load step instead of counting steps.
  struct LoadStatus {
    double fraction = 0;  // of the full load
    std::string text;     // the rest of the line
  };
  Progress(bool show, bool terminal, double particles, long firstStep, long lastStep, double dt,
           std::function<LoadStatus()> status = {});
  void update(long step);  // after each step
  void finish(long step);  // ends the line (terminal) and prints the last one
  // The quasi-static line for `step`, `fromFraction` of the load having been applied when
  // this run began `seconds` ago (exposed for tests).
  static std::string loadLine(long step, const LoadStatus& s, double fromFraction, double seconds);

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
  std::function<LoadStatus()> status_;
  double fromFraction_ = 0;
};

// "1:02:03", "4:05" or "6 s".
std::string duration(double seconds);

}  // namespace pdq::cli
