#include "io/gather.hpp"

#include <algorithm>
#include <stdexcept>

namespace pdq {

std::vector<double> gatherSortedRows(const Comm& comm, const std::vector<double>& rows, int width,
                                     int keyColumns) {
  if (keyColumns < 1 || keyColumns > 2)
    throw std::invalid_argument("gatherSortedRows: 1 or 2 key columns");
  const char* b = reinterpret_cast<const char*>(rows.data());
  auto blocks = comm.gather(std::vector<char>(b, b + rows.size() * sizeof(double)));
  std::vector<double> all;
  std::vector<std::size_t> starts;  // the first row of each rank's block
  for (auto& blk : blocks) {
    starts.push_back(all.size() / width);
    const double* d = reinterpret_cast<const double*>(blk.data());
    all.insert(all.end(), d, d + blk.size() / sizeof(double));
  }
  // Sorted by keys copied out of the rows (not by indices into them): the keys sit
  // together in memory, which matters for the millions of rows of a problem's bonds.
  struct Key {
    double k0, k1;
    std::size_t row;
  };
  const std::size_t n = all.size() / width;
  std::vector<Key> keys(n);
  for (std::size_t r = 0; r < n; ++r)
    keys[r] = {all[r * width], keyColumns > 1 ? all[r * width + 1] : 0.0, r};
  auto less = [](const Key& p, const Key& q) { return p.k0 != q.k0 ? p.k0 < q.k0 : p.k1 < q.k1; };
  // Each rank's rows already in order (restart files send them so) are merged, not sorted.
  starts.push_back(n);
  bool blocksSorted = true;
  for (std::size_t k = 0; k + 1 < starts.size() && blocksSorted; ++k)
    blocksSorted = std::is_sorted(keys.begin() + starts[k], keys.begin() + starts[k + 1], less);
  if (!blocksSorted)
    std::sort(keys.begin(), keys.end(), less);
  else
    for (std::size_t k = 1; k + 1 < starts.size(); ++k)
      std::inplace_merge(keys.begin(), keys.begin() + starts[k], keys.begin() + starts[k + 1],
                         less);
  if (std::is_sorted(keys.begin(), keys.end(),
                     [](const Key& p, const Key& q) { return p.row < q.row; }))
    return all;  // already in order: no copy
  std::vector<double> out(all.size());
  for (std::size_t k = 0; k < n; ++k)
    std::copy_n(&all[keys[k].row * width], width, &out[k * width]);
  return out;
}

}  // namespace pdq
