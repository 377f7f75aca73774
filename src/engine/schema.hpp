#pragma once
// The attributes a model declares. Every particle has a global ID; the first three
// fixed attributes are its reference position (X, Y, Z) and the first three alterable
// ones its current position (x, y, z), as in the thesis's files. Attributes are grouped
// by how often they travel:
//   fixed   never change; sent only when a particle or ghost is (re)created
//   alter   change every step; the halo exchange sends the first `haloColumns` of them
//           (all by default) for ghosts: a model whose force reads only its ghosts'
//           positions sets 3, and its ghosts' other alterable values are those of the
//           last border pass
//   integ   per-step scratch of owned particles (forces, accumulators); never sent,
//           never written to restart files, so a model must recompute them each step
//   bond    per-bond state (damage, ...); travels with the bond's owning particle
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace pdq {

using Gid = std::int64_t;

struct Schema {
  std::vector<std::string> fixed{"X", "Y", "Z"};
  std::vector<std::string> alter{"x", "y", "z"};
  std::vector<std::string> integ;
  std::vector<std::string> bond;
  int haloColumns = -1;  // leading alterable attributes the halo sends; -1: all

  // Positions are prepended: make({"volume"}, {"vx","vy","vz"}, {"fx","fy","fz"}, {"damage"}).
  static Schema make(std::vector<std::string> fixedExtra, std::vector<std::string> alterExtra,
                     std::vector<std::string> integ = {}, std::vector<std::string> bond = {});

  int nFixed() const { return static_cast<int>(fixed.size()); }
  int nAlter() const { return static_cast<int>(alter.size()); }
  int nInteg() const { return static_cast<int>(integ.size()); }
  int nBond() const { return static_cast<int>(bond.size()); }
  int nHalo() const { return haloColumns < 0 ? nAlter() : std::min(haloColumns, nAlter()); }
  // Column of a named attribute, or -1.
  int fixedIndex(const std::string& name) const;
  int alterIndex(const std::string& name) const;
  int integIndex(const std::string& name) const;
  int bondIndex(const std::string& name) const;
};

}  // namespace pdq
