// An mplm2d run restarted from a step in the load ramp, from one in the hold (after the
// hold-phase damping was computed), and from the last step of a shorter run (another
// `--steps`) ends with the same bits as the uninterrupted run: the load protocol runs in
// simulated time and the integrator's state travels in State.<step>.rst. A run whose
// length is given as [loading] hold_time instead of steps (steps < 0 in the engine) lasts
// ramp_time + hold_time in whole steps, rounded up, and is the same run, through the
// thesis's files and from a restart too.
#include "io/restart.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/standard_outputs.hpp"
#include "io/thesis_input.hpp"
#include "scenario/scenario.hpp"
#include "support/harness.hpp"

namespace pdq {
namespace {

int rank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

// A small tension plate, damaged, ramped over 200 steps, then held with damping. It runs
// `steps` steps or, when `holdTime` is given, the ramp and a hold of `holdTime` seconds.
Scenario plateScenario(const std::string& dir, long steps, const std::string& holdTime = "") {
  const std::string path = dir + ".toml";
  if (rank() == 0) {
    std::ofstream f(path);
    if (holdTime.empty()) f << "steps = " << steps << "\n";
    f << R"([model]
name = "mplm2d"
dt = 1.808e-7
[loading]
load_scale = 4
ramp_time = 3.616e-5
hold_damping_ratio = 1
)";
    if (!holdTime.empty()) f << "hold_time = " << holdTime << "\n";
    f << R"([particles]
generator = "mplm_plate"
width = 0.1
height = 0.12
[output]
restart_every = 100
)";
  }
  MPI_Barrier(MPI_COMM_WORLD);
  return readScenario(path);
}

Problem plate(const std::string& dir, long steps, const std::string& holdTime = "") {
  Problem pb = std::move(plateScenario(dir, steps, holdTime).problem);
  pb.run.outDir = dir;
  return pb;
}

// Runs the problem, which must end at step `last`.
test::State run(Problem pb, long last = 400) {
  Comm comm;
  const auto sim = makeSimulation(std::move(pb), comm);
  sim->run();
  EXPECT_EQ(sim->step(), last);
  return test::gatherState(*sim);
}

// Ramp and hold of 200 steps each: the 400-step run.
const char* const hold200 = "3.616e-5";

class MplmRestart : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (rank() == 0)
      for (const char* d : {"mplm_restart_full", "mplm_restart_short", "mplm_restart_again",
                            "mplm_restart_hold", "mplm_restart_hold_dat"})
        std::filesystem::remove_all(d);
    MPI_Barrier(MPI_COMM_WORLD);
    full_ = new test::State(run(plate("mplm_restart_full", 400)));
  }
  static void TearDownTestSuite() { delete full_; }

  static void expectFull(const test::State& s, const std::string& what) {
    if (rank() != 0) return;
    EXPECT_FALSE(full_->particles.empty());
    EXPECT_TRUE(*full_ == s) << what << " differs from the uninterrupted 400-step run";
  }

  // Restarts from `from`'s restart file at `step` and runs to step 400 (given as steps, or
  // as hold_time).
  static void resume(const std::string& from, long step, const std::string& holdTime = "") {
    Problem again = plate("mplm_restart_again", 400, holdTime);
    again.restart = readRestart(restartPath(from, step), again);
    const RestartState& st = *again.restart;
    EXPECT_EQ(again.run.firstStep, step);
    EXPECT_TRUE(st.hasState);
    // The hold-phase damping is computed once the loads are held (from step 201 on).
    EXPECT_EQ(st.integrator.size(), 1u);
    const double hold = st.integrator.empty() ? 0.0 : st.integrator[0];
    if (step > 200) {
      EXPECT_GT(hold, 0) << "no hold damping before the restart";
    } else {
      EXPECT_LT(hold, 0);
    }
    expectFull(run(std::move(again)), "the run restarted at step " + std::to_string(step));
  }
  static test::State* full_;
};
test::State* MplmRestart::full_ = nullptr;

TEST_F(MplmRestart, InTheRamp) { resume("mplm_restart_full", 100); }
TEST_F(MplmRestart, InTheHold) { resume("mplm_restart_full", 300); }
TEST_F(MplmRestart, FromARunWithFewerSteps) {
  run(plate("mplm_restart_short", 300), 300);
  resume("mplm_restart_short", 300);
}

TEST_F(MplmRestart, HoldTimeGivesTheSameRun) {
  Problem pb = plate("mplm_restart_hold", 0, hold200);
  EXPECT_EQ(pb.run.steps, -1);
  expectFull(run(std::move(pb)), "the run given by hold_time");
  resume("mplm_restart_hold", 300, hold200);
}

TEST_F(MplmRestart, HoldTimeThroughTheThesisFiles) {
  const std::string dir = "mplm_restart_hold_dat";
  Scenario sc = plateScenario(dir, 0, hold200);
  if (rank() == 0) writeThesisInput(dir, sc.problem, sc.modelParams);
  MPI_Barrier(MPI_COMM_WORLD);
  Problem pb = readThesisInput(dir);
  EXPECT_EQ(pb.run.steps, -1);
  EXPECT_EQ(pb.run.loading.holdTime, sc.problem.run.loading.holdTime);
  pb.run.outDir = dir + "/out";
  expectFull(run(std::move(pb)), "the run from the thesis's files with hold_time");
}

// The step count from ramp_time + hold_time, set up without running.
long stepsFor(const std::string& holdTime) {
  Comm comm;
  Problem pb = plate("mplm_restart_length", 0, holdTime);
  pb.output = {.finalRestart = false};
  const auto sim = makeSimulation(std::move(pb), comm);
  sim->setup();
  return sim->context().steps();
}

TEST(MplmHoldTime, LastsWholeStepsRoundedUpButNotForRoundOff) {
  EXPECT_EQ(stepsFor(hold200), 400);
  EXPECT_EQ(stepsFor("3.6e-5"), 400);  // 399.1 steps: the hold is never cut short
  // 139 steps, 339.00000000000006 in floating point: within round-off of 339.
  EXPECT_EQ(stepsFor("2.51312e-5"), 339);
  EXPECT_EQ(stepsFor("0"), 200);  // the ramp alone
}

}  // namespace
}  // namespace pdq
