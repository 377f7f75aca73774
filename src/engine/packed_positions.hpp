#pragma once
// The positions of every local particle (owned and ghosts) packed in rows of four doubles
// (x, y, z, and 0 or a value of the model's), each row on a 32-byte boundary: what a force
// kernel reads of a partner, one aligned 256-bit load a row, in two thirds of the cache the
// alterable rows would take. Refilled by pack() whenever the positions may have changed.
#include <cstddef>
#include <vector>

namespace pdq {

class Particles;

class PackedPositions {
 public:
  static constexpr std::size_t kRow = 4;
  // Copies the current positions (the first three alterable columns), and fourth[k] into
  // row k's last column when given (one value per local particle); returns rows().
  const double* pack(const Particles& P, const double* fourth = nullptr);
  const double* rows() const { return rows_; }

 private:
  std::vector<double> buffer_;  // rows_ starts at its first 32-byte boundary
  double* rows_ = nullptr;
};

}  // namespace pdq
