#include "prep/mplm/generators.hpp"

#include <stdexcept>

#include "engine/error.hpp"
#include "models/mplm/2d/attributes.hpp"
#include "models/mplm/2d/parameters.hpp"
#include "prep/generator.hpp"

namespace pdq::mplm {
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

Generated generated(Example ex, const Params& p, const Schema& schema) {
  if (schema.nFixed() != N_FIXED || schema.nAlter() != N_ALTER)
    fail(p, "this generator makes MPLM particles; use it with model mplm2d");
  Generated g;
  g.particles = std::move(ex.particles);
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
  return s;
}

BeamSpec beamSpec(const Params& p, const Params& model) {
  const Parameters2d par = modelParameters(model);
  BeamSpec b;
  b.spacing = par.s;
  b.thickness = par.thickness;
  b.span = p.number("span", b.span, 1e-300, big);
  b.depth = p.number("depth", b.depth, 1e-300, big);
  b.barDiameter = p.number("bar_diameter", b.barDiameter, 0.0, big);
  b.barCentroid = p.number("bar_centroid", b.barCentroid, 0.0, b.depth);
  b.stirrupDiameter = p.number("stirrup_diameter", b.stirrupDiameter, 0.0, big);
  b.stirrupFirst = p.number("stirrup_first", b.stirrupFirst, 0.0, b.span);
  b.stirrupSpacing = p.number("stirrup_spacing", b.stirrupSpacing, 1e-300, big);
  b.stirrupCover = p.number("stirrup_cover", b.stirrupCover, 0.0, b.depth);
  b.supportWidth = p.number("support_width", b.supportWidth, 0.0, b.span / 2);
  b.supports = p.choice("supports", b.supports, {"simple", "bearings", "none"});
  b.lineLoad = p.number("line_load", b.lineLoad, -big, big);
  return b;
}

PDQ_REGISTER_GENERATOR(plateGenerator, "mplm_plate",
                       "MPLM plate loaded along Y at both ends (thesis §4.4.1-2): width, height, "
                       "orientation, loading, stress, traction");
PDQ_REGISTER_GENERATOR(beamGenerator, "mplm_beam",
                       "MPLM simply supported beam with bars and stirrups (thesis §4.4.3-6): "
                       "span, depth, bar_*, stirrup_*, supports, support_width, line_load");

}  // namespace pdq::mplm
