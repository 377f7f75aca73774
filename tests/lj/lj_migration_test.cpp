// 10,000 steps of a 4000-atom Lennard-Jones melt (T* = 1.44, density 0.8442) with particles
// migrating between ranks: no particle is ever lost or duplicated (the gathered set of
// global IDs is exactly 1..4000 every 1000 steps), particles really changed ranks, and the
// total energy is conserved.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>

#include "lj_setup.hpp"

namespace pdq {
namespace {

// Global ID -> owning rank, on rank 0.
std::map<Gid, int> owners(Simulation& sim) {
  const Particles& P = sim.particles();
  std::vector<char> mine(P.owned() * sizeof(Gid));
  for (std::size_t i = 0; i < P.owned(); ++i) {
    const Gid g = P.gid(i);
    std::memcpy(&mine[i * sizeof g], &g, sizeof g);
  }
  std::map<Gid, int> out;
  const auto blocks = sim.comm().gather(mine);
  for (std::size_t r = 0; r < blocks.size(); ++r)
    for (std::size_t k = 0; k < blocks[r].size() / sizeof(Gid); ++k) {
      Gid g;
      std::memcpy(&g, &blocks[r][k * sizeof g], sizeof g);
      out.emplace(g, static_cast<int>(r));  // a duplicate keeps its first owner
    }
  return out;
}

TEST(LjMigration, NoParticleIsLostOrDuplicatedOver10000Steps) {
  Comm comm;
  ljtest::Melt m;
  m.cells = 10;  // 4000 atoms
  m.steps = 10000;
  auto sim = ljtest::makeMelt(m, comm);
  const double e0 = test::global(*sim, "total");
  const long n = 4L * m.cells * m.cells * m.cells;
  const std::map<Gid, int> start = owners(*sim);
  long checks = 0;
  while (sim->advance()) {
    if (sim->step() % 1000) continue;
    const long owned = comm.sum(static_cast<long>(sim->particles().owned()));
    const std::map<Gid, int> now = owners(*sim);
    EXPECT_EQ(owned, n) << "step " << sim->step();
    if (comm.root()) {
      // The map drops duplicates, so n distinct IDs from n particles means none was
      // duplicated, and IDs 1..n present means none was lost.
      EXPECT_EQ(static_cast<long>(now.size()), n) << "step " << sim->step();
      EXPECT_EQ(now.begin()->first, 1);
      EXPECT_EQ(now.rbegin()->first, n);
    }
    ++checks;
  }
  EXPECT_EQ(checks, 9);  // steps 1000..9000; the last step is checked below
  const std::vector<double> end = test::gatherState(*sim).particles;  // gid, alterable row
  const std::size_t width = 1 + sim->particles().schema().nAlter();
  const std::map<Gid, int> last = owners(*sim);
  if (comm.root()) {
    ASSERT_EQ(end.size(), n * width);
    for (long k = 0; k < n; ++k) ASSERT_EQ(end[k * width], k + 1) << "lost or duplicated";
    long moved = 0;
    for (const auto& [g, r] : last) moved += start.at(g) != r;
    if (comm.size() > 1) {
      EXPECT_GT(moved, n / 10) << "particles hardly migrated";
    }
    std::printf("%ld of %ld particles end on another rank than they started on\n", moved, n);
  }
  EXPECT_GT(sim->stats().shuffles, 100u);
  const double e = test::global(*sim, "total");
  EXPECT_LT(std::fabs(e - e0) / std::fabs(e0), 1e-3) << "E0 " << e0 << " E " << e;
}

}  // namespace
}  // namespace pdq
