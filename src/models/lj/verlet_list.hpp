#pragma once
// Verlet neighbour lists: for every owned particle, all particles (owned or ghost) within
// a radius at the time of the build, found through the engine's cells and SORTED BY
// GLOBAL ID. A force summed along such a list adds its terms in an order that depends on
// neither the memory layout, the processor grid nor the moment of the last rebuild, which
// keeps results bitwise identical on any number of ranks and threads.
#include <cstdint>
#include <vector>

#include "engine/context.hpp"

namespace pdq::lj {

class VerletList {
 public:
  void build(const Context& ctx, double radius);

  const std::uint32_t* begin(std::size_t i) const { return index_.data() + start_[i]; }
  const std::uint32_t* end(std::size_t i) const { return index_.data() + start_[i + 1]; }
  std::size_t size() const { return start_.empty() ? 0 : start_.size() - 1; }
  std::size_t entries() const { return index_.size(); }
  std::size_t longest() const { return longest_; }

 private:
  struct Scratch {                            // one per thread
    std::vector<std::uint32_t> out;           // the lists of the thread's particles
    std::vector<std::uint32_t> near;          // kept candidates of one particle
    std::vector<std::uint64_t> pairs, spare;  // (rank << 32 | particle in block) of a block
    std::vector<std::size_t> cursor;
  };
  std::vector<std::size_t> start_;
  std::size_t longest_ = 0;
  std::vector<std::uint32_t> index_;
  std::vector<std::uint32_t> rank_, byRank_;  // local index <-> position in global-ID order
  std::vector<double> xyz_;                   // packed positions during a build
  std::vector<Scratch> threads_;
};

}  // namespace pdq::lj
