// Bitwise identity of the final state of the same problems on 1, 2, 3 and 4 ranks, on
// different processor grids, and on 1 and 2 threads. The world (4 ranks) is split into
// sub-communicators, each runs the problem, and world rank 0 (rank 0 of every group)
// compares the gathered states with the one-rank, one-thread run.
#include <gtest/gtest.h>
#include <mpi.h>
#include <omp.h>
#include <unistd.h>

#include <cmath>
#include <cstring>

#include "pd_fixture.hpp"
#include "prep/cantilever.hpp"

namespace pdq::pdtest {
namespace {

using State = std::map<Gid, std::vector<double>>;

// A barrier that sleeps while it waits, so that ranks left out of a sub-communicator do
// not spin on the cores the running ones need.
void sleepyBarrier() {
  MPI_Request req;
  MPI_Ibarrier(MPI_COMM_WORLD, &req);
  int done = 0;
  while (MPI_Test(&req, &done, MPI_STATUS_IGNORE), !done) usleep(2000);
}

// Runs `make()` on world ranks [0, ranks) with the grid and thread count given; returns
// the gathered final alterable state and every bond's weight on world rank 0.
template <class Make>
State runOn(int ranks, std::array<int, 3> grid, int threads, Make make) {
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  MPI_Comm sub;
  MPI_Comm_split(MPI_COMM_WORLD, me < ranks ? 0 : MPI_UNDEFINED, me, &sub);
  State out;
  if (sub != MPI_COMM_NULL) {
    Comm comm(sub);
    omp_set_num_threads(threads);
    Problem pb = make();
    pb.run.procs = grid;
    auto sim = makeSimulation(std::move(pb), comm);
    sim->run();
    out = gatherAlter(*sim);
    // Broken bonds count too: append each particle's number of intact bonds. Bond rows:
    // owner, partner, dead, attributes.
    const std::vector<double> bonds = test::gatherState(*sim).bonds;
    const std::size_t width = 3 + sim->bonds().nAttr();
    std::map<Gid, double> intact;
    for (auto& [g, row] : out) intact[g] = 0;
    for (std::size_t r = 0; r < bonds.size(); r += width)
      intact[static_cast<Gid>(bonds[r])] += bonds[r + 3 + 1] == 0;
    for (auto& [g, row] : out) row.push_back(intact[g]);
    MPI_Comm_free(&sub);
  }
  omp_set_num_threads(1);
  sleepyBarrier();
  return out;
}

// Returns the reference state (world rank 0) after comparing every case with it.
template <class Make>
State checkIdentical(Make make) {
  int world = 0, me = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &world);
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  const State reference = runOn(1, {1, 1, 1}, 1, make);
  struct Case {
    int ranks;
    std::array<int, 3> grid;
    int threads;
  };
  const std::vector<Case> cases{{1, {1, 1, 1}, 2}, {2, {2, 1, 1}, 1}, {2, {1, 2, 1}, 2},
                                {3, {3, 1, 1}, 1}, {4, {2, 2, 1}, 1}, {4, {4, 1, 1}, 2}};
  int run = 0;
  for (const Case& c : cases) {
    if (c.ranks > world) continue;
    const State s = runOn(c.ranks, c.grid, c.threads, make);
    ++run;
    if (me != 0) continue;
    EXPECT_EQ(s.size(), reference.size());
    for (auto& [id, row] : reference)
      EXPECT_EQ(0, std::memcmp(row.data(), s.at(id).data(), row.size() * sizeof(double)))
          << "particle " << id << " differs on " << c.ranks << " ranks, grid " << c.grid[0] << "x"
          << c.grid[1] << ", " << c.threads << " threads";
  }
  EXPECT_EQ(run, world == 4 ? 6 : (world >= 2 ? 3 : 1));
  return reference;
}

// The thesis cantilever, small, LPS and PMB (damped, loaded, supported).
TEST(PdDeterminism, CantileverLps) {
  checkIdentical([] {
    prep::CantileverSpec spec;
    spec.m = 40;
    spec.n = 12;
    spec.steps = 30;
    prep::CantileverProblem c = prep::thesisCantilever(spec);
    Problem pb;
    pb.model = c.model;
    pb.params = c.params;
    pb.ps = std::move(c.particles);
    pb.run = c.run;
    pb.run.outDir = "pd_det_out";
    return pb;
  });
}

// A 3D block of PMB with breaking bonds: a fast velocity field tears it.
TEST(PdDeterminism, BreakingPmb3D) {
  const State ref = checkIdentical([] {
    Problem pb = latticeProblem("pmb",
                                {{"E", 1.0},
                                 {"horizon", 2.0},
                                 {"density", 1.0},
                                 {"dt", 0.2},
                                 {"critical_stretch", 0.01},
                                 {"lattice_spacing", 1.0}},
                                prep::cubicLattice(12, 10, 8, 1.0));
    pb.params.set("surface_correction", "true");
    const int vx = pb.acol("vx");
    for (std::size_t k = 0; k < pb.ps.size(); ++k) {
      const double* X = pb.ps.fixedRow(k);
      pb.ps.alterRow(k)[vx] = 0.04 * (X[0] - 5.5) + 0.003 * X[1] * X[2];
      pb.ps.alterRow(k)[vx + 1] = 0.01 * std::sin(X[0]);
    }
    pb.run.steps = 40;
    pb.run.outDir = "pd_det_out";
    return pb;
  });
  double broken = 0;
  for (auto& [id, row] : ref) broken += row.back();
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  if (me == 0) {
    EXPECT_GT(broken, 100) << "the block should tear";
  }
}

}  // namespace
}  // namespace pdq::pdtest
