#pragma once
// The bonds' (reference length, weight) rows, two consecutive bonds' to a row. The bonds of a
// regular lattice hold a few hundred distinct (length, weight) and some ten thousand distinct
// pairs of them, so a kernel that reads a 4-byte pair offset per bond streams a fraction of
// the bytes of the attributes themselves, reads the very same doubles, and gets two bonds'
// in one 32-byte load. The bonds' own attributes stay the record (restart files, energies,
// damage); the rows are rebuilt from them whenever the bonds change (Bonds::version) or the
// model rewrites them (forget).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/bonds.hpp"

namespace pdq::peri {

// What a kernel reads: bonds b and b + 1 side by side. pair[b] is where their pair row starts,
// row[pair[b] ..] its four doubles (length and weight of bond b, then of b + 1): an offset,
// not a row number, spares a kernel a multiplication per load. broken[p / 2 + s] is where the
// pair row at p starts with its bond s (0: the first) broken, weight 0. A vector
// kernel takes the rows of bonds b, b + 2, ... for its lanes; a bond's own length and weight
// are the first half of its pair row (rowOf). The last bond of a particle shares its row with
// the next particle's first, whose half is read only in lanes a kernel masks: so a kernel
// that breaks a bond updates only pair offsets of its own particle (breakRows), and no thread
// writes another's.
//
// at[b], where made (BondClasses given a row stride): where bond b's partner's position row
// starts, its local index times the stride, so that a kernel adds it to the rows' address as
// it is.
struct BondRows {
  std::uint32_t* pair = nullptr;
  const double* row = nullptr;
  const std::uint32_t* broken = nullptr;
  const std::int32_t* at = nullptr;
};

inline const double* rowOf(const BondRows& r, std::size_t b) { return r.row + r.pair[b]; }

// Bond b, of the particle whose bonds start at b0, has broken.
inline void breakRows(const BondRows& r, std::size_t b0, std::size_t b) {
  r.pair[b] = r.broken[r.pair[b] / 2];
  if (b > b0) r.pair[b - 1] = r.broken[r.pair[b - 1] / 2 + 1];
}

class BondClasses {
 public:
  // partnerRowStride: the doubles of a position row, for BondRows::at (0: none made).
  explicit BondClasses(std::size_t partnerRowStride = 0) : partnerRowStride_(partnerRowStride) {}
  // Rebuilds the rows if the bonds changed since the last call, or after forget(); true
  // when it did.
  bool update(const Bonds& B);
  void forget() { built_ = false; }
  BondRows rows() {
    return {pair_.data(), pairRows_.data(), pairBroken_.data(), at_.empty() ? nullptr : at_.data()};
  }
  // Distinct (length, weight) rows, with their broken twins.
  std::size_t count() const { return broken_.size(); }

 private:
  // The row's number, added if new.
  std::uint32_t find(const double row[2]);
  // The pair row of rows a and b, added if new.
  std::uint32_t findPair(std::uint32_t a, std::uint32_t b);

  std::size_t partnerRowStride_;
  bool built_ = false;
  std::uint64_t version_ = 0;
  std::vector<double> rows_;  // two doubles per row
  std::vector<std::uint32_t> broken_;
  std::vector<std::uint32_t> slots_;  // open addressing: row number + 1, 0 = empty
  std::vector<std::uint32_t> pair_;   // per bond: the pair row of it and the next
  std::vector<double> pairRows_;      // four doubles per pair row
  std::vector<std::uint32_t> pairBroken_;
  std::vector<std::uint64_t> pairKeys_;   // the two rows of each pair row
  std::vector<std::uint32_t> pairSlots_;  // as slots_
  std::vector<std::int32_t> at_;
};

}  // namespace pdq::peri
