// Scenario generators for the square (2D) and simple-cubic (3D) lattices of prep/lattice.hpp:
//     [particles]
//     generator = "square"      # or "cubic"
//     nx = 80                   # points along X, Y (, Z)
//     ny = 40
//     spacing = 0.01
//     origin = [0, 0, 0]        # optional; first_id = 1 optional
#include <algorithm>

#include "engine/error.hpp"
#include "prep/generator.hpp"
#include "prep/lattice.hpp"

namespace pdq::prep {
namespace {

Generated lattice(const Params& p, const Schema& schema, bool cubic) {
  Lattice L;
  const char* keys[3] = {"nx", "ny", "nz"};
  for (int a = 0; a < (cubic ? 3 : 2); ++a) {
    const long n = p.integer(keys[a]);
    if (n < 1 || n > 100000000) {
      const auto v = p.raw(keys[a]);
      throw InputError(v->file, v->line, std::string(keys[a]) + " must be a whole number >= 1");
    }
    L.n[a] = static_cast<int>(n);
  }
  L.spacing = p.number("spacing", 1.0, 1e-300, 1e300);
  if (p.has("origin")) {
    const auto o = p.numbers("origin");
    if (o.size() != 3) {
      const auto v = p.raw("origin");
      throw InputError(v->file, v->line, "origin needs 3 numbers");
    }
    std::copy(o.begin(), o.end(), L.origin.begin());
  }
  L.firstId = p.integer("first_id", 1);
  Generated g;
  g.particles.nFixed = schema.nFixed();
  g.particles.nAlter = schema.nAlter();
  appendLattice(g.particles, L);
  return g;
}

Generated square(const Params& p, const Schema& s) { return lattice(p, s, false); }
Generated cubic(const Params& p, const Schema& s) { return lattice(p, s, true); }

}  // namespace

PDQ_REGISTER_GENERATOR(square, "square", "square lattice (2D): nx, ny, spacing, origin, first_id");
PDQ_REGISTER_GENERATOR(cubic, "cubic",
                       "simple-cubic lattice (3D): nx, ny, nz, spacing, origin, first_id");

}  // namespace pdq::prep
