#include "models/peri/simd.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "engine/error.hpp"

namespace pdq::peri {

Simd processorSimd() {
  if (__builtin_cpu_supports("x86-64-v4")) return Simd::avx512;
  return __builtin_cpu_supports("avx2") ? Simd::avx2 : Simd::portable;
}

Simd widestSimd() {
  const Simd widest = processorSimd();
  const char* cap = std::getenv("PDQ_SIMD");
  if (!cap) return widest;
  const std::string c = cap;
  Simd asked = Simd::portable;
  if (c == "avx512")
    asked = Simd::avx512;
  else if (c == "avx2")
    asked = Simd::avx2;
  else if (c != "portable")
    throw InputError("environment", 0, "PDQ_SIMD=" + c + ": expected portable, avx2 or avx512");
  return std::min(asked, widest);
}

}  // namespace pdq::peri
