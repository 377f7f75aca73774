// Scaling benchmark driver (bench/scaling/run.sh runs it; docs/scaling.md explains the model):
//   scaling_bench network                  on 2 ranks: the time of one exchange (both ranks
//                                          send and receive B bytes in one MPI_Sendrecv,
//                                          as every halo direction does) for B from 8 bytes
//                                          to 2 MiB, and of the step's reduction (a max of
//                                          4 doubles): the fastest and the median of 30
//                                          rounds (on a shared machine, noise only adds)
//   scaling_bench run SCENARIO STEPS       the scenario's time loop for STEPS steps after
//                                          one untimed step (its one-off work), without
//                                          outputs: CPU time of the model's force and
//                                          integration, CPU and wall time of the loop, the median
//                                          step, and the point-to-point messages and bytes
//                                          per step (all of them, and the halo's alone),
//                                          each the largest over the ranks
//   scaling_bench geometry SCENARIO N P... on 1 rank: for each rank count P, the processor
//                                          grid pdq takes and, on the busiest rank, the
//                                          owned particles, the wall particles its halo
//                                          sends to other ranks and its messages, from the
//                                          particles per cell and Plimpton's six steps; with
//                                          N > 0 the same member at N particles (cells
//                                          shrunk by (N/particles)^(1/dim), each fine cell
//                                          holding what its coarse cell held); cells as the
//                                          engine takes them (fewer along a cut axis when
//                                          the model's results allow, Model::resultsDependOnCells)
// Lines are `key=value` pairs for the script.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "engine/comm.hpp"
#include "engine/decomposition.hpp"
#include "engine/error.hpp"
#include "engine/model.hpp"
#include "engine/simulation.hpp"
#include "io/standard_outputs.hpp"
#include "scenario/scenario.hpp"

namespace {

using namespace pdq;

double cpuNow() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double wallNow() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

int network(Comm& comm) {
  if (comm.size() != 2) throw InputError("scaling_bench", 0, "network runs on 2 ranks");
  const int other = 1 - comm.rank();
  for (std::size_t bytes = 8; bytes <= (std::size_t(2) << 20); bytes *= 8) {
    const std::size_t n = bytes / sizeof(double);
    std::vector<double> out(n, 1.0), in(n);
    // Rounds of about a millisecond or less, so that the fastest fits in a time slice.
    const int reps = bytes <= 4096 ? 200 : bytes <= 32768 ? 50 : bytes <= 262144 ? 10 : 2;
    for (int k = 0; k < 20; ++k) comm.sendrecvKnown(out.data(), n, other, in.data(), n, other, 7);
    std::vector<double> rounds;
    for (int round = 0; round < 30; ++round) {
      comm.barrier();
      const double t0 = wallNow();
      for (int k = 0; k < reps; ++k)
        comm.sendrecvKnown(out.data(), n, other, in.data(), n, other, 7);
      rounds.push_back(comm.max(wallNow() - t0) / reps);
    }
    if (comm.root())
      std::printf("exchange bytes=%zu us=%.4f median_us=%.4f\n", bytes,
                  1e6 * *std::min_element(rounds.begin(), rounds.end()), 1e6 * median(rounds));
  }
  std::vector<double> rounds;
  for (int round = 0; round < 30; ++round) {
    comm.barrier();
    const double t0 = wallNow();
    for (int k = 0; k < 200; ++k) comm.max(std::vector<double>(4, comm.rank() + k));
    rounds.push_back(comm.max(wallNow() - t0) / 200);
  }
  if (comm.root())
    std::printf("reduction ranks=2 us=%.4f median_us=%.4f\n",
                1e6 * *std::min_element(rounds.begin(), rounds.end()), 1e6 * median(rounds));
  return 0;
}

// The scenario's model with the CPU time of its force and integration counted: the work
// that the model takes as proportional to the particles (Model is forwarded whole).
class CpuTimedModel : public Model {
 public:
  explicit CpuTimedModel(std::unique_ptr<Model> m) : m_(std::move(m)) {}
  double computeSeconds() const { return seconds_; }

