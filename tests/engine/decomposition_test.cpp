#include "engine/decomposition.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/error.hpp"

namespace pdq {
namespace {

Domain box(double lx, double ly, double lz, int dim) {
  Domain d;
  d.hi = {lx, ly, lz};
  d.dim = dim;
  return d;
}

TEST(Decomposition, CoresAreBlocksOfTheGlobalCellLattice) {
  const Domain d = box(10, 4, 1, 2);
  int covered = 0;
  for (int r = 0; r < 3; ++r) {
    Decomposition dec(d, 1.0, {3, 1, 1}, 3, r);
    EXPECT_EQ(dec.globalCells(0), 10);
    EXPECT_EQ(dec.globalCells(2), 1);  // 2D: one cell layer in Z
    covered += dec.coreCells(0);
    for (int g = dec.coreLo(0); g < dec.coreHi(0); ++g) EXPECT_EQ(dec.ownerCoord(0, g), r);
  }
  EXPECT_EQ(covered, 10);
}

TEST(Decomposition, BalanceCutsAtEqualWeights) {
  // 10 cells along X: the first 4 hold 3 particles each, the rest 1 (18 in all). Equal
  // cell counts would give 3 ranks 9, 5 and 4 particles; the balanced cuts 6 each (2, 2
  // and 6 cells).
  std::array<std::vector<double>, 3> w{std::vector<double>{3, 3, 3, 3, 1, 1, 1, 1, 1, 1}, {}, {}};
  const Domain d = box(10, 4, 1, 2);
  std::array<int, 3> lo{}, hi{};
  for (int r = 0; r < 3; ++r) {
    Decomposition dec(d, 1.0, {3, 1, 1}, 3, r);
    dec.balance(w);
    lo[r] = dec.coreLo(0);
    hi[r] = dec.coreHi(0);
    for (int g = 0; g < 10; ++g) EXPECT_EQ(dec.ownerCoord(0, g) == r, g >= lo[r] && g < hi[r]);
  }
  EXPECT_EQ(lo, (std::array<int, 3>{0, 2, 4}));
  EXPECT_EQ(hi, (std::array<int, 3>{2, 4, 10}));
  // Every core keeps a cell, however the weight lies.
  for (auto heavy : {0, 9}) {
    w[0].assign(10, 0.0);
    w[0][heavy] = 100;
    int covered = 0;
    for (int r = 0; r < 3; ++r) {
      Decomposition dec(d, 1.0, {3, 1, 1}, 3, r);
      dec.balance(w);
      EXPECT_GE(dec.coreCells(0), 1);
      covered += dec.coreCells(0);
    }
    EXPECT_EQ(covered, 10);
  }
}

TEST(Decomposition, ChooseCellsTakesTheCountThatSplitsTheWeightBest) {
  // 47 planes of particles at x = 0.5 .. 46.5: cells of at least 2.76 make 17 along X, and
  // 2 cores of whole cells hold 25 and 22 planes at best; 16 cells (8 | 8) hold 23 and 24.
  // 14 cells would split as well; of equal splits the most cells are kept.
  auto planesIn = [](int planes) {
    return [planes](int, int n) {
      std::vector<double> w(n, 0.0);
      for (int k = 0; k < planes; ++k)
        w[static_cast<int>(std::floor((k + 0.5) / (static_cast<double>(planes) / n)))] += 1;
      return w;
    };
  };
  const auto layers = planesIn(47);
  const Domain d = box(47, 47, 47, 3);
  std::array<int, 2> planes{};
  for (int r = 0; r < 2; ++r) {
    Decomposition dec(d, 2.76, {2, 1, 1}, 2, r);
    EXPECT_EQ(dec.globalCells(0), 17);
    dec.chooseCells(layers);
    EXPECT_EQ(dec.globalCells(0), 16);
    EXPECT_EQ(dec.globalCells(1), 17);  // one core along Y: its cells stay
    EXPECT_DOUBLE_EQ(dec.cellSize(0), 47.0 / 16);
    dec.balance({layers(0, 16), layers(1, 17), {}});
    EXPECT_EQ(dec.coreCells(0), 8);
    const std::vector<double> w = layers(0, 16);
    for (int g = dec.coreLo(0); g < dec.coreHi(0); ++g) planes[r] += static_cast<int>(w[g]);
  }
  EXPECT_EQ(planes, (std::array<int, 2>{23, 24}));
  // Cells that split evenly already stay as they are.
  Decomposition even(box(48, 8, 8, 3), 3.0, {2, 1, 1}, 2, 0);
  even.chooseCells(planesIn(48));
  EXPECT_EQ(even.globalCells(0), 16);
}

TEST(Decomposition, AutomaticGridCutsTheLongAxis) {
  Decomposition dec(box(40, 5, 5, 3), 1.0, {0, 0, 0}, 4, 0);
  EXPECT_EQ(dec.procs(0), 4);
  EXPECT_EQ(dec.procs(1), 1);
}

TEST(Decomposition, NeighboursAndPeriodicWrap) {
  Domain d = box(9, 9, 9, 3);
  d.periodic = {true, false, false};
  Decomposition left(d, 1.0, {2, 1, 1}, 2, 0);
  EXPECT_EQ(left.neighbour(0, -1), 1);
  EXPECT_TRUE(left.wraps(0, -1));
  EXPECT_EQ(left.neighbour(1, +1), -1);
  Decomposition self(d, 1.0, {1, 1, 1}, 1, 0);
  EXPECT_EQ(self.neighbour(0, +1), 0);  // one rank owns both sides of the periodic axis
}

TEST(Decomposition, TooManyRanksIsAClearError) {
  try {
    Decomposition dec(box(3, 3, 3, 3), 1.0, {4, 1, 1}, 4, 0, "pdQInput.dat");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("only 3 cells"), std::string::npos) << e.what();
  }
  EXPECT_THROW(Decomposition(box(3, 3, 3, 3), 1.0, {2, 1, 1}, 4, 0), InputError);
}

TEST(Decomposition, DivisionsCutCellsAndKeepTheReach) {
  // 11 cells of 1.1 (at least 1.05) along X; two ranks cut whole cells 5 | 6 (by equal weights of a
  // uniform fill), halves of them 11 | 11.
  const Domain d = box(12.1, 3.3, 3.3, 3);
  for (int div : {1, 2}) {
    std::array<int, 2> core{};
    for (int r = 0; r < 2; ++r) {
      Decomposition dec(d, 1.05, {2, 1, 1}, 2, r, "test", div);
      EXPECT_EQ(dec.globalCells(0), 11 * div);
      EXPECT_EQ(dec.globalCells(1), 3 * div);
      EXPECT_DOUBLE_EQ(dec.cellSize(0), 1.1 / div);
      EXPECT_EQ(dec.reach(0), 12.1 / 11);  // the same bits whatever the divisions
      EXPECT_EQ(dec.minActiveCellSize(), 12.1 / 11);
      std::array<std::vector<double>, 3> w;
      w[0].assign(dec.globalCells(0), 1.0);
      dec.balance(w);
      core[r] = dec.coreCells(0);
    }
    EXPECT_EQ(core[0] + core[1], 11 * div);
    EXPECT_EQ(std::abs(core[0] - core[1]), div == 1 ? 1 : 0);
  }
  // One rank has no cuts: whole cells.
  EXPECT_EQ(Decomposition(d, 1.05, {1, 1, 1}, 1, 0, "test", 2).globalCells(0), 11);
  // Each rank needs a whole cell (divisions sub-cells) along each axis it is cut along.
  EXPECT_THROW(Decomposition(box(3.3, 3.3, 3.3, 3), 1.05, {4, 1, 1}, 4, 0, "test", 2), InputError);
  EXPECT_NO_THROW(Decomposition(box(3.3, 3.3, 3.3, 3), 1.05, {3, 1, 1}, 3, 0, "test", 2));
}

}  // namespace
}  // namespace pdq
