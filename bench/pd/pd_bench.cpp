// Peridynamics benchmark driver (run under mpirun):
//   pd_bench cantilever M N MODEL [PX PY]   the thesis benchmark (§3.5): prints the
//                                           monitored particle's final Y (16 digits),
//                                           the time of the steps and the peak memory
//   pd_bench block N MODEL STEPS [DIR [DT]] an N×N×N simple-cubic block, δ = 3 s, started
//                                           from a smooth velocity field at rest position:
//                                           prints throughput; with DIR writes DIR/pdq.disp
//                                           (ID ux uy uz) and DIR/lammps.data + DIR/lammps.in,
//                                           the same problem for LAMMPS's PERI package
//   pd_bench compare FILE_A FILE_B          largest |u_a - u_b| over the largest |u_a|
#include <mpi.h>
#include <omp.h>
#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>

#include "engine/atomic_file.hpp"
#include "engine/comm.hpp"
#include "engine/error.hpp"
#include "engine/model.hpp"
#include "engine/simulation.hpp"
#include "models/peri/peri_model.hpp"
#include "prep/cantilever.hpp"
#include "prep/lattice.hpp"

namespace {

using namespace pdq;

double peakMemoryMiB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;  // kB on Linux
}

// Runs the steps and returns their wall time (max over ranks), setup excluded.
double timedRun(Simulation& sim, Comm& comm) {
  sim.setup();
  comm.barrier();
  const double t0 = MPI_Wtime();
  while (sim.advance()) {
  }
  const double t = comm.max(MPI_Wtime() - t0);
  sim.finish();
  return t;
}

// Sum over ranks of one owned particle's alterable attribute (exact: one term is non-zero).
double attributeOf(Simulation& sim, Gid id, int column) {
  Particles& P = sim.particles();
  return sim.context().sumOwned(
      [&](std::size_t i) { return P.gid(i) == id ? P.alter(i)[column] : 0.0; });
}

std::string num(double v) {
  std::ostringstream os;
  os << std::setprecision(17) << v;
  return os.str();
}

int cantilever(int argc, char** argv, Comm& comm) {
  if (argc < 5) throw InputError("pd_bench", 0, "usage: pd_bench cantilever M N MODEL [PX PY]");
  prep::CantileverSpec spec;
  spec.m = std::stoi(argv[2]);
  spec.n = std::stoi(argv[3]);
  spec.model = argv[4];
  prep::CantileverProblem pb = prep::thesisCantilever(spec);
  if (argc >= 7) pb.run.procs = {std::stoi(argv[5]), std::stoi(argv[6]), 1};
  pb.run.outDir = "pd_cantilever_out";
  const std::size_t nParticles = pb.particles.size();
  auto model = ModelRegistry::create(pb.model);
  model->configure(pb.params);
  pb.params.checkAllUsed();
  Simulation sim(std::move(model), std::move(pb.particles), pb.run, comm);
  const double t = timedRun(sim, comm);
  const double y = attributeOf(sim, pb.monitored, 1);
  const long bonds = comm.sum(static_cast<long>(sim.bonds().count()));
  double mem = peakMemoryMiB();
  ExactSum acc;
  acc.add(mem);
  mem = comm.sum(acc);
  if (comm.root())
    std::printf(
        "%s m=%d n=%d particles=%zu bonds=%ld ranks=%d grid=%dx%d threads=%d  Y=%.16g  "
        "steps_s=%.3f  peak_MiB=%.1f\n",
        spec.model.c_str(), spec.m, spec.n, nParticles, bonds, comm.size(),
        sim.decomposition().procs(0), sim.decomposition().procs(1), omp_get_max_threads(), y, t,
        mem);
  return 0;
}

// The block problem shared by pdq and LAMMPS.
struct Block {
  int n = 47;
  double s = 0.0254, E = 24.85e9, nu = 0.25, rho = 2323, dt = 1.0e-6;
  double v0 = 0.5;  // m/s amplitude of the initial velocity field
  double delta() const { return 3.0 * s; }
  void velocity(const double* X, double* v) const {
    const double L = n * s, k = 2 * std::numbers::pi / L;
    v[0] = v0 * std::sin(k * X[0]) * std::cos(0.5 * k * X[1]);
    v[1] = v0 * std::sin(k * X[1] + 1.0) * std::cos(0.5 * k * X[2]);
    v[2] = v0 * std::sin(k * X[2] + 2.0) * std::cos(0.5 * k * X[0]);
  }
};

