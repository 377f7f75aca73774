// Independence of the cell size: the same Lennard-Jones melt (1372 atoms, 100 steps, with
// shuffles and periodic wraps) in cells of the model's size (cutoff + skin) and in wider
// ones ends in the same bits — positions, velocities and the global energies.
#include <gtest/gtest.h>

#include <cstring>

#include "lj_setup.hpp"

namespace pdq {
namespace {

struct Outcome {
  std::vector<double> state;  // rows (global ID, alterable attributes) in ID order, globals
  double cellSize = 0;
  std::size_t shuffles = 0;
};

Outcome simulate(double minCellSize) {
  Comm comm;
  ljtest::Melt m;
  m.cells = 7;
  m.steps = 100;
  m.minCellSize = minCellSize;
  auto sim = ljtest::makeMelt(m, comm);
  while (sim->advance()) {
  }
  Outcome out;
  out.state = test::gatherState(*sim).particles;
  const std::vector<double> globals = sim->model().globalValues(sim->context());
  out.state.insert(out.state.end(), globals.begin(), globals.end());
  out.cellSize = sim->context().cellSize();
  out.shuffles = sim->stats().shuffles;
  return out;
}

TEST(LjCellSize, SameBitsInWiderCells) {
  const Outcome ref = simulate(0);  // cutoff + skin
  const Outcome wide = simulate(3.7);
  EXPECT_GT(wide.cellSize, ref.cellSize + 0.5);  // really other cells
  EXPECT_GT(ref.shuffles, 5u);
  ASSERT_GT(ref.state.size(), 1372u);
  ASSERT_EQ(wide.state.size(), ref.state.size());
  EXPECT_EQ(0, std::memcmp(wide.state.data(), ref.state.data(), ref.state.size() * sizeof(double)))
      << "cells of " << wide.cellSize << " end in other bits than cells of " << ref.cellSize;
}

}  // namespace
}  // namespace pdq
