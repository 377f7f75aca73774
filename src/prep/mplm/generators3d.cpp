#include "prep/mplm/generators3d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "engine/error.hpp"
#include "models/mplm/3d/attributes.hpp"
#include "models/mplm/common/parameters.hpp"
#include "prep/generator.hpp"
#include "prep/lattice.hpp"
#include "prep/mplm/specimen.hpp"
#include "prep/mplm/specimen3d.hpp"

namespace pdq::mplm3d {
namespace {

constexpr double big = 1e300;

// An error in the member, reported at the key's line (or the generator's).
[[noreturn]] void fail(const Params& p, const std::string& why,
                       const std::string& key = "generator") {
  auto v = p.raw(key);
  if (!v) v = p.raw("generator");
  throw InputError(v ? v->file : p.owner(), v ? v->line : 0, why);
}

std::string metres(double v) {
  char t[32];
  std::snprintf(t, sizeof t, "%.4g m", v);
  return t;
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

// The section of `<prefix>_size` (an ASTM designation) or `<prefix>_diameter` (m); none
// when neither is given.
std::optional<prep::BarSection> barSection(const Params& p, const std::string& prefix) {
  const std::string size = prefix + "_size", diameter = prefix + "_diameter";
  if (p.has(size) && p.has(diameter))
    fail(p, "give " + size + " or " + diameter + ", not both", diameter);
  if (p.has(size)) {
    const std::string name = p.text(size);
    const auto bar = prep::astmBar(name);
    if (!bar)
      fail(p, "'" + name + "' is not an ASTM bar size: give one of " + prep::astmBarSizes(), size);
    return bar;
  }
  if (p.has(diameter)) return prep::BarSection{p.number(diameter, 0.0, 1e-300, big)};
  return std::nullopt;
}

// The longitudinal bars: in one row at a face, or at the given centroids.
std::vector<BarSpec> readBars(const Params& p, const BeamSpec& b) {
  const auto section = barSection(p, "bar");
  if (!section) return {};
  const double r = section->diameter / 2;
  std::vector<BarSpec> bars;
  std::string where = "bar_y";
  if (p.has("bar_y") || p.has("bar_z")) {
    const auto ys = p.numbers("bar_y"), zs = p.numbers("bar_z");
    if (ys.size() != zs.size() || ys.empty())
      fail(p, "bar_y and bar_z must list the same number of bars (one centroid each)", "bar_z");
    for (std::size_t k = 0; k < ys.size(); ++k) bars.push_back({ys[k], zs[k], *section});
  } else {
    where = "bar_cover";
    const long count = p.integer("bar_count", 2);
    const std::string face = p.choice("bar_face", "bottom", {"top", "bottom"});
    const double cover = p.number("bar_cover", 0.04, 0.0, big);
    if (count < 1) fail(p, "bar_count must be at least 1", "bar_count");
    const double half = std::min(b.depth, b.width) / 2;
    if (cover > half)
      fail(p,
           "bar_cover " + metres(cover) + " is larger than half the section (" + metres(half) +
               "): the bars would lie outside it",
           "bar_cover");
    const double clear = b.width - 2 * cover - 2 * r * static_cast<double>(count);
    if (count > 1 && clear < 0)
      fail(p,
           std::to_string(count) + " bars of " + metres(section->diameter) +
               " do not fit in a row across the width " + metres(b.width) + " with cover " +
               metres(cover),
           "bar_count");
    const double y = face == "bottom" ? cover + r : b.depth - cover - r;
    for (long k = 0; k < count; ++k) {
      const double z = count == 1 ? b.width / 2
                                  : cover + r +
                                        static_cast<double>(k) * (b.width - 2 * cover - 2 * r) /
                                            static_cast<double>(count - 1);
      bars.push_back({y, z, *section});
    }
  }
  for (std::size_t k = 0; k < bars.size(); ++k) {
    const BarSpec& bar = bars[k];
    if (bar.y - r < 0 || bar.y + r > b.depth || bar.z - r < 0 || bar.z + r > b.width) {
      char why[200];
      std::snprintf(why, sizeof why,
                    "bar %zu (centroid y = %.4g m, z = %.4g m, diameter %.4g m) lies outside the "
                    "%.4g x %.4g m section (depth x width)",
                    k + 1, bar.y, bar.z, section->diameter, b.depth, b.width);
      fail(p, why, where);
    }
  }
  return bars;
}

// Points of a closed hoop that would interact other than with their neighbours around it
// (steel particles of one bar within s interact): true when a hoop is too small for s.
bool crossesCorners(const std::vector<prep::Point>& pts, double s) {
  const double within = s * (1 + 1e-6);
  const std::size_t n = pts.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // the loop's closing segment
      const double d =
          std::hypot(pts[j][0] - pts[i][0], pts[j][1] - pts[i][1], pts[j][2] - pts[i][2]);
      if (d <= within) return true;
    }
  return false;
}

std::optional<StirrupSpec> readStirrups(const Params& p, const BeamSpec& b, double s) {
  const auto section = barSection(p, "stirrup");
  if (!section) return std::nullopt;
  StirrupSpec st;
  st.section = *section;
  st.spacing = p.number("stirrup_spacing", 0.15, 1e-300, big);
  if (st.spacing < s * (1 - 1e-9))
    fail(p,
         "stirrup_spacing " + metres(st.spacing) + " is below the lattice spacing s = " +
             metres(s) + ": the lattice cannot hold hoops closer than one spacing",
         "stirrup_spacing");
  st.cover = p.number("stirrup_cover", 0.02, 0.0, big);
  const double half = std::min(b.depth, b.width) / 2;
  if (st.cover + section->diameter >= half)
    fail(p,
         "stirrup_cover " + metres(st.cover) + " is larger than half the section (" + metres(half) +
             ") less the stirrup's diameter: no hoop fits",
         "stirrup_cover");
  st.first = p.number("stirrup_first", st.spacing / 2, 0.0, b.length);
  return st;
}

Generated beamGenerator(const Params& p, const Schema& schema, const Params& model) {
  if (schema.nFixed() != N_FIXED || schema.nAlter() != N_ALTER)
    fail(p, "mplm3d_beam makes 3D MPLM particles; use it with model mplm3d");
  Generated g;
  g.particles = beam(beamSpec(p, model));
  return g;
}

SizeEstimate beamSize(const Params& p, const Params& model) {
  const BeamSpec b = beamSpec(p, model);
  const std::array<double, 3> size{b.length, b.depth, b.width};
  const auto inset = closePackedInset(b.lattice);
  SizeEstimate e;
  e.particles = closePackedFillCount(b.lattice, size);
  for (int a = 0; a < 3; ++a) {
    e.lo[a] = inset[a];
    e.hi[a] = size[a];
  }
  e.stride = closePackedMinimumBox(b.lattice);
  for (const auto& v : closePackedVectors(b.lattice)) e.primitive.push_back(v);
  const double s = b.lattice.s;
  e.extraParticles = static_cast<double>(b.bars.size()) * (std::ceil(b.length / s) + 1);
  if (b.stirrups) {
    const double around = 2 * (b.hoopYHi() - b.hoopYLo() + b.hoopZHi() - b.hoopZLo());
    e.extraParticles +=
        prep::latticeSteps(b.length - b.stirrups->first, b.stirrups->first, b.stirrups->spacing) *
        std::ceil(around / s);
  }
  // Steel interacts with its neighbours along its bar, and every other steel particle (a
  // link) with the concrete within s: about (4/3) pi s^3 / (s^3 / sqrt(2)) of it.
  e.extraPairs = e.extraParticles * (1 + 4.0 / 3 * std::numbers::pi * std::sqrt(2.0) / 2);
  return e;
}

}  // namespace

double BeamSpec::hoopYLo() const { return stirrups->cover + stirrups->section.diameter / 2; }
double BeamSpec::hoopYHi() const { return depth - hoopYLo(); }
double BeamSpec::hoopZLo() const { return hoopYLo(); }
double BeamSpec::hoopZHi() const { return width - hoopYLo(); }

BeamSpec beamSpec(const Params& p, const Params& model) {
  mplm::Parameters par;
  par.read(model);
  const double s = par.s;
  BeamSpec b;
  b.length = p.number("length", b.length, 1e-300, big);
  b.depth = p.number("depth", b.depth, 1e-300, big);
  b.width = p.number("width", b.width, 1e-300, big);
  b.lattice = {s, axisOf(p, "bonds_along", "x"), axisOf(p, "layers_along", "z")};
  if (b.lattice.bondAxis == b.lattice.stackAxis)
    fail(p, "bonds_along and layers_along must be different axes", "layers_along");
  b.supports = p.choice("supports", b.supports, {"clamped", "simple", "bearings", "none"});
  b.loading = p.choice("loading", b.loading, {"tip", "top", "none"});
  b.load = p.number("load", b.load, -big, big);
  b.clampedPlanes = p.integer("clamped_planes", b.clampedPlanes);
  b.supportWidth = p.number("support_width", b.supportWidth, 0.0, b.length / 2);
  if (b.supports == "clamped" && b.clampedPlanes < 1)
    fail(p, "clamped_planes must be at least 1", "clamped_planes");

  const std::array<double, 3> size{b.length, b.depth, b.width};
  const char* keys[3] = {"length", "depth", "width"};
  // The lattice's cells fill the box (closePackedFill): two planes need a stride plus the
  // inset from the first face.
  const auto pitch = closePackedMinimumBox(b.lattice);
  const auto inset = closePackedInset(b.lattice);
  for (int a = 0; a < 3; ++a)
    if (size[a] < pitch[a] + inset[a])
      fail(p,
           "the lattice does not fit the box: " + std::string(keys[a]) + " " + metres(size[a]) +
               " is less than the lattice's stride " + metres(pitch[a] + inset[a]) +
               " along it (two particles at least)",
           keys[a]);
  if (b.supports == "clamped" &&
      static_cast<double>(b.clampedPlanes + 1) * pitch[0] > b.length + 1e-9 * s)
    fail(p, "clamped_planes leaves no free plane of particles along the length", "clamped_planes");
  b.bars = readBars(p, b);
  b.stirrups = readStirrups(p, b, s);
  if (b.stirrups) {
    const prep::Hoop hoop{0,           b.hoopYLo(), b.hoopYHi(),
                          b.hoopZLo(), b.hoopZHi(), b.stirrups->section};
    if (crossesCorners(prep::hoopPoints(hoop, s), s))
      fail(p,
           "the stirrups' hoops (" + metres(hoop.yHi - hoop.yLo) + " x " +
               metres(hoop.zHi - hoop.zLo) +
               " between centre lines) are too small for the lattice spacing " + metres(s) +
               ": their particles would interact across the corners",
           "stirrup_cover");
  }
  return b;
}

ParticleSet beam(const BeamSpec& b) {
  const double s = b.lattice.s;
  const std::array<double, 3> size{b.length, b.depth, b.width};
  ParticleSet ps = newParticleSet();
  addConcrete(ps, closePackedFill(b.lattice, size));
  // A plane of the lattice normal to an axis: the slab one stride thick (s along the bonds,
  // (√3/2)s across the rows, √(2/3)s across the layers) that holds one particle of every
  // row of every layer; the cells fill the box, so the planes start at its faces.
  const auto pitch = closePackedMinimumBox(b.lattice);
  auto fromLow = [&](const double* f, int axis, double planes) {
    return !isSteel(f) && f[axis] < planes * pitch[axis];
  };
  auto fromHigh = [&](const double* f, int axis, double planes) {
    return !isSteel(f) && f[axis] > size[axis] - planes * pitch[axis];
  };
  // Steel: bars along the concrete's length (its first to its last plane), then hoops.
  double x0 = big, x1 = -big;
  for (std::size_t k = 0; k < ps.size(); ++k) {
    x0 = std::min(x0, ps.fixedRow(k)[FX_X]);
    x1 = std::max(x1, ps.fixedRow(k)[FX_X]);
  }
  int barId = 1;
  for (const BarSpec& bar : b.bars)
    mplm::addBar(ps, {{x0, bar.y, bar.z}, {x1, bar.y, bar.z}, bar.section}, s, barId++);
  if (b.stirrups)
    for (double x :
         prep::stations(b.stirrups->first, b.stirrups->spacing, b.length - b.stirrups->first))
      mplm::addSteel(
          ps,
          prep::hoopPoints(
              {x, b.hoopYLo(), b.hoopYHi(), b.hoopZLo(), b.hoopZHi(), b.stirrups->section}, s),
          b.stirrups->section, barId++);

  const auto bottom = [&](bool left) {
    return mplm::select(ps, [&](const double* f) {
      return fromLow(f, 1, 1) &&
             (left ? f[0] <= b.supportWidth : f[0] >= b.length - b.supportWidth);
    });
  };
  if (b.supports == "clamped") {
    const auto held = static_cast<double>(b.clampedPlanes);
    // Steel within the clamped planes is held with the concrete around it.
    constrain(ps, mplm::select(ps, [&](const double* f) { return f[0] < held * pitch[0]; }),
              FIX_ALL);
  } else if (b.supports == "simple") {
    constrain(ps, bottom(true), FIX_X | FIX_Y | FIX_Z);
    constrain(ps, bottom(false), FIX_Y | FIX_Z);
  } else if (b.supports == "bearings") {
    const auto left = bottom(true), right = bottom(false);
    constrain(ps, left, REST_Y | FIX_Z);
    constrain(ps, right, REST_Y | FIX_Z);
    constrain(
        ps, mplm::select(ps, [&](const double* f) { return fromLow(f, 1, 1) && fromLow(f, 0, 1); }),
        FIX_X);
  }
  if (b.loading == "tip") {
    const auto end = mplm::select(ps, [&](const double* f) { return fromHigh(f, 0, 1); });
    load3(ps, end, b.load);
    monitor(ps, end);
  } else if (b.loading == "top") {
    load3(ps, mplm::select(ps, [&](const double* f) { return fromHigh(f, 1, 1); }),
          b.load * b.length);
    // Midspan bottom: the bottom plane's particles within half a plane of X = length / 2.
    monitor(ps, mplm::select(ps, [&](const double* f) {
              return fromLow(f, 1, 1) && std::fabs(f[0] - b.length / 2) <= pitch[0] / 2;
            }));
  }
  return ps;
}

PDQ_REGISTER_ESTIMATE(beamSize, "mplm3d_beam");
PDQ_REGISTER_GENERATOR(beamGenerator, "mplm3d_beam",
                       "3D MPLM member (fcc lattice): length, depth, width, bonds_along, "
                       "layers_along, supports (clamped, simple, bearings), loading (tip, top), "
                       "load, bar_* (bars by ASTM size or diameter), stirrup_* (closed hoops)\n"
                       "  length, depth, width  along X, Y, Z in m (default 2.0, 0.35, 0.16)\n"
                       "  bonds_along, layers_along  axes x, y or z (default x, z)\n"
                       "  supports       clamped, simple, bearings or none (default clamped); "
                       "clamped_planes 2, support_width 0.04\n"
                       "  loading        tip, top or none (default tip); load, N (default 1)\n"
                       "  bars           bar_size (ASTM, e.g. #19) or bar_diameter; bar_count 2, "
                       "bar_face bottom, bar_cover 0.04; or bar_y, bar_z\n"
                       "  stirrups       stirrup_size or stirrup_diameter; stirrup_spacing 0.15, "
                       "stirrup_cover 0.02, stirrup_first spacing/2\n"
                       "  spacing: the [model]'s\n"
                       "  IDs            from 0, layer by layer, row by row, along each row; "
                       "then each bar's steel, then each hoop's");

}  // namespace pdq::mplm3d
