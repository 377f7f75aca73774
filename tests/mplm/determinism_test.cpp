// A cracking run (plate, reinforced beam) gives the same bits on one rank and on all ranks
// of the test, with both copies of every interaction agreeing.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cstring>
#include <map>
#include <vector>

#include "harness.hpp"
#include "models/mplm/2d/attributes.hpp"
#include "prep/mplm/generators.hpp"

namespace pdq::mplm {
namespace {

struct State {
  std::map<Gid, std::vector<double>> particles;              // gid -> alterable row
  std::map<std::pair<Gid, Gid>, std::vector<double>> bonds;  // (owner, partner) -> state
};

// A specimen and the model's parameters, run for `steps`.
struct Case {
  ParticleSet particles;
  Params params;
  long steps = 0;
};

// Runs the case at `load` on `comm` and gathers the final state on the comm's rank 0.
State runAndGather(const Case& c, double load, MPI_Comm mpiComm) {
  Comm comm(mpiComm);
  Params p = c.params;
  p.set("load_scale", std::to_string(load));
  auto sim = test::simulation(comm, p, c.particles, c.steps);
  sim->run();
  const Particles& P = sim->particles();
  const Bonds& B = sim->bonds();
  std::vector<double> rows, bonds;
  for (std::size_t i = 0; i < P.owned(); ++i) {
    rows.push_back(static_cast<double>(P.gid(i)));
    rows.insert(rows.end(), P.alter(i), P.alter(i) + N_ALTER);
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
      bonds.push_back(static_cast<double>(P.gid(i)));
      bonds.push_back(static_cast<double>(B.partnerGid(b)));
      bonds.insert(bonds.end(), B.attr(b), B.attr(b) + N_BOND);
    }
  }
  auto gather = [&](const std::vector<double>& mine) {
    int n = static_cast<int>(mine.size()), size = 0, rank = 0;
    MPI_Comm_size(mpiComm, &size);
    MPI_Comm_rank(mpiComm, &rank);
    std::vector<int> counts(size), displs(size);
    MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, mpiComm);
    int total = 0;
    for (int r = 0; r < size; ++r) {
      displs[r] = total;
      total += counts[r];
    }
    std::vector<double> all(rank == 0 ? total : 0);
    MPI_Gatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, 0,
                mpiComm);
    return all;
  };
  const auto allRows = gather(rows), allBonds = gather(bonds);
  State s;
  for (std::size_t k = 0; k < allRows.size(); k += 1 + N_ALTER)
    s.particles[static_cast<Gid>(allRows[k])] =
        std::vector<double>(allRows.begin() + k + 1, allRows.begin() + k + 1 + N_ALTER);
  for (std::size_t k = 0; k < allBonds.size(); k += 2 + N_BOND)
    s.bonds[{static_cast<Gid>(allBonds[k]), static_cast<Gid>(allBonds[k + 1])}] =
        std::vector<double>(allBonds.begin() + k + 2, allBonds.begin() + k + 2 + N_BOND);
  return s;
}

bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

void checkDeterministic(const Case& c, double load) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const State all = runAndGather(c, load, MPI_COMM_WORLD);
  MPI_Comm single;
  MPI_Comm_split(MPI_COMM_WORLD, rank == 0 ? 0 : MPI_UNDEFINED, 0, &single);
  if (rank != 0) return;
  const State one = runAndGather(c, load, single);
  MPI_Comm_free(&single);
  ASSERT_EQ(all.particles.size(), c.particles.size());
  ASSERT_EQ(one.particles.size(), all.particles.size());
  for (const auto& [gid, row] : all.particles)
    ASSERT_TRUE(sameBits(row, one.particles.at(gid))) << "particle " << gid;
  ASSERT_EQ(one.bonds.size(), all.bonds.size());
  long broken = 0;
  for (const auto& [key, st] : all.bonds) {
    ASSERT_TRUE(sameBits(st, one.bonds.at(key))) << "bond " << key.first << "-" << key.second;
    // Both copies of the interaction evolve alike.
    ASSERT_TRUE(sameBits(st, all.bonds.at({key.second, key.first})))
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
  BeamSpec b;
  b.span = 0.4;
  b.depth = 0.1;
  b.barDiameter = 0.01;
  b.stirrupDiameter = 0.006;
  b.stirrupFirst = 0.04;
  b.stirrupSpacing = 0.1;
  checkDeterministic({beam(b), test::params({}), 3000}, 200);
}

}  // namespace
}  // namespace pdq::mplm
