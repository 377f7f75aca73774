// The reference model: a lattice of point masses joined by linear springs that may break.
// It is the guide to writing a model for pdq — read it top to bottom. Everything a model
// does is here: parameters, attributes, setup of bonds, force, masses, output.
// The engine owns everything else (decomposition, ghosts, exchange, shuffle, files).
#include <algorithm>
#include <cmath>

#include "engine/model.hpp"

namespace pdq {
namespace {

class Spring final : public Model {
  // 1. Attribute columns. Positions come first in both tables (the engine's rule), so the
  //    model's own columns start at 3. Naming them keeps the kernels readable.
  enum Alter { X = 0, Y, Z, VX, VY, VZ };  // current position, velocity
  enum Integ { FX = 0, FY, FZ };           // force: scratch, recomputed every step
  enum BondAttr { MAX_STRETCH = 0 };       // the largest stretch the spring has seen

 public:
  // 2. Parameters, from the scenario's [model] table or pdQUserInput.dat. Every key read
  //    here is "known"; anything else in the file is reported as an error afterwards.
  void configure(const Params& p) override {
    k_ = p.number("stiffness", 1.0, 0.0, 1e300);
    mass_ = p.number("mass", 1.0, 1e-300, 1e300);
    horizon_ = p.number("horizon", 1.5, 1e-300, 1e300);
    dt_ = p.number("dt", 0.01, 1e-300, 1e300);
    breakStretch_ = p.number("critical_stretch", 0.0, 0.0, 1e300);  // 0: never breaks
    damping_ = p.number("damping", 0.0, 0.0, 1e300);
    shuffle_ = p.flag("shuffle", false);
  }

  // 3. The attributes the engine stores, sends and writes for this model.
  Schema schema() const override {
    return Schema::make({}, {"vx", "vy", "vz"}, {"fx", "fy", "fz"}, {"max_stretch"});
  }
  double horizon() const override { return horizon_; }
  // A spring lattice keeps its neighbours; `shuffle = true` lets particles migrate anyway
  // (bonds follow them by global ID), which the engine's tests use.
  bool shuffles() const override { return shuffle_; }
  // Its force (5. below) reads the bonds' partners and nothing else: the quasi-static
  // solver's probes may colour the bond graph.
  bool forcesFromBonds() const override { return true; }

  // 4. Setup: bond every owned particle to every particle within the horizon in the
  //    reference configuration. forEachNearby visits owned and ghost particles alike, so
  //    bonds across rank boundaries need no special care.
  void setup(Context& ctx) override {
    Particles& P = ctx.particles;
    for (std::size_t i = 0; i < P.owned(); ++i) {
      const double* Xi = P.fixed(i);
      ctx.forEachNearby(i, [&](std::size_t j) {
        const double* Xj = P.fixed(j);
        const double d2 = sq(Xj[0] - Xi[0]) + sq(Xj[1] - Xi[1]) + sq(Xj[2] - Xi[2]);
        if (d2 <= horizon_ * horizon_) ctx.bonds.add(i, P.gid(j));
      });
    }
    ctx.setDt(dt_);
  }

  // 5. Force: each owned particle sums its own bonds, in the bonds' fixed order (sorted by
  //    partner ID), and writes only its own row — so threads need no atomics and the
  //    result does not depend on the number of ranks or threads.
  void force(Context& ctx) override {
    Particles& P = ctx.particles;
    Bonds& B = ctx.bonds;
    const long n = static_cast<long>(P.owned());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
      const double* xi = P.alter(i);
      const double* Xi = P.fixed(i);
      double f[3] = {0, 0, 0};
      for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
        if (!B.alive(b)) continue;  // snapped: never heals
        const std::size_t j = B.partner(b);
        const double* xj = P.alter(j);
        const double* Xj = P.fixed(j);
        const double r[3] = {xj[X] - xi[X], xj[Y] - xi[Y], xj[Z] - xi[Z]};
        const double len = std::sqrt(sq(r[0]) + sq(r[1]) + sq(r[2]));
        const double len0 = std::sqrt(sq(Xj[0] - Xi[0]) + sq(Xj[1] - Xi[1]) + sq(Xj[2] - Xi[2]));
        const double stretch = (len - len0) / len0;
        double* state = B.attr(b);
        state[MAX_STRETCH] = std::max(state[MAX_STRETCH], stretch);
        if (breakStretch_ > 0 && stretch > breakStretch_) {
          B.kill(b);  // both sides of the bond judge alike, from the same numbers
          continue;
        }
        const double t = k_ * (len - len0) / len;
        for (int a = 0; a < 3; ++a) f[a] += t * r[a];
        if (damping_ > 0) {
          for (int a = 0; a < 3; ++a) f[a] += damping_ * (xj[VX + a] - xi[VX + a]);
        }
      }
      double* F = P.integ(i);
      F[FX] = f[0];
      F[FY] = f[1];
      F[FZ] = f[2];
    }
  }

