// An mplm2d run restarted from a step in the load ramp, from one in the hold (after the
// hold-phase damping was computed), and from the last step of a shorter run (another
// `--steps`) ends with the same bits as the uninterrupted run: the load protocol runs in
// simulated time and the integrator's state travels in State.<step>.rst.
#include "io/restart.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/standard_outputs.hpp"
#include "scenario/scenario.hpp"
#include "support/harness.hpp"

namespace pdq {
namespace {

// A small tension plate, damaged, ramped over 200 of 400 steps, then held with damping.
Problem plate(const std::string& dir, long steps) {
  const std::string path = dir + ".toml";
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::ofstream(path) << "steps = " << steps << R"(
[model]
name = "mplm2d"
dt = 1.808e-7
[loading]
load_scale = 4
ramp_time = 3.616e-5
hold_damping_ratio = 1
[particles]
generator = "mplm_plate"
width = 0.1
height = 0.12
[output]
restart_every = 100
)";
  MPI_Barrier(MPI_COMM_WORLD);
  Problem pb = std::move(readScenario(path).problem);
  pb.run.outDir = dir;
  return pb;
}

test::State run(Problem pb) {
  Comm comm;
  const auto sim = makeSimulation(std::move(pb), comm);
  sim->run();
  return test::gatherState(*sim);
}

class MplmRestart : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank == 0)
      for (const char* d : {"mplm_restart_full", "mplm_restart_short", "mplm_restart_again"})
        std::filesystem::remove_all(d);
    MPI_Barrier(MPI_COMM_WORLD);
    full_ = new test::State(run(plate("mplm_restart_full", 400)));
  }
  static void TearDownTestSuite() { delete full_; }

  // Restarts from `from`'s restart file at `step` and runs to step 400.
  static void resume(const std::string& from, long step) {
    Problem again = plate("mplm_restart_again", 400);
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
    const test::State resumed = run(std::move(again));
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank == 0) {
      EXPECT_FALSE(full_->particles.empty());
      EXPECT_TRUE(*full_ == resumed) << "the run restarted at step " << step << " differs";
    }
  }
  static test::State* full_;
};
test::State* MplmRestart::full_ = nullptr;

TEST_F(MplmRestart, InTheRamp) { resume("mplm_restart_full", 100); }
TEST_F(MplmRestart, InTheHold) { resume("mplm_restart_full", 300); }
TEST_F(MplmRestart, FromARunWithFewerSteps) {
  run(plate("mplm_restart_short", 300));
  resume("mplm_restart_short", 300);
}

}  // namespace
}  // namespace pdq
