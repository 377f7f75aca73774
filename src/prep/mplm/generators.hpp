#pragma once
// Scenario generators for the MPLM specimens of thesis §4.4 (docs/scenario.md lists their
// keys; examples/mplm/*.toml uses them):
//
//     [particles]
//     generator = "mplm_beam"     # or "mplm_plate"
//     span = 1.16                 # ...
//
// The lattice spacing and thickness are the model's (`spacing`, `thickness` in [model]),
// so particles and interactions can never disagree on them. Each specimen is built for a
// unit load (load_scale = 1 gives `stress` on the plate's section, `line_load` on the beam).
#include <string>
#include <vector>

#include "engine/params.hpp"
#include "engine/particle_set.hpp"

namespace pdq::mplm {

// §4.4.1/4.4.2: the 14 × 24 cm plate loaded along Y on its two end layers each side.
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
ParticleSet plate(const PlateSpec& spec);

// §4.4.3–4.4.6: a beam with its bottom-left corner at the origin, bars and stirrups, every
// top-layer particle loaded downward (uniform line load), the bottom particles nearest
// midspan monitored. Laboratory specimens add overhangs beyond the supports and a notch.
struct BeamSpec {
  double span = 1.16, depth = 0.26, thickness = 0.12, spacing = 0.02;
  // The beam extends this far beyond each support: its length is span + 2 overhang.
  double overhang = 0;
  // A slot up from the bottom face at midspan: concrete particles below notchDepth and
  // within notchWidth/2 of midspan are left out (0: no notch). notchWidth must be at
  // least the spacing, or interactions would still cross the slot.
  double notchDepth = 0, notchWidth = 0.02;
  // Longitudinal bar layers, each one line of steel particles along the beam for `count`
  // equal bars of `diameter` with their centroid `centroid` above the bottom face; none:
  // plain concrete.
  struct BarLayer {
    double diameter = 0, centroid = 0.02;
    int count = 1;
  };
  std::vector<BarLayer> bars;
  double stirrupDiameter = 0, stirrupFirst = 0.04, stirrupSpacing = 0.15;
  double stirrupCover = 0.02;  // stirrups run from the lowest bar's centroid to depth − cover
  // Bottom-row particles within this distance of an end are supported (0: the corner
  // particle alone); with an overhang, those within half of it of each support's line. A single
  // particle carrying the whole reaction (8.7 kN at the plain beam's cracking load) is damaged long
  // before the beam fails.
  double supportWidth = 0.04;
  // "simple": pinned at the left, roller at the right (held both ways); "bearings": the
  // beam rests on both (it may lift off; the left one also holds X at its corner);
  // "none": the scenario sets its own.
  std::string supports = "simple";
  double lineLoad = 1e3;  // peak uniform load on the top layer at load_scale 1 (N/m); 0: none
  // Steel plates, each a row of steel particles one spacing above (loading) or below
  // (bearing) the face particles it covers, each bonded to the one it covers; of
  // plateThickness (m) by the beam's thickness in section, so much stiffer in bending than
  // the concrete under it that the covered particles move together. A loading plate is
  // centred at each of loadPlates (m along the beam) over the top particles within
  // plateWidth/2, and carries plateLoad (N, downward, shared equally by its particles) at
  // load_scale 1. bearingPlates: each support is a plate under its supported particles
  // held at its particle on the support's line only (a pin or roller the plate turns on).
  std::vector<double> loadPlates;
  double plateWidth = 0.1, plateLoad = 1e3, plateThickness = 0.025;
  bool bearingPlates = false;
};
// std::invalid_argument when the span or the overhang is not a whole number of spacings,
// the notch is narrower than the spacing, or a loading plate covers no top particle.
ParticleSet beam(const BeamSpec& spec);

// The specimen a generator table describes (InputError naming the key's line when a value
// is out of range); `model` is the [model] table (spacing, thickness).
PlateSpec plateSpec(const Params& generator, const Params& model);
BeamSpec beamSpec(const Params& generator, const Params& model);
// The bars' total area and its centroid's height above the bottom face (0, 0: none).
double barArea(const BeamSpec& spec);
double barCentroid(const BeamSpec& spec);

}  // namespace pdq::mplm
