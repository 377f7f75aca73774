#pragma once
// Stopping a run early but cleanly: SIGTERM, SIGINT, SIGHUP and SIGUSR1 (what batch
// systems send before they kill a job) and a wall-time limit. The run stops at the next
// step boundary, on every rank at the same step, with a checkpoint written there
// (docs/reliability.md). A second signal of the same kind ends pdq at once.
#include <string>

namespace pdq::cli {

class StopRequest {
 public:
  // Installs the signal handlers; `maxWallSeconds` > 0 also stops before that much wall
  // time has passed since the program started.
  explicit StopRequest(double maxWallSeconds);
  ~StopRequest();  // restores the previous handlers
  StopRequest(const StopRequest&) = delete;
  StopRequest& operator=(const StopRequest&) = delete;

  // Called once a step on this rank: 0 to go on, else why to stop: a signal's number, or
  // kWallTime. Ranks disagree until the engine takes the largest over them.
  int poll();
  static constexpr int kWallTime = 1000;
  // "SIGTERM", "the wall-time limit (--max-wall-time)".
  static std::string describe(int code);

 private:
  double maxWall_;
  double start_, last_ = -1, longestStep_ = 0;
};

// Seconds from "3600", "90m", "2h", "1h30m", "45s"; throws a message naming the text.
double parseWallTime(const std::string& text);

}  // namespace pdq::cli
