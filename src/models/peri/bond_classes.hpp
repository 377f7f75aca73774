#pragma once
// The distinct (reference length, weight) pairs of the bonds, and each bond's pair. The
// bonds of a regular lattice hold a few hundred distinct pairs, so a kernel that reads a
// 4-byte row number per bond streams a fraction of the bytes of the pairs themselves, and
// reads the very same doubles. The bonds' own attributes stay the record (restart files,
// energies, damage); the rows are rebuilt from them whenever the bonds change
// (Bonds::version) or the model rewrites them (forget).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/bonds.hpp"

namespace pdq::peri {

// What a kernel reads: row[2 index[b]] and row[2 index[b] + 1] are bond b's first two
// attributes, its reference length and weight. A kernel that breaks bond b sets
// index[b] = broken[index[b]], the same length with weight 0, as it zeroes the bond's own.
struct BondRows {
  std::uint32_t* index = nullptr;
  const double* row = nullptr;
  const std::uint32_t* broken = nullptr;
};

class BondClasses {
 public:
  // Rebuilds the rows if the bonds changed since the last call, or after forget(); true
  // when it did.
  bool update(const Bonds& B);
  void forget() { built_ = false; }
  BondRows rows() { return {index_.data(), rows_.data(), broken_.data()}; }
  std::size_t count() const { return broken_.size(); }

 private:
  // The row's number, added if new.
  std::uint32_t find(const double row[2]);

  bool built_ = false;
  std::uint64_t version_ = 0;
  std::vector<std::uint32_t> index_;  // per bond
  std::vector<double> rows_;          // two doubles per row
  std::vector<std::uint32_t> broken_;
  std::vector<std::uint32_t> slots_;  // open addressing: row number + 1, 0 = empty
};

}  // namespace pdq::peri
