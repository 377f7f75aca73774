// A cracking run (plate, reinforced beam) gives the same bits on one rank and on all ranks
// of the test, with both copies of every interaction agreeing.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cstring>
#include <map>
#include <utility>

#include "harness.hpp"
#include "models/mplm/2d/attributes.hpp"
#include "prep/mplm/generators.hpp"
#include "support/harness.hpp"

namespace pdq::mplm {
namespace {

// A specimen and the model's parameters, run for `steps`.
struct Case {
  ParticleSet particles;
  Params params;
  long steps = 0;
};

// Runs the case at `load` on `comm` and gathers the final state on the comm's rank 0.
pdq::test::State runAndGather(const Case& c, double load, MPI_Comm mpiComm) {
  Comm comm(mpiComm);
  Params p = c.params;
  Loading loading;
  loading.scale = load;
  auto sim = test::simulation(comm, p, c.particles, c.steps, "mplm2d", loading);
  sim->run();
  return pdq::test::gatherState(*sim);
}

void checkDeterministic(const Case& c, double load) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const pdq::test::State all = runAndGather(c, load, MPI_COMM_WORLD);
  MPI_Comm single;
  MPI_Comm_split(MPI_COMM_WORLD, rank == 0 ? 0 : MPI_UNDEFINED, 0, &single);
  if (rank != 0) return;
  const pdq::test::State one = runAndGather(c, load, single);
  MPI_Comm_free(&single);
  ASSERT_EQ(all.particles.size(), c.particles.size() * (1 + N_ALTER));
  EXPECT_TRUE(one == all) << "one rank and all ranks differ";
  // Both copies of every interaction evolve alike. Bond rows: owner, partner, dead, state.
  const std::size_t width = 3 + N_BOND;
  std::map<std::pair<Gid, Gid>, const double*> state;
  for (std::size_t k = 0; k < all.bonds.size(); k += width)
    state[{static_cast<Gid>(all.bonds[k]), static_cast<Gid>(all.bonds[k + 1])}] = &all.bonds[k + 3];
  long broken = 0;
  for (const auto& [key, st] : state) {
    ASSERT_EQ(std::memcmp(st, state.at({key.second, key.first}), N_BOND * sizeof(double)), 0)
        << "bond " << key.first << "-" << key.second;
    if (std::max(st[OMEGA_T], st[OMEGA_C]) >= 1) ++broken;
  }
  EXPECT_GT(broken, 0) << "the run should crack";
}

TEST(Determinism, CrackingPlateSameBitsOnOneAndAllRanks) {
  const Scenario sc = test::example("tension_x");
  checkDeterministic({sc.problem.particles, sc.modelParams, 4000}, 3.5);
}

TEST(Determinism, ReinforcedBeamSameBitsOnOneAndAllRanks) {
  checkDeterministic({test::smallBeam(), test::params({}), 3000}, 200);
}

}  // namespace
}  // namespace pdq::mplm
