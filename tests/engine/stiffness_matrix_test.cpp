// The assembled stiffness (engine/stiffness_matrix.hpp) on real ranks: a 3D block's matrix,
// six DOFs per particle coupled along its bonds, fills in enough to take the supernodal
// factor, whose solves use its values in single precision; they solve K x = b to that
// precision for the block's condition, the same bits on any number of ranks.
#include "engine/stiffness_matrix.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "engine/exact_sum.hpp"
#include "io/standard_outputs.hpp"
#include "support/harness.hpp"

namespace pdq {
namespace {

constexpr int kDofs = 6;

// A 6×6 block, symmetric positive definite: 2 on the diagonal, 0.5 between neighbouring
// DOFs (eigenvalues 2 + cos(kπ/7), all over 1).
double coupling(int a, int b) { return a == b ? 2.0 : std::abs(a - b) == 1 ? 0.5 : 0.0; }

// The solution asked for, from the particle's global ID alone.
double wanted(Gid g, int d) { return std::sin(0.37 * static_cast<double>(g) + 1.3 * d) + 0.2 * d; }

// The block's system solved on the ranks of `c`; the solution as (gid, x…) rows in
// global-ID order on its rank 0.
test::State solveOn(MPI_Comm c) {
  Comm comm(c);
  Problem pb = makeProblem("spring", test::params({{"horizon", "1.5"}, {"dt", "0.05"}}), {});
  pb.particles = test::cubicBlock(pb.model->schema(), 12, 9, 8, 1.0);
  pb.run.steps = 1;
  pb.run.outDir = "out_stiffness_matrix";
  const auto sim = makeSimulation(std::move(pb), comm);
  sim->run();
  Context& ctx = sim->context();
  const Particles& P = ctx.particles;
  const std::size_t n = P.owned();

  // K = Σ over bonds of w (e_i − e_j)(e_i − e_j)ᵀ ⊗ C, w = 1 / length; the particles of the
  // face x = 0 are held (their DOFs not free), which makes it definite.
  std::vector<Gid> gids(n);
  std::vector<unsigned char> free(n * kDofs);
  std::vector<double> diag(n * kDofs, 1.0), b(n * kDofs, 0.0), x(n * kDofs);
  std::vector<StiffnessEntry> entries;
  for (std::size_t i = 0; i < n; ++i) {
    gids[i] = P.gid(i);
    const bool held = P.fixed(i)[0] < 0.5;
    for (int d = 0; d < kDofs; ++d) free[kDofs * i + d] = held ? 0 : 1;
    if (held) continue;
    std::vector<double> own(kDofs * kDofs, 0.0);
    for (std::size_t k = ctx.bonds.begin(i); k < ctx.bonds.end(i); ++k) {
      const auto j = static_cast<std::size_t>(ctx.bonds.partner(k));
      double r2 = 0;
      for (int a = 0; a < 3; ++a) r2 += std::pow(P.fixed(j)[a] - P.fixed(i)[a], 2);
      const double w = 1 / std::sqrt(r2);
      for (int a = 0; a < kDofs; ++a)
        for (int c = 0; c < kDofs; ++c) {
          const double v = w * coupling(a, c);
          if (v == 0) continue;
          own[kDofs * a + c] += v;
          entries.push_back({P.gid(i), P.gid(j), a, c, -v});
          b[kDofs * i + a] -= v * wanted(P.gid(j), c) * (P.fixed(j)[0] < 0.5 ? 0 : 1);
        }
    }
    for (int a = 0; a < kDofs; ++a)
      for (int c = 0; c < kDofs; ++c) {
        if (own[kDofs * a + c] == 0) continue;
        entries.push_back({P.gid(i), P.gid(i), a, c, own[kDofs * a + c]});
        b[kDofs * i + a] += own[kDofs * a + c] * wanted(P.gid(i), c);
      }
  }
  StiffnessMatrix m;
  EXPECT_EQ(m.factorise(ctx, gids, kDofs, free, entries, diag, 0.0, 100.0),
            StiffnessMatrix::Outcome::Factorised);
  if (comm.root()) {
    EXPECT_EQ(m.unknowns(), 11 * 9 * 8 * kDofs);
    EXPECT_GT(m.factorNonzeros(), 5 * m.matrixStored()) << "not in the supernodal regime";
  }
  const double bx = m.solve(ctx, b, x);

  // The error: single precision (a relative 6e-8 per entry of the factor) times the
  // condition of a block 11 bonds long: far below 1e-5, far above double's round-off.
  double worst = 0;
  ExactSum here;
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < kDofs; ++d) {
      const std::size_t k = kDofs * i + d;
      if (!free[k]) {
        EXPECT_EQ(x[k], 0.0);
        continue;
      }
      worst = std::max(worst, std::fabs(x[k] - wanted(P.gid(i), d)));
      here.add(b[k] * x[k]);
    }
  worst = ctx.max(worst);
  EXPECT_LT(worst, 1e-5);
  EXPECT_GT(worst, 1e-12) << "the solves were expected to use the factor in single precision";
  EXPECT_NEAR(bx, ctx.sum(here), 1e-12 * std::fabs(bx)) << "bᵀx";

  std::vector<std::pair<Gid, std::size_t>> order;
  for (std::size_t i = 0; i < n; ++i) order.push_back({P.gid(i), i});
  std::vector<char> mine;
  for (const auto& [g, i] : order) {
    const double row[1 + kDofs] = {static_cast<double>(g), x[kDofs * i],     x[kDofs * i + 1],
                                   x[kDofs * i + 2],       x[kDofs * i + 3], x[kDofs * i + 4],
                                   x[kDofs * i + 5]};
    const char* bytes = reinterpret_cast<const char*>(row);
    mine.insert(mine.end(), bytes, bytes + sizeof row);
  }
  std::vector<std::size_t> starts;
  const std::vector<char> all = comm.gather(mine, starts);
  test::State s;
  if (!comm.root()) return s;
  std::vector<double> rows(all.size() / sizeof(double));
  std::memcpy(rows.data(), all.data(), all.size());
  std::vector<std::vector<double>> sorted;
  for (std::size_t k = 0; k < rows.size(); k += 1 + kDofs)
    sorted.emplace_back(rows.begin() + k, rows.begin() + k + 1 + kDofs);
  std::sort(sorted.begin(), sorted.end());
  for (const auto& r : sorted) s.particles.insert(s.particles.end(), r.begin(), r.end());
  return s;
}

TEST(StiffnessMatrix, SupernodalSolvesInSinglePrecisionTheSameOnAnyRanks) {
  int world = 1, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &world);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  test::State reference;
  for (int ranks = 1; ranks <= world; ++ranks) {
    MPI_Comm c = test::firstRanks(ranks);
    test::State s;
    if (c != MPI_COMM_NULL) {
      s = solveOn(c);
      MPI_Comm_free(&c);
    }
    s = test::toWorldRoot(s, 0);
    if (rank != 0) continue;
    ASSERT_EQ(s.particles.size(), 12u * 9u * 8u * (1 + kDofs));
    if (ranks == 1)
      reference = s;
    else
      EXPECT_TRUE(s == reference) << "the solution differs on " << ranks << " ranks";
  }
}

}  // namespace
}  // namespace pdq