  void configure(const Params& params) override { m_->configure(params); }
  Schema schema() const override { return m_->schema(); }
  double horizon() const override { return m_->horizon(); }
  double minCellSize() const override { return m_->minCellSize(); }
  bool shuffles() const override { return m_->shuffles(); }
  bool resultsDependOnCells() const override { return m_->resultsDependOnCells(); }
  void setup(Context& ctx) override { m_->setup(ctx); }
  void prepare(Context& ctx) override { m_->prepare(ctx); }
  void neighboursChanged(Context& ctx) override { m_->neighboursChanged(ctx); }
  void force(Context& ctx) override {
    const double t0 = cpuNow();
    m_->force(ctx);
    seconds_ += cpuNow() - t0;
  }
  void integrate(Context& ctx) override {
    const double t0 = cpuNow();
    m_->integrate(ctx);
    seconds_ += cpuNow() - t0;
  }
  Motion motion() const override { return m_->motion(); }
  void bodies(const Context& ctx, std::span<Body> owned) const override { m_->bodies(ctx, owned); }
  std::vector<double> saveState() const override { return m_->saveState(); }
  void loadState(std::span<const double> saved) override { m_->loadState(saved); }
  std::vector<std::string> fields() const override { return m_->fields(); }
  void field(const Context& ctx, int k, std::span<double> values) const override {
    m_->field(ctx, k, values);
  }
  std::vector<std::string> globals() const override { return m_->globals(); }
  std::vector<double> globalValues(Context& ctx) override { return m_->globalValues(ctx); }
  StrengthSpec strengthSpec() override { return m_->strengthSpec(); }

