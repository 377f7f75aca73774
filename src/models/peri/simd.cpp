#include "models/peri/simd.hpp"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace pdq::peri {

Simd widestSimd() {
  Simd widest = Simd::portable;
  if (__builtin_cpu_supports("x86-64-v4"))
    widest = Simd::avx512;
  else if (__builtin_cpu_supports("avx2"))
    widest = Simd::avx2;
  const char* cap = std::getenv("PDQ_SIMD");
  if (!cap) return widest;
  const std::string c = cap;
  const Simd asked =
      c == "portable" ? Simd::portable
      : c == "avx2"   ? Simd::avx2
      : c == "avx512"
          ? Simd::avx512
          : throw std::runtime_error("PDQ_SIMD=" + c + ": expected portable, avx2 or avx512");
  return std::min(asked, widest);
}

}  // namespace pdq::peri
