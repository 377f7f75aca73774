// Scenario generators for the square (2D) and simple-cubic (3D) lattices of prep/lattice.hpp:
//     [particles]
//     generator = "square"      # or "cubic"
//     nx = 80                   # points along X, Y (, Z)
//     ny = 40
//     spacing = 0.01
//     origin = [0, 0, 0]        # optional; first_id = 1 optional
// IDs run from first_id with X fastest, then Y, then Z. A model with a "volume" attribute
// gets each particle's cell volume.
#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/error.hpp"
#include "prep/generator.hpp"
#include "prep/lattice.hpp"

namespace pdq::prep {
namespace {

Lattice readLattice(const Params& p, bool cubic) {
  Lattice L;
  const char* keys[3] = {"nx", "ny", "nz"};
  for (int a = 0; a < (cubic ? 3 : 2); ++a) {
    const double n = p.number(keys[a]);
    const auto v = p.raw(keys[a]);
    if (n < 1 || n != std::floor(n))
      throw InputError(v->file, v->line, std::string(keys[a]) + " must be a whole number >= 1");
    if (n > std::numeric_limits<int>::max())
      throw InputError(v->file, v->line,
                       std::string(keys[a]) + " = " + v->text + " exceeds the largest count " +
                           "along an axis, " + std::to_string(std::numeric_limits<int>::max()));
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
  return L;
}

Generated lattice(const Params& p, const Schema& schema, const Params& model, bool cubic) {
  const Lattice L = readLattice(p, cubic);
  Generated g;
  g.particles.nFixed = schema.nFixed();
  g.particles.nAlter = schema.nAlter();
  appendLattice(g.particles, L);
  // A model whose particles carry a volume (peridynamics) gets each point's cell: s^3, or
  // s^2 times the model's thickness in 2D. [[particles.set]] may still override it.
  if (const int vol = schema.fixedIndex("volume"); vol >= 0) {
    const double s = L.spacing;
    const double v = cubic ? s * s * s : s * s * model.number("thickness", 1.0);
    for (std::size_t k = 0; k < g.particles.size(); ++k) g.particles.fixedRow(k)[vol] = v;
  }
  return g;
}

Generated square(const Params& p, const Schema& s, const Params& m) {
  return lattice(p, s, m, false);
}
Generated cubic(const Params& p, const Schema& s, const Params& m) {
  return lattice(p, s, m, true);
}

SizeEstimate latticeSize(const Params& p, bool cubic) {
  const Lattice L = readLattice(p, cubic);
  SizeEstimate e;
  e.particles = double(L.n[0]) * L.n[1] * L.n[2];
  for (int a = 0; a < (cubic ? 3 : 2); ++a) {
    e.lo[a] = L.origin[a];
    e.hi[a] = L.origin[a] + (L.n[a] - 1) * L.spacing;
    e.stride[a] = L.spacing;
    std::array<double, 3> v{};
    v[a] = L.spacing;
    e.primitive.push_back(v);
  }
  return e;
}

SizeEstimate squareSize(const Params& p, const Params&) { return latticeSize(p, false); }
SizeEstimate cubicSize(const Params& p, const Params&) { return latticeSize(p, true); }

}  // namespace

PDQ_REGISTER_ESTIMATE(squareSize, "square");
PDQ_REGISTER_ESTIMATE(cubicSize, "cubic");
PDQ_REGISTER_GENERATOR(square, "square",
                       "square lattice (2D): nx, ny, spacing, origin, first_id\n"
                       "  nx, ny      points along X and Y (required; whole numbers >= 1)\n"
                       "  spacing     distance between neighbours (default 1)\n"
                       "  origin      [x, y, z] of the first point (default [0, 0, 0])\n"
                       "  first_id    ID of the first point (default 1)\n"
                       "  IDs         from first_id, X fastest, then Y\n"
                       "  volume      set for models that have one: spacing^2 x [model] "
                       "thickness (default 1)");
PDQ_REGISTER_GENERATOR(cubic, "cubic",
                       "simple-cubic lattice (3D): nx, ny, nz, spacing, origin, first_id\n"
                       "  nx, ny, nz  points along X, Y and Z (required; whole numbers >= 1)\n"
                       "  spacing     distance between neighbours (default 1)\n"
                       "  origin      [x, y, z] of the first point (default [0, 0, 0])\n"
                       "  first_id    ID of the first point (default 1)\n"
                       "  IDs         from first_id, X fastest, then Y, then Z\n"
                       "  volume      set for models that have one: spacing^3");

}  // namespace pdq::prep
