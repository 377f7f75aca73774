#include "io/gather.hpp"

#include <algorithm>
#include <numeric>

namespace pdq {

std::vector<double> gatherSortedRows(const Comm& comm, const std::vector<double>& rows, int width,
                                     int keyColumns) {
  const char* b = reinterpret_cast<const char*>(rows.data());
  auto blocks = comm.gather(std::vector<char>(b, b + rows.size() * sizeof(double)));
  std::vector<double> all;
  for (auto& blk : blocks) {
    const double* d = reinterpret_cast<const double*>(blk.data());
    all.insert(all.end(), d, d + blk.size() / sizeof(double));
  }
  const std::size_t n = all.size() / width;
  std::vector<std::size_t> idx(n);
  std::iota(idx.begin(), idx.end(), 0);
  std::sort(idx.begin(), idx.end(), [&](std::size_t p, std::size_t q) {
    for (int k = 0; k < keyColumns; ++k)
      if (all[p * width + k] != all[q * width + k]) return all[p * width + k] < all[q * width + k];
    return false;
  });
  std::vector<double> out(all.size());
  for (std::size_t k = 0; k < n; ++k) std::copy_n(&all[idx[k] * width], width, &out[k * width]);
  return out;
}

}  // namespace pdq