  // 6. Motion: the engine's integrator (velocity Verlet) moves the particles. The default
  //    motion (positions x y z, velocities vx vy vz, forces fx fy fz, no rotation) is this
  //    model's; it gives each owned particle its mass (and could give constraints and loads).
  void bodies(const Context&, std::span<Body> owned) const override {
    for (Body& b : owned) b.mass = mass_;
  }

  // 7. Output: per-particle damage (fraction of broken springs) and global energies,
  //    summed exactly so they are the same bits on any number of ranks.
  std::vector<std::string> fields() const override { return {"damage"}; }
  void field(const Context& ctx, int, std::span<double> out) const override {
    const Bonds& B = ctx.bonds;
    for (std::size_t i = 0; i < out.size(); ++i) {
      const std::size_t n = B.end(i) - B.begin(i);
      double broken = 0;
      for (std::size_t b = B.begin(i); b < B.end(i); ++b) broken += B.alive(b) ? 0 : 1;
      out[i] = n ? broken / n : 0.0;
    }
  }
  std::vector<std::string> globals() const override {
    return {"kinetic", "broken_bonds", "potential"};
  }
  std::vector<double> globalValues(Context& ctx) override {
    const Particles& P = ctx.particles;
    const double ke = ctx.sumOwned([&](std::size_t i) {
      const double* x = P.alter(i);
      return 0.5 * mass_ * (sq(x[VX]) + sq(x[VY]) + sq(x[VZ]));
    });
    const double broken = ctx.sumOwned([&](std::size_t i) {
      double s = 0;
      for (std::size_t b = ctx.bonds.begin(i); b < ctx.bonds.end(i); ++b)
        s += ctx.bonds.alive(b) ? 0 : 1;
      return s;
    });
    // ½ k (len − len0)² per intact spring, half of it on each of its two particles.
    const double pe = ctx.sumOwned([&](std::size_t i) {
      const double* xi = P.alter(i);
      const double* Xi = P.fixed(i);
      double e = 0;
      for (std::size_t b = ctx.bonds.begin(i); b < ctx.bonds.end(i); ++b) {
        if (!ctx.bonds.alive(b)) continue;
        const double* xj = P.alter(ctx.bonds.partner(b));
        const double* Xj = P.fixed(ctx.bonds.partner(b));
        const double len = std::sqrt(sq(xj[X] - xi[X]) + sq(xj[Y] - xi[Y]) + sq(xj[Z] - xi[Z]));
        const double len0 = std::sqrt(sq(Xj[0] - Xi[0]) + sq(Xj[1] - Xi[1]) + sq(Xj[2] - Xi[2]));
        e += 0.25 * k_ * sq(len - len0);
      }
      return e;
    });
    return {ke, broken / 2, pe};
  }

 private:
  static double sq(double v) { return v * v; }
  double k_ = 1, mass_ = 1, horizon_ = 1.5, dt_ = 0.01, breakStretch_ = 0, damping_ = 0;
  bool shuffle_ = false;
};

// 8. Registration: one line, and a scenario can say `model = "spring"`.
PDQ_REGISTER_MODEL(Spring, "spring",
                   "linear springs between particles within a horizon, optionally breaking");

}  // namespace
}  // namespace pdq
