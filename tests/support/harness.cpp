#include "support/harness.hpp"

#include <cstring>
#include <stdexcept>

#include "engine/comm.hpp"
#include "io/gather.hpp"
#include "io/standard_outputs.hpp"

namespace pdq::test {

MPI_Comm firstRanks(int n) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm c;
  MPI_Comm_split(MPI_COMM_WORLD, rank < n ? 0 : MPI_UNDEFINED, rank, &c);
  return c;
}

bool State::operator==(const State& o) const {
  return particles.size() == o.particles.size() && bonds.size() == o.bonds.size() &&
         std::memcmp(particles.data(), o.particles.data(), particles.size() * sizeof(double)) ==
             0 &&
         std::memcmp(bonds.data(), o.bonds.data(), bonds.size() * sizeof(double)) == 0;
}

State gatherState(Simulation& sim) {
  Particles& P = sim.particles();
  Bonds& B = sim.bonds();
  const int nA = P.schema().nAlter(), nB = B.nAttr();
  std::vector<double> rows, brows;
  for (std::size_t i = 0; i < P.owned(); ++i) {
    rows.push_back(static_cast<double>(P.gid(i)));
    rows.insert(rows.end(), P.alter(i), P.alter(i) + nA);
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
      brows.push_back(static_cast<double>(P.gid(i)));
      brows.push_back(static_cast<double>(B.partnerGid(b)));
      brows.push_back(B.alive(b) ? 0.0 : 1.0);
      brows.insert(brows.end(), B.attr(b), B.attr(b) + nB);
    }
  }
  State s;
  s.particles = gatherSortedRows(sim.comm(), rows, 1 + nA, 1);
  s.bonds = gatherSortedRows(sim.comm(), brows, 3 + nB, 2);
  return s;
}

State toWorldRoot(const State& s, int from) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (from == 0) return s;
  State out;
  for (int part = 0; part < 2; ++part) {
    const std::vector<double>& src = part ? s.bonds : s.particles;
    std::vector<double>& dst = part ? out.bonds : out.particles;
    if (rank == from) {
      long n = static_cast<long>(src.size());
      MPI_Send(&n, 1, MPI_LONG, 0, 90 + part, MPI_COMM_WORLD);
      MPI_Send(src.data(), static_cast<int>(n), MPI_DOUBLE, 0, 92 + part, MPI_COMM_WORLD);
    } else if (rank == 0) {
      long n = 0;
      MPI_Recv(&n, 1, MPI_LONG, from, 90 + part, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      dst.resize(n);
      MPI_Recv(dst.data(), static_cast<int>(n), MPI_DOUBLE, from, 92 + part, MPI_COMM_WORLD,
               MPI_STATUS_IGNORE);
    }
  }
  return out;
}

ParticleSet cubicBlock(const Schema& schema, int nx, int ny, int nz, double h) {
  ParticleSet ps;
  ps.nFixed = schema.nFixed();
  ps.nAlter = schema.nAlter();
  Gid id = 1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) ps.add(id++, i * h, j * h, k * h);
  return ps;
}

Params params(const std::vector<std::pair<std::string, std::string>>& kv) {
  Params p("test");
  for (const auto& [k, v] : kv) p.set(k, v, "test", 0);
  return p;
}

std::unique_ptr<Simulation> simulation(Comm& comm, const std::string& model, const Params& params,
                                       ParticleSet particles, long steps, const Loading& loading) {
  RunConfig run;
  run.steps = steps;
  run.loading = loading;
  auto sim = makeSimulation(makeProblem(model, params, std::move(particles), run), comm);
  sim->setup();
  return sim;
}

double global(Simulation& sim, const std::string& name) {
  const auto names = sim.model().globals();
  const auto values = sim.model().globalValues(sim.context());
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return values[k];
  throw std::runtime_error("no global " + name);
}

}  // namespace pdq::test
