// Scenario generator for 3D MPLM members (model mplm3d): a box of the fcc lattice with
// supports, loads and monitors, the counterparts of the 2D generators.
//     [particles]
//     generator = "mplm3d_beam"
//     length = 2.0          # X (m)
//     depth = 0.35          # Y, vertical (m)
//     width = 0.16          # Z (m)
//     bonds_along = "x"     # lattice orientation: the axis of one bond direction ...
//     layers_along = "z"    # ... and the axis the close-packed layers are stacked along
//     supports = "clamped"  # clamped | simple | bearings | none
//     clamped_planes = 2    # clamped: planes of particles held at X = 0
//     support_width = 0.04  # simple, bearings: bottom-plane particles this close to an end
//     loading = "tip"       # tip: the last plane at X = length; top: the top plane; none
// A plane is every particle within one lattice stride of a face (all rows, all layers).
//     load = 1.0            # tip: total force (N); top: line load (N/m); downward
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "engine/error.hpp"
#include "models/mplm/3d/attributes.hpp"
#include "models/mplm/common/parameters.hpp"
#include "prep/fcc.hpp"
#include "prep/generator.hpp"
#include "prep/mplm/specimen.hpp"
#include "prep/mplm/specimen3d.hpp"

namespace pdq::mplm3d {
namespace {

constexpr double big = 1e300;

// An error in building the member, reported at the generator's line (or the key's).
[[noreturn]] void fail(const Params& p, const std::string& why, const char* key = "generator") {
  auto v = p.raw(key);
  if (!v) v = p.raw("generator");
  throw InputError(v ? v->file : p.owner(), v ? v->line : 0, why);
}

int axisOf(const Params& p, const char* key, const std::string& fallback) {
  const std::string a = p.choice(key, fallback, {"x", "y", "z"});
  return a == "x" ? 0 : (a == "y" ? 1 : 2);
}

// Shares a total downward force equally among the particles.
void load3(ParticleSet& ps, const std::vector<std::size_t>& idx, double total) {
  if (idx.empty()) return;
  load(ps, idx, {0, -total / static_cast<double>(idx.size()), 0, 0, 0, 0});
}

Generated beam3d(const Params& p, const Schema& schema, const Params& model) {
  if (schema.nFixed() != N_FIXED || schema.nAlter() != N_ALTER)
    fail(p, "mplm3d_beam makes 3D MPLM particles; use it with model mplm3d");
  mplm::Parameters par;
  par.read(model);
  const double s = par.s;
  const double length = p.number("length", 2.0, 1e-300, big);
  const double depth = p.number("depth", 0.35, 1e-300, big);
  const double width = p.number("width", 0.16, 1e-300, big);
  ClosePacked lattice{s, axisOf(p, "bonds_along", "x"), axisOf(p, "layers_along", "z")};
  if (lattice.bondAxis == lattice.stackAxis)
    fail(p, "bonds_along and layers_along must be different axes", "layers_along");
  const std::string supports =
      p.choice("supports", "clamped", {"clamped", "simple", "bearings", "none"});
  const std::string loading = p.choice("loading", "tip", {"tip", "top", "none"});
  const double load = p.number("load", 1.0, -big, big);
  const long clampedPlanes = p.integer("clamped_planes", 2);
  const double supportWidth = p.number("support_width", 0.04, 0.0, length / 2);
  if (supports == "clamped" && clampedPlanes < 1)
    fail(p, "clamped_planes must be at least 1", "clamped_planes");

  const std::array<double, 3> size{length, depth, width};
  const char* keys[3] = {"length", "depth", "width"};
  // The lattice's cells fill the box (closePackedFill): two planes need a stride plus the
  // inset from the first face.
  auto need = closePackedMinimumBox(lattice);
  const auto inset = closePackedInset(lattice);
  for (int a = 0; a < 3; ++a) need[a] += inset[a];
  for (int a = 0; a < 3; ++a)
    if (size[a] < need[a])
      fail(p,
           "the lattice does not fit the box: " + std::string(keys[a]) + " " +
               std::to_string(size[a]) + " m is less than the lattice's stride " +
               std::to_string(need[a]) + " m along it (two particles at least)",
           keys[a]);
  ParticleSet ps = newParticleSet();
  addConcrete(ps, closePackedFill(lattice, size));
  // A plane of the lattice normal to an axis: the slab one stride thick (s along the bonds,
  // (√3/2)s across the rows, √(2/3)s across the layers) that holds one particle of every
  // row of every layer; the cells fill the box, so the planes start at its faces.
  const auto& pitch = closePackedMinimumBox(lattice);
  auto fromLow = [&](const double* f, int axis, double planes) {
    return f[axis] < planes * pitch[axis];
  };
  auto fromHigh = [&](const double* f, int axis, double planes) {
    return f[axis] > size[axis] - planes * pitch[axis];
  };
  if (supports == "clamped" &&
      static_cast<double>(clampedPlanes + 1) * pitch[0] > length + 1e-9 * s)
    fail(p, "clamped_planes leaves no free plane of particles along the length", "clamped_planes");
  const auto bottom = [&](bool left) {
    return mplm::select(ps, [&](const double* f) {
      return fromLow(f, 1, 1) && (left ? f[0] <= supportWidth : f[0] >= length - supportWidth);
    });
  };
  if (supports == "clamped") {
    const auto held = static_cast<double>(clampedPlanes);
    constrain(ps, mplm::select(ps, [&](const double* f) { return fromLow(f, 0, held); }), FIX_ALL);
  } else if (supports == "simple") {
    constrain(ps, bottom(true), FIX_X | FIX_Y | FIX_Z);
    constrain(ps, bottom(false), FIX_Y | FIX_Z);
  } else if (supports == "bearings") {
    const auto left = bottom(true), right = bottom(false);
    constrain(ps, left, REST_Y | FIX_Z);
    constrain(ps, right, REST_Y | FIX_Z);
    constrain(
        ps, mplm::select(ps, [&](const double* f) { return fromLow(f, 1, 1) && fromLow(f, 0, 1); }),
        FIX_X);
  }
  if (loading == "tip") {
    const auto end = mplm::select(ps, [&](const double* f) { return fromHigh(f, 0, 1); });
    load3(ps, end, load);
    monitor(ps, end);
  } else if (loading == "top") {
    load3(ps, mplm::select(ps, [&](const double* f) { return fromHigh(f, 1, 1); }), load * length);
    // Midspan bottom: the bottom plane's particles within half a plane of X = length / 2.
    monitor(ps, mplm::select(ps, [&](const double* f) {
              return fromLow(f, 1, 1) && std::fabs(f[0] - length / 2) <= pitch[0] / 2;
            }));
  }
  Generated g;
  g.particles = std::move(ps);
  return g;
}

}  // namespace

PDQ_REGISTER_GENERATOR(beam3d, "mplm3d_beam",
                       "3D MPLM member (fcc lattice): length, depth, width, bonds_along, "
                       "layers_along, supports (clamped, simple, bearings), loading (tip, top), "
                       "load\n"
                       "  length, depth, width  along X, Y, Z in m (default 2.0, 0.35, 0.16)\n"
                       "  bonds_along, layers_along  axes x, y or z (default x, z)\n"
                       "  supports       clamped, simple, bearings or none (default clamped); "
                       "clamped_planes 2, support_width 0.04\n"
                       "  loading        tip, top or none (default tip); load, N (default 1)\n"
                       "  spacing: the [model]'s\n"
                       "  IDs            from 0, layer by layer, row by row, along each row");

}  // namespace pdq::mplm3d
