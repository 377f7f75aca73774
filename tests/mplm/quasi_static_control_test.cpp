// Displacement control of the quasi-static solver: a notched plain beam in three-point
// bending, its midspan top pushed down, shows a peak load and a descending branch, with load
// steps cut back where too many interactions break at once; the same bits on 1, 2 and 3
// ranks and from a restart in the middle of the run.
#include <gtest/gtest.h>
#include <mpi.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include "harness.hpp"
#include "io/restart.hpp"
#include "quasi_static.hpp"
#include "support/harness.hpp"

namespace pdq::mplm {
namespace {

constexpr double kSpan = 0.4, kDepth = 0.1;

// The beam (no line load), its bottom notched at midspan, and the solver pushing the
// midspan top particles down by 0.2 mm in steps of at most 0.02 mm.
Problem notchedBeam(const std::string& dir) {
  BeamSpec b;
  b.span = kSpan;
  b.depth = kDepth;
  b.lineLoad = 0;
  ParticleSet all = beam(b), ps;
  ps.nFixed = all.nFixed;
  ps.nAlter = all.nAlter;
  for (std::size_t k = 0; k < all.size(); ++k) {
    const double* X = all.fixedRow(k);
    if (std::fabs(X[0] - kSpan / 2) < 0.011 && X[1] < 0.03) continue;  // the notch
    ps.gid.push_back(all.gid[k]);
    ps.fixed.insert(ps.fixed.end(), X, X + all.nFixed);
    ps.alter.insert(ps.alter.end(), all.alterRow(k), all.alterRow(k) + all.nAlter);
  }
  Solver s = test::solver(1e-5, 10);
  s.maxBroken = 2;
  s.control.axis = 1;
  s.control.displacement = -2e-4;
  for (std::size_t k = 0; k < ps.size(); ++k)
    if (std::fabs(ps.fixedRow(k)[0] - kSpan / 2) < 0.015 && ps.fixedRow(k)[1] > kDepth - 0.02)
      s.control.ids.push_back(ps.gid[k]);
  std::sort(s.control.ids.begin(), s.control.ids.end());
  RunConfig run;
  run.solver = s;
  run.steps = s.loadSteps;
  run.outDir = dir;
  // A brittle lattice (α_t = 10: 51 N/m at s = 2 cm, where the default G_F gives 34.3),
  // so that cracks run and load steps are cut back.
  Problem pb = makeProblem("mplm2d", test::params({{"tensile_ratio", "10"}}), std::move(ps), run);
  pb.output.restartEvery = 4;
  return pb;
}

struct Result {
  pdq::test::State state;
  std::vector<std::vector<double>> curve;  // quasi_static.csv
};

Result runOn(int ranks, int threads, const std::string& dir, std::optional<long> restartFrom = {}) {
  Result r;
  auto problem = [&](Comm& comm) {
    if (restartFrom && comm.root()) {
      // The curve so far, which the restarted run continues.
      std::filesystem::create_directories(dir);
      std::filesystem::copy_file("qs_control_1/quasi_static.csv", dir + "/quasi_static.csv",
                                 std::filesystem::copy_options::overwrite_existing);
    }
    return notchedBeam(dir);
  };
  test::runOnRanks(ranks, threads, problem, "qs_control_1", restartFrom, [&](Simulation& sim) {
    r.state = pdq::test::gatherState(sim);
    r.curve = test::loadStepRows(dir);
  });
  return r;
}

TEST(QuasiStaticControl, PeakAndDescendingBranchSameBitsOnRanksAndRestart) {
  int size = 0, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  ASSERT_EQ(size, 3);
  const Result one = runOn(1, 1, "qs_control_1");
  MPI_Barrier(MPI_COMM_WORLD);
  const Result two = runOn(2, 1, "qs_control_2");
  const Result three = runOn(3, 1, "qs_control_3");
  const Result resumed = runOn(2, 1, "qs_control_resumed", 4);
  if (rank != 0) return;
  ASSERT_FALSE(one.state.particles.empty());
  EXPECT_TRUE(one.state == two.state) << "1 and 2 ranks differ";
  EXPECT_TRUE(one.state == three.state) << "1 and 3 ranks differ";
  EXPECT_TRUE(one.state == resumed.state) << "the run restarted at load step 4 differs";
  EXPECT_EQ(one.curve, two.curve);
  EXPECT_EQ(one.curve, three.curve);
  EXPECT_EQ(one.curve, resumed.curve) << "the restarted run's curve differs";

  // Columns: load_step, load_factor, iterations, residual, reference, relative, load,
  // displacement, broken.
  const auto& c = one.curve;
  ASSERT_GE(c.size(), 10u);
  EXPECT_DOUBLE_EQ(c.back()[7], 2e-4) << "the run ends at the full displacement";
  std::size_t peak = 0;
  for (std::size_t k = 0; k < c.size(); ++k) {
    EXPECT_LE(c[k][5], 1e-5) << "load step " << c[k][0] << " converged";
    if (k > 0) {
      EXPECT_GT(c[k][7], c[k - 1][7]) << "the displacement grows";
      EXPECT_LE(c[k][8] - c[k - 1][8], 2) << "at most max_broken broke in a step";
    }
    if (c[k][6] > c[peak][6]) peak = k;
  }
  EXPECT_GT(c[peak][6], 0) << "the push is resisted";
  EXPECT_GT(peak, 0u) << "the load rises first";
  EXPECT_LT(peak + 1, c.size()) << "a peak before the end";
  EXPECT_LT(c.back()[6], 0.7 * c[peak][6]) << "a descending branch after the peak";
  EXPECT_GT(c.back()[8], c[peak][8]) << "cracking continues after the peak";
  // Cut back where too many interactions would break: some increment is below the largest.
  bool cut = false;
  for (std::size_t k = 1; k < c.size(); ++k) cut |= c[k][7] - c[k - 1][7] < 1.5e-5;
  EXPECT_TRUE(cut) << "no load step was cut back";
}

}  // namespace
}  // namespace pdq::mplm