void writeLammps(const Block& bl, const std::string& model, long steps, const std::string& dir,
                 const ParticleSet& ps) {
  std::ostringstream d;
  d << std::setprecision(17);
  d << "pdq block for LAMMPS peri (written by pd_bench)\n\n"
    << ps.size() << " atoms\n1 atom types\n\n";
  const double lo = -bl.s, hi = bl.n * bl.s;
  for (const char* ax : {"x", "y", "z"}) d << lo << " " << hi << " " << ax << "lo " << ax << "hi\n";
  d << "\nAtoms # peri\n\n";
  for (std::size_t k = 0; k < ps.size(); ++k) {
    const double* X = ps.fixedRow(k);
    d << ps.gid[k] << " 1 " << bl.s * bl.s * bl.s << " " << bl.rho << " " << X[0] << " " << X[1]
      << " " << X[2] << "\n";
  }
  d << "\nVelocities\n\n";
  for (std::size_t k = 0; k < ps.size(); ++k) {
    double v[3];
    bl.velocity(ps.fixedRow(k), v);
    d << ps.gid[k] << " " << v[0] << " " << v[1] << " " << v[2] << "\n";
  }
  writeFileAtomically(dir + "/lammps.data", d.str());
  std::ostringstream in;
  in << std::setprecision(17);
  in << "# The pd_bench block in LAMMPS (units si: m, kg, s, Pa)\nunits si\nboundary s s s\n"
        "atom_style peri\natom_modify map array\n"
     << "lattice sc " << bl.s << "\nread_data lammps.data\n";
  if (model == "pmb") {
    in << "pair_style peri/pmb\npair_coeff * * " << peri::pmbMicromodulus(3, bl.E, bl.delta(), 1)
       << " " << bl.delta() << " 1.0e10 0.0\n";
  } else {
    const double K = bl.E / (3 * (1 - 2 * bl.nu)), G = bl.E / (2 * (1 + bl.nu));
    in << "pair_style peri/lps\npair_coeff * * " << K << " " << G << " " << bl.delta()
       << " 1.0e10 0.0\n";
  }
  // LAMMPS judges bond breaking against the previous step's critical stretch s0, which
  // is not yet set on the first step (in the Debian 2021 package, peri/lps breaks every
  // stretched bond there); a first step of zero length stretches nothing and sets it.
  in << "neighbor " << 0.1 * bl.s << " bin\nfix 1 all nve\ntimestep 0\nrun 1\ntimestep " << bl.dt
     << "\nthermo " << steps << "\nrun " << steps << "\n"
     << "write_dump all custom lammps.dump id x y z modify sort id format float %.17g\n";
  writeFileAtomically(dir + "/lammps.in", in.str());
}

