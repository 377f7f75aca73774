// Lennard-Jones throughput: an fcc crystal at density 0.8442 melting from T* = 1.44
// (rc = 2.5, skin 0.3, dt = 0.005, energy-shifted), timed over the time loop only, as
// LAMMPS's "Loop time". Prints one line of key=value pairs on rank 0.
//
//   mpirun -np R lj_bench CELLS STEPS [DIVISIONS]   (4 CELLS^3 atoms; the model's
//                                                    cell_divisions, default its own)
#include <mpi.h>
#include <omp.h>
#include <time.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "engine/model.hpp"
#include "engine/simulation.hpp"
#include "io/standard_outputs.hpp"
#include "prep/fcc.hpp"

namespace {

int run(int argc, char** argv) {
  if (argc != 3 && argc != 4) {
    std::fprintf(stderr, "usage: lj_bench CELLS STEPS [DIVISIONS]\n");
    return 2;
  }
  const int cells = std::atoi(argv[1]);
  const long steps = std::atol(argv[2]);
  pdq::Comm comm;

  pdq::Params p("lj_bench");
  p.set("cutoff", "2.5");
  p.set("skin", "0.3");
  p.set("dt", "0.005");
  p.set("shift", "energy");
  if (argc == 4) p.set("cell_divisions", argv[3]);
  pdq::Problem pb = pdq::makeProblem("lj", p, {});
  pdq::ParticleSet& ps = pb.particles;
  pdq::FccSpec spec;
  spec.cells = {cells, cells, cells};
  spec.density = 0.8442;
  spec.temperature = 1.44;
  spec.seed = 87287;
  spec.velocityColumn = pb.model->schema().alterIndex("vx");
  const pdq::FccBox box = pdq::makeFcc(spec, ps);
  const double atoms = static_cast<double>(ps.size());

  pdq::RunConfig& cfg = pb.run;
  cfg.periodic = {true, true, true};
  cfg.boxLo = box.lo;
  cfg.boxHi = box.hi;
  cfg.minCellSize = 2.5 + 0.3;
  cfg.steps = steps;
  cfg.checkEvery = 0;
  const auto simulation = pdq::makeSimulation(std::move(pb), comm);
  pdq::Simulation& sim = *simulation;
  sim.setup();
  const double e0 = sim.model().globalValues(sim.context())[2];
  auto cpuSeconds = [] {
    timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
  };
  comm.barrier();
  const double t0 = MPI_Wtime(), c0 = cpuSeconds();
  while (sim.advance()) {
  }
  const double mine = cpuSeconds() - c0;
  const double cpu = comm.max(mine);
  const double cpuSum = comm.sum(static_cast<long>(1e6 * mine)) * 1e-6;
  comm.barrier();
  const double seconds = MPI_Wtime() - t0;
  const double e1 = sim.model().globalValues(sim.context())[2];
  const pdq::Timers& t = sim.timers();
  if (comm.root())
    std::printf(
        "code=pdq atoms=%.0f ranks=%d threads=%d steps=%ld seconds=%.4f "
        "particle_steps_per_s=%.4e cpu_seconds=%.4f cpu_sum=%.4f force=%.3f shuffle=%.3f comm=%.3f "
        "integrate=%.3f "
        "shuffles=%llu drift=%.2e\n",
        atoms, comm.size(), omp_get_max_threads(), steps, seconds, atoms * steps / seconds, cpu,
        cpuSum, t[pdq::Phase::Force], t[pdq::Phase::Shuffle], t[pdq::Phase::Communication],
        t[pdq::Phase::Integrate], static_cast<unsigned long long>(sim.stats().shuffles),
        (e1 - e0) / std::abs(e0));
  // One line per rank: the CPU seconds of its steps by phase.
  const std::string line = "  rank=" + std::to_string(comm.rank()) +
                           " owned=" + std::to_string(sim.particles().owned()) +
                           " cpu=" + std::to_string(mine) + " " + pdq::cpuBreakdown(t, mine) + "\n";
  for (const auto& b : comm.gather(std::vector<char>(line.begin(), line.end())))
    if (comm.root()) std::fwrite(b.data(), 1, b.size(), stdout);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  pdq::MpiSession mpi(&argc, &argv);
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {  // bad sizes: the engine's message, not an abort
    std::fprintf(stderr, "lj_bench: %s\n", e.what());
    return 1;
  }
}
