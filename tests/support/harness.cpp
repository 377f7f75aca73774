#include "support/harness.hpp"

#include <algorithm>
#include <cstring>
#include <numeric>

#include "engine/comm.hpp"

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

static std::vector<double> sortRows(std::vector<std::vector<char>> blocks, int width, int keys) {
  std::vector<double> all;
  for (auto& b : blocks) {
    const double* d = reinterpret_cast<const double*>(b.data());
    all.insert(all.end(), d, d + b.size() / sizeof(double));
  }
  const std::size_t n = width ? all.size() / width : 0;
  std::vector<std::size_t> idx(n);
  std::iota(idx.begin(), idx.end(), 0);
  std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
    for (int k = 0; k < keys; ++k)
      if (all[a * width + k] != all[b * width + k]) return all[a * width + k] < all[b * width + k];
    return false;
  });
  std::vector<double> out(all.size());
  for (std::size_t k = 0; k < n; ++k) std::copy_n(&all[idx[k] * width], width, &out[k * width]);
  return out;
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
  auto bytes = [](const std::vector<double>& v) {
    return std::vector<char>(reinterpret_cast<const char*>(v.data()),
                             reinterpret_cast<const char*>(v.data() + v.size()));
  };
  State s;
  s.particles = sortRows(sim.comm().gather(bytes(rows)), 1 + nA, 1);
  s.bonds = sortRows(sim.comm().gather(bytes(brows)), 3 + nB, 2);
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

std::unique_ptr<Model> makeModel(const std::string& name,
                                 const std::vector<std::pair<std::string, std::string>>& params) {
  auto m = ModelRegistry::create(name);
  Params p(name);
  for (const auto& [k, v] : params) p.set(k, v, "test", 0);
  m->configure(p);
  p.checkAllUsed();
  return m;
}

}  // namespace pdq::test
