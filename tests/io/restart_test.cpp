// A run restarted from ParticleAlterAttrs.<step>.rst (with its Bonds.<step>.rst) ends with
// the same bits as the uninterrupted run, for a bonded lattice with breaking springs, with
// particles fixed in their cells and with shuffling across periodic boundaries.
#include "io/restart.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "engine/error.hpp"
#include "io/standard_outputs.hpp"
#include "support/harness.hpp"

namespace pdq {
namespace {

Problem springProblem(bool shuffle, const std::string& dir) {
  Problem pb = makeProblem("spring",
                           test::params({{"horizon", "1.5"},
                                         {"dt", "0.05"},
                                         {"critical_stretch", "0.08"},
                                         {"shuffle", shuffle ? "true" : "false"}}),
                           {});
  pb.particles = test::cubicBlock(pb.model->schema(), 8, 6, 5, 1.0);
  for (std::size_t k = 0; k < pb.particles.size(); ++k) {
    const double g = static_cast<double>(pb.particles.gid[k]);
    pb.particles.alterRow(k)[3] = 0.3 * std::sin(1.7 * g);
    pb.particles.alterRow(k)[4] = 0.3 * std::cos(2.3 * g);
  }
  pb.run.steps = 300;
  pb.run.outDir = dir;
  if (shuffle) {
    pb.run.minCellSize = 2.0;
    pb.run.periodic = {true, true, true};
    pb.run.boxLo = {-0.5, -0.5, -0.5};
    pb.run.boxHi = {7.5, 5.5, 6.5};
  }
  pb.output.restartEvery = 120;
  pb.output.finalRestart = true;
  return pb;
}

test::State runProblem(Problem pb) {
  Comm comm;
  const auto sim = makeSimulation(std::move(pb), comm);
  sim->run();
  return test::gatherState(*sim);
}

void checkRestart(bool shuffle) {
  const std::string dir = shuffle ? "out_restart_shuffle" : "out_restart_fixed";
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) std::filesystem::remove_all(dir);
  MPI_Barrier(MPI_COMM_WORLD);
  const test::State full = runProblem(springProblem(shuffle, dir));
  Problem again = springProblem(shuffle, dir + "_again");
  again.restart = readRestart(restartPath(dir, 240), again);
  EXPECT_EQ(again.run.firstStep, 240);
  EXPECT_FALSE(again.restart->owner.empty());
  long dead = 0;
  for (auto d : again.restart->dead) dead += d;
  EXPECT_GT(dead, 0) << "no spring broke before the restart; the test would prove little";
  const test::State resumed = runProblem(std::move(again));
  if (rank == 0) {
    EXPECT_FALSE(full.particles.empty());
    EXPECT_TRUE(full == resumed) << "the restarted run differs from the uninterrupted one";
  }
}

TEST(Restart, BondedLatticeContinuesBitwise) { checkRestart(false); }
TEST(Restart, ShufflingPeriodicLatticeContinuesBitwise) { checkRestart(true); }

TEST(Restart, RejectsAFileThatIsNotARestart) {
  Problem pb = springProblem(false, "out_restart_bad");
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) {
    std::filesystem::create_directories("out_restart_bad");
    std::ofstream f("out_restart_bad/ParticleAlterAttrs.5.rst");
    f << "1 0 0 0 0 0 0\n";
  }
  MPI_Barrier(MPI_COMM_WORLD);
  EXPECT_THROW(readRestart("out_restart_bad/ParticleAlterAttrs.5.rst", pb), InputError);
}

}  // namespace
}  // namespace pdq
