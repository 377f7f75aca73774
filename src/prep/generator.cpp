#include "prep/generator.hpp"

#include <algorithm>
#include <cmath>

namespace pdq {

template <>
Registry<Generator>::Table& Registry<Generator>::table() {
  static Table t{"generator"};
  return t;
}

template <>
Registry<GeneratorEstimate>::Table& Registry<GeneratorEstimate>::table() {
  static Table t{"generator", "no size estimate for generator"};
  return t;
}

double SizeEstimate::pairsWithin(double r) const {
  const std::size_t dim = primitive.size();
  if (dim == 0 || !(r > 0)) return 0;
  double shortest = HUGE_VAL;
  for (const auto& v : primitive) shortest = std::min(shortest, std::hypot(v[0], v[1], v[2]));
  // Enough multiples of each vector to reach r on the skewed lattices used (hexagonal, fcc).
  const int reach = static_cast<int>(std::ceil(2 * r / shortest)) + 2;
  const double r2 = r * r * (1 + 1e-9);
  std::array<double, 3> extent{};
  for (int a = 0; a < 3; ++a) extent[a] = hi[a] - lo[a] + stride[a];
  double share = 0;
  const int span[3] = {reach, dim > 1 ? reach : 0, dim > 2 ? reach : 0};
  for (int i = -span[0]; i <= span[0]; ++i)
    for (int j = -span[1]; j <= span[1]; ++j)
      for (int k = -span[2]; k <= span[2]; ++k) {
        std::array<double, 3> d{};
        const int m[3] = {i, j, k};
        for (std::size_t v = 0; v < dim; ++v)
          for (int a = 0; a < 3; ++a) d[a] += m[v] * primitive[v][a];
        const double d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        if (d2 == 0 || d2 > r2) continue;
        double f = 1;
        for (int a = 0; a < 3; ++a)
          if (d[a] != 0) f *= std::max(0.0, 1 - std::fabs(d[a]) / extent[a]);
        share += f;
      }
  return particles * share / 2;
}

}  // namespace pdq
