// Peridynamics benchmark driver (run under mpirun):
//   pd_bench cantilever M N MODEL [PX PY [STEPS]]
//                                           the thesis benchmark (§3.5): prints the
//                                           monitored particle's final Y (16 digits),
//                                           the time of the steps and the peak memory
//   pd_bench block N MODEL STEPS [DIR [DT]] an N×N×N simple-cubic block, δ = 3 s, started
//                                           from a smooth velocity field at rest position:
//                                           prints throughput; with DIR writes DIR/pdq.disp
//                                           (ID ux uy uz) and DIR/lammps.data + DIR/lammps.in,
//                                           the same problem for LAMMPS's PERI package
//   pd_bench check_cost N STEPS [RUNS]      the block (PMB) checked at every second
//                                           step: the instability check's cost (CPU
//                                           and wall time, checked steps over the others)
//   pd_bench check_steps N STEPS EVERY      the block (PMB) checked every EVERY steps (0:
//                                           never): prints its CPU time; run under
//                                           valgrind --tool=callgrind with EVERY 1 and 0,
//                                           the instructions of Simulation::advance give
//                                           the checks' share of a step
//   pd_bench checkpoint_cost N STEPS EVERY  the block (PMB) with and without a checkpoint
//                                           every EVERY steps: their cost
//   pd_bench compare FILE_A FILE_B          largest |u_a - u_b| over the largest |u_a|
//   pd_bench bandwidth                      one core's memory read bandwidth
//   pd_bench divider                        one core's square-root and division throughput
//   pd_bench incore [BONDS]                 the PMB kernel with all it reads in the cache:
//                                           the core's own time a bond
#include <immintrin.h>
#include <mpi.h>
#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "engine/atomic_file.hpp"
#include "engine/comm.hpp"
#include "engine/error.hpp"
#include "engine/packed_positions.hpp"
#include "engine/problem.hpp"
#include "engine/simulation.hpp"
#include "io/checkpoint.hpp"
#include "io/standard_outputs.hpp"
#include "io/thesis_input.hpp"
#include "lammps_peer.hpp"
#include "models/peri/bond_classes.hpp"
#include "models/peri/peri_model.hpp"
#include "models/pmb/pmb_kernel.hpp"
#include "prep/cantilever.hpp"
#include "prep/lattice.hpp"

namespace {

using namespace pdq;

double peakMemoryMiB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;  // kB on Linux
}

double cpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// The time of the steps, setup excluded: wall clock and the busiest rank's CPU time (on a
// shared machine the CPU time is the work done; the wall clock also counts waiting for a core).
// Per rank: its own CPU and wall time, messages sent, page faults and context switches.
struct RunTime {
  double wall, cpu, cpuSum, cpuMine;  // cpu: the busiest rank's; cpuSum: every rank's
  double wallMine = 0;
  std::uint64_t messages = 0;
  long faults = 0, voluntary = 0, involuntary = 0;
};

RunTime timedRun(Simulation& sim, Comm& comm) {
  sim.setup();
  comm.barrier();
  rusage u0{}, u1{};
  getrusage(RUSAGE_SELF, &u0);
  const std::uint64_t m0 = comm.messages();
  const double t0 = MPI_Wtime(), c0 = cpuSeconds();
  while (sim.advance()) {
  }
  const double mine = cpuSeconds() - c0, wallMine = MPI_Wtime() - t0;
  getrusage(RUSAGE_SELF, &u1);
  const double cpu = comm.max(mine);
  ExactSum acc;
  acc.add(mine);
  const double sum = comm.sum(acc);
  const double t = comm.max(MPI_Wtime() - t0);
  sim.finish();
  RunTime rt{t, cpu, sum, mine};
  rt.wallMine = wallMine;
  rt.messages = comm.messages() - m0;
  rt.faults = u1.ru_minflt - u0.ru_minflt + u1.ru_majflt - u0.ru_majflt;
  rt.voluntary = u1.ru_nvcsw - u0.ru_nvcsw;
  rt.involuntary = u1.ru_nivcsw - u0.ru_nivcsw;
  return rt;
}

