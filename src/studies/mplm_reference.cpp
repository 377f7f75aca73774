#include "studies/mplm_reference.hpp"

#include "prep/rebar.hpp"

namespace pdq::mplm {
namespace {

Parameters parameters(const Params& model) {
  Parameters par;
  par.read(model);
  return par;
}

double barArea(double diameter) { return prep::BarSection{diameter}.area(); }

}  // namespace

Strengths strengths(const Parameters& par) {
  Strengths s;
  s.ft = par.E * par.law.epsT;
  s.fc = 10 * s.ft;
  s.Es = par.steelE;
  s.fy = par.steelE * par.steelYield;
  return s;
}

aci318::Section section(const BeamSpec& b, const Parameters& par) {
  const Strengths m = strengths(par);
  aci318::Section sec;
  sec.b = b.thickness;
  sec.h = b.depth;
  sec.d = b.depth - barCentroid(b);
  sec.As = barArea(b);
  sec.fc = m.fc;
  sec.fy = sec.fyt = m.fy;
  sec.Es = m.Es;
  if (b.stirrupDiameter > 0) {
    sec.Av = barArea(b.stirrupDiameter);
    sec.sv = b.stirrupSpacing;
  }
  return sec;
}

Reference plateReference(const Params& generator, const Params& model) {
  const PlateSpec spec = plateSpec(generator, model);
  Reference r;
  if (!spec.loaded) return r;
  const Strengths m = strengths(parameters(model));
  r.unit = "MPa";
  r.unitLoad = spec.stress / 1e6;
  r.value = (spec.compression ? m.fc : m.ft) / 1e6;
  r.label = "classical";
  r.mode = spec.compression ? "compression" : "tension";
  return r;
}

Reference beamReference(const Params& generator, const Params& model) {
  const BeamSpec b = beamSpec(generator, model);
  Reference r;
  if (b.lineLoad == 0) return r;
  r.unit = "kN/m";
  r.unitLoad = b.lineLoad / 1e3;
  if (b.supports == "none") return r;
  const Parameters par = parameters(model);
  if (!b.bars.empty()) {
    const aci318::Capacity c = aci318::simplySupportedUniform(section(b, par), b.span);
    r.value = c.governing() / 1e3;
    r.label = "ACI 318";
    r.mode = c.mode();
  } else {
    const double Mcr = aci318::crackingMoment(strengths(par).ft, b.thickness, b.depth);
    r.value = aci318::uniformLoadFromMoment(Mcr, b.span) / 1e3;
    r.label = "classical";
    r.mode = "cracking";
  }
  return r;
}

std::optional<aci318::Section> section(const mplm3d::BeamSpec& b, const Parameters& par) {
  // Downward loads put the top in tension on a cantilever, the bottom on a simple span.
  const bool topInTension = (b.supports == "clamped") == (b.load > 0);
  double area = 0, moment = 0;
  for (const mplm3d::BarSpec& bar : b.bars)
    if ((bar.y > b.depth / 2) == topInTension) {
      area += bar.section.area();
      moment += bar.section.area() * bar.y;
    }
  if (!(area > 0)) return std::nullopt;
  const Strengths m = strengths(par);
  aci318::Section sec;
  sec.b = b.width;
  sec.h = b.depth;
  sec.d = topInTension ? moment / area : b.depth - moment / area;
  sec.As = area;
  sec.fc = m.fc;
  sec.fy = sec.fyt = m.fy;
  sec.Es = m.Es;
  if (b.stirrups) {
    sec.Av = 2 * b.stirrups->section.area();
    sec.sv = b.stirrups->spacing;
  }
  return sec;
}

Reference memberReference(const Params& generator, const Params& model) {
  const mplm3d::BeamSpec b = mplm3d::beamSpec(generator, model);
  Reference r;
  const bool tip = b.loading == "tip" && b.supports == "clamped";
  const bool top = b.loading == "top" && (b.supports == "simple" || b.supports == "bearings");
  if (b.loading == "tip") {
    r.unit = "N";
    r.unitLoad = b.load;
  } else if (b.loading == "top") {
    r.unit = "kN/m";
    r.unitLoad = b.load / 1e3;
  }
  if (!tip && !top) return r;
  const Parameters par = parameters(model);
  const double scale = tip ? 1.0 : 1e-3;
  if (const auto sec = section(b, par)) {
    const aci318::Capacity c = tip ? aci318::cantileverTip(*sec, b.length)
                                   : aci318::simplySupportedUniform(*sec, b.length);
    r.value = c.governing() * scale;
    r.label = "ACI 318";
    r.mode = c.mode();
  } else {
    const double Mcr = aci318::crackingMoment(strengths(par).ft, b.width, b.depth);
    r.value = (tip ? Mcr / b.length : aci318::uniformLoadFromMoment(Mcr, b.length)) * scale;
    r.label = "classical";
    r.mode = "cracking";
  }
  return r;
}

}  // namespace pdq::mplm
