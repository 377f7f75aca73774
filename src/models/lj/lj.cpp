// Lennard-Jones molecular dynamics in reduced units (epsilon, sigma, mass), the engine's
// first shuffling model: particles wander between cells and ranks.
//
//   neighbours   half Verlet lists (verlet_list.hpp) of radius one cell edge, rebuilt after
//                every engine shuffle. The model's horizon is rc and it asks for cells of
//                at least rc + skin, whole by default; cell_divisions > 1 cuts each into
//                sub-cells on more than one rank, so that the cuts between ranks are finer
//                (docs/lj.md: the list builds then cost more than the balance saves). The
//                engine shuffles once some particle moved more than (cell - rc) / 2 since
//                the last rebuild.
//   force        each pair once (Newton's third law between owned particles; a pair with
//                a ghost is computed by each side's rank), summed exactly (kernel.hpp), so
//                the bits do not depend on the order of the pairs, hence on neither the
//                processor grid nor the threads. No forces travel back to other ranks.
//   integration  the engine's velocity Verlet (leapfrog form, engine/integrator.hpp): the
//                stored velocity is v(0) at step 0 and the half-step v(n-1/2) after.
//   globals      potential, kinetic and total energy, temperature and pressure at the current
//                step n, with the kinetic energy from v(n) = v(n-1/2) + F(n) dt / 2m
//                (v(0) at step 0), which needs F(n): the globals evaluate the forces at
//                x(n) once more.
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "engine/error.hpp"
#include "engine/model.hpp"
#include "engine/packed_positions.hpp"
#include "models/lj/kernel.hpp"
#include "models/lj/pair_lj.hpp"
#include "models/lj/verlet_list.hpp"

namespace pdq::lj {
namespace {

class LennardJones final : public Model {
  enum Alter { X = 0, Y, Z, VX, VY, VZ };
  enum Integ { FX = 0, FY, FZ };

 public:
  void configure(const Params& p) override {
    const double epsilon = p.number("epsilon", 1.0, 1e-300, 1e300);
    const double sigma = p.number("sigma", 1.0, 1e-300, 1e300);
    mass_ = p.number("mass", 1.0, 1e-300, 1e300);
    const double rc = p.number("cutoff", 2.5, 1e-300, 1e300);
    skin_ = p.number("skin", 0.3, 0.0, 1e300);
    dt_ = p.number("dt", 0.005, 1e-300, 1e300);
    divisions_ = static_cast<int>(p.integer("cell_divisions", 1, 1, 4));
    portable_ = p.choice("kernel", "auto", {"auto", "portable"}) == "portable";
    const std::string s = p.choice("shift", "energy", {"none", "energy", "force"});
    const Shift shift = s == "none" ? Shift::None : s == "energy" ? Shift::Energy : Shift::Force;
    pair_ = PairLJ(epsilon, sigma, rc, shift);
    forceGrid_ = Grid(24 * epsilon / sigma);
    energyGrid_ = Grid(epsilon);
    // The closest pair whose terms stay within the grids' limits: below it the repulsive
    // r^-12 terms dominate and bound the force, energy and virial terms (with room).
    closest_ = 1.05 * std::max({std::pow(pair_.f12 / forceGrid_.limit, 1.0 / 13),
                                std::pow(pair_.u12 / energyGrid_.limit, 1.0 / 12),
                                std::pow(pair_.f12 / energyGrid_.limit, 1.0 / 12)});
  }

  Schema schema() const override {
    Schema s = Schema::make({}, {"vx", "vy", "vz"}, {"fx", "fy", "fz"});
    s.haloColumns = 3;  // pairs read their ghost atoms' positions only
    return s;
  }
  double horizon() const override { return pair_.rc; }
  double minCellSize() const override { return pair_.rc + skin_; }
  int cellDivisions() const override { return divisions_; }
  bool shuffles() const override { return true; }
  // Exact sums (below) make the forces independent of the order pairs are visited in, and
  // the shuffles' rhythm is the requested cells' (Context::listRadius): the engine may cut
  // fewer, larger cells along an axis split among ranks to balance them.
  bool resultsDependOnCells() const override { return false; }
  bool bondsWithinHorizon() const override { return false; }  // pair lists, no bonds

  void setup(Context& ctx) override { ctx.setDt(dt_); }
  void prepare(Context& ctx) override { buildLists(ctx); }
  void neighboursChanged(Context& ctx) override { buildLists(ctx); }

  void force(Context& ctx) override { evaluate(ctx, forces(ctx.particles), nullptr); }

  void bodies(const Context&, std::span<Body> owned) const override {
    for (Body& b : owned) b.mass = mass_;
  }

  std::vector<std::string> fields() const override { return {"potential_energy"}; }
  void field(const Context& ctx, int, std::span<double> out) const override {
    evaluate(ctx, nullptr, out.data());
  }

