#include "engine/frequency.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace pdq {
namespace {

// A start vector that depends only on the particle's global ID and the DOF, so every
// decomposition iterates the same vector.
double startValue(Gid id, int dofs, int dof) {
  std::uint64_t z = static_cast<std::uint64_t>(id) * dofs + dof + 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53 - 0.5;
}

}  // namespace

double highestFrequency(Context& ctx, const DofSystem& sys, const RestoringForce& restoring,
                        int iterations) {
  const Particles& P = ctx.particles;
  const std::size_t n = P.owned(), nd = static_cast<std::size_t>(sys.dofs);
  std::vector<double> w(nd * n), z(nd * n), f(nd * n), u(nd * P.local());
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t d = 0; d < nd; ++d)
      w[nd * i + d] = sys.held[nd * i + d] ? 0.0 : startValue(P.gid(i), sys.dofs, int(d));
  auto dot = [&](const std::vector<double>& a, const std::vector<double>& b) {
    return ctx.sumOwned([&](std::size_t i) {
      double s = 0;
      for (std::size_t d = 0; d < nd; ++d) s += a[nd * i + d] * b[nd * i + d];
      return s;
    });
  };
  const double scale = std::sqrt(dot(w, w));
  for (double& v : w) v /= scale;
  double lambda = 0;
  for (int it = 0; it < iterations; ++it) {
    // u = M^(−½) w at every local particle; z = M^(−½) K u.
    for (std::size_t k = 0; k < nd * n; ++k) u[k] = w[k] / std::sqrt(sys.mass[k]);
    ctx.refreshGhosts(u, sys.dofs);
    restoring(u, f);
    for (std::size_t k = 0; k < nd * n; ++k)
      z[k] = sys.held[k] ? 0.0 : -f[k] / std::sqrt(sys.mass[k]);
    // Rayleigh quotient w·z (w has unit norm), then normalise.
    lambda = dot(w, z);
    const double nz = std::sqrt(dot(z, z));
    if (!(nz > 0)) break;
    for (std::size_t k = 0; k < w.size(); ++k) w[k] = z[k] / nz;
  }
  return std::sqrt(std::max(lambda, 0.0));
}

}  // namespace pdq
