// The quasi-static solver gives the same bits on 1, 2 and 3 ranks, on 1 and 2 threads, and
// when restarted from a load step's restart file: a reinforced beam cracked in four load
// steps. Its first two load steps damage nothing, so the third reuses the stiffness probed
// at the first, where the run restarted at load step 2 probes it afresh.
#include <gtest/gtest.h>
#include <mpi.h>
#include <omp.h>

#include <algorithm>
#include <fstream>
#include <optional>
#include <string>

#include "harness.hpp"
#include "io/restart.hpp"
#include "models/mplm/2d/attributes.hpp"
#include "quasi_static.hpp"
#include "support/harness.hpp"

namespace pdq::mplm {
namespace {

constexpr double kScale = 120;
constexpr long kSteps = 4;

Problem beamProblem(const std::string& dir, Solver::Masses masses) {
  RunConfig run;
  run.solver = test::solver(1e-6, kSteps);
  run.solver.masses = masses;
  run.steps = kSteps;
  run.loading.scale = kScale;
  run.outDir = dir;
  Problem pb = makeProblem("mplm2d", test::params({}), test::smallBeam(), run);
  pb.output.restartEvery = 2;
  return pb;
}

// The beam on the first `ranks` world ranks, gathered on world rank 0.
pdq::test::State runOn(Solver::Masses masses, int ranks, int threads, const std::string& dir,
                       const std::string& first, std::optional<long> restartFrom = {}) {
  pdq::test::State s;
  test::runOnRanks(
      ranks, threads, [&](Comm&) { return beamProblem(dir, masses); }, first, restartFrom,
      [&](Simulation& sim) { s = pdq::test::gatherState(sim); });
  return s;
}

// Every run of the beam with the given fictitious masses against the first, on world rank 0.
void expectSameBits(Solver::Masses masses, const std::string& tag) {
  int size = 0, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  ASSERT_EQ(size, 3);
  const std::string first = "qs_det" + tag + "_1";
  const pdq::test::State one = runOn(masses, 1, 1, first, first);
  MPI_Barrier(MPI_COMM_WORLD);
  const pdq::test::State twoThreads = runOn(masses, 1, 2, "qs_det" + tag + "_1t2", first);
  const pdq::test::State two = runOn(masses, 2, 1, "qs_det" + tag + "_2", first);
  const pdq::test::State three = runOn(masses, 3, 2, "qs_det" + tag + "_3", first);
  const pdq::test::State resumed = runOn(masses, 2, 1, "qs_det" + tag + "_resumed", first, 2);
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
  // The probes were made before load steps 1 and 4 only.
  std::ifstream log(first + "/debug.txt");
  ASSERT_TRUE(log) << first << "/debug.txt";
  long probed = 0;
  for (std::string line; std::getline(log, line);)
    probed += line.find("stiffness probes") != std::string::npos;
  EXPECT_EQ(probed, 2);
}

TEST(QuasiStaticDeterminism, SameBitsOnRanksThreadsAndRestart) {
  expectSameBits(Solver::Masses::Stiffness, "");
}

// The assembled stiffness is gathered, factorised and solved on rank 0 in the order of
// global IDs: the same bits too.
TEST(QuasiStaticDeterminism, AssembledStiffnessSameBitsOnRanksThreadsAndRestart) {
  expectSameBits(Solver::Masses::Assembled, "_assembled");
}

}  // namespace
}  // namespace pdq::mplm
