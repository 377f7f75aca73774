// A cracking 3D run gives the same bits on 1, 2 and 3 ranks, on processor grids cut along
// X and along Z, and on 1 or 2 threads.
#include <gtest/gtest.h>
#include <omp.h>

#include <array>
#include <map>
#include <string>

#include "io/standard_outputs.hpp"
#include "models/mplm/3d/attributes.hpp"
#include "support/harness.hpp"
#include "support/mplm3d_bar.hpp"

namespace pdq::mplm3d {
namespace {

struct Layout {
  int ranks;
  std::array<int, 3> grid;
  int threads;
};

// The cracking bar of support/mplm3d_bar.hpp, its far end moved at once.
test::State run(MPI_Comm c, const Layout& l) {
  omp_set_num_threads(l.threads);
  Problem pb = test::crackingBar3d();
  pb.run.procs = l.grid;
  pb.run.steps = 300;
  pb.run.outDir = "out_mplm3d_determinism";
  Comm comm(c);
  const auto sim = makeSimulation(std::move(pb), comm);
  sim->run();
  // The strength search's failure classifier sees the cracks (on every rank alike).
  const std::string mode = sim->model().strengthSpec().failureMode(sim->context());
  EXPECT_TRUE(mode == "flexural" || mode == "shear" || mode == "compression") << mode;
  return test::gatherState(*sim);
}

TEST(Mplm3dDeterminism, CrackingBarSameBitsOnRanksGridsThreads) {
  int world = 1, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &world);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const std::vector<Layout> layouts = {{1, {1, 1, 1}, 1}, {1, {1, 1, 1}, 2}, {2, {2, 1, 1}, 1},
                                       {2, {1, 1, 2}, 2}, {3, {3, 1, 1}, 1}, {3, {1, 1, 3}, 1}};
  test::State reference;
  bool haveReference = false;
  for (const Layout& l : layouts) {
    if (l.ranks > world) continue;
    MPI_Comm c = test::firstRanks(l.ranks);
    test::State st;
    if (c != MPI_COMM_NULL) {
      st = run(c, l);
      MPI_Comm_free(&c);
    }
    st = test::toWorldRoot(st, 0);
    if (rank != 0) continue;
    if (!haveReference) {
      reference = st;
      haveReference = true;
      // Bond rows: owner, partner, dead, ω_t, ω_c, plastic.
      double broken = 0;
      std::map<std::pair<double, double>, std::array<double, 3>> state;
      for (std::size_t b = 0; b + 5 < st.bonds.size(); b += 6) {
        if (std::max(st.bonds[b + 3], st.bonds[b + 4]) >= 1) broken += 1;
        state[{st.bonds[b], st.bonds[b + 1]}] = {st.bonds[b + 3], st.bonds[b + 4], st.bonds[b + 5]};
      }
      EXPECT_GT(broken, 0) << "the run should crack";
      // Both copies of every interaction evolve alike, bit for bit.
      for (const auto& [key, v] : state)
        ASSERT_TRUE(v == state.at({key.second, key.first})) << key.first << "-" << key.second;
    } else {
      EXPECT_TRUE(st == reference)
          << "differs on " << l.ranks << " ranks, grid " << l.grid[0] << "x" << l.grid[1] << "x"
          << l.grid[2] << ", " << l.threads << " threads";
    }
  }
  EXPECT_GE(world, 3);
}

}  // namespace
}  // namespace pdq::mplm3d
