#include "prep/mplm/specimen3d.hpp"

#include "models/mplm/3d/attributes.hpp"

namespace pdq::mplm3d {

ParticleSet newParticleSet() {
  ParticleSet ps;
  ps.nFixed = N_FIXED;
  ps.nAlter = N_ALTER;
  return ps;
}

void addConcrete(ParticleSet& ps, const std::vector<std::array<double, 3>>& points) {
  for (const auto& p : points) ps.add(static_cast<Gid>(ps.size()), p[0], p[1], p[2]);
}

void constrain(ParticleSet& ps, const std::vector<std::size_t>& idx, int bits,
               const std::array<double, 6>& peak) {
  for (std::size_t k : idx) {
    double* f = ps.fixedRow(k);
    f[CONSTRAINT] = static_cast<double>(static_cast<int>(f[CONSTRAINT]) | bits);
    for (int d = 0; d < 6; ++d)
      if (bits & (1 << d)) f[DISP_X + d] = peak[d];
  }
}

void load(ParticleSet& ps, const std::vector<std::size_t>& idx, const std::array<double, 6>& fm) {
  for (std::size_t k : idx)
    for (int d = 0; d < 6; ++d) ps.fixedRow(k)[LOAD_X + d] += fm[d];
}

void monitor(ParticleSet& ps, const std::vector<std::size_t>& idx) {
  for (std::size_t k : idx) ps.fixedRow(k)[MONITOR] = 1;
}

}  // namespace pdq::mplm3d
