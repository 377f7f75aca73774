#include "models/lj/verlet_list.hpp"

#include <omp.h>

#include <algorithm>

namespace pdq::lj {

std::size_t keepNear(const double* cx, const double* cy, const double* cz, const std::uint32_t* id,
                     std::size_t from, std::size_t to, double x, double y, double z, double r2max,
                     std::uint32_t* out) {
  std::size_t m = 0;
  for (std::size_t k = from; k < to; ++k) {
    const double dx = cx[k] - x, dy = cy[k] - y, dz = cz[k] - z;
    out[m] = id[k];
    m += dx * dx + dy * dy + dz * dz < r2max;
  }
  return m;
}

KeepNear chosenKeepNear() {
  return __builtin_cpu_supports("x86-64-v4") ? keepNearAvx512 : keepNear;
}

void VerletList::build(const Context& ctx, const double* pos, std::size_t stride, double radius,
                       bool portable) {
  const std::size_t n = ctx.particles.owned();
  static const KeepNear chosen = chosenKeepNear();
  const KeepNear keep = portable ? keepNear : chosen;

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
    const std::size_t lo = n * t / nt, hi = n * (t + 1) / nt;
    s.count.assign(2 * (hi - lo), 0);
    std::size_t next = 0;  // first gathered owned candidate of index above i
    for (std::size_t i = lo; i < hi; ++i) {
      // Owned particles of one cell are consecutive and share their candidates: gather
      // them once per cell (positions packed, owned ones sorted by index, ghosts after).
      if (i == lo || ctx.cellOf(i) != ctx.cellOf(i - 1)) {
        s.near.clear();
        s.ghost.clear();
        ctx.forEachNearbyInMemoryOrder(i, [&](std::size_t j) {
          (j < n ? s.near : s.ghost).push_back(static_cast<std::uint32_t>(j));
        });
        // Owned particles are sorted by cell and the cells visited in memory order, so the
        // owned candidates come sorted by index; sort them only if not.
        if (!std::is_sorted(s.near.begin(), s.near.end())) std::sort(s.near.begin(), s.near.end());
        s.owned = s.near.size();
        s.near.insert(s.near.end(), s.ghost.begin(), s.ghost.end());
        const std::size_t nc = s.near.size();
        s.xyz.resize(3 * nc);
        for (std::size_t k = 0; k < nc; ++k)
          for (int a = 0; a < 3; ++a) s.xyz[a * nc + k] = pos[s.near[k] * stride + a];
        next = 0;
      }
      while (next < s.owned && s.near[next] <= i) ++next;
      const double* xi = pos + i * stride;
      // Owned partners of higher index, then ghosts, those within the radius.
      const std::size_t nc = s.near.size();
      const double *cx = s.xyz.data(), *cy = cx + nc, *cz = cy + nc;
      const std::size_t at = s.out.size();
      s.out.resize(at + nc - next + 8);
      std::uint32_t* o = s.out.data() + at;
      const std::size_t owned =
          keep(cx, cy, cz, s.near.data(), next, s.owned, xi[0], xi[1], xi[2], r2max, o);
      const std::size_t m = owned + keep(cx, cy, cz, s.near.data(), s.owned, nc, xi[0], xi[1],
                                         xi[2], r2max, o + owned);
      s.out.resize(at + m);
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
