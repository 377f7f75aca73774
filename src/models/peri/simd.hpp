#pragma once
// The vector widths the peridynamic kernels come in; every width gives the same bits.
namespace pdq::peri {

enum class Simd { portable, avx2, avx512 };

// The widest this processor runs.
Simd processorSimd();

// That, at most the PDQ_SIMD environment variable's (portable, avx2 or avx512) where it is
// set, to compare the widths' speed; an InputError for other values.
Simd widestSimd();

}  // namespace pdq::peri
