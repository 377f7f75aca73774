#include "cli/stop.hpp"

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <stdexcept>

namespace pdq::cli {

namespace {

volatile std::sig_atomic_t caught = 0;
const int kSignals[] = {SIGTERM, SIGINT, SIGHUP, SIGUSR1};
struct sigaction previous[4];

extern "C" void onSignal(int sig) { caught = sig; }

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// The wall time of a batch job counts from its start: take the time as the program loads.
const double programStart = now();

}  // namespace

StopRequest::StopRequest(double maxWallSeconds) : maxWall_(maxWallSeconds), start_(programStart) {
  caught = 0;
  struct sigaction sa {};
  sa.sa_handler = onSignal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESETHAND | SA_RESTART;  // a second signal takes the default action
  for (int k = 0; k < 4; ++k) sigaction(kSignals[k], &sa, &previous[k]);
}

StopRequest::~StopRequest() {
  for (int k = 0; k < 4; ++k) sigaction(kSignals[k], &previous[k], nullptr);
}

int StopRequest::poll() {
  if (caught) return caught;
  if (maxWall_ <= 0) return 0;
  // Stop when one more step and a checkpoint as long as the longest step so far (a step
  // that wrote outputs) might not finish within the limit.
  const double t = now();
  if (last_ >= 0) longestStep_ = std::max(longestStep_, t - last_);
  last_ = t;
  return t - start_ + 2 * longestStep_ >= maxWall_ ? kWallTime : 0;
}

std::string StopRequest::describe(int code) {
  if (code == kWallTime) return "the wall-time limit (--max-wall-time)";
  switch (code) {
    case SIGTERM:
      return "SIGTERM";
    case SIGINT:
      return "SIGINT";
    case SIGHUP:
      return "SIGHUP";
    case SIGUSR1:
      return "SIGUSR1";
  }
  return "signal " + std::to_string(code);
}

double parseWallTime(const std::string& text) {
  const std::string bad =
      "--max-wall-time: '" + text + "' is not a duration (seconds, or e.g. 90m, 2h, 1h30m, 45s)";
  double total = 0;
  std::size_t at = 0;
  bool any = false;
  while (at < text.size()) {
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(text.substr(at), &used);
    } catch (const std::exception&) {
      throw std::invalid_argument(bad);
    }
    if (!std::isfinite(v) || v < 0 || text[at] == '+' || text[at] == '-')
      throw std::invalid_argument(bad);
    at += used;
    double unit = 1;
    if (at < text.size()) {
      const char u = text[at++];
      unit = u == 'h' ? 3600 : u == 'm' ? 60 : u == 's' ? 1 : -1;
      if (unit < 0) throw std::invalid_argument(bad);
    } else if (any) {
      throw std::invalid_argument(bad);  // "1h30": the 30 of what?
    }
    total += v * unit;
    any = true;
  }
  if (!any || !(total > 0)) throw std::invalid_argument(bad);
  return total;
}

}  // namespace pdq::cli
