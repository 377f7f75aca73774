#pragma once
// The thesis's 2D examples (§4.4.1–4.4.6) as particle sets and parameters for mplm2d.
// Each is built for a unit load (load_scale = 1 means 1 MPa of stress for the plates,
// 1 kN/m of line load for the beams), so a strength search varies load_scale only.
// The scenario generators "mplm_plate" and "mplm_beam" (generators.cpp) build the same
// specimens from a scenario's [particles] table.
#include <map>
#include <string>
#include <vector>

#include "engine/particle_set.hpp"

namespace pdq::mplm {

struct Example {
  std::string name, title;
  ParticleSet particles;
  std::map<std::string, std::string> params;  // mplm2d parameters
  long steps = 0;
  std::string unit;       // "MPa" or "kN/m"
  double unitLoad = 1;    // the load, in `unit`, at load_scale = 1
  bool beam = false;      // simply supported beam (else a plate in tension or compression)
  double span = 0;        // beams: distance between supports (m)
  double thesisMplm = 0;  // the thesis's MPLM strength, in `unit`
  double classical = 0;   // the thesis's classical / ACI 318 value, in `unit`
  double aci = 0;         // our ACI 318 (beams) or classical (plates) value, in `unit`
  std::string aciMode;    // flexural, shear, cracking (plain beam), tension, compression
};

// Names: tension_x, tension_y, compression_x, compression_y, plain_beam, rc_beam,
// rc_beam_stirrups, rc_beam_shear, deep_beam.
std::vector<std::string> exampleNames();
Example example(const std::string& name);

// §4.4.1/4.4.2: the 14 × 24 × 12 cm plate loaded along Y on its two end layers each side.
struct PlateSpec {
  double width = 0.14, height = 0.24, thickness = 0.12, spacing = 0.02;
  // "x" (bonds along X: the load is across the bonds, Fig. 4.6a) or "y".
  std::string orientation = "x";
  bool compression = false;
  bool loaded = true;   // false: no loads (the scenario sets its own)
  double stress = 1e6;  // peak stress on the section at load_scale 1 (Pa)
  // As in the thesis, every loaded particle carries the same force; `traction` instead
  // shares the force by tributary width, as the nodal loads of a uniform traction.
  bool traction = false;
};
Example plate(const PlateSpec& spec);
Example plate(const std::string& orientation, bool compression, bool traction = false);

struct BeamSpec {
  double span = 1.16, depth = 0.26, thickness = 0.12, spacing = 0.02;
  double barDiameter = 0, barCentroid = 0.02;  // 0: plain concrete
  double stirrupDiameter = 0, stirrupFirst = 0.04, stirrupSpacing = 0.15;
  double stirrupCover = 0.02;  // stirrups run from the bar's centroid to depth − cover
  // Bottom-row particles within this distance of an end are supported (0: the corner
  // particle alone). A single particle carrying the whole reaction (8.7 kN at the plain
  // beam's cracking load) is damaged long before the beam fails.
  double supportWidth = 0.04;
  // "simple": pinned at the left, roller at the right (held both ways); "bearings": the
  // beam rests on both (it may lift off; the left one also holds X at its corner);
  // "none": the scenario sets its own.
  std::string supports = "simple";
  double lineLoad = 1e3;  // peak uniform load on the top layer at load_scale 1 (N/m); 0: none
};
// §4.4.3–4.4.6: simply supported (pinned at the bottom-left end, roller at the right), every
// top-layer particle loaded downward (uniform line load), monitor at bottom midspan.
Example beam(const BeamSpec& spec);

}  // namespace pdq::mplm