  std::vector<std::string> globals() const override {
    return {"potential", "kinetic", "total", "temperature", "pressure"};
  }
  std::vector<double> globalValues(Context& ctx) override {
    Particles& P = ctx.particles;
    energy_.resize(P.owned());
    evaluate(ctx, forces(P), energy_.data());
    const double half = ctx.step() == 0 ? 0.0 : 0.5 * ctx.dt() / mass_;
    const double pe = ctx.sumOwned([&](std::size_t i) { return energy_[i]; });
    const double ke = ctx.sumOwned([&](std::size_t i) {
      const double* x = P.alter(i);
      const double* F = P.integ(i);
      double v2 = 0;
      for (int a = 0; a < 3; ++a) v2 += sq(x[VX + a] + F[FX + a] * half);
      return 0.5 * mass_ * v2;
    });
    const long n = ctx.count(static_cast<long>(P.owned()));
    const int d = ctx.dim();
    const double dof = n > 1 ? static_cast<double>(d * (n - 1)) : d;
    // P = (2 KE + Σ_pairs r·F(r)) / (d V), V the periodic box's volume: LAMMPS's
    // `thermo pressure` (no tail correction).
    const double w = ctx.sumOwned([&](std::size_t i) { return virial_[i]; });
    double volume = 1;
    for (int a = 0; a < d; ++a) volume *= ctx.domain().length(a);
    return {pe, ke, pe + ke, 2 * ke / dof, (2 * ke + w) / (d * volume)};
  }

 private:
  static double sq(double v) { return v * v; }

  // Pair sums of every owned particle at the current positions: forces into `force`
  // (rows of three: the integ table) unless null, and, unless `energy` is null, each
  // particle's potential energy and virial (half of its pair energies and of its pair
  // virials r·F(r), the latter into virial_).
  void evaluate(const Context& ctx, double* force, double* energy) const {
    const Particles& P = ctx.particles;
    const long n = static_cast<long>(P.owned());
    if (n == 0) return;
    pos_.pack(P);
    if (energy) virial_.resize(n);
    const int threads = omp_get_max_threads();
    scratch_.resize(std::max<std::size_t>(scratch_.size(), threads));
    // One accumulator per thread (Newton's third law writes to other particles' rows);
    // their exact sums add up in any order.
    acc_.resize(threads);
    double closest2 = pair_.rc2;
#pragma omp parallel reduction(min : closest2)
    {
      const int nt = omp_get_num_threads(), t = omp_get_thread_num();
      Accumulator& a = acc_[t];
      a.force.assign(kForceRow * n, 0.0);
      if (energy) a.energy.assign(kEnergyRow * n, 0.0);
      KernelScratch& scratch = scratch_[t];
      scratch.reserve(lists_.longest());
      KernelOut out;
      out.force = a.force.data();
      out.energy = energy ? a.energy.data() : nullptr;
      out.closest2 = pair_.rc2;
      pairSumsRange(pair_, forceGrid_, energyGrid_, pos_.rows(), PackedPositions::kRow, lists_,
                    n * t / nt, n * (t + 1) / nt, out, scratch, portable_);
      closest2 = out.closest2;
#pragma omp barrier
#pragma omp for schedule(static)
      for (long i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) {
          double h = 0, l = 0;
          for (int u = 0; u < nt; ++u)
            h += acc_[u].force[kForceRow * i + c], l += acc_[u].force[kForceRow * i + 3 + c];
          if (force) force[3 * i + c] = h + l;
        }
        if (energy) {
          double s[4] = {0, 0, 0, 0};
          for (int u = 0; u < nt; ++u)
            for (int c = 0; c < 4; ++c) s[c] += acc_[u].energy[kEnergyRow * i + c];
          energy[i] = s[0] + s[1];
          virial_[i] = s[2] + s[3];
        }
      }
    }
    if (closest2 < closest_ * closest_) {
      std::ostringstream os;
      os << "lj: at step " << ctx.step() << " two atoms are " << std::sqrt(closest2)
         << " apart, closer than " << closest_
         << ", where pair forces leave the range of the exact sums (the system is unstable, "
            "the time step too large, or atoms overlap in the input)";
      throw RunError(os.str());
    }
  }
  static double* forces(Particles& P) { return P.owned() ? P.integ(0) : nullptr; }

  // Positions packed four to a row (32 bytes), a denser copy of the alterable table for
  // the kernel's scattered reads.
  void buildLists(Context& ctx) {
    pos_.pack(ctx.particles);
    lists_.build(ctx, pos_.rows(), PackedPositions::kRow, ctx.listRadius(), portable_);
  }

  struct Accumulator {
    std::vector<double> force, energy;
  };

  PairLJ pair_;
  Grid forceGrid_, energyGrid_;
  double closest_ = 0;  // closest pair allowed
  double mass_ = 1, skin_ = 0.3, dt_ = 0.005;
  int divisions_ = 1;
  bool portable_ = false;  // kernel = "portable": no AVX-512 loops (the same bits)
  VerletList lists_;
  std::vector<double> energy_;
  mutable std::vector<KernelScratch> scratch_;  // one per OpenMP thread
  mutable PackedPositions pos_;                 // the positions the kernel reads
  mutable std::vector<double> virial_;          // per owned particle (globals)
  mutable std::vector<Accumulator> acc_;        // one per OpenMP thread
};

PDQ_REGISTER_MODEL(LennardJones, "lj",
                   "Lennard-Jones molecular dynamics (reduced units, cut-off, Verlet lists)");

}  // namespace
}  // namespace pdq::lj
