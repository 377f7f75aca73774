#pragma once
// A small breaking spring lattice for the output tests: nx x ny particles at unit
// spacing (2D), pulled apart along X by an initial velocity field: fast in the upper
// half, whose springs break within a few steps, slow in the lower half, whose do not.
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "engine/comm.hpp"
#include "engine/model.hpp"
#include "engine/params.hpp"
#include "engine/simulation.hpp"

namespace pdq::test {

inline std::unique_ptr<Simulation> springLattice(Comm& comm, int nx, int ny, long steps,
                                                 const std::string& outDir, long firstStep = 0) {
  Params p("test");
  p.set("critical_stretch", "0.02");
  p.set("dt", "0.05");
  p.set("horizon", "1.5");
  auto model = ModelRegistry::create("spring");
  model->configure(p);
  const Schema s = model->schema();
  ParticleSet ps;
  ps.nFixed = s.nFixed();
  ps.nAlter = s.nAlter();
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const std::size_t k = ps.add(j * nx + i, i, j, 0);
      ps.alterRow(k)[3] = 0.05 * (i - 0.5 * (nx - 1)) * (2 * j >= ny ? 1.0 : 0.1);  // vx
      ps.alterRow(k)[4] = 0.005 * (j - 0.5 * (ny - 1));                             // vy
    }
  RunConfig cfg;
  cfg.steps = steps;
  cfg.firstStep = firstStep;
  cfg.outDir = outDir;
  return std::make_unique<Simulation>(std::move(model), std::move(ps), cfg, comm);
}

// Every rank's (global ID -> value of alterable column k) for its owned particles,
// gathered on rank 0.
inline std::map<long, double> gatherAlter(Simulation& sim, int k) {
  const Particles& P = sim.particles();
  std::vector<char> block;
  for (std::size_t i = 0; i < P.owned(); ++i) {
    const long id = P.gid(i);
    const double v = P.alter(i)[k];
    block.insert(block.end(), reinterpret_cast<const char*>(&id),
                 reinterpret_cast<const char*>(&id) + sizeof id);
    block.insert(block.end(), reinterpret_cast<const char*>(&v),
                 reinterpret_cast<const char*>(&v) + sizeof v);
  }
  std::map<long, double> all;
  for (const auto& b : sim.comm().gather(block))
    for (std::size_t o = 0; o + 16 <= b.size(); o += 16) {
      long id;
      double v;
      std::memcpy(&id, &b[o], 8);
      std::memcpy(&v, &b[o + 8], 8);
      all[id] = v;
    }
  return all;
}

// Every bond once, (smaller ID, larger ID) -> its first attribute, gathered on rank 0.
inline std::map<std::pair<long, long>, double> gatherBonds(Simulation& sim) {
  const Particles& P = sim.particles();
  const Bonds& B = sim.bonds();
  std::vector<char> block;
  auto put = [&](const void* p) {
    block.insert(block.end(), static_cast<const char*>(p), static_cast<const char*>(p) + 8);
  };
  for (std::size_t i = 0; i < P.owned(); ++i)
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
      const long a = P.gid(i), c = B.partnerGid(b);
      if (c < a) continue;
      const double broken = B.alive(b) ? 0.0 : 1.0;
      put(&a);
      put(&c);
      put(&broken);
    }
  std::map<std::pair<long, long>, double> all;
  for (const auto& b : sim.comm().gather(block))
    for (std::size_t o = 0; o + 24 <= b.size(); o += 24) {
      long a, c;
      double v;
      std::memcpy(&a, &b[o], 8);
      std::memcpy(&c, &b[o + 8], 8);
      std::memcpy(&v, &b[o + 16], 8);
      all[{a, c}] = v;
    }
  return all;
}

}  // namespace pdq::test
