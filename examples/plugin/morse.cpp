// An out-of-tree model for pdq: atoms interacting through the Morse potential
//     U(r) = D [(1 - exp(-a (r - r0)))^2 - 1]      (cut off at r_cut)
// moved by pdq's integrator (velocity Verlet), and a generator that builds a simple-cubic
// block of atoms to start from. Loaded at run time:
//     pdq run cluster.toml --plugin build/libmorse.so
// Only pdq's installed headers are used; docs/write-your-own-model.md walks through it.
#include <cmath>

#include "engine/model.hpp"
#include "prep/generator.hpp"

namespace {

class Morse final : public pdq::Model {
  enum Alter { X = 0, Y, Z, VX, VY, VZ };
  enum Integ { FX = 0, FY, FZ, ENERGY };

 public:
  void configure(const pdq::Params& p) override {
    depth_ = p.number("depth", 1.0, 1e-300, 1e300);       // D
    width_ = p.number("stiffness", 6.0, 1e-300, 1e300);   // a, per unit length
    r0_ = p.number("equilibrium", 1.0, 1e-300, 1e300);    // r0
    cutoff_ = p.number("cutoff", 2.0 * r0_, r0_, 1e300);  // r_cut
    mass_ = p.number("mass", 1.0, 1e-300, 1e300);
    dt_ = p.number("dt", 0.002, 1e-300, 1e300);
  }

  pdq::Schema schema() const override {
    return pdq::Schema::make({}, {"vx", "vy", "vz"}, {"fx", "fy", "fz", "energy"});
  }
  double horizon() const override { return cutoff_; }
  bool shuffles() const override { return true; }  // atoms change neighbours
  void setup(pdq::Context& ctx) override { ctx.setDt(dt_); }

  // Each owned atom sums its neighbours in pdq's canonical order and writes only its own
  // row, so the result is the same on any number of ranks and threads.
  void force(pdq::Context& ctx) override {
    pdq::Particles& P = ctx.particles;
    const long n = static_cast<long>(P.owned());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
      const double* xi = P.alter(i);
      double f[3] = {0, 0, 0}, u = 0;
      ctx.forEachNearby(i, [&](std::size_t j) {
        const double* xj = P.alter(j);
        const double d[3] = {xi[X] - xj[X], xi[Y] - xj[Y], xi[Z] - xj[Z]};
        const double r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (r >= cutoff_) return;
        const double e = std::exp(-width_ * (r - r0_));
        u += 0.5 * depth_ * ((1 - e) * (1 - e) - 1);  // half: the pair is seen twice
        const double dUdr = 2 * depth_ * width_ * e * (1 - e);
        for (int a = 0; a < 3; ++a) f[a] -= dUdr * d[a] / r;  // -dU/dr along i - j
      });
      double* F = P.integ(i);
      F[FX] = f[0];
      F[FY] = f[1];
      F[FZ] = f[2];
      F[ENERGY] = u;
    }
  }

  // Forces (and energies) before the first step, so that step 0's history has them.
  void prepare(pdq::Context& ctx) override { force(ctx); }

  // The engine integrates x y z, vx vy vz with forces fx fy fz; it needs the masses.
  void bodies(const pdq::Context&, std::span<pdq::Body> owned) const override {
    for (pdq::Body& b : owned) b.mass = mass_;
  }

  std::vector<std::string> globals() const override { return {"kinetic", "potential"}; }
  std::vector<double> globalValues(pdq::Context& ctx) override {
    const pdq::Particles& P = ctx.particles;
    const double ke = ctx.sumOwned([&](std::size_t i) {
      const double* x = P.alter(i);
      return 0.5 * mass_ * (x[VX] * x[VX] + x[VY] * x[VY] + x[VZ] * x[VZ]);
    });
    // The energies of the last force evaluation (prepare() made one for step 0).
    const double pe = ctx.sumOwned([&](std::size_t i) { return P.integ(i)[ENERGY]; });
    return {ke, pe};
  }

 private:
  double depth_ = 1, width_ = 6, r0_ = 1, cutoff_ = 2, mass_ = 1, dt_ = 0.002;
};

PDQ_REGISTER_MODEL(Morse, "morse", "atoms with the Morse pair potential (example plugin)");

// The generator: nx x ny x nz atoms on a simple-cubic lattice of the given spacing, IDs
// 1, 2, ... with X fastest, the atoms at rest.
pdq::Generated block(const pdq::Params& p, const pdq::Schema& schema) {
  const long nx = p.integer("nx"), ny = p.integer("ny", 1), nz = p.integer("nz", 1);
  const double h = p.number("spacing", 1.0, 1e-300, 1e300);
  pdq::Generated g;
  g.particles.nFixed = schema.nFixed();
  g.particles.nAlter = schema.nAlter();
  pdq::Gid id = 1;
  for (long k = 0; k < nz; ++k)
    for (long j = 0; j < ny; ++j)
      for (long i = 0; i < nx; ++i) g.particles.add(id++, i * h, j * h, k * h);
  return g;
}

PDQ_REGISTER_GENERATOR(block, "morse_block", "a simple-cubic block of atoms (example plugin)");

}  // namespace
