#include "cli/progress.hpp"

#include <algorithm>
#include <cmath>

namespace pdq::cli {

std::string duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  const long s = std::lround(seconds);
  char buf[48];
  if (s < 60)
    std::snprintf(buf, sizeof buf, "%ld s", s);
  else if (s < 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  return buf;
}

std::string Progress::line(long step, long firstStep, long lastStep, double dt, double particles,
                           double seconds) {
  const long done = step - firstStep, total = lastStep - firstStep;
  const double rate = seconds > 0 ? particles * done / seconds : 0;
  const double toGo = done > 0 ? seconds / done * (lastStep - step) : NAN;
  char buf[200];
  if (done <= 0 && step < lastStep) {
    std::snprintf(buf, sizeof buf, "step %ld/%ld (0%%)  t = %.6g  %.0f particles", step, lastStep,
                  step * dt, particles);
    return buf;
  }
  std::snprintf(buf, sizeof buf, "step %ld/%ld (%.0f%%)  t = %.6g  %.3g particle-steps/s  %s", step,
                lastStep, total > 0 ? 100.0 * done / total : 100.0, step * dt, rate,
                step >= lastStep ? ("took " + duration(seconds)).c_str()
                                 : (duration(toGo) + " to go").c_str());
  return buf;
}

std::string Progress::loadLine(long step, const LoadStatus& s, double fromFraction,
                               double seconds) {
  const double done = s.fraction - fromFraction;
  const double toGo = done > 0 ? seconds / done * (1 - s.fraction) : NAN;
  char buf[320];
  std::snprintf(buf, sizeof buf, "load step %ld  %s (%.0f%%)  %s", step, s.text.c_str(),
                100 * s.fraction,
                s.fraction >= 1 ? ("took " + duration(seconds)).c_str()
                                : (duration(toGo) + " to go").c_str());
  return buf;
}

Progress::Progress(bool show, bool terminal, double particles, long firstStep, long lastStep,
                   double dt, std::function<LoadStatus()> status)
    : show_(show),
      terminal_(terminal),
      particles_(particles),
      dt_(dt),
      first_(firstStep),
      last_(lastStep),
      nextLogStep_(firstStep),
      start_(Clock::now()),
      lastPrint_(start_),
      status_(std::move(status)) {
  if (status_) {
    fromFraction_ = status_().fraction;
    return;  // nothing to tell before the first load step
  }
  if (show_) print(first_, false);
}

void Progress::update(long step) {
  if (show_ && status_) {
    print(step, false);  // load steps are few and slow: each one is told
    return;
  }
  if (!show_ || step >= last_) return;  // finish() prints the last step
  const auto now = Clock::now();
  const double since = std::chrono::duration<double>(now - lastPrint_).count();
  if (terminal_ ? since >= 0.25 : (step >= nextLogStep_ || since >= 60)) print(step, false);
}

void Progress::finish(long step) {
  if (!show_) return;
  print(step, true);
}

void Progress::print(long step, bool final) {
  lastPrint_ = Clock::now();
  const double seconds = std::chrono::duration<double>(lastPrint_ - start_).count();
  const std::string text = status_ ? loadLine(step, status_(), fromFraction_, seconds)
                                   : line(step, first_, last_, dt_, particles_, seconds);
  if (terminal_) {
    // Rewrite the line in place, padding over a longer previous one.
    std::printf("\r%s%*s", text.c_str(),
                static_cast<int>(width_ > text.size() ? width_ - text.size() : 0), "");
    width_ = text.size();
    if (final) std::printf("\n");
  } else {
    std::printf("%s\n", text.c_str());
    const long tenth = std::max(1L, (last_ - first_) / 10);
    nextLogStep_ = step + tenth;
  }
  std::fflush(stdout);
}

}  // namespace pdq::cli