// One line per rank: its owned particles, the CPU seconds of its steps by phase, then the
// wall seconds of the phases, messages, page faults and context switches of the steps.
void printRankCpu(Simulation& sim, const RunTime& rt, Comm& comm) {
  char head[96], tail[320];
  std::snprintf(head, sizeof head, "  rank=%d owned=%zu ghosts=%zu cpu=%.3f ", comm.rank(),
                sim.particles().owned(), sim.particles().ghosts(), rt.cpuMine);
  const Timers& t = sim.timers();
  std::snprintf(tail, sizeof tail,
                " | wall=%.3f force=%.3f integrate=%.3f communication=%.3f messages=%llu "
                "faults=%ld csw=%ld/%ld\n",
                rt.wallMine, t[Phase::Force], t[Phase::Integrate], t[Phase::Communication],
                static_cast<unsigned long long>(rt.messages), rt.faults, rt.voluntary,
                rt.involuntary);
  const std::string line = head + cpuBreakdown(t, rt.cpuMine) + tail;
  auto blocks = comm.gather(std::vector<char>(line.begin(), line.end()));
  if (comm.root())
    for (auto& b : blocks) std::fwrite(b.data(), 1, b.size(), stdout);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

// Sum over ranks of one owned particle's alterable attribute (exact: one term is non-zero).
double attributeOf(Simulation& sim, Gid id, int column) {
  Particles& P = sim.particles();
  return sim.context().sumOwned(
      [&](std::size_t i) { return P.gid(i) == id ? P.alter(i)[column] : 0.0; });
}

int cantilever(int argc, char** argv, Comm& comm) {
  if (argc < 5)
    throw InputError("pd_bench", 0, "usage: pd_bench cantilever M N MODEL [PX PY [STEPS]]");
  prep::CantileverSpec spec;
  spec.m = std::stoi(argv[2]);
  spec.n = std::stoi(argv[3]);
  spec.model = argv[4];
  if (argc >= 8) spec.steps = std::stol(argv[7]);
  // The preprocessor writes the thesis's input files; the run reads them back.
  const std::string dir = "pd_cantilever_" + spec.model + "_" + argv[2] + "x" + argv[3] + "_np" +
                          std::to_string(comm.size());
  if (comm.root()) prep::writeThesisCantilever(spec, dir);
  comm.barrier();
  Problem pb = readThesisInput(dir);
  if (argc >= 7) pb.run.procs = {std::stoi(argv[5]), std::stoi(argv[6]), 1};
  pb.run.outDir = dir + "/out";
  pb.output = OutputSettings{};  // the steps alone are timed
  pb.output.finalRestart = false;
  const std::size_t nParticles = pb.particles.size();
  Gid monitored = 0;
  for (Gid g : pb.particles.gid) monitored = std::max(monitored, g);
  const auto simulation = makeSimulation(std::move(pb), comm);
  Simulation& sim = *simulation;
  const double t = timedRun(sim, comm).wall;
  const double y = attributeOf(sim, monitored, 1);
  const long bonds = comm.sum(static_cast<long>(sim.bonds().count()));
  double mem = peakMemoryMiB();
  ExactSum acc;
  acc.add(mem);
  mem = comm.sum(acc);
  if (comm.root())
    std::printf(
        "%s m=%d n=%d particles=%zu bonds=%ld ranks=%d grid=%dx%d threads=%d  Y=%.16g  "
        "time_s=%.3f  peak_MiB=%.1f\n",
        spec.model.c_str(), spec.m, spec.n, nParticles, bonds, comm.size(),
        sim.decomposition().procs(0), sim.decomposition().procs(1), omp_get_max_threads(), y, t,
        mem);
  return 0;
}

int block(int argc, char** argv, Comm& comm) {
  if (argc < 5) throw InputError("pd_bench", 0, "usage: pd_bench block N MODEL STEPS [DIR [DT]]");
  lammps::Block bl;
  bl.n = std::stoi(argv[2]);
  const std::string model = argv[3];
  const long steps = std::stol(argv[4]);
  const std::string dir = argc >= 6 ? argv[5] : "";
  if (argc >= 7) bl.dt = std::stod(argv[6]);
  Problem pb = makeProblem(model, lammps::blockParams(bl, model), {});
  pb.particles = lammps::blockParticles(bl, pb.model->schema());
  if (!dir.empty() && comm.root()) lammps::writeLammps(bl, model, steps, dir, pb.particles);
  pb.run.steps = steps;
  pb.run.outDir = dir.empty() ? "pd_block_out" : dir + "/pdq_out";
  const std::size_t nParticles = pb.particles.size();
  const auto simulation = makeSimulation(std::move(pb), comm);
  Simulation& sim = *simulation;
  const RunTime rt = timedRun(sim, comm);
  const double t = rt.wall;
  const long bonds = comm.sum(static_cast<long>(sim.bonds().count()));
  const Timers& tm = sim.timers();
  const double force = comm.max(tm[Phase::Force]), halo = comm.max(tm[Phase::Communication]);
  if (comm.root())
    std::printf(
        "pdq %s N=%zu bonds=%ld ranks=%d threads=%d steps=%ld time=%.4f s  "
        "particle-steps/s=%.4g  bond-steps/s=%.4g  cpu=%.4f s  cpu-particle-steps/s=%.4g  "
        "cpu_sum=%.4f s  force=%.3f s  halo=%.3f s  peak_MiB(rank0)=%.1f\n",
        model.c_str(), nParticles, bonds, comm.size(), omp_get_max_threads(), steps, t,
        nParticles * steps / t, bonds * double(steps) / t, rt.cpu, nParticles * steps / rt.cpu,
        rt.cpuSum, force, halo, peakMemoryMiB());
  printRankCpu(sim, rt, comm);
  if (!dir.empty()) {
    Particles& P = sim.particles();
    std::ostringstream os;
    os << std::setprecision(17);
    for (std::size_t i = 0; i < P.owned(); ++i)
      os << P.gid(i) << " " << P.alter(i)[0] - P.fixed(i)[0] << " " << P.alter(i)[1] - P.fixed(i)[1]
         << " " << P.alter(i)[2] - P.fixed(i)[2] << "\n";
    const std::string text = os.str();
    auto blocks = comm.gather(std::vector<char>(text.begin(), text.end()));
    if (comm.root()) {
      std::string all;
      for (auto& b : blocks) all.append(b.begin(), b.end());
      writeFileAtomically(dir + "/pdq.disp", all);
    }
  }
  return 0;
}

// The cost of the instability check every step (check_cost N STEPS [RUNS]; check_steps N
// STEPS EVERY for instruction counts) or of checkpoints every EVERY steps (checkpoint_cost
// N STEPS EVERY): the PMB block run without it and with it.
//
// The checks: RUNS runs (default 3) of the block checked at every second step, each
// step's CPU time (the busiest rank's, all its threads) and wall time taken alone. A machine shared
// with others slows a step by far more than the checks cost, and by varying amounts from
// one second to the next, so the cost is taken from steps next to each other: per run, the
// median of the checked steps over the median of the others, less 1; printed for each run,
// with the median and range over runs.
// Checkpoints: three runs with and three without, alternately, the fastest of each kind.
int featureCost(int argc, char** argv, Comm& comm) {
  const std::string what = argv[1];
  const bool checkpoints = what == "checkpoint_cost", counted = what == "check_steps";
  if (argc < (checkpoints || counted ? 5 : 4))
    throw InputError("pd_bench", 0,
                     "usage: pd_bench check_cost N STEPS [RUNS] | check_steps N STEPS EVERY | "
                     "checkpoint_cost N STEPS EVERY");
  lammps::Block bl;
  bl.n = std::stoi(argv[2]);
  const long steps = std::stol(argv[3]);
  const long every = checkpoints || counted ? std::stol(argv[4]) : 0;
  const std::string dir = checkpoints ? "pd_checkpoint_cost_out" : "pd_check_cost_out";
  auto simulation = [&](bool checks, bool written) {
    Problem pb = makeProblem("pmb", lammps::blockParams(bl, "pmb"), {});
    pb.particles = lammps::blockParticles(bl, pb.model->schema());
    pb.run.steps = steps;
    pb.run.outDir = dir;
    pb.run.checkEvery = counted ? every : checks ? 2 : 0;
    pb.output.checkpointEvery = every;
    pb.output.finalRestart = false;
    auto out = std::make_unique<CheckpointOutput>(pb.output, 0);
    auto sim = makeSimulation(std::move(pb), comm);
    if (written) sim->addOutput(std::move(out));
    return sim;
  };
  if (counted) {
    const RunTime t = timedRun(*simulation(true, false), comm);
    if (comm.root())
      std::printf("pmb N=%d^3 steps=%ld ranks=%d checked every %ld steps (0: never): %.4f s CPU\n",
                  bl.n, steps, comm.size(), every, t.cpu);
    return 0;
  }
  if (!checkpoints) {
    const int runs = argc > 4 ? std::stoi(argv[4]) : 3;
    if (runs < 1) throw InputError("pd_bench", 0, "RUNS must be at least 1");
    std::vector<double> cpuCost, wallCost;
    for (int r = 0; r < runs; ++r) {
      const auto sim = simulation(true, false);
      sim->setup();
      std::vector<double> cpu[2], wall[2];  // unchecked, checked steps
      for (;;) {
        comm.barrier();
        const double t0 = MPI_Wtime(), c0 = cpuSeconds();
        const bool more = sim->advance();
        const double c = comm.max(cpuSeconds() - c0);
        const double w = comm.max(MPI_Wtime() - t0);
        const int checked = sim->step() % 2 == 0 ? 1 : 0;
        cpu[checked].push_back(c);
        wall[checked].push_back(w);
        if (!more) break;
      }
      sim->finish();
      cpuCost.push_back(100 * (median(cpu[1]) / median(cpu[0]) - 1));
      wallCost.push_back(100 * (median(wall[1]) / median(wall[0]) - 1));
      if (comm.root())
        std::printf(
            "run %d: a step %.3f ms CPU, %.3f ms wall (medians without the check); "
            "check cost: CPU %.2f%%, wall %.2f%%\n",
            r + 1, 1e3 * median(cpu[0]), 1e3 * median(wall[0]), cpuCost.back(), wallCost.back());
    }
    if (comm.root())
      std::printf(
          "pmb N=%d^3 steps=%ld ranks=%d threads=%d, %d runs checked every second step: "
          "check cost CPU %.2f%% of a step (median; runs from %.2f%% to %.2f%%), wall %.2f%% "
          "(from %.2f%% to %.2f%%)\n",
          bl.n, steps, comm.size(), omp_get_max_threads(), runs, median(cpuCost),
          *std::min_element(cpuCost.begin(), cpuCost.end()),
          *std::max_element(cpuCost.begin(), cpuCost.end()), median(wallCost),
          *std::min_element(wallCost.begin(), wallCost.end()),
          *std::max_element(wallCost.begin(), wallCost.end()));
    return 0;
  }
  std::vector<double> times[2];
  for (int round = 0; round < 6; ++round) {
    const int on = round % 2;
    times[on].push_back(timedRun(*simulation(false, on), comm).wall);
  }
  if (!comm.root()) return 0;
  double best[2] = {1e300, 1e300};
  for (int on = 0; on < 2; ++on)
    for (double t : times[on]) best[on] = std::min(best[on], t);
  const double cost = 100 * (best[1] - best[0]) / best[0];
  const long count = steps / every + (steps % every ? 1 : 0);
  std::printf(
      "pmb N=%d^3 steps=%ld ranks=%d: without checkpoints %.4f s, with one every %ld steps "
      "(%ld, %.1f MB each) %.4f s: %.2f s per checkpoint, %.2f%% of the run\n",
      bl.n, steps, comm.size(), best[0], every, count,
      static_cast<double>(std::filesystem::file_size(checkpointPath(dir, steps))) / 1e6, best[1],
      (best[1] - best[0]) / static_cast<double>(count), cost);
  return 0;
}

int compare(int argc, char** argv) {
  if (argc < 4) throw InputError("pd_bench", 0, "usage: pd_bench compare A B");
  const lammps::Difference d = lammps::compare(lammps::readDisplacements(argv[2]),
                                               lammps::readDisplacements(argv[3]), argv[3]);
  std::printf("particles=%zu max|u|=%.6e max|du|=%.6e relative=%.3e\n", d.particles, d.maxU,
              d.maxDiff, d.relative());
  return 0;
}

// Read bandwidth of one core: sums a 512 MiB array several times (the bond arrays are
// streamed the same way), as a yardstick for the kernels' bytes per bond. CPU time, as the
// machine is shared (a busy machine still lowers it: the other jobs share the memory bus).
int bandwidth() {
  const std::size_t n = std::size_t(64) << 20;  // doubles
  std::vector<double> a(n, 1.0);
  double best = 0, sum = 0;
  for (int rep = 0; rep < 5; ++rep) {
    const double t0 = cpuSeconds();
    double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
    for (std::size_t k = 0; k < n; k += 4) {
      s0 += a[k];
      s1 += a[k + 1];
      s2 += a[k + 2];
      s3 += a[k + 3];
    }
    const double t = cpuSeconds() - t0;
    sum += s0 + s1 + s2 + s3;
    best = std::max(best, n * sizeof(double) / t);
  }
  std::printf("read bandwidth (1 core, CPU time, best of 5): %.2f GB/s  (check %.0f)\n", best / 1e9,
              sum);
  return 0;
}

// The square-root and division throughput of one core (eight independent streams of four
// or eight doubles): the PMB kernel needs one square root and one division per bond, the
// LPS kernels two square roots and one division, and the exact results the bitwise tests
// demand rule out a reciprocal estimate, so these bound the bond-steps/s. Times are CPU time
// (the machine is shared), best of five, per double.
[[gnu::target("avx2")]] double dividerSeconds4(int ops, long n, double* check) {
  __m256d a[8], s[8];
  for (int k = 0; k < 8; ++k) {
    a[k] = _mm256_set1_pd(1.5 + k);
    s[k] = _mm256_setzero_pd();
  }
  const __m256d step = _mm256_set1_pd(1e-9), one = _mm256_set1_pd(1.0);
  const double c0 = cpuSeconds();
  for (long r = 0; r < n; ++r)
    for (int k = 0; k < 8; ++k) {
      a[k] = _mm256_add_pd(a[k], step);
      __m256d v = a[k];
      if (ops & 1) v = _mm256_sqrt_pd(v);
      if (ops & 2) v = _mm256_div_pd(one, v);
      if (ops & 4) v = _mm256_sqrt_pd(_mm256_add_pd(v, one));
      s[k] = _mm256_add_pd(s[k], v);
    }
  const double t = cpuSeconds() - c0;
  for (int k = 0; k < 8; ++k) *check += _mm256_cvtsd_f64(s[k]);
  return t / static_cast<double>(4 * 8 * n);
}

// The same eight doubles an instruction (the AVX-512 kernels'). GCC 12's _mm512_sqrt_pd
// leaves lanes it overwrites uninitialised, which its own warning then reports.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
[[gnu::target("arch=x86-64-v4")]] double dividerSeconds8(int ops, long n, double* check) {
  __m512d a[8], s[8];
  for (int k = 0; k < 8; ++k) {
    a[k] = _mm512_set1_pd(1.5 + k);
    s[k] = _mm512_setzero_pd();
  }
  const __m512d step = _mm512_set1_pd(1e-9), one = _mm512_set1_pd(1.0);
  const double c0 = cpuSeconds();
  for (long r = 0; r < n; ++r)
    for (int k = 0; k < 8; ++k) {
      a[k] = _mm512_add_pd(a[k], step);
      __m512d v = a[k];
      if (ops & 1) v = _mm512_sqrt_pd(v);
      if (ops & 2) v = _mm512_div_pd(one, v);
      if (ops & 4) v = _mm512_sqrt_pd(_mm512_add_pd(v, one));
      s[k] = _mm512_add_pd(s[k], v);
    }
  const double t = cpuSeconds() - c0;
  alignas(64) double l[8];
  for (int k = 0; k < 8; ++k) {
    _mm512_store_pd(l, s[k]);
    *check += l[0];
  }
  return t / static_cast<double>(8 * 8 * n);
}
#pragma GCC diagnostic pop

int divider() {
  const long n = 20'000'000;
  for (int width : {4, 8}) {
    if (!(width == 4 ? __builtin_cpu_supports("avx2") : __builtin_cpu_supports("x86-64-v4"))) {
      std::printf("divider: no %s on this CPU\n", width == 4 ? "AVX2" : "AVX-512");
      continue;
    }
    double check = 0, best[8] = {1, 1, 1, 1, 1, 1, 1, 1};
    for (int rep = 0; rep < 5; ++rep)
      for (int ops : {1, 2, 3, 7})
        best[ops] = std::min(best[ops], width == 4 ? dividerSeconds4(ops, n / 2, &check)
                                                   : dividerSeconds8(ops, n / 4, &check));
    std::printf(
        "divider (1 core, CPU time, best of 5, %d doubles an instruction), per double: sqrt "
        "%.3f ns, div %.3f ns, sqrt+div %.3f ns, 2 sqrt+div %.3f ns  (check %.6g)\n",
        width, 1e9 * best[1], 1e9 * best[2], 1e9 * best[3], 1e9 * best[7], check);
    std::printf(
        "divider bound, %d-wide: PMB %.3g bond-steps/s (sqrt+div a bond), LPS %.3g (2 "
        "sqrt+div)\n",
        width, 1 / best[3], 1 / best[7]);
  }
  return 0;
}

// The PMB kernel of each vector width with everything it reads in the first-level cache:
// 200 particles of BONDS bonds (default 100, about the 47³ block's mean), partners among the
// next 16 rows, eight (length, weight) rows. Its time a bond is the core's own cost of a
// bond (loads, shuffles, square root, division, sums): the block's speed if memory cost
// nothing. CPU time, best of five.
int incore(int argc, char** argv) {
  const std::size_t particles = 200, near = 16, kRow = PackedPositions::kRow;
  const std::size_t nb = argc > 2 ? std::stoul(argv[2]) : 100;
  if (nb < 1 || nb > 1000) throw InputError("pd_bench", 0, "incore BONDS: 1 to 1000");
  std::vector<double> x(kRow * (particles + near + 1));
  for (std::size_t k = 0; k < x.size(); ++k)
    x[k] = 0.01 * static_cast<double>(k / kRow) + 0.1 * static_cast<double>(k % kRow);
  Bonds B(2);
  for (std::size_t i = 0; i < particles; ++i)
    for (std::size_t b = 0; b < nb; ++b) B.add(i, static_cast<Gid>(i * nb + b + 1));
  B.finish(particles);
  std::vector<std::int32_t> partner(B.count());
  for (std::size_t b = 0; b < B.count(); ++b) {
    partner[b] = static_cast<std::int32_t>(b / nb + 1 + (7 * b) % near);
    B.attr(b)[0] = 0.05 * static_cast<double>(1 + b % 8);
    B.attr(b)[1] = 1 + B.attr(b)[0];
  }
  B.renumberPartners() = partner;
  peri::BondClasses classes(kRow);
  classes.update(B);
  std::vector<double> acc(3 * particles);
  for (peri::Simd width : {peri::Simd::portable, peri::Simd::avx2, peri::Simd::avx512}) {
    if (width > peri::processorSimd()) continue;
    const peri::PmbKernel kernel = peri::pmbKernel(width);
    const peri::PmbView view{partner.data(),
                             B.attr(0),
                             kernel.readRows ? classes.rows() : peri::BondRows{},
                             x.data(),
                             kRow,
                             0.0,
                             &B};
    double best = 1e9;
    for (int rep = 0; rep < 5; ++rep) {
      const double c0 = cpuSeconds();
      for (int sweep = 0; sweep < 200; ++sweep) kernel.force(view, 0, particles, acc.data(), 3);
      best = std::min(best, (cpuSeconds() - c0) / (200.0 * particles));
    }
    double check = 0;  // the same at every width
    for (double a : acc) check += a;
    const char* name[] = {"portable", "AVX2", "AVX-512"};
    std::printf(
        "in-core PMB kernel (1 core, CPU time, best of 5, all in cache), %s: %.3f ns a bond, "
        "%.3g bond-steps/s, %.3g particle-steps/s at %zu bonds a particle  (check %.17g)\n",
        name[static_cast<int>(width)], 1e9 * best / static_cast<double>(nb),
        static_cast<double>(nb) / best, 1 / best, nb, check);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  MpiSession mpi(&argc, &argv);
  Comm comm;
  try {
    const std::string what = argc > 1 ? argv[1] : "";
    if (what == "cantilever") return cantilever(argc, argv, comm);
    if (what == "block") return block(argc, argv, comm);
    if (what == "check_cost" || what == "check_steps" || what == "checkpoint_cost")
      return featureCost(argc, argv, comm);
    if (what == "compare") return comm.root() ? compare(argc, argv) : 0;
    if (what == "bandwidth") return comm.root() ? bandwidth() : 0;
    if (what == "divider") return comm.root() ? divider() : 0;
    if (what == "incore") return comm.root() ? incore(argc, argv) : 0;
    std::fprintf(
        stderr,
        "usage: pd_bench "
        "cantilever|block|check_cost|check_steps|checkpoint_cost|compare|bandwidth|divider|"
        "incore "
        "...\n");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pd_bench: %s\n", e.what());
    comm.abort(1);
  }
}
