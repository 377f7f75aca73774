// Bitwise identity: the same Lennard-Jones melt (1372 atoms, 100 steps, with shuffles and
// migration) run on 1 rank with 1 and 2 OpenMP threads, on 2 and 3 ranks and on 4 ranks
// with several processor grids, and on 2 ranks with cells cut into 1, 8 (the model's
// default) or 27 sub-cells, and on 1 rank with the portable kernel (kernel = "portable": no
// AVX-512 loops, which the others take where the processor has them), ends in the same bits
// — positions, velocities and the global energies. Each run uses a sub-communicator of the ranks
// this test was started on; runs on disjoint ranks go side by side, and world rank 0 compares every
// run's final state with the first.
#include <gtest/gtest.h>
#include <mpi.h>
#include <omp.h>

#include <cstring>
#include <sstream>

#include "lj_setup.hpp"

namespace pdq {
namespace {

struct Config {
  int first, ranks;  // world ranks first .. first + ranks - 1
  std::array<int, 3> grid;
  int threads;
  int divisions = 0;  // the model's cell_divisions; 0: its default
  bool portable = false;
  std::string describe() const {
    std::ostringstream os;
    os << ranks << " rank(s), grid " << grid[0] << "x" << grid[1] << "x" << grid[2] << " ("
       << (grid[0] ? "given" : "automatic") << "), " << threads << " thread(s)";
    if (divisions) os << ", cell divisions " << divisions;
    if (portable) os << ", portable kernel";
    return os.str();
  }
};

// Particles' rows (global ID, alterable attributes) in ID order, then the globals.
using Outcome = std::vector<double>;

Outcome simulate(const Config& r, MPI_Comm sub) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(r.threads);
  Outcome out;
  {
    Comm comm(sub);
    ljtest::Melt m;
    m.cells = 7;  // 4 cells of 2.94 per axis: room for 4 ranks along one axis
    m.steps = 100;
    m.procs = r.grid;
    m.divisions = r.divisions;
    m.portable = r.portable;
    auto sim = ljtest::makeMelt(m, comm);
    const int along = sim->decomposition().globalCells(0) / 4;  // 4 whole cells
    EXPECT_EQ(along, r.ranks == 1 || !r.divisions ? 1 : r.divisions) << r.describe();
    while (sim->advance()) {
    }
    EXPECT_GT(sim->stats().shuffles, 5u);
    const std::vector<double> globals = sim->model().globalValues(sim->context());
    out = test::gatherState(*sim).particles;
    out.insert(out.end(), globals.begin(), globals.end());
  }
  omp_set_num_threads(before);
  return out;
}

// Runs one round of side-by-side runs; world rank 0 returns every run's outcome.
std::vector<Outcome> round(const std::vector<Config>& runs) {
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  int colour = MPI_UNDEFINED;
  for (std::size_t k = 0; k < runs.size(); ++k)
    if (me >= runs[k].first && me < runs[k].first + runs[k].ranks) colour = static_cast<int>(k);
  MPI_Comm sub;
  MPI_Comm_split(MPI_COMM_WORLD, colour, me, &sub);
  Outcome mine;
  if (sub != MPI_COMM_NULL) {
    mine = simulate(runs[colour], sub);
    MPI_Comm_free(&sub);
  }
  // Each run's first rank holds its outcome; bring them all to world rank 0.
  std::vector<Outcome> all(runs.size());
  for (std::size_t k = 0; k < runs.size(); ++k)
    all[k] = test::toWorldRoot({mine, {}}, runs[k].first).particles;
  return all;
}

TEST(LjIdentity, SameBitsOnAnyRankCountGridAndThreadCount) {
  int size = 0, me = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  // Rounds of runs on disjoint ranks; the first run is the reference.
  const std::vector<std::vector<Config>> rounds = {
      {{0, 1, {1, 1, 1}, 1}, {1, 1, {1, 1, 1}, 2}},
      {{0, 1, {1, 1, 1}, 1, 0, true}, {1, 1, {1, 1, 1}, 2, 0, true}},
      {{0, 2, {0, 0, 0}, 1}, {2, 2, {1, 2, 1}, 2}},
      {{0, 2, {2, 1, 1}, 1, 2}, {2, 2, {2, 1, 1}, 1, 3}},
      {{0, 3, {3, 1, 1}, 1}},
      {{0, 4, {4, 1, 1}, 1}},
      {{0, 4, {2, 2, 1}, 1}},
      {{0, 4, {1, 1, 4}, 2}},
  };
  std::vector<std::pair<Config, Outcome>> done;
  for (const auto& r : rounds) {
    std::vector<Config> fitting;
    for (const Config& run : r)
      if (run.first + run.ranks <= size) fitting.push_back(run);
    const std::vector<Outcome> outs = round(fitting);
    for (std::size_t k = 0; k < fitting.size(); ++k) done.emplace_back(fitting[k], outs[k]);
  }
  if (me != 0) return;
  const Outcome& ref = done.front().second;
  ASSERT_GT(ref.size(), 1372u);
  EXPECT_EQ(ref[0], 1.0);  // rows start with the global IDs
  for (std::size_t k = 1; k < done.size(); ++k) {
    const auto& [run, o] = done[k];
    ASSERT_EQ(o.size(), ref.size()) << run.describe();
    EXPECT_EQ(0, std::memcmp(o.data(), ref.data(), ref.size() * sizeof(double)))
        << run.describe() << " differs from " << done.front().first.describe();
  }
  EXPECT_EQ(done.size(), size >= 4 ? 12u : size >= 2 ? 6u : 2u);
}

}  // namespace
}  // namespace pdq
