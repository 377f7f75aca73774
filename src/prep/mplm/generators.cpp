#include "prep/mplm/generators.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

#include "engine/error.hpp"
#include "models/mplm/2d/attributes.hpp"
#include "models/mplm/2d/parameters.hpp"
#include "prep/generator.hpp"
#include "prep/hexagonal.hpp"
#include "prep/lattice.hpp"
#include "prep/mplm/specimen.hpp"
#include "prep/rebar.hpp"

namespace pdq::mplm {

ParticleSet plate(const PlateSpec& spec) {
  const double s = spec.spacing, t = spec.thickness;
  const auto o = prep::hexOrientation(spec.orientation);
  ParticleSet ps = newParticleSet();
  addConcrete(ps, prep::hexagonalRectangle(spec.width, spec.height, s, o));
  // Two layers at each end: rows (√3/2 s apart) or zig-zag layers (s/2 apart).
  const double layer = o == prep::HexOrientation::BondsAlongX ? prep::hexPitch(s) : s / 2;
  const double reach = 1.5 * layer;
  const double yMax = maxCoord(ps, 1);
  const auto top = select(ps, [&](const double* f) { return f[1] > yMax - reach; });
  const auto bottom = select(ps, [&](const double* f) { return f[1] < reach; });
  const double force = spec.stress * spec.width * t * (spec.compression ? -1 : 1);
  if (spec.loaded && spec.traction) {
    loadUniform(ps, top, 0, 0, spec.width, 0, force);
    loadUniform(ps, bottom, 0, 0, spec.width, 0, -force);
  } else if (spec.loaded) {
    load(ps, top, 0, force / top.size());
    load(ps, bottom, 0, -force / bottom.size());
  }
  monitor(ps, top);
  return ps;
}

namespace {
// Stirrups stand on the lowest bar layer (without bars: at its default height).
double stirrupFoot(const BeamSpec& b) {
  double y = b.bars.empty() ? BeamSpec::BarLayer{}.centroid : b.bars.front().centroid;
  for (const auto& layer : b.bars) y = std::min(y, layer.centroid);
  return y;
}
}  // namespace

ParticleSet beam(const BeamSpec& b) {
  const double s = b.spacing, tol = 1e-6 * s;
  const double length = b.span + 2 * b.overhang, mid = length / 2;
  if (b.notchDepth > 0 && b.notchWidth < s - tol)
    throw std::invalid_argument("the notch width " + numberText(b.notchWidth) +
                                " is less than the spacing " + numberText(s) +
                                ": interactions would cross the notch");
  auto inNotch = [&](double x, double y) {
    return y < b.notchDepth - tol && std::fabs(x - mid) <= b.notchWidth / 2 + tol;
  };
  std::vector<std::array<double, 2>> points;
  for (const auto& p :
       prep::hexagonalRectangle(length, b.depth, s, prep::HexOrientation::BondsAlongX))
    if (!inNotch(p[0], p[1])) points.push_back(p);
  ParticleSet ps = newParticleSet();
  addConcrete(ps, points);
  int barId = 1;
  for (const auto& layer : b.bars)
    addBar(ps, prep::longitudinalBar(0, length, 0, layer.centroid, layer.diameter), s, barId++,
           layer.count);
  if (b.stirrupDiameter > 0)
    for (const auto& st : prep::stirrups(
             b.stirrupFirst, b.stirrupSpacing, length - b.stirrupFirst + b.stirrupSpacing / 2,
             stirrupFoot(b), b.depth - b.stirrupCover, b.stirrupDiameter))
      addBar(ps, st, s, barId++);
  const double yTop = maxCoord(ps, 1);
  auto concreteAt = [&](double x, double y) {
    return select(ps, [=](const double* f) {
      return isConcrete(f) && std::fabs(f[0] - x) < tol && std::fabs(f[1] - y) < tol;
    });
  };
  for (const auto& [what, x] :
       {std::pair{"the span plus the overhangs", length}, std::pair{"the overhang", b.overhang}})
    if (concreteAt(x, 0).size() != 1)
      throw std::invalid_argument(std::string(what) + ", " + numberText(x) +
                                  ", is not a whole number of spacings: no lattice particle "
                                  "on the bottom face at the support");
  // A steel plate at dy from the face particles `covered` (a row, in X order): its indices.
  const double plateArea = b.plateThickness * b.thickness;
  const double plateInertia = b.thickness * std::pow(b.plateThickness, 3) / 12;
  auto addPlateAt = [&](const std::vector<std::size_t>& covered, double dy) {
    std::vector<prep::Point> points;
    for (std::size_t k : covered)
      points.push_back({ps.fixedRow(k)[0], ps.fixedRow(k)[1] + dy, 0.0});
    std::vector<std::size_t> idx(points.size());
    std::iota(idx.begin(), idx.end(), ps.size());
    addPlate(ps, points, plateArea, plateInertia, barId++);
    return idx;
  };
  if (b.supports != "none") {
    // Without an overhang the supports reach in from the ends; with one, they are centred
    // on the support lines.
    const double reach = b.overhang > 0 ? b.supportWidth / 2 : b.supportWidth;
    const double lo = b.overhang > 0 ? b.overhang : 0, hi = length - lo;
    auto left = select(ps, [&](const double* f) {
      return isConcrete(f) && f[1] < tol && std::fabs(f[0] - lo) <= reach + tol;
    });
    auto right = select(ps, [&](const double* f) {
      return isConcrete(f) && f[1] < tol && std::fabs(f[0] - hi) <= reach + tol;
    });
    auto corner = concreteAt(lo, 0);
    if (b.bearingPlates) {
      // Held at the plate's particle on the support's line only.
      auto onLine = [&](const std::vector<std::size_t>& plate, double x) {
        std::vector<std::size_t> held;
        for (std::size_t k : plate)
          if (std::fabs(ps.fixedRow(k)[0] - x) < tol) held.push_back(k);
        return held;
      };
      left = onLine(addPlateAt(left, -s), lo);
      right = onLine(addPlateAt(right, -s), hi);
      corner = left;
    }
    if (b.supports == "bearings") {
      constrain(ps, left, REST_Y);
      constrain(ps, corner, FIX_X);
      constrain(ps, right, REST_Y);
    } else {
      constrain(ps, left, FIX_X | FIX_Y);
      constrain(ps, right, FIX_Y);
    }
  }
  const auto top = select(ps, [&](const double* f) { return isConcrete(f) && f[1] > yTop - tol; });
  if (b.lineLoad != 0) loadUniform(ps, top, 0, 0, length, 0, -b.lineLoad * length);
  for (const double x : b.loadPlates) {
    std::vector<std::size_t> covered;
    for (std::size_t k : top)
      if (std::fabs(ps.fixedRow(k)[0] - x) <= b.plateWidth / 2 + tol) covered.push_back(k);
    if (covered.empty())
      throw std::invalid_argument("the loading plate at x = " + numberText(x) + " of width " +
                                  numberText(b.plateWidth) +
                                  " covers no top particle: widen it (plate_width)");
    const auto plate = addPlateAt(covered, s);
    load(ps, plate, 0, -b.plateLoad / static_cast<double>(plate.size()));
  }
  // The bottom particles nearest midspan (either side of a notch).
  double nearest = std::numeric_limits<double>::max();
  for (std::size_t k = 0; k < ps.size(); ++k) {
    const double* f = ps.fixedRow(k);
    if (isConcrete(f) && f[1] < tol) nearest = std::min(nearest, std::fabs(f[0] - mid));
  }
  monitor(ps, select(ps, [&](const double* f) {
            return isConcrete(f) && f[1] < tol && std::fabs(f[0] - mid) <= nearest + tol;
          }));
  return ps;
}

namespace {

constexpr double big = 1e300;

Parameters2d modelParameters(const Params& model) {
  Parameters2d par;
  par.read(model);
  return par;
}

// An error in building the specimen, reported at the generator's line.
[[noreturn]] void fail(const Params& p, const std::string& why) {
  const auto g = p.raw("generator");
  throw InputError(g ? g->file : p.owner(), g ? g->line : 0, why);
}

Generated generated(ParticleSet ps, const Params& p, const Schema& schema) {
  if (schema.nFixed() != N_FIXED || schema.nAlter() != N_ALTER)
    fail(p, "this generator makes MPLM particles; use it with model mplm2d");
  Generated g;
  g.particles = std::move(ps);
  return g;
}

Generated plateGenerator(const Params& p, const Schema& schema, const Params& model) {
  const PlateSpec spec = plateSpec(p, model);
  try {
    return generated(plate(spec), p, schema);
  } catch (const std::invalid_argument& e) {
    fail(p, e.what());
  }
}

Generated beamGenerator(const Params& p, const Schema& schema, const Params& model) {
  const BeamSpec spec = beamSpec(p, model);
  try {
    return generated(beam(spec), p, schema);
  } catch (const std::invalid_argument& e) {
    fail(p, e.what());
  }
}

// A hexagonal lattice of `lx` by `ly` from the origin, as hexagonalRectangle lays it.
SizeEstimate hexagonalSize(double lx, double ly, double s, prep::HexOrientation o) {
  SizeEstimate e;
  e.particles = prep::hexagonalRectangleCount(lx, ly, s, o);
  const bool alongX = o == prep::HexOrientation::BondsAlongX;
  const double p = prep::hexPitch(s);
  e.hi = {lx, ly, 0};
  e.stride = {alongX ? s : p, alongX ? p : s, 0};
  e.primitive = {alongX ? std::array<double, 3>{s, 0, 0} : std::array<double, 3>{0, s, 0},
                 alongX ? std::array<double, 3>{s / 2, p, 0} : std::array<double, 3>{p, s / 2, 0}};
  return e;
}

SizeEstimate plateSize(const Params& p, const Params& model) {
  const PlateSpec spec = plateSpec(p, model);
  return hexagonalSize(spec.width, spec.height, spec.spacing,
                       prep::hexOrientation(spec.orientation));
}

SizeEstimate beamSize(const Params& p, const Params& model) {
  const BeamSpec b = beamSpec(p, model);
  const double s = b.spacing, length = b.span + 2 * b.overhang;
  SizeEstimate e = hexagonalSize(length, b.depth, s, prep::HexOrientation::BondsAlongX);
  // The notch leaves out about its area's share of the lattice (s (sqrt(3)/2) s a site).
  if (b.notchDepth > 0) e.particles -= b.notchDepth * b.notchWidth / (s * prep::hexPitch(s));
  e.extraParticles += b.bars.size() * (std::ceil(length / s) + 1);
  if (b.stirrupDiameter > 0)
    e.extraParticles += prep::latticeSteps(length - b.stirrupFirst + b.stirrupSpacing / 2,
                                           b.stirrupFirst, b.stirrupSpacing) *
                        (std::ceil((b.depth - b.stirrupCover - stirrupFoot(b)) / s) + 1);
  const double plateSites = b.loadPlates.size() * (b.plateWidth / s + 1) +
                            (b.bearingPlates ? 2 * (b.supportWidth / s + 1) : 0);
  e.extraParticles += plateSites;
  // Steel interacts with its neighbours along its bar, and every other steel particle (a
  // link) with the concrete within s: about pi s^2 / (s (sqrt(3)/2) s) of it.
  e.extraPairs = e.extraParticles * (1 + std::numbers::pi / prep::hexPitch(1) / 2);
  return e;
}

}  // namespace

PlateSpec plateSpec(const Params& p, const Params& model) {
  const Parameters2d par = modelParameters(model);
  PlateSpec s;
  s.spacing = par.s;
  s.thickness = par.thickness;
  s.width = p.number("width", s.width, 0.0, big);
  s.height = p.number("height", s.height, 0.0, big);
  s.orientation = p.choice("orientation", s.orientation, {"x", "y"});
  const std::string loading = p.choice("loading", "tension", {"tension", "compression", "none"});
  s.compression = loading == "compression";
  s.loaded = loading != "none";
  s.stress = p.number("stress", s.stress, 1e-300, big);
  s.traction = p.flag("traction", s.traction);
  // Two rows and two particles a row at least, or the plate is not two-dimensional.
  const bool alongX = s.orientation == "x";
  const double pitch = prep::hexPitch(s.spacing);
  for (const auto& [key, size, least] :
       {std::tuple{"width", s.width, alongX ? s.spacing : pitch},
        std::tuple{"height", s.height, alongX ? pitch : s.spacing}})
    if (size < least) {
      const auto v = p.raw(key);
      throw InputError(v ? v->file : p.owner(), v ? v->line : 0,
                       std::string(key) + " = " + numberText(size) +
                           " m is less than the lattice's stride " + numberText(least) +
                           " m across it (spacing " + numberText(s.spacing) +
                           " m): the plate would be a single row of particles; give at least " +
                           numberText(least));
    }
  return s;
}

namespace {

// bar_diameter, bar_centroid, bar_count: a number each (one layer) or lists of one length.
std::vector<BeamSpec::BarLayer> barLayers(const Params& p, double depth) {
  if (!p.has("bar_diameter")) {
    for (const char* key : {"bar_centroid", "bar_count"})
      if (const auto v = p.raw(key))
        throw InputError(v->file, v->line, std::string(key) + " without bar_diameter");
    return {};
  }
  auto list = [&](const char* key, double fallback) {
    return p.has(key) ? p.numbers(key) : std::vector<double>{fallback};
  };
  const auto d = list("bar_diameter", 0), y = list("bar_centroid", BeamSpec::BarLayer{}.centroid),
             n = list("bar_count", 1);
  const std::size_t layers = std::max({d.size(), y.size(), n.size()});
  std::vector<BeamSpec::BarLayer> bars;
  for (std::size_t k = 0; k < layers; ++k) {
    auto item = [&](const std::vector<double>& v, const char* key, double lo, double hi) {
      const auto raw = p.raw(key);
      const std::string where = raw ? raw->file : p.owner();
      const int line = raw ? raw->line : 0;
      if (v.size() != 1 && v.size() != layers)
        throw InputError(where, line,
                         std::string(key) + " has " + std::to_string(v.size()) +
                             " values where another bar_ key has " + std::to_string(layers) +
                             ": give one value, or one per bar layer");
      const double x = v[v.size() == 1 ? 0 : k];
      if (!(x >= lo && x <= hi))
        throw InputError(where, line,
                         std::string(key) + " = " + numberText(x) + " is outside [" +
                             numberText(lo) + ", " + numberText(hi) + "]");
      return x;
    };
    BeamSpec::BarLayer layer;
    layer.diameter = item(d, "bar_diameter", 0, big);
    layer.centroid = item(y, "bar_centroid", 0, depth);
    const double count = item(n, "bar_count", 1, 1e6);
    if (count != std::floor(count)) {
      const auto raw = p.raw("bar_count");
      throw InputError(raw->file, raw->line, "bar_count must be whole numbers");
    }
    layer.count = static_cast<int>(count);
    if (layer.diameter > 0) bars.push_back(layer);
  }
  return bars;
}

}  // namespace

double barArea(const BeamSpec& b) {
  double area = 0;
  for (const auto& layer : b.bars) area += layer.count * prep::BarSection{layer.diameter}.area();
  return area;
}

double barCentroid(const BeamSpec& b) {
  double moment = 0;
  for (const auto& layer : b.bars)
    moment += layer.count * prep::BarSection{layer.diameter}.area() * layer.centroid;
  const double area = barArea(b);
  return area > 0 ? moment / area : 0;
}

BeamSpec beamSpec(const Params& p, const Params& model) {
  const Parameters2d par = modelParameters(model);
  BeamSpec b;
  b.spacing = par.s;
  b.thickness = par.thickness;
  b.span = p.number("span", b.span, 1e-300, big);
  b.depth = p.number("depth", b.depth, 1e-300, big);
  b.bars = barLayers(p, b.depth);
  b.stirrupDiameter = p.number("stirrup_diameter", b.stirrupDiameter, 0.0, big);
  b.stirrupFirst = p.number("stirrup_first", b.stirrupFirst, 0.0, b.span);
  b.stirrupSpacing = p.number("stirrup_spacing", b.stirrupSpacing, 1e-300, big);
  b.stirrupCover = p.number("stirrup_cover", b.stirrupCover, 0.0, b.depth);
  b.overhang = p.number("overhang", b.overhang, 0.0, big);
  b.supportWidth =
      p.number("support_width", b.supportWidth, 0.0, b.overhang > 0 ? 2 * b.overhang : b.span / 2);
  b.notchDepth = p.number("notch_depth", b.notchDepth, 0.0, b.depth);
  b.notchWidth = p.number("notch_width", b.spacing, 0.0, b.span);
  b.supports = p.choice("supports", b.supports, {"simple", "bearings", "none"});
  b.lineLoad = p.number("line_load", b.lineLoad, -big, big);
  if (p.raw("load_plates")) b.loadPlates = p.numbers("load_plates");
  const double length = b.span + 2 * b.overhang;
  for (const double x : b.loadPlates)
    if (x < 0 || x > length) {
      const auto v = p.raw("load_plates");
      throw InputError(v->file, v->line,
                       "load_plates: " + numberText(x) + " is outside the beam, [0, " +
                           numberText(length) + "] m");
    }
  b.plateWidth = p.number("plate_width", b.plateWidth, 0.0, length);
  b.plateLoad = p.number("plate_load", b.plateLoad, -big, big);
  b.plateThickness = p.number("plate_thickness", b.plateThickness, 1e-300, big);
  b.bearingPlates = p.flag("bearing_plates", b.bearingPlates);
  return b;
}

PDQ_REGISTER_ESTIMATE(plateSize, "mplm_plate");
PDQ_REGISTER_ESTIMATE(beamSize, "mplm_beam");
PDQ_REGISTER_GENERATOR(plateGenerator, "mplm_plate",
                       "MPLM plate loaded along Y at both ends (thesis §4.4.1-2): width, height, "
                       "orientation, loading, stress, traction\n"
                       "  width, height  the plate along X and Y in m (default 0.14, 0.24)\n"
                       "  orientation    \"x\": bonds along X, \"y\": along Y (default x)\n"
                       "  loading        tension, compression or none (default tension)\n"
                       "  stress         peak stress on the section at load_scale 1, Pa "
                       "(default 1e6)\n"
                       "  traction       share the load by tributary width (default false)\n"
                       "  spacing, thickness: the [model]'s\n"
                       "  IDs            from 0, row by row from the bottom, along each row");
PDQ_REGISTER_GENERATOR(beamGenerator, "mplm_beam",
                       "MPLM simply supported beam with bars and stirrups (thesis §4.4.3-6): "
                       "span, depth, overhang, notch_*, bar_*, stirrup_*, supports, "
                       "support_width, line_load, load_plates, plate_*, bearing_plates\n"
                       "  span, depth       in m (default 1.16, 0.26)\n"
                       "  overhang          beyond each support, m (default 0: supports at the "
                       "ends); the length is span + 2 overhang\n"
                       "  notch_depth       a slot up from the bottom at midspan, m (default 0: "
                       "none); notch_width its width, m (default and least: the spacing)\n"
                       "  bar_diameter      longitudinal bar, m (default 0: plain concrete)\n"
                       "  bar_centroid      its height above the bottom, m (default 0.02)\n"
                       "  bar_count         bars side by side in it (default 1); arrays of "
                       "the three: one bar layer per item\n"
                       "  stirrup_diameter  m (default 0: none); stirrup_first 0.04, "
                       "stirrup_spacing 0.15, stirrup_cover 0.02\n"
                       "  supports          simple, bearings or none (default simple); "
                       "support_width 0.04 (from each end; with an overhang, centred on the "
                       "support)\n"
                       "  line_load         on the top layer at load_scale 1, N/m (default "
                       "1e3)\n"
                       "  load_plates       centres of rigid steel loading plates on the top "
                       "face, m along the beam (default none); plate_width 0.1 (the top "
                       "particles within half of it under each), plate_load 1e3 (N down on "
                       "each at load_scale 1), plate_thickness 0.025 m\n"
                       "  bearing_plates    each support a steel plate under its particles, "
                       "held on the support's line only: free to turn (default false)\n"
                       "  spacing, thickness: the [model]'s\n"
                       "  IDs               from 0: the concrete row by row from the bottom "
                       "(the notch left out), then each bar's particles along it");

}  // namespace pdq::mplm
