// The quasi-static solver gives the same bits on 1, 2 and 3 ranks, on 1 and 2 threads, and
// when restarted from a load step's restart file: a reinforced beam cracked in four load
// steps.
#include <gtest/gtest.h>
#include <mpi.h>
#include <omp.h>

#include <algorithm>
#include <optional>

#include "harness.hpp"
#include "io/restart.hpp"
#include "models/mplm/2d/attributes.hpp"
#include "quasi_static.hpp"
#include "support/harness.hpp"

namespace pdq::mplm {
namespace {

constexpr double kScale = 120;
constexpr long kSteps = 4;

Problem beamProblem(const std::string& dir) {
  RunConfig run;
  run.solver = test::solver(1e-6, kSteps);
  run.steps = kSteps;
  run.loading.scale = kScale;
  run.outDir = dir;
  Problem pb = makeProblem("mplm2d", test::params({}), test::smallBeam(), run);
  pb.output.restartEvery = 2;
  return pb;
}

// The beam on the first `ranks` world ranks, gathered on world rank 0.
pdq::test::State runOn(int ranks, int threads, const std::string& dir,
                       std::optional<long> restartFrom = {}) {
  pdq::test::State s;
  test::runOnRanks(
      ranks, threads, [&](Comm&) { return beamProblem(dir); }, "qs_det_1", restartFrom,
      [&](Simulation& sim) { s = pdq::test::gatherState(sim); });
  return s;
}

TEST(QuasiStaticDeterminism, SameBitsOnRanksThreadsAndRestart) {
  int size = 0, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  ASSERT_EQ(size, 3);
  const pdq::test::State one = runOn(1, 1, "qs_det_1");
  MPI_Barrier(MPI_COMM_WORLD);
  const pdq::test::State twoThreads = runOn(1, 2, "qs_det_1t2");
  const pdq::test::State two = runOn(2, 1, "qs_det_2");
  const pdq::test::State three = runOn(3, 2, "qs_det_3");
  const pdq::test::State resumed = runOn(2, 1, "qs_det_resumed", 2);
  if (rank != 0) return;
  ASSERT_FALSE(one.particles.empty());
  EXPECT_TRUE(one == twoThreads) << "1 and 2 threads differ";
  EXPECT_TRUE(one == two) << "1 and 2 ranks differ";
  EXPECT_TRUE(one == three) << "1 and 3 ranks differ";
  EXPECT_TRUE(one == resumed) << "the run restarted at load step 2 differs";
  // The load cracked the beam: some interaction is damaged.
  const std::size_t width = 3 + N_BOND;
  long damaged = 0;
  for (std::size_t k = 0; k < one.bonds.size(); k += width)
    damaged += std::max(one.bonds[k + 3 + OMEGA_T], one.bonds[k + 3 + OMEGA_C]) > 0;
  EXPECT_GT(damaged, 0);
}

}  // namespace
}  // namespace pdq::mplm
