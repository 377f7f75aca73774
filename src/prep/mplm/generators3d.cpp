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
//     support_width = 0.04  # simple, bearings: bottom particles this close to an end
//     loading = "tip"       # tip: the last plane at X = length; top: the top face; none
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

// The distinct values of coordinate `axis` (to 1e-6 s), ascending.
std::vector<double> planes(const ParticleSet& ps, int axis, double s) {
  std::vector<double> v;
  for (std::size_t k = 0; k < ps.size(); ++k) v.push_back(ps.fixedRow(k)[axis]);
  std::sort(v.begin(), v.end());
  std::vector<double> out;
  for (double x : v)
    if (out.empty() || x - out.back() > 1e-6 * s) out.push_back(x);
  return out;
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
  const auto xs = planes(ps, 0, s), ys = planes(ps, 1, s);
  if (supports == "clamped" && static_cast<std::size_t>(clampedPlanes) + 1 >= xs.size())
    fail(p, "clamped_planes leaves no free particles along the length", "clamped_planes");
  const double tol = 1e-6 * s, x0 = xs.front(), x1 = xs.back(), y0 = ys.front(), y1 = ys.back();
  auto at = [&](double v, double c) { return std::fabs(v - c) <= tol; };
  const auto end = mplm::select(ps, [&](const double* f) { return at(f[0], x1); });
  const auto bottom = [&](bool left) {
    return mplm::select(ps, [&](const double* f) {
      return at(f[1], y0) &&
             (left ? f[0] <= x0 + supportWidth + tol : f[0] >= x1 - supportWidth - tol);
    });
  };
  if (supports == "clamped") {
    const double last = xs[static_cast<std::size_t>(clampedPlanes) - 1];
    constrain(ps, mplm::select(ps, [&](const double* f) { return f[0] <= last + tol; }), FIX_ALL);
  } else if (supports == "simple") {
    constrain(ps, bottom(true), FIX_X | FIX_Y | FIX_Z);
    constrain(ps, bottom(false), FIX_Y | FIX_Z);
  } else if (supports == "bearings") {
    const auto left = bottom(true), right = bottom(false);
    constrain(ps, left, REST_Y | FIX_Z);
    constrain(ps, right, REST_Y | FIX_Z);
    constrain(ps, mplm::select(ps, [&](const double* f) { return at(f[1], y0) && at(f[0], x0); }),
              FIX_X);
  }
  if (loading == "tip") {
    load3(ps, end, load);
    monitor(ps, end);
  } else if (loading == "top") {
    const auto top = mplm::select(ps, [&](const double* f) { return at(f[1], y1); });
    load3(ps, top, load * length);
    // Midspan bottom: the bottom particles nearest to X = length / 2.
    double best = big;
    for (double x : xs) best = std::min(best, std::fabs(x - 0.5 * (x0 + x1)));
    monitor(ps, mplm::select(ps, [&](const double* f) {
              return at(f[1], y0) && std::fabs(std::fabs(f[0] - 0.5 * (x0 + x1)) - best) <= tol;
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
                       "load");

}  // namespace pdq::mplm3d
