#include "prep/mplm/examples.hpp"

#include <cmath>
#include <stdexcept>

#include "studies/aci318.hpp"
#include "models/mplm/2d/attributes.hpp"
#include "prep/mplm/specimen.hpp"
#include "prep/hexagonal.hpp"

namespace pdq::mplm {
namespace {

// Thesis §4.4: Δt = s / (24 c0(steel)) = 1.808e-7 s.
const std::map<std::string, std::string> thesisParams = {{"dt", "1.808e-7"}};

std::string number(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace

std::vector<std::string> exampleNames() {
  return {"tension_x", "tension_y",        "compression_x", "compression_y", "plain_beam",
          "rc_beam",   "rc_beam_stirrups", "rc_beam_shear", "deep_beam"};
}

Example plate(const PlateSpec& spec) {
  const double s = spec.spacing, t = spec.thickness;
  const auto o = prep::hexOrientation(spec.orientation);
  Example ex;
  ex.name = std::string(spec.compression ? "compression_" : "tension_") + spec.orientation;
  ex.title = std::string("2D uniaxial ") + (spec.compression ? "compression" : "tension") +
             ", bonds along " + (spec.orientation == "x" ? "X" : "Y") + ", load along Y";
  ex.particles = newParticleSet();
  addConcrete(ex.particles, prep::hexagonalRectangle(spec.width, spec.height, s, o));
  // Two layers at each end: rows (√3/2 s apart) or zig-zag layers (s/2 apart).
  const double layer = o == prep::HexOrientation::BondsAlongX ? prep::hexPitch(s) : s / 2;
  const double reach = 1.5 * layer;
  const double yMax = maxCoord(ex.particles, 1);
  const auto top = select(ex.particles, [&](const double* f) { return f[1] > yMax - reach; });
  const auto bottom = select(ex.particles, [&](const double* f) { return f[1] < reach; });
  const double force = spec.stress * spec.width * t * (spec.compression ? -1 : 1);
  if (spec.loaded && spec.traction) {
    loadUniform(ex.particles, top, 0, 0, spec.width, 0, force);
    loadUniform(ex.particles, bottom, 0, 0, spec.width, 0, -force);
  } else if (spec.loaded) {
    load(ex.particles, top, 0, force / top.size());
    load(ex.particles, bottom, 0, -force / bottom.size());
  }
  monitor(ex.particles, top);
  ex.params["thickness"] = number(t);
  ex.params["spacing"] = number(s);
  ex.steps = 10000;
  ex.unit = "MPa";
  ex.unitLoad = spec.stress / 1e6;
  if (spec.loaded) {
    ex.aci = spec.compression ? 27.58 : 2.758;  // f'c and f_t of Table 4.1
    ex.aciMode = spec.compression ? "compression" : "tension";
  }
  return ex;
}

Example plate(const std::string& orientation, bool compression, bool traction) {
  PlateSpec spec;
  spec.orientation = orientation;
  spec.compression = compression;
  spec.traction = traction;
  Example ex = plate(spec);
  ex.params.insert(thesisParams.begin(), thesisParams.end());
  if (compression) {
    ex.thesisMplm = orientation == "x" ? 28.48 : 61.06;
    ex.classical = 27.58;
  } else {
    ex.thesisMplm = orientation == "x" ? 2.784 : 3.226;
    ex.classical = 2.758;
  }
  return ex;
}

Example beam(const BeamSpec& b) {
  const double s = b.spacing;
  Example ex;
  ex.particles = newParticleSet();
  ParticleSet& ps = ex.particles;
  addConcrete(ps, prep::hexagonalRectangle(b.span, b.depth, s, prep::HexOrientation::BondsAlongX));
  int barId = 1;
  if (b.barDiameter > 0)
    addBar(ps, prep::longitudinalBar(0, b.span, 0, b.barCentroid, b.barDiameter), s, barId++);
  if (b.stirrupDiameter > 0)
    for (const auto& st : prep::stirrups(
             b.stirrupFirst, b.stirrupSpacing, b.span - b.stirrupFirst + b.stirrupSpacing / 2,
             b.barCentroid, b.depth - b.stirrupCover, b.stirrupDiameter))
      addBar(ps, st, s, barId++);
  const double tol = 1e-6 * s;
  const double yTop = maxCoord(ps, 1);
  auto concreteAt = [&](double x, double y) {
    return select(ps, [=](const double* f) {
      return isConcrete(f) && std::fabs(f[0] - x) < tol && std::fabs(f[1] - y) < tol;
    });
  };
  if (concreteAt(0, 0).size() != 1 || concreteAt(b.span, 0).size() != 1)
    throw std::invalid_argument("the span " + number(b.span) +
                                " is not a whole number of spacings: no lattice particle at the "
                                "bottom-right corner to support");
  if (b.supports != "none") {
    const auto left = select(ps, [&](const double* f) {
      return isConcrete(f) && f[1] < tol && f[0] <= b.supportWidth + tol;
    });
    const auto right = select(ps, [&](const double* f) {
      return isConcrete(f) && f[1] < tol && f[0] >= b.span - b.supportWidth - tol;
    });
    if (b.supports == "bearings") {
      constrain(ps, left, REST_Y);
      constrain(ps, concreteAt(0, 0), FIX_X);
      constrain(ps, right, REST_Y);
    } else {
      constrain(ps, left, FIX_X | FIX_Y);
      constrain(ps, right, FIX_Y);
    }
  }
  const auto top = select(ps, [&](const double* f) { return isConcrete(f) && f[1] > yTop - tol; });
  if (b.lineLoad != 0) loadUniform(ps, top, 0, 0, b.span, 0, -b.lineLoad * b.span);
  const auto mid = select(ps, [&](const double* f) {
    return isConcrete(f) && f[1] < tol && std::fabs(f[0] - b.span / 2) <= s / 2 + tol;
  });
  monitor(ps, mid);
  ex.params["thickness"] = number(b.thickness);
  ex.params["spacing"] = number(s);
  ex.unit = "kN/m";
  ex.unitLoad = b.lineLoad / 1e3;
  ex.beam = true;
  ex.span = b.span;
  if (b.barDiameter > 0) {
    aci318::Section sec;
    sec.b = b.thickness;
    sec.h = b.depth;
    sec.d = b.depth - b.barCentroid;
    sec.As = prep::Bar{0, 0, 0, 0, b.barDiameter}.area();
    if (b.stirrupDiameter > 0) {
      sec.Av = prep::Bar{0, 0, 0, 0, b.stirrupDiameter}.area();
      sec.sv = b.stirrupSpacing;
    }
    const aci318::Capacity c = aci318::simplySupportedUniform(sec, b.span);
    ex.aci = c.governing() / 1e3;
    ex.aciMode = c.mode();
  } else {
    // Classical: the bending stress reaches f_t (§4.4.3).
    ex.aci = aci318::uniformLoadFromMoment(aci318::crackingMoment(2.758e6, b.thickness, b.depth),
                                           b.span) /
             1e3;
    ex.aciMode = "cracking";
  }
  return ex;
}

Example example(const std::string& name) {
  if (name == "tension_x") return plate("x", false);
  if (name == "tension_y") return plate("y", false);
  if (name == "compression_x") return plate("x", true);
  if (name == "compression_y") return plate("y", true);
  BeamSpec b;
  Example ex;
  if (name == "plain_beam") {
    ex = beam(b);
    ex.title = "2D plain concrete beam, simply supported (§4.4.3)";
    ex.steps = 40000;
    ex.thesisMplm = 57;
    ex.classical = 22.14;
  } else if (name == "rc_beam") {
    b.barDiameter = 0.0127;
    ex = beam(b);
    ex.title = "2D RC beam, one 1.27 cm bar, no stirrups (§4.4.4)";
    ex.steps = 80000;
    ex.thesisMplm = 78.74;
    ex.classical = 72.24;
  } else if (name == "rc_beam_stirrups") {
    b.barDiameter = 0.0127;
    b.stirrupDiameter = 0.01;
    ex = beam(b);
    ex.title = "2D RC beam with stirrups, bending failure (§4.4.5)";
    ex.steps = 80000;
    ex.thesisMplm = 68.63;
    ex.classical = 72.24;
  } else if (name == "rc_beam_shear") {
    b.barDiameter = 0.03175;
    b.stirrupDiameter = 0.01;
    ex = beam(b);
    ex.title = "2D RC beam, 3.175 cm bar and stirrups, shear failure (§4.4.6)";
    ex.steps = 80000;
    ex.thesisMplm = 252;
    ex.classical = 210;
  } else if (name == "deep_beam") {
    b.span = 4.06;
    b.depth = 1.02;
    b.thickness = 0.41;
    b.barDiameter = 0.1016;
    b.barCentroid = 0.051;
    b.stirrupDiameter = 0.0254;
    b.stirrupFirst = 0.089;
    b.stirrupSpacing = 0.432;
    b.stirrupCover = 0.051;
    // Bearings in proportion to the beam, which it rests on: 4 cm ones crush and tear
    // under the 0.8 MN reaction, and the beam fails at its supports (docs/mplm.md).
    b.supportWidth = 0.2;
    b.supports = "bearings";
    ex = beam(b);
    ex.title = "2D RC beam 4.06 x 1.02 x 0.41 m with stirrups (§4.4.6)";
    ex.steps = 45000;
    ex.thesisMplm = 497;
    ex.classical = 599;
  } else {
    throw std::invalid_argument("unknown MPLM example '" + name + "'");
  }
  ex.name = name;
  ex.params.insert(thesisParams.begin(), thesisParams.end());
  return ex;
}

}  // namespace pdq::mplm
