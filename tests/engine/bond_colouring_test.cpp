// The bond graph's distance-2 colouring (engine/bond_colouring.hpp), on real ranks: every
// particle's colour differs from its partners' and theirs from each other's, and the
// colours are those of the greedy colouring in global-ID order worked out here from the
// lattice's geometry alone, whatever the number of ranks.
#include "engine/bond_colouring.hpp"
#include "io/standard_outputs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "support/harness.hpp"

namespace pdq {
namespace {

TEST(BondColouring, DistanceTwoAndTheSameOnAnyRanks) {
  Comm comm;
  const double horizon = 1.5;  // 18 partners inside the block
  Problem pb = makeProblem("spring", test::params({{"horizon", "1.5"}, {"dt", "0.05"}}), {});
  ParticleSet& ps = pb.particles = test::cubicBlock(pb.model->schema(), 7, 6, 5, 1.0);
  const ParticleSet block = ps;
  pb.run.steps = 1;
  pb.run.outDir = "out_bond_colouring";
  const auto sim = makeSimulation(std::move(pb), comm);
  sim->run();
  Context& ctx = sim->context();
  long count = 0;
  const std::vector<long> colour = bondColours(ctx, count);
  const Particles& P = ctx.particles;
  ASSERT_EQ(colour.size(), P.owned());

  // The reference: particles in global-ID order, each taking the lowest colour not taken
  // within two bonds (pairs within the horizon), from positions alone.
  std::vector<std::pair<Gid, std::size_t>> order;
  for (std::size_t k = 0; k < block.size(); ++k) order.push_back({block.gid[k], k});
  std::sort(order.begin(), order.end());
  const std::size_t n = order.size();
  std::vector<std::vector<char>> near(n, std::vector<char>(n, 0));
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b) {
      const double* x = block.fixedRow(order[a].second);
      const double* y = block.fixedRow(order[b].second);
      const double d2 = (x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
                        (x[2] - y[2]) * (x[2] - y[2]);
      near[a][b] = a != b && d2 <= horizon * horizon;
    }
  std::map<Gid, long> reference;
  std::vector<long> ref(n, -1);
  for (std::size_t a = 0; a < n; ++a) {
    std::set<long> taken;
    for (std::size_t b = 0; b < a; ++b) {
      bool close = near[a][b];
      for (std::size_t m = 0; m < n && !close; ++m) close = near[a][m] && near[m][b];
      if (close) taken.insert(ref[b]);
    }
    long c = 0;
    while (taken.count(c)) ++c;
    ref[a] = c;
    reference[order[a].first] = c;
  }
  long most = 0;
  for (const auto& [g, c] : reference) most = std::max(most, c + 1);
  EXPECT_EQ(count, most);
  EXPECT_GE(count, 19) << "an interior particle and its 18 partners need 19 colours";
  for (std::size_t i = 0; i < P.owned(); ++i) EXPECT_EQ(colour[i], reference[P.gid(i)]);

  // Distance 2 on the bonds themselves, ghosts' colours fetched from their owners.
  std::vector<double> local(P.local(), -1.0);
  for (std::size_t i = 0; i < P.owned(); ++i) local[i] = static_cast<double>(colour[i]);
  ctx.refreshGhosts(local, 1);
  for (std::size_t i = 0; i < P.owned(); ++i) {
    std::set<double> seen{local[i]};
    for (std::size_t b = ctx.bonds.begin(i); b < ctx.bonds.end(i); ++b) {
      const double c = local[static_cast<std::size_t>(ctx.bonds.partner(b))];
      EXPECT_GE(c, 0.0);
      EXPECT_TRUE(seen.insert(c).second) << "particle " << P.gid(i) << ": colour " << c;
    }
  }
}

}  // namespace
}  // namespace pdq
