#include "models/lj/verlet_list.hpp"

#include <omp.h>

#include <algorithm>

namespace pdq::lj {

void VerletList::build(const Context& ctx, const double* pos, std::size_t stride, double radius) {
  const std::size_t nLocal = ctx.particles.local(), n = ctx.particles.owned();

  const double r2max = radius * radius;
  start_.assign(n + 1, 0);
  ghost_.assign(n, 0);
  // Each thread lists a contiguous range of particles into its own buffer; the buffers
  // are then concatenated in order.
#pragma omp parallel
  {
    const int nt = omp_get_num_threads(), t = omp_get_thread_num();
#pragma omp single
    threads_.resize(nt);
    Scratch& s = threads_[t];
    s.out.clear();
    s.near.resize(nLocal);
    const std::size_t lo = n * t / nt, hi = n * (t + 1) / nt;
    s.count.assign(2 * (hi - lo), 0);
    for (std::size_t i = lo; i < hi; ++i) {
      const double* xi = pos + i * stride;
      const double x = xi[0], y = xi[1], z = xi[2];
      // Candidates kept without branches: partners of higher index (an owned pair is
      // listed by its lower index; ghosts come after the owned) within the radius.
      std::uint32_t* c = s.near.data();
      std::size_t m = 0;
      ctx.forEachNearby(i, [&](std::size_t j) {
        if (j < i) return;  // whole cells at a time: a well predicted branch
        const double* xj = pos + j * stride;
        const double dx = xj[0] - x, dy = xj[1] - y, dz = xj[2] - z;
        c[m] = static_cast<std::uint32_t>(j);
        m += dx * dx + dy * dy + dz * dz < r2max;
      });
      std::size_t owned = 0;
      for (std::size_t k = 0; k < m; ++k)
        if (c[k] < n) s.out.push_back(c[k]), ++owned;
      for (std::size_t k = 0; k < m; ++k)
        if (c[k] >= n) s.out.push_back(c[k]);
      s.count[2 * (i - lo)] = m;
      s.count[2 * (i - lo) + 1] = owned;
    }
#pragma omp barrier
#pragma omp single
    {
      std::size_t at = 0;
      longest_ = 0;
      for (int u = 0; u < nt; ++u) {
        const std::size_t ulo = n * u / nt, uhi = n * (u + 1) / nt;
        for (std::size_t i = ulo; i < uhi; ++i) {
          const std::size_t len = threads_[u].count[2 * (i - ulo)];
          ghost_[i] = at + threads_[u].count[2 * (i - ulo) + 1];
          longest_ = std::max(longest_, len);
          at += len;
          start_[i + 1] = at;
        }
      }
      index_.resize(at);
    }
    std::copy(s.out.begin(), s.out.end(), index_.begin() + start_[lo]);
  }
}

}  // namespace pdq::lj
