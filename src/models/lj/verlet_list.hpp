#pragma once
// Half Verlet neighbour lists: for every owned particle i, the owned particles j > i and
// all the ghosts closer than a radius at the time of the build, found through the
// engine's cells (gathered once per cell). A pair of owned particles appears once (its force is
// computed once and added to both, Newton's third law); a pair with a ghost appears in
// the owned particle's list only (the ghost's own rank computes its side). The lists
// carry no summation order: the kernel sums exactly (see kernel.hpp), so any order of the
// pairs gives the same bits.
//
//
// The radius is the engine's cell edge: the engine shuffles (and the model rebuilds)
// before any particle moved more than half of (that edge - rc), so until then no pair
// closer than rc can be missing.
#include <cstdint>
#include <vector>

#include "engine/context.hpp"

namespace pdq::lj {

// Appends to `out` the candidates k in [from, to) (positions cx, cy, cz; indices id) closer
// to (x, y, z) than sqrt(r2max), returns how many. May write 8 entries past them.
std::size_t keepNear(const double* cx, const double* cy, const double* cz, const std::uint32_t* id,
                     std::size_t from, std::size_t to, double x, double y, double z, double r2max,
                     std::uint32_t* out);
// The same in AVX-512 (avx512.cpp), for processors that have it (x86-64-v4).
std::size_t keepNearAvx512(const double* cx, const double* cy, const double* cz,
                           const std::uint32_t* id, std::size_t from, std::size_t to, double x,
                           double y, double z, double r2max, std::uint32_t* out);

// The filter the list build uses: keepNearAvx512 where the processor has AVX-512, else
// keepNear.
using KeepNear = std::size_t (*)(const double*, const double*, const double*, const std::uint32_t*,
                                 std::size_t, std::size_t, double, double, double, double,
                                 std::uint32_t*);
KeepNear chosenKeepNear();

class VerletList {
 public:
  // pos: packed positions of the local particles, `stride` doubles a row (x, y, z first).
  // `portable`: keepNear even where the processor has AVX-512.
  void build(const Context& ctx, const double* pos, std::size_t stride, double radius,
             bool portable);

  // Partners of owned particle i: [begin, ghosts) owned partners, [ghosts, end) ghosts.
  const std::uint32_t* begin(std::size_t i) const { return index_.data() + start_[i]; }
  const std::uint32_t* ghosts(std::size_t i) const { return index_.data() + ghost_[i]; }
  const std::uint32_t* end(std::size_t i) const { return index_.data() + start_[i + 1]; }
  std::size_t size() const { return start_.empty() ? 0 : start_.size() - 1; }
  std::size_t entries() const { return index_.size(); }
  std::size_t longest() const { return longest_; }

 private:
  struct Scratch {                     // one per thread
    std::vector<std::uint32_t> out;    // the lists of the thread's particles
    std::vector<std::uint32_t> near;   // candidates of one cell: owned by index, then ghosts
    std::vector<std::uint32_t> ghost;  // its ghost candidates, while gathering
    std::size_t owned = 0;             // owned candidates
    std::vector<double> xyz;           // their x, y, z (one array each), then distances
    std::vector<std::size_t> count;    // list length and owned partners, per particle
  };
  std::vector<std::size_t> start_, ghost_;
  std::size_t longest_ = 0;
  std::vector<std::uint32_t> index_;
  std::vector<Scratch> threads_;
};

}  // namespace pdq::lj