int block(int argc, char** argv, Comm& comm) {
  if (argc < 5) throw InputError("pd_bench", 0, "usage: pd_bench block N MODEL STEPS [DIR [DT]]");
  Block bl;
  bl.n = std::stoi(argv[2]);
  const std::string model = argv[3];
  const long steps = std::stol(argv[4]);
  const std::string dir = argc >= 6 ? argv[5] : "";
  if (argc >= 7) bl.dt = std::stod(argv[6]);
  Params p("block");
  p.set("E", num(bl.E));
  if (model == "lps") p.set("nu", num(bl.nu));
  p.set("horizon", num(bl.delta()));
  p.set("density", num(bl.rho));
  p.set("dt", num(bl.dt));
  p.set("lattice_spacing", num(bl.s));
  auto m = ModelRegistry::create(model);
  m->configure(p);
  p.checkAllUsed();
  const Schema schema = m->schema();
  ParticleSet ps;
  ps.nFixed = schema.nFixed();
  ps.nAlter = schema.nAlter();
  prep::appendLattice(ps, prep::cubicLattice(bl.n, bl.n, bl.n, bl.s));
  const int vol = schema.fixedIndex("volume"), vx = schema.alterIndex("vx");
  for (std::size_t k = 0; k < ps.size(); ++k) {
    ps.fixedRow(k)[vol] = bl.s * bl.s * bl.s;
    bl.velocity(ps.fixedRow(k), ps.alterRow(k) + vx);
  }
  if (!dir.empty() && comm.root()) writeLammps(bl, model, steps, dir, ps);
  RunConfig cfg;
  cfg.steps = steps;
  cfg.finalRestart = false;
  cfg.outDir = dir.empty() ? "pd_block_out" : dir + "/pdq_out";
  const std::size_t nParticles = ps.size();
  std::vector<double> X0;
  Simulation sim(std::move(m), std::move(ps), cfg, comm);
  const double t = timedRun(sim, comm);
  const long bonds = comm.sum(static_cast<long>(sim.bonds().count()));
  if (comm.root())
    std::printf(
        "pdq %s N=%zu bonds=%ld ranks=%d threads=%d steps=%ld time=%.4f s  "
        "particle-steps/s=%.4g  bond-steps/s=%.4g  peak_MiB(rank0)=%.1f\n",
        model.c_str(), nParticles, bonds, comm.size(), omp_get_max_threads(), steps, t,
        nParticles * steps / t, bonds * double(steps) / t, peakMemoryMiB());
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

// Reads "ID ux uy uz" (pdq.disp) or a LAMMPS dump of "id x y z" (then the lattice
// position is subtracted using the block's data file next to it).
std::map<long, std::array<double, 3>> readDisplacements(const std::string& file) {
  std::map<long, std::array<double, 3>> u;
  std::ifstream in(file);
  if (!in) throw InputError(file, 0, "cannot open");
  const bool dump = file.size() > 5 && file.substr(file.size() - 5) == ".dump";
  std::map<long, std::array<double, 3>> ref;
  if (dump) {
    const std::string data = file.substr(0, file.rfind('/') + 1) + "lammps.data";
    std::ifstream d(data);
    std::string line;
    bool atoms = false;
    while (std::getline(d, line)) {
      if (line.rfind("Atoms", 0) == 0) {
        atoms = true;
        continue;
      }
      if (line.rfind("Velocities", 0) == 0) break;
      std::istringstream ls(line);
      long id;
      int type;
      double v, rho, x, y, z;
      if (atoms && (ls >> id >> type >> v >> rho >> x >> y >> z)) ref[id] = {x, y, z};
    }
  }
  std::string line;
  int lineNo = 0;
  bool inAtoms = !dump;
  while (std::getline(in, line)) {
    ++lineNo;
    if (dump && line.rfind("ITEM: ATOMS", 0) == 0) {
      inAtoms = true;
      continue;
    }
    if (!inAtoms || line.rfind("ITEM", 0) == 0) continue;
    std::istringstream ls(line);
    long id;
    double a, b, c;
    if (!(ls >> id >> a >> b >> c))
      throw InputError(file, lineNo, "expected: ID and three numbers");
    if (dump) {
      auto it = ref.find(id);
      if (it == ref.end()) throw InputError(file, lineNo, "atom not in lammps.data");
      a -= it->second[0];
      b -= it->second[1];
      c -= it->second[2];
    }
    u[id] = {a, b, c};
  }
  return u;
}

int compare(int argc, char** argv) {
  if (argc < 4) throw InputError("pd_bench", 0, "usage: pd_bench compare A B");
  auto a = readDisplacements(argv[2]), b = readDisplacements(argv[3]);
  if (a.size() != b.size()) throw InputError(argv[3], 0, "a different number of particles");
  double umax = 0, dmax = 0;
  for (auto& [id, ua] : a) {
    auto it = b.find(id);
    if (it == b.end()) throw InputError(argv[3], 0, "particle " + std::to_string(id) + " missing");
    umax = std::max(umax, std::hypot(ua[0], ua[1], ua[2]));
    dmax = std::max(
        dmax, std::hypot(ua[0] - it->second[0], ua[1] - it->second[1], ua[2] - it->second[2]));
  }
  std::printf("particles=%zu max|u|=%.6e max|du|=%.6e relative=%.3e\n", a.size(), umax, dmax,
              dmax / umax);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  MpiSession mpi(&argc, &argv);
  Comm comm(MPI_COMM_WORLD);
  try {
    const std::string what = argc > 1 ? argv[1] : "";
    if (what == "cantilever") return cantilever(argc, argv, comm);
    if (what == "block") return block(argc, argv, comm);
    if (what == "compare") return comm.root() ? compare(argc, argv) : 0;
    std::fprintf(stderr, "usage: pd_bench cantilever|block|compare ...\n");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pd_bench: %s\n", e.what());
    comm.abort(1);
  }
}
