// Independence of the cells: the same Lennard-Jones melt (100 steps, with shuffles and
// periodic wraps) ends in the same bits in cells of the model's size (cutoff + skin), in
// wider ones (a larger minimum cell size), and on 2 ranks whose cut axis the engine gives
// fewer, wider cells to balance the ranks — positions, velocities and the global energies.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cstring>

#include "lj_setup.hpp"

namespace pdq {
namespace {

struct Outcome {
  std::vector<double> state;  // rows (global ID, alterable attributes) in ID order, globals
  double cellSize = 0, listRadius = 0;
  std::size_t shuffles = 0;
  std::array<int, 3> cells{}, procs{};
  double busiest = 0;  // the most atoms a rank owned at the start, over all atoms
};

Outcome simulate(int fccCells, double minCellSize, Comm& comm) {
  ljtest::Melt m;
  m.cells = fccCells;
  m.steps = 100;
  m.minCellSize = minCellSize;
  auto sim = ljtest::makeMelt(m, comm);
  Outcome out;
  const Decomposition& d = sim->decomposition();
  out.cellSize = d.cellSize(0);
  for (int a = 0; a < 3; ++a) out.cells[a] = d.globalCells(a), out.procs[a] = d.procs(a);
  out.listRadius = sim->context().listRadius();
  const double owned = static_cast<double>(sim->particles().owned());
  out.busiest = comm.max(owned) / (4.0 * fccCells * fccCells * fccCells);
  while (sim->advance()) {
  }
  out.state = test::gatherState(*sim).particles;
  const std::vector<double> globals = sim->model().globalValues(sim->context());
  out.state.insert(out.state.end(), globals.begin(), globals.end());
  out.shuffles = sim->stats().shuffles;
  return out;
}

bool sameBits(const Outcome& a, const Outcome& b) {
  return a.state.size() == b.state.size() &&
         std::memcmp(a.state.data(), b.state.data(), a.state.size() * sizeof(double)) == 0;
}

TEST(LjCellSize, SameBitsInWiderCells) {
  Comm self(MPI_COMM_SELF);
  const Outcome ref = simulate(7, 0, self);  // 1372 atoms, cutoff + skin: cells of 2.94
  const Outcome wide = simulate(7, 3.7, self);
  EXPECT_GT(wide.cellSize, ref.cellSize + 0.5);  // really other cells
  EXPECT_EQ(wide.listRadius, ref.listRadius);    // lists of the cells the model asks for
  EXPECT_GT(ref.shuffles, 5u);
  ASSERT_GT(ref.state.size(), 1372u);
  EXPECT_TRUE(sameBits(wide, ref))
      << "cells of " << wide.cellSize << " end in other bits than cells of " << ref.cellSize;
}

// 2916 atoms in a box of 15.1 make 5 cells of 3.02 per axis; 2 ranks would own 2 | 3 of them
// along the cut axis, so the engine cuts that axis into 4 cells of 3.78 (2 | 2).
TEST(LjCellSize, TwoRanksBalancedByWiderCellsSameBits) {
  int size = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  ASSERT_EQ(size, 2) << "run on 2 ranks";
  Comm self(MPI_COMM_SELF), world;
  const Outcome one = simulate(9, 0, self);
  const Outcome two = simulate(9, 0, world);
  EXPECT_EQ(one.cells, (std::array<int, 3>{5, 5, 5}));
  int cut = -1;
  for (int a = 0; a < 3; ++a)
    if (two.procs[a] == 2) cut = a;
  ASSERT_GE(cut, 0);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(two.cells[a], a == cut ? 4 : 5) << "axis " << a;
  EXPECT_LT(two.busiest, 0.52);  // 2 | 3 cells would give one rank 60 %
  EXPECT_EQ(two.listRadius, one.listRadius);
  EXPECT_GT(one.shuffles, 5u);
  EXPECT_EQ(two.shuffles, one.shuffles);
  ASSERT_GT(one.state.size(), 2916u);
  if (world.root()) {
    EXPECT_TRUE(sameBits(two, one)) << "2 ranks with wider cells differ from 1 rank";
  }
}

}  // namespace
}  // namespace pdq