 private:
  std::unique_ptr<Model> m_;
  double seconds_ = 0;
};

// The scenario set up for a timed run in `dir` with no outputs.
struct SetUp {
  std::string model;
  const CpuTimedModel* timed;
  std::unique_ptr<Simulation> sim;
};
SetUp setUp(const std::string& path, long steps, const std::string& dir, Comm& comm) {
  Scenario sc = loadScenario(path);
  Problem& pb = sc.problem;
  pb.run.steps = steps;
  pb.run.outDir = dir;
  pb.output = {.finalRestart = false};
  auto timed = std::make_unique<CpuTimedModel>(std::move(pb.model));
  CpuTimedModel* model = timed.get();
  pb.model = std::move(timed);
  SetUp s{pb.modelName, model, makeSimulation(std::move(pb), comm)};
  s.sim->setup();
  return s;
}

int run(int argc, char** argv, Comm& comm) {
  if (argc < 4) throw InputError("scaling_bench", 0, "usage: scaling_bench run SCENARIO STEPS");
  const long steps = std::stol(argv[3]);
  const SetUp s = setUp(argv[2], steps + 1, "scaling_run_np" + std::to_string(comm.size()), comm);
  Simulation* sim = s.sim.get();
  sim->advance();
  const std::uint64_t m0 = comm.messages(), b0 = comm.bytes();
  std::uint64_t haloMessages = 0, haloBytes = 0;
  std::vector<double> stepWall;
  comm.barrier();
  const double c0 = cpuNow(), w0 = wallNow(), m0Cpu = s.timed->computeSeconds();
  for (double t = wallNow(); sim->advance(); t = wallNow()) {
    stepWall.push_back(wallNow() - t);
    haloMessages += sim->stats().haloMessages;
    haloBytes += sim->stats().haloBytes;
  }
  const double cpu = cpuNow() - c0, wall = wallNow() - w0;
  const double compute = s.timed->computeSeconds() - m0Cpu;
  const double n = static_cast<double>(stepWall.size());
  const double messages = static_cast<double>(comm.messages() - m0) / n;
  const double bytes = static_cast<double>(comm.bytes() - b0) / n;
  const double record = static_cast<double>(sim->procCube().haloRecordBytes());
  const std::vector<double> mx = comm.max(std::vector<double>{
      cpu, wall, median(stepWall), static_cast<double>(sim->particles().owned()), messages, bytes,
      static_cast<double>(haloMessages) / n, static_cast<double>(haloBytes) / n, compute});
  const long particles = comm.sum(static_cast<long>(sim->particles().owned()));
  const long cpuSumUs = comm.sum(static_cast<long>(1e6 * cpu));
  if (comm.root())
    std::printf(
        "run model=%s particles=%ld ranks=%d grid=%dx%dx%d steps=%ld compute_cpu_s=%.4f cpu_s=%.4f "
        "cpu_sum_s=%.4f "
        "wall_s=%.4f step_median_s=%.6g owned_max=%.0f messages=%.2f bytes=%.0f "
        "halo_messages=%.2f halo_bytes=%.0f halo_record=%.0f halo_wall=%.0f\n",
        s.model.c_str(), particles, comm.size(), sim->decomposition().procs(0),
        sim->decomposition().procs(1), sim->decomposition().procs(2), steps, mx[8], mx[0],
        1e-6 * static_cast<double>(cpuSumUs), mx[1], mx[2], mx[3], mx[4], mx[5], mx[6], mx[7],
        record, mx[7] / record);
  return 0;
}

// Particles per global cell, indexed with periodic wrap-around.
struct CellCounts {
  std::array<int, 3> n{1, 1, 1};
  std::array<bool, 3> periodic{};
  std::vector<double> count;
  double at(std::array<int, 3> c) const {
    for (int a = 0; a < 3; ++a)
      if (periodic[a]) c[a] = ((c[a] % n[a]) + n[a]) % n[a];
    return count[(static_cast<std::size_t>(c[2]) * n[1] + c[1]) * n[0] + c[0]];
  }
};

struct RankLoad {
  double owned = 0, wall = 0;  // owned particles; wall particles sent to other ranks a halo
  int messages = 0;            // messages sent to other ranks a halo
};

// What one rank owns and sends in one halo: the border pass's plan, Plimpton's six steps
// (the wall along axis a includes the skin already received along the axes before it).
RankLoad loadOf(const Decomposition& d, const CellCounts& cc, int rank) {
  RankLoad r;
  std::array<int, 3> lo{}, hi{};
  for (int a = 0; a < 3; ++a) {
    lo[a] = d.coreLo(a);
    hi[a] = d.coreHi(a);
  }
  auto sum = [&](std::array<int, 3> from, std::array<int, 3> to) {
    double s = 0;
    for (int z = from[2]; z < to[2]; ++z)
      for (int y = from[1]; y < to[1]; ++y)
        for (int x = from[0]; x < to[0]; ++x) s += cc.at({x, y, z});
    return s;
  };
  r.owned = sum(lo, hi);
  std::array<int, 3> from = lo, to = hi;
  for (int a = 0; a < d.dim(); ++a) {
    for (int dir : {+1, -1}) {
      const int dest = d.neighbour(a, dir);
      if (dest < 0 || dest == rank) continue;
      std::array<int, 3> f = from, t = to;
      f[a] = dir > 0 ? hi[a] - 1 : lo[a];
      t[a] = f[a] + 1;
      r.wall += sum(f, t);
      ++r.messages;
    }
    if (d.neighbour(a, -1) >= 0) from[a] = lo[a] - 1;
    if (d.neighbour(a, +1) >= 0) to[a] = hi[a] + 1;
  }
  return r;
}

int geometry(int argc, char** argv, Comm& comm) {
  if (argc < 5 || comm.size() != 1)
    throw InputError("scaling_bench", 0,
                     "usage (1 rank): scaling_bench geometry SCENARIO PARTICLES P...");
  const double target = std::stod(argv[3]);
  const SetUp s = setUp(argv[2], 0, "scaling_geometry", comm);
  Simulation* sim = s.sim.get();
  const Decomposition& dec = sim->decomposition();
  const Domain& dom = dec.domain();
  const Particles& P = sim->particles();
  const bool moving = sim->model().shuffles();
  CellCounts coarse;
  for (int a = 0; a < 3; ++a) {
    coarse.n[a] = dec.globalCells(a);
    coarse.periodic[a] = dom.periodic[a];
  }
  coarse.count.assign(static_cast<std::size_t>(coarse.n[0]) * coarse.n[1] * coarse.n[2], 0);
  for (std::size_t i = 0; i < P.owned(); ++i) {
    const double* x = moving ? P.alter(i) : P.fixed(i);
    std::array<int, 3> c{0, 0, 0};
    for (int a = 0; a < dec.dim(); ++a)
      c[a] = std::clamp(dec.globalCell(a, x[a]), 0, coarse.n[a] - 1);
    coarse.count[(static_cast<std::size_t>(c[2]) * coarse.n[1] + c[1]) * coarse.n[0] + c[0]] += 1;
  }
  const double particles = static_cast<double>(P.owned());
  const double scale = target > 0 ? std::pow(target / particles, 1.0 / dec.dim()) : 1.0;
  const double minCell =
      (sim->config().minCellSize > 0 ? sim->config().minCellSize : sim->model().minCellSize()) /
      scale;
  // The fine lattice: each fine cell holds what the coarse cell at its centre held, scaled
  // so that the whole holds the target.
  const Decomposition one(dom, minCell, {1, 1, 1}, 1, 0);
  CellCounts fine = coarse;
  if (target > 0) {
    for (int a = 0; a < 3; ++a) fine.n[a] = one.globalCells(a);
    fine.count.assign(static_cast<std::size_t>(fine.n[0]) * fine.n[1] * fine.n[2], 0);
    double total = 0;
    for (int z = 0; z < fine.n[2]; ++z)
      for (int y = 0; y < fine.n[1]; ++y)
        for (int x = 0; x < fine.n[0]; ++x) {
          std::array<int, 3> c{x, y, z}, o{};
          for (int a = 0; a < 3; ++a)
            o[a] =
                std::min(coarse.n[a] - 1, static_cast<int>((c[a] + 0.5) * coarse.n[a] / fine.n[a]));
          const double v = coarse.at(o);
          fine.count[(static_cast<std::size_t>(z) * fine.n[1] + y) * fine.n[0] + x] = v;
          total += v;
        }
    for (double& v : fine.count) v *= target / total;
  }
  std::printf("geometry model=%s particles=%.0f cells=%dx%dx%d dim=%d halo_record=%llu\n",
              s.model.c_str(), target > 0 ? target : particles, fine.n[0], fine.n[1], fine.n[2],
              dec.dim(), static_cast<unsigned long long>(sim->procCube().haloRecordBytes()));
  // The engine cuts the cores at equal particle counts: the layers' counts along each axis.
  std::array<std::vector<double>, 3> layers;
  for (int a = 0; a < 3; ++a) layers[a].assign(fine.n[a], 0.0);
  for (int z = 0; z < fine.n[2]; ++z)
    for (int y = 0; y < fine.n[1]; ++y)
      for (int x = 0; x < fine.n[0]; ++x) {
        const double v = fine.count[(static_cast<std::size_t>(z) * fine.n[1] + y) * fine.n[0] + x];
        layers[0][x] += v;
        layers[1][y] += v;
        layers[2][z] += v;
      }
  // A model whose results do not depend on the cells lets the engine take fewer cells along
  // an axis cut among cores (Decomposition::chooseCells), from the particles themselves.
  const bool cellsFree = !moving && !sim->model().resultsDependOnCells() && target <= 0;
  auto cellOf = [&](std::size_t i, int a, int n) {
    const double* x = P.fixed(i);
    const int g = static_cast<int>(std::floor((x[a] - dom.lo[a]) / (dom.length(a) / n)));
    return std::clamp(g, 0, n - 1);
  };
  auto layerWeights = [&](int a, int n) {
    std::vector<double> w(n, 0.0);
    for (std::size_t i = 0; i < P.owned(); ++i) w[cellOf(i, a, n)] += 1;
    return w;
  };
  for (int k = 4; k < argc; ++k) {
    const int ranks = std::stoi(argv[k]);
    RankLoad busiest;
    double ownedMax = 0, wallMax = 0, wallSum = 0;
    int messagesMax = 0;
    std::array<int, 3> grid{};
    CellCounts cells = fine;
    std::array<std::vector<double>, 3> weights = layers;
    if (cellsFree) {
      Decomposition d(dom, minCell, sim->config().procs, ranks, 0);
      d.chooseCells(layerWeights);
      for (int a = 0; a < 3; ++a) cells.n[a] = d.globalCells(a);
      cells.count.assign(static_cast<std::size_t>(cells.n[0]) * cells.n[1] * cells.n[2], 0);
      for (std::size_t i = 0; i < P.owned(); ++i) {
        std::array<int, 3> c{0, 0, 0};
        for (int a = 0; a < dec.dim(); ++a) c[a] = cellOf(i, a, cells.n[a]);
        cells.count[(static_cast<std::size_t>(c[2]) * cells.n[1] + c[1]) * cells.n[0] + c[0]] += 1;
      }
      for (int a = 0; a < dec.dim(); ++a) weights[a] = layerWeights(a, cells.n[a]);
    }
    for (int r = 0; r < ranks; ++r) {
      Decomposition d(dom, minCell, sim->config().procs, ranks, r);
      if (cellsFree) d.chooseCells(layerWeights);
      d.balance(weights);
      grid = {d.procs(0), d.procs(1), d.procs(2)};
      const RankLoad l = loadOf(d, cells, r);
      ownedMax = std::max(ownedMax, l.owned);
      wallMax = std::max(wallMax, l.wall);
      wallSum += l.wall;
      messagesMax = std::max(messagesMax, l.messages);
      if (l.owned > busiest.owned) busiest = l;
    }
    std::printf(
        "ranks=%d grid=%dx%dx%d cells_per_rank=%dx%dx%d owned_max=%.0f wall_max=%.0f "
        "wall_mean=%.0f messages_max=%d\n",
        ranks, grid[0], grid[1], grid[2], (cells.n[0] + grid[0] - 1) / grid[0],
        (cells.n[1] + grid[1] - 1) / grid[1], (cells.n[2] + grid[2] - 1) / grid[2], ownedMax,
        wallMax, wallSum / ranks, messagesMax);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  MpiSession mpi(&argc, &argv);
  Comm comm;
  using Command = int (*)(int, char**, Comm&);
  const std::map<std::string, Command> commands{
      {"network", [](int, char**, Comm& c) { return network(c); }},
      {"run", run},
      {"geometry", geometry}};
  const auto command = commands.find(argc > 1 ? argv[1] : "");
  if (command == commands.end()) {
    std::fprintf(stderr, "usage: scaling_bench network|run|geometry ...\n");
    return 2;
  }
  try {
    return command->second(argc, argv, comm);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "scaling_bench: %s\n", e.what());
    comm.abort(1);
  }
}
