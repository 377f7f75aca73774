#include "models/mplm/2d/frequency.hpp"

#include <cmath>
#include <cstdint>

#include "models/mplm/2d/attributes.hpp"

namespace pdq::mplm {
namespace {

// A start vector that depends only on the particle's global ID and the DOF, so every
// decomposition iterates the same vector.
double startValue(Gid id, int dof) {
  std::uint64_t z = static_cast<std::uint64_t>(id) * 3 + dof + 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53 - 0.5;
}

}  // namespace

double highestFrequency(Context& ctx, const std::vector<Interaction>& inter, const Inertia& in,
                        int iterations) {
  Particles& P = ctx.particles;
  const std::size_t n = P.owned();
  const int cols[3] = {VX, VY, OMEGA};
  const int bits[3] = {FIX_X, FIX_Y, FIX_T};
  std::vector<double> saved(3 * n), w(3 * n), z(3 * n);
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) {
      saved[3 * i + d] = P.alter(i)[cols[d]];
      w[3 * i + d] = (in.constraint[i] & bits[d]) ? 0.0 : startValue(P.gid(i), d);
    }
  auto norm2 = [&](const std::vector<double>& v) {
    return ctx.sumOwned([&](std::size_t i) {
      return v[3 * i] * v[3 * i] + v[3 * i + 1] * v[3 * i + 1] + v[3 * i + 2] * v[3 * i + 2];
    });
  };
  const double scale = std::sqrt(norm2(w));
  for (double& v : w) v /= scale;
  double lambda = 0;
  for (int it = 0; it < iterations; ++it) {
    // v = M^(−½) w, stored where the ghosts can see it.
    for (std::size_t i = 0; i < n; ++i) {
      double* a = P.alter(i);
      a[VX] = w[3 * i] / std::sqrt(in.mass[i]);
      a[VY] = w[3 * i + 1] / std::sqrt(in.mass[i]);
      a[OMEGA] = w[3 * i + 2] / std::sqrt(in.inertia[i]);
    }
    ctx.refreshGhosts({VX, VY, OMEGA});
    // z = M^(−½) K v, with K v = −(elastic force of the displacement field v).
    for (std::size_t i = 0; i < n; ++i) {
      const double* a = P.alter(i);
      double fx = 0, fy = 0, m = 0;
      for (std::size_t b = ctx.bonds.begin(i); b < ctx.bonds.end(i); ++b) {
        const Interaction& k = inter[b];
        const double* aj = P.alter(k.j);
        const Chord ch = smallChord(k, aj[VX] - a[VX], aj[VY] - a[VY], a[OMEGA], aj[OMEGA]);
        const EndLoad e = elasticForce(k, ch, DamageLaw{}, nullptr, false);
        fx += e.fx;
        fy += e.fy;
        m += e.m;
      }
      z[3 * i] = (in.constraint[i] & FIX_X) ? 0.0 : -fx / std::sqrt(in.mass[i]);
      z[3 * i + 1] = (in.constraint[i] & FIX_Y) ? 0.0 : -fy / std::sqrt(in.mass[i]);
      z[3 * i + 2] = (in.constraint[i] & FIX_T) ? 0.0 : -m / std::sqrt(in.inertia[i]);
    }
    // Rayleigh quotient w·z (w has unit norm), then normalise.
    lambda = ctx.sumOwned([&](std::size_t i) {
      return w[3 * i] * z[3 * i] + w[3 * i + 1] * z[3 * i + 1] + w[3 * i + 2] * z[3 * i + 2];
    });
    const double nz = std::sqrt(norm2(z));
    if (!(nz > 0)) break;
    for (std::size_t k = 0; k < w.size(); ++k) w[k] = z[k] / nz;
  }
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) P.alter(i)[cols[d]] = saved[3 * i + d];
  ctx.refreshGhosts({VX, VY, OMEGA});
  return std::sqrt(std::max(lambda, 0.0));
}

}  // namespace pdq::mplm
