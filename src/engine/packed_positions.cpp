#include "engine/packed_positions.hpp"

#include <cstdint>

#include "engine/particles.hpp"

namespace pdq {

const double* PackedPositions::pack(const Particles& P, const double* fourth) {
  const long nl = static_cast<long>(P.local());
  constexpr std::size_t kBytes = kRow * sizeof(double);
  buffer_.resize(kRow * static_cast<std::size_t>(nl) + kRow);
  const std::size_t off = reinterpret_cast<std::uintptr_t>(buffer_.data()) % kBytes;
  rows_ = buffer_.data() + (kBytes - off) % kBytes / sizeof(double);
#pragma omp parallel for schedule(static)
  for (long k = 0; k < nl; ++k) {
    const double* a = P.alter(static_cast<std::size_t>(k));
    double* r = rows_ + kRow * static_cast<std::size_t>(k);
    r[0] = a[0], r[1] = a[1], r[2] = a[2], r[3] = fourth ? fourth[k] : 0;
  }
  return rows_;
}

}  // namespace pdq
