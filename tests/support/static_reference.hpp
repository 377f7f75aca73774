#pragma once
// The linear static solution K u = P of a problem set up on one rank, independent of the
// quasi-static solver: K is assembled column by column from central differences of the
// model's forces about the reference state, and the system is solved by Gaussian
// elimination with partial pivoting.
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "engine/simulation.hpp"

namespace pdq::test {

// One free degree of freedom: owned particle, its alterable column (position or angle),
// the integ column of its force, the factor from that column to a force (the mass for a
// per-mass model, else 1) and the external load on it.
struct FreeDof {
  std::size_t particle;
  int alter, integ;
  double toForce, load;
};

// u for every free DOF (the other DOFs at their reference value); `step` is the probe.
inline std::vector<double> linearStatic(Simulation& sim, const std::vector<FreeDof>& dofs,
                                        double step) {
  Particles& P = sim.particles();
  Context& ctx = sim.context();
  const std::size_t n = dofs.size();
  std::vector<double> K(n * n), rhs(n);
  auto forces = [&](std::vector<double>& out) {
    sim.model().force(ctx);
    out.resize(n);
    for (std::size_t r = 0; r < n; ++r)
      out[r] = P.integ(dofs[r].particle)[dofs[r].integ] * dofs[r].toForce;
  };
  std::vector<double> plus, minus;
  for (std::size_t c = 0; c < n; ++c) {
    double& x = P.alter(dofs[c].particle)[dofs[c].alter];
    const double x0 = x;
    x = x0 + step;
    forces(plus);
    x = x0 - step;
    forces(minus);
    x = x0;
    for (std::size_t r = 0; r < n; ++r) K[r * n + c] = -(plus[r] - minus[r]) / (2 * step);
  }
  for (std::size_t r = 0; r < n; ++r) rhs[r] = dofs[r].load;
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t p = k;
    for (std::size_t r = k + 1; r < n; ++r)
      if (std::fabs(K[r * n + k]) > std::fabs(K[p * n + k])) p = r;
    if (K[p * n + k] == 0) throw std::runtime_error("singular stiffness");
    if (p != k) {
      for (std::size_t c = 0; c < n; ++c) std::swap(K[k * n + c], K[p * n + c]);
      std::swap(rhs[k], rhs[p]);
    }
    for (std::size_t r = k + 1; r < n; ++r) {
      const double f = K[r * n + k] / K[k * n + k];
      if (f == 0) continue;
      for (std::size_t c = k; c < n; ++c) K[r * n + c] -= f * K[k * n + c];
      rhs[r] -= f * rhs[k];
    }
  }
  std::vector<double> u(n);
  for (std::size_t k = n; k-- > 0;) {
    double s = rhs[k];
    for (std::size_t c = k + 1; c < n; ++c) s -= K[k * n + c] * u[c];
    u[k] = s / K[k * n + k];
  }
  return u;
}

}  // namespace pdq::test
