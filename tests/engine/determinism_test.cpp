// A bonded spring lattice gives bitwise identical results after 1000 steps for every rank
// count, processor grid and thread count, with particles fixed in their cells and with
// shuffling and migration across a periodic boundary.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>

#include "io/standard_outputs.hpp"
#include "support/harness.hpp"

namespace pdq {
namespace {

struct Layout {
  int ranks;
  std::array<int, 3> grid;
  int threads;
};

test::State runSpring(MPI_Comm c, const Layout& l, bool shuffle, long steps) {
  omp_set_num_threads(l.threads);
  Problem pb = makeProblem("spring",
                           test::params({{"stiffness", "1.0"},
                                         {"horizon", "1.5"},
                                         {"dt", "0.05"},
                                         {"critical_stretch", "0.08"},
                                         {"shuffle", shuffle ? "true" : "false"}}),
                           {});
  ParticleSet& ps = pb.particles = test::cubicBlock(pb.model->schema(), 10, 8, 6, 1.0);
  for (std::size_t k = 0; k < ps.size(); ++k) {  // a deterministic, rough initial velocity field
    const double g = static_cast<double>(ps.gid[k]);
    ps.alterRow(k)[3] = 0.3 * std::sin(1.7 * g);
    ps.alterRow(k)[4] = 0.3 * std::cos(2.3 * g);
    ps.alterRow(k)[5] = 0.3 * std::sin(0.9 * g + 1.0);
  }
  RunConfig& cfg = pb.run;
  cfg.procs = l.grid;
  cfg.steps = steps;
  cfg.outDir = "out_determinism";
  if (shuffle) {
    cfg.minCellSize = 2.0;
    cfg.periodic = {true, true, true};  // free fragments stay in the box
    cfg.boxLo = {-0.5, -0.5, -0.5};
    cfg.boxHi = {9.5, 7.5, 5.5};
  }
  Comm comm(c);
  auto sim = makeSimulation(std::move(pb), comm);
  sim->run();
  return test::gatherState(*sim);
}

void checkAllLayouts(bool shuffle) {
  int world = 1, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &world);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const std::vector<Layout> layouts = {{1, {1, 1, 1}, 1}, {1, {1, 1, 1}, 2}, {2, {2, 1, 1}, 1},
                                       {2, {1, 2, 1}, 2}, {3, {3, 1, 1}, 1}, {3, {1, 1, 3}, 1},
                                       {4, {4, 1, 1}, 1}, {4, {2, 2, 1}, 2}, {4, {1, 4, 1}, 1},
                                       {4, {1, 2, 2}, 1}, {4, {0, 0, 0}, 1}};
  test::State reference;
  bool haveReference = false;
  for (const Layout& l : layouts) {
    if (l.ranks > world) continue;
    MPI_Comm c = test::firstRanks(l.ranks);
    test::State s;
    if (c != MPI_COMM_NULL) {
      s = runSpring(c, l, shuffle, 1000);
      MPI_Comm_free(&c);
    }
    s = test::toWorldRoot(s, 0);
    if (rank == 0) {
      ASSERT_EQ(s.particles.size(), 480u * 7u) << "particles lost or duplicated";
      if (!haveReference) {
        reference = s;
        haveReference = true;
        // The lattice must actually have moved and some springs broken for this to test much.
        double moved = 0;
        for (std::size_t k = 0; k < 480; ++k)
          moved = std::max(moved, std::fabs(s.particles[k * 7 + 4]));
        EXPECT_GT(moved, 0.01);
        double broken = 0;
        for (std::size_t b = 0; b < s.bonds.size() / 4; ++b) broken += s.bonds[b * 4 + 2];
        EXPECT_GT(broken, 0);
      } else {
        EXPECT_TRUE(s == reference)
            << "differs on " << l.ranks << " ranks, grid " << l.grid[0] << "x" << l.grid[1] << "x"
            << l.grid[2] << ", " << l.threads << " threads";
      }
    }
  }
}

TEST(Determinism, SpringLatticeFixedCells) { checkAllLayouts(false); }
TEST(Determinism, SpringLatticeShufflingPeriodic) { checkAllLayouts(true); }

}  // namespace
}  // namespace pdq
