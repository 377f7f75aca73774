#include "engine/timers.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace pdq {
namespace {

using namespace std::chrono_literals;

double sum(const Timers& t) {
  double s = 0;
  for (int p = 0; p < static_cast<int>(Phase::Count); ++p) s += t[static_cast<Phase>(p)];
  return s;
}

// The quasi-static relaxation is timed as integrate and calls the force inside: the force's
// time is the force's alone.
TEST(Timers, InnerScopesAreNotCountedTwice) {
  Timers t;
  {
    Timers::Scope outer(t, Phase::Integrate);
    std::this_thread::sleep_for(10ms);
    {
      Timers::Scope inner(t, Phase::Force);
      std::this_thread::sleep_for(60ms);
    }
    std::this_thread::sleep_for(10ms);
  }
  EXPECT_GE(t[Phase::Force], 0.06);
  EXPECT_GE(t[Phase::Integrate], 0.02);
  EXPECT_LT(t[Phase::Integrate], t[Phase::Force]);  // without the inner 60 ms
  {
    Timers::Scope again(t, Phase::Integrate);  // a scope after a nest adds to its phase
    std::this_thread::sleep_for(10ms);
  }
  EXPECT_GE(t[Phase::Integrate], 0.03);
  EXPECT_LT(t[Phase::Integrate], t[Phase::Force]);
}

// `other` is the time since start() outside every phase: the phases add up to the run.
TEST(Timers, OtherIsTheRestOfTheRun) {
  Timers t;
  const auto begin = std::chrono::steady_clock::now();
  t.start();
  std::this_thread::sleep_for(30ms);  // outside every phase
  {
    Timers::Scope s(t, Phase::Force);
    std::this_thread::sleep_for(20ms);
  }
  t.settleOther();
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  EXPECT_GE(t[Phase::Other], 0.03);
  EXPECT_GE(t[Phase::Force], 0.02);
  EXPECT_LE(sum(t), elapsed);
  EXPECT_GE(sum(t), 0.05);
  // Settled again, `other` is replaced, not added to.
  t.settleOther();
  EXPECT_LE(sum(t),
            std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count());
}

}  // namespace
}  // namespace pdq
